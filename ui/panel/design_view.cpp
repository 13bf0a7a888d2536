#include "ui/panel/design_view.hpp"

#include <algorithm>
#include <atomic>
#include <stop_token>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "model/design/default_forcing.hpp"
#include "model/design/design_grid_file.hpp"
#include "model/design/prediction_file.hpp"
#include "model/design/stylus_export.hpp"
#include "model/io/printer_profile.hpp"
#include "ui/figures/stylus_sheet.hpp"
#include "model/io/atomic_file.hpp"
#include "model/design/tool_sound.hpp"
#include "model/space/bootstrap.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace design = model::design;

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Cell centres spread over the grid, `count` of them (all when fewer).
std::vector<std::pair<double, double>> spread_cell_centres(const design::GridAxes& axes, std::size_t count) {
  std::vector<std::pair<double, double>> all;
  for (std::size_t i = 0; i + 1 < axes.fractions.size(); ++i)
    for (std::size_t j = 0; j + 1 < axes.tips_m.size(); ++j)
      all.emplace_back(0.5 * (axes.fractions[i] + axes.fractions[i + 1]), 0.5 * (axes.tips_m[j] + axes.tips_m[j + 1]));
  if (all.size() <= count || count == 0) return all;
  std::vector<std::pair<double, double>> picked;
  for (std::size_t k = 0; k < count; ++k) picked.push_back(all[(2 * k + 1) * all.size() / (2 * count)]);
  return picked;
}

// "fine grid: 5 of 23 designs solved, about 70 s left", the time from the rate so far.
std::string grid_progress_text(const std::string& step, std::size_t done, std::size_t total, double elapsed_s) {
  std::string text = step + ": " + std::to_string(done) + " of " + std::to_string(total) + " designs solved";
  if (done == 0 || done >= total) return text + (done == 0 ? " (the first sets the pace)" : "");
  const double left = elapsed_s / static_cast<double>(done) * static_cast<double>(total - done);
  return text + ", about " + duration_words(left) + " left";
}

model::space::Placement placement_of(const SceneTool& t) {
  model::space::Placement p;
  p.mean = t.region.mean;
  p.covariance = t.region.covariance.size() > 0 ? t.region.covariance
                                                : Eigen::MatrixXd::Zero(t.region.mean.size(), t.region.mean.size());
  return p;
}

}  // namespace

DesignView::DesignView(PanelAudio& audio, std::filesystem::path catalog, std::filesystem::path forcing,
                       DesignSettings settings)
    : audio_(audio), catalog_(std::move(catalog)), forcing_(std::move(forcing)), settings_(std::move(settings)) {
  space_ = std::make_unique<SpaceView>(SpaceScene{}, [this](const std::vector<ToolChoice>&) {
    if (!space_->chosen().empty()) set_target(space_->chosen().back());
  });
  space_->set_side_panel(false);
  space_->set_overlay([this](ImDrawList* draw, const PlotFrame& frame, int ax, int ay) { draw_overlay(draw, frame, ax, ay); });
}

DesignView::~DesignView() {
  // The jobs use the inputs and the grid: stopped and joined before those go.
  error_job_.reset();
  job_.reset();
}

void DesignView::stop_work() {
  if (job_) job_->cancel();
  if (error_job_) error_job_->cancel();
}

void DesignView::set_space(const SpaceScene& scene, std::optional<model::space::DescriptorMap> map) {
  space_->set_scene(scene);
  map_ = std::move(map);
  place_loop();  // the loop's target is a tool of the new scene, or none
  if (grid_ && !coarse_) {
    if (error_job_) {
      error_stale_ = true;
      error_job_->cancel();
    } else {
      start_error_job();
    }
  }
  targets_.clear();
  search_.reset();
  update_design(false);
}

void DesignView::prepare() {
  if (inputs_ || job_) return;
  coarse_handover_ = std::make_shared<CoarseHandover>();
  job_ = std::make_unique<BackgroundJob<DesignInputs>>(
      "design grid", [catalog = catalog_, forcing = forcing_, s = settings_,
                      handover = coarse_handover_](JobControl& control) {
        model::forcing::ForcingInputOptions options;
        options.catalog = catalog;
        options.mesh_size = s.mesh_size_m;
        options.modes = s.modes;
        DesignInputs made;
        if (forcing.empty()) {  // the demo's forcing model, fitted once and kept in the user cache
          design::DefaultsOptions defaults;
          defaults.catalog = catalog;
          defaults.stop = control.stop_token();
          defaults.progress = step_reporter(control, "the default forcing model (fitted once, then kept): ");
          auto model = design::default_forcing_model(defaults);
          made.inputs = design::load_prediction_inputs(options, model.file, std::move(model.value));
        } else {
          control.message("reading the forcing model");
          made.inputs = design::load_prediction_inputs(options, forcing);
        }
        const auto axes = design::even_axes(s.material_a, s.material_b, s.fraction_points, s.min_tip_m, s.max_tip_m,
                                            s.tip_points);
        control.message("looking for the design grid in the user cache");
        // The time left, measured as the step goes: this machine's own rate, whatever its load.
        auto step_start = std::chrono::steady_clock::now();
        std::string step;
        const model::numeric::StepProgress progress = [&](const std::string& name, std::size_t done, std::size_t total) {
          if (name != step) step = name, step_start = std::chrono::steady_clock::now();
          const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
          control.progress(total ? static_cast<double>(done) / static_cast<double>(total) : 0.0);
          control.message(grid_progress_text(name, done, total, elapsed));
        };
        made.grid = design::cached_design_response_grid(
            *made.inputs, axes, progress, control.stop_token(), 0,
            [&](const design::DesignResponseGrid& coarse) {
              std::lock_guard lock(handover->mutex);
              handover->inputs = made.inputs;
              handover->grid = coarse;
              if (auto wake = job_done_hook.load()) wake();
            });
        return made;
      });
}

void DesignView::set_design(double fraction, double tip_mm) {
  fraction_ = static_cast<float>(fraction);
  tip_mm_ = static_cast<float>(tip_mm);
  update_design(true);
}

void DesignView::set_target(std::size_t tool) {
  if (tool >= space_->scene().tools.size()) return;
  const auto at = std::find(targets_.begin(), targets_.end(), tool);
  if (!group_mode_) {
    targets_ = {tool};
  } else if (at == targets_.end()) {
    targets_.push_back(tool);
  } else {
    targets_.erase(at);
  }
  search_.reset();
  update_design(true);
}

void DesignView::set_group_mode(bool group) {
  group_mode_ = group;
  if (!group && targets_.size() > 1) targets_.resize(1), search_.reset();
}

std::string DesignView::surface() const {
  return targets_.empty() ? "office" : space_->scene().tools[targets_.front()].choice.surface;
}

design::Evaluate DesignView::search_evaluation() const {
  auto predict = design::grid_predictor(inputs_->setup, *grid_, surface());
  std::vector<model::space::Placement> placements;
  for (std::size_t t : targets_) placements.push_back(placement_of(space_->scene().tools[t]));
  // 500 draws: a search compares hundreds of candidates per slider-speed interaction.
  if (placements.size() == 1) return design::distance_to_target(std::move(predict), *map_, placements.front(), 500);
  return design::distance_to_targets(std::move(predict), *map_, std::move(placements), aim_, 500);
}

void DesignView::update_design(bool sound) {
  if (!inputs_ || !grid_) return;
  const auto start = std::chrono::steady_clock::now();
  try {
    predicted_ = design::predict_from_grid(inputs_->setup, *grid_, fraction_, tip_mm_ * 1e-3, surface());
    // The sound first: the ear notices a late change, the eye not a placement a millisecond later.
    if (play_ && sound) {
      audio_.play_now(design::predicted_sound(*predicted_));
      last_sound_sent_ = std::chrono::steady_clock::now();
    }
    placement_.reset();
    if (map_) placement_ = design::place_predicted(*map_, *predicted_);
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  last_update_ms_ = milliseconds_since(start);
}

void DesignView::search(bool two_d) {
  if (!inputs_ || !grid_ || !map_ || targets_.empty()) {
    error_ = "a search needs the grid, a space with a descriptor map and a target tool";
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    const auto evaluate = search_evaluation();
    if (two_d) {
      design::RangeSearchOptions options;
      options.first_material = grid_->axes.material_a;
      options.second_material = grid_->axes.material_b;
      options.min_tip_m = grid_->axes.tips_m.front();
      options.max_tip_m = grid_->axes.tips_m.back();
      options.constraints = constraints_;
      search_ = design::range_search(evaluate, options);
    } else {
      design::LineSearchOptions options;
      options.constraints = constraints_;
      search_ = design::line_search(design::grid_point(grid_->axes, 0.0, tip_mm_ * 1e-3),
                                    design::grid_point(grid_->axes, 1.0, tip_mm_ * 1e-3), evaluate, options);
    }
    const auto& best = search_->best().point;
    set_design(best.fraction_of(grid_->axes.material_b), best.tip_diameter_m * 1e3);
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  last_search_ms_ = milliseconds_since(start);
}

std::string DesignView::save_prediction(const std::filesystem::path& file) const {
  if (!predicted_ || !inputs_) return "there is no design to save yet (the grid is not ready)";
  try {
    const std::string source = inputs_->threshold ? inputs_->threshold->source() : std::string();
    model::io::write_file_atomically(file, design::prediction_json(*predicted_, source).dump(2) + "\n");
    return {};
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::function<void()> DesignView::stylus_export(const std::filesystem::path& file,
                                                std::optional<model::space::SpaceFile> space) const {
  if (!predicted_ || !inputs_) return {};
  // The design is placed on the sheet when there is a space with a map and targets to measure the
  // distance to; a judged target is drawn by the space itself, a placed one as placed.
  std::vector<figures::SheetTarget> targets;
  std::vector<model::space::Placement> placements;
  if (map_ && space)
    for (std::size_t i : targets_) {
      const auto& t = space_->scene().tools[i];
      placements.push_back(placement_of(t));
      targets.push_back({t.choice.tool + "/" + t.choice.surface, t.judged ? std::nullopt : std::optional(placements.back())});
    }
  return [file, point = predicted_->point, surface = surface(), inputs = inputs_, map = map_,
          space = std::move(space), targets = std::move(targets), placements = std::move(placements), aim = aim_,
          printer = printer_] {
    // The sheet's prediction solves the design itself (the sliders show the grid's interpolation).
    std::optional<design::PredictedTool> tool;
    const design::Predict predict = [&](const design::DesignPoint& p) {
      tool = design::predict_tool(inputs->setup, p, surface);
      return *tool;
    };
    figures::StylusSheetInputs sheet;
    sheet.aim = aim == model::space::GroupAim::mean ? "mean" : "largest";
    auto print = design::stylus_print(inputs->setup, point);
    if (!printer.empty()) print.printer = model::io::find_printer_profile(printer);  // the library refuses what it cannot make
    if (!placements.empty()) {
      const auto candidate = design::distance_to_targets(predict, *map, placements, aim)(point);
      // A printer that cannot mix prints one material: each alone, placed, against the targets.
      print.substitutes = design::single_material_substitutes(
          point, design::distance_to_target(inputs->setup, surface, *map, candidate.placement), placements, aim);
      sheet.space = &*space;
      sheet.placement = candidate.placement;
      sheet.targets = targets;
      for (std::size_t t = 0; t < targets.size(); ++t) {
        sheet.targets[t].distance = candidate.target_distances[t];
        sheet.targets[t].distance_sd = candidate.target_distance_sds[t];
      }
    } else {
      predict(point);
    }
    sheet.tool = &*tool;
    figures::export_stylus(file, print, sheet);
  };
}

std::string DesignView::open_prediction(const std::filesystem::path& file) {
  if (!inputs_ || !grid_ || !inputs_->threshold) return "the design grid is not ready yet";
  try {
    const auto read = design::read_prediction(file, *inputs_->threshold);
    const auto& axes = grid_->axes;
    for (const auto& share : read.point.mix)
      if (share.material != axes.material_a && share.material != axes.material_b)
        return file.string() + ": the design " + design::label(read.point) + " has " + share.material +
               ", and this grid mixes " + axes.material_a + " and " + axes.material_b + " only";
    const double tip_mm = read.point.tip_diameter_m * 1e3;
    if (tip_mm < axes.tips_m.front() * 1e3 - 1e-9 || tip_mm > axes.tips_m.back() * 1e3 + 1e-9) {
      char range[96];
      std::snprintf(range, sizeof range, "the tip %.3g mm is outside the grid's %.3g-%.3g mm", tip_mm,
                    axes.tips_m.front() * 1e3, axes.tips_m.back() * 1e3);
      return file.string() + ": " + range;
    }
    set_design(read.point.fraction_of(axes.material_b), tip_mm);
    return error_;
  } catch (const std::exception& e) {
    return e.what();
  }
}

bool DesignView::design_heard() const {
  const auto heard = audio_.sounding();
  return heard && predicted_ && heard->tool == design::predicted_sound(*predicted_).name;
}

void DesignView::take_grids() {
  if (coarse_handover_ && !grid_) {
    std::lock_guard lock(coarse_handover_->mutex);
    if (coarse_handover_->grid) {
      inputs_ = coarse_handover_->inputs;
      grid_ = std::move(*coarse_handover_->grid);
      coarse_handover_->grid.reset();
      coarse_ = true;
      tip_mm_ = std::clamp(tip_mm_, static_cast<float>(grid_->axes.tips_m.front() * 1e3),
                           static_cast<float>(grid_->axes.tips_m.back() * 1e3));
      update_design(false);
    }
  }
  if (!job_ || !job_->done()) return;
  if (auto made = job_->take_result()) {
    const bool heard = design_heard();
    inputs_ = std::move(made->inputs);
    grid_ = std::move(made->grid);
    coarse_ = false;
    tip_mm_ = std::clamp(tip_mm_, static_cast<float>(grid_->axes.tips_m.front() * 1e3),
                         static_cast<float>(grid_->axes.tips_m.back() * 1e3));
    update_design(heard);  // the finer prediction replaces the one heard, if it is heard
    start_error_job();
  } else {
    error_ = job_->error();
  }
  job_.reset();
  coarse_handover_.reset();
}

// The interpolation's error against the full FEM, measured in the background in the space shown
// (its map places the cells): a space opened meanwhile makes the measurement start again once the
// one running ends, since the UI does not wait for a cell's FEM solve.
void DesignView::start_error_job() {
  error_stale_ = false;
  grid_error_.reset();
  error_job_ = std::make_unique<BackgroundJob<design::GridError>>(
      "grid error", [this, points = spread_cell_centres(grid_->axes, settings_.error_points), map = map_,
                     surface = surface()](JobControl& control) {
        const std::size_t dims = map ? map->descriptor_names.size() : 2;
        return design::measure_grid_error_at(
            inputs_->setup, *grid_, points, surface, dims, map ? &*map : nullptr,
            [&control](std::size_t done, std::size_t total) {
              control.progress(static_cast<double>(done) / static_cast<double>(total));
            },
            control.stop_token(), 1);
      });
}

void DesignView::draw() {
  take_grids();
  if (error_job_ && error_job_->done()) {
    auto measured = error_job_->take_result();
    error_job_.reset();
    if (error_stale_) start_error_job();
    else if (measured) grid_error_ = std::move(*measured);
  }
  if (!inputs_ && !job_ && error_.empty()) prepare();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  ImGui::BeginChild("design-space", {avail.x - 360.0f, avail.y});
  space_->draw();
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("design-controls", {0.0f, avail.y});
  draw_controls();
  ImGui::EndChild();
}

void DesignView::draw_target_controls() {
  section(targets_.size() > 1 ? "Targets" : "Target");
  ImGui::TextDisabled(group_mode_ ? "click tools to add or remove them" : "click a tool in the space");
  if (targets_.empty()) ImGui::TextWrapped("none yet");
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    const auto& t = space_->scene().tools[targets_[i]];
    if (search_ && search_->best().target_distances.size() == targets_.size())
      ImGui::TextWrapped("%s: %.2f (sd %.2f)", t.label.c_str(), search_->best().target_distances[i],
                         search_->best().target_distance_sds[i]);
    else
      ImGui::TextWrapped("%s", t.label.c_str());
  }
  bool group = group_mode_;
  if (ImGui::Checkbox("one design for a group", &group)) set_group_mode(group);
  if (group_mode_) {
    int aim = aim_ == model::space::GroupAim::mean ? 1 : 0;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120.0f);
    if (ImGui::Combo("##aim", &aim, "largest distance\0mean distance\0")) {
      aim_ = aim == 1 ? model::space::GroupAim::mean : model::space::GroupAim::largest;
      search_.reset();
    }
  }
  ImGui::Text("surface: %s", surface().c_str());
}

void DesignView::draw_constraint_controls() {
  if (!ImGui::CollapsingHeader("Constraints")) return;
  auto& c = constraints_;
  const float lo = static_cast<float>(grid_->axes.tips_m.front() * 1e3), hi = static_cast<float>(grid_->axes.tips_m.back() * 1e3);
  bool tips = c.min_tip_m || c.max_tip_m;
  float tip_lo = c.min_tip_m ? static_cast<float>(*c.min_tip_m * 1e3) : lo;
  float tip_hi = c.max_tip_m ? static_cast<float>(*c.max_tip_m * 1e3) : hi;
  bool changed = ImGui::Checkbox("tips", &tips);
  ImGui::SameLine();
  changed |= ImGui::DragFloatRange2("mm##tips", &tip_lo, &tip_hi, 0.01f, lo, hi, "%.2f", "%.2f");
  if (changed) {
    c.min_tip_m.reset(), c.max_tip_m.reset();
    if (tips) c.min_tip_m = tip_lo * 1e-3, c.max_tip_m = std::max(tip_lo, tip_hi) * 1e-3;
  }
  for (const auto* material : {&grid_->axes.material_a, &grid_->axes.material_b}) {
    const bool listed = c.materials.empty() || std::find(c.materials.begin(), c.materials.end(), *material) != c.materials.end();
    bool allowed = listed;
    if (ImGui::Checkbox(("allow " + *material).c_str(), &allowed) && allowed != listed) {
      if (c.materials.empty()) c.materials = {grid_->axes.material_a, grid_->axes.material_b};
      if (allowed) c.materials.push_back(*material);
      else std::erase(c.materials, *material);
      changed = true;
    }
    if (material == &grid_->axes.material_a) ImGui::SameLine();
  }
  for (const auto* material : {&grid_->axes.material_a, &grid_->axes.material_b}) {
    float cost = static_cast<float>(c.cost.count(*material) ? c.cost.at(*material) : 1.0);
    ImGui::SetNextItemWidth(90.0f);
    if (ImGui::InputFloat(("cost of " + *material).c_str(), &cost, 0.0f, 0.0f, "%.3g")) c.cost[*material] = cost, changed = true;
    else if (!c.cost.count(*material)) c.cost[*material] = cost;
  }
  bool limited = c.max_cost.has_value();
  float max_cost = static_cast<float>(c.max_cost.value_or(2.0));
  changed |= ImGui::Checkbox("cost at most", &limited);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f);
  changed |= ImGui::InputFloat("##max-cost", &max_cost, 0.0f, 0.0f, "%.3g");
  if (changed) {
    c.max_cost.reset();
    if (limited) c.max_cost = max_cost;
    search_.reset();
  }
  if (c.any()) ImGui::TextWrapped("within %s", design::describe(c).c_str());
}

void DesignView::draw_controls() {
  if (loop_ && loop_->refresh_if_changed()) place_loop();
  if (loop_) loop_->draw_table();
  draw_target_controls();
  section("Design");
  if (job_) {
    if (coarse_) ImGui::TextWrapped("A coarse grid is in use while the fine one is solved:");
    if (progress_with_cancel("design-grid", static_cast<float>(job_->progress()), job_->message().c_str())) job_->cancel();
    if (!grid_) return;
  }
  if (!grid_) {
    if (!error_.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", error_.c_str());
    if (ImGui::Button("Solve the grid")) prepare();
    return;
  }
  bool moved = false;
  char label[64];
  std::snprintf(label, sizeof label, "%s share", grid_->axes.material_b.c_str());
  moved |= ImGui::SliderFloat(label, &fraction_, 0.0f, 1.0f, "%.2f");
  mix_slider_ = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
  moved |= ImGui::SliderFloat("tip mm", &tip_mm_, static_cast<float>(grid_->axes.tips_m.front() * 1e3),
                              static_cast<float>(grid_->axes.tips_m.back() * 1e3), "%.2f");
  if (ImGui::Checkbox("play as it moves", &play_) && !play_) audio_.stop();
  if (play_ && stroke_widgets(audio_.stroke())) audio_.stroke_changed();
  if (moved) update_design(true);
  if (predicted_) {
    ImGui::TextWrapped("%s", design::label(predicted_->point).c_str());
    ImGui::Text("mu %.3f, weighted mean %.3g, first mode %.0f Hz", predicted_->mu, predicted_->vibration.weighted_mean,
                predicted_->first_mode_hz);
  }
  ImGui::Text("slider to placement and sound: %.1f ms", last_update_ms_);
  if (!map_) ImGui::TextWrapped("This space has no descriptor map: designs cannot be placed in it.");
  section("Search");
  draw_constraint_controls();
  if (ImGui::Button("Line search along the mix")) search(false);
  ImGui::SameLine();
  if (ImGui::Button("2-D search")) search(true);
  if (search_) {
    const auto& best = search_->best();
    ImGui::TextWrapped("%zu designs in %.0f ms; nearest%s: %s at %.2f (sd %.2f)", search_->evaluated.size(),
                       last_search_ms_, targets_.size() > 1 ? (aim_ == model::space::GroupAim::mean ? " on mean" : " at worst") : "",
                       design::label(best.point).c_str(), best.distance, best.distance_sd);
  }
  draw_printer_choice();
  section("Interpolation against the FEM");
  if (error_job_) ImGui::ProgressBar(static_cast<float>(error_job_->progress()), {-1.0f, 0.0f}, "solving cell centres");
  if (grid_error_) {
    ImGui::TextWrapped("at %zu cell centres: |H| within %.2f dB rms; placement within %.2g (its own sd %.2g)",
                       grid_error_->cells.size(), grid_error_->response_rms_db, grid_error_->placement_distance,
                       grid_error_->placement_sd);
  }
  ImGui::TextWrapped("%s grid %zu x %zu, %s-%s, %zu mode crossings blended", coarse_ ? "coarse" : "the",
                     grid_->axes.fractions.size(), grid_->axes.tips_m.size(), grid_->axes.material_a.c_str(),
                     grid_->axes.material_b.c_str(), grid_->mode_jumps);
  if (!error_.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", error_.c_str());
}

// The printer "Export stylus for printing..." writes for: the bundled profiles and the lab's own,
// listed once (a folder read is not for every frame).
void DesignView::draw_printer_choice() {
  section("Printing");
  if (printer_names_.empty()) {
    printer_names_ = model::io::bundled_printer_names();
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(model::io::user_printers_folder(), ec))
      if (e.path().extension() == ".json") printer_names_.push_back(e.path().stem().string());
  }
  const std::string none = "none (the printer's own settings)";
  if (ImGui::BeginCombo("printer", printer_.empty() ? none.c_str() : printer_.c_str())) {
    if (ImGui::Selectable(none.c_str(), printer_.empty())) printer_.clear();
    for (const auto& name : printer_names_)
      if (ImGui::Selectable(name.c_str(), name == printer_)) printer_ = name;
    ImGui::EndCombo();
  }
}

std::string DesignView::open_loop(const std::filesystem::path& folder_or_file) {
  const auto folder =
      folder_or_file.filename() == "loop.json" ? folder_or_file.parent_path() : folder_or_file;
  try {
    LoopRounds opened(folder);  // a loop that does not read leaves the one shown
    loop_ = std::move(opened);
  } catch (const std::exception& e) {
    return e.what();
  }
  place_loop();
  return {};
}

void DesignView::place_loop() {
  if (!loop_) return;
  std::vector<Eigen::VectorXd> places;
  for (const auto& r : loop_->rounds()) {
    places.push_back(r.predicted_position);
    if (r.measured) places.push_back(r.measured->position);
  }
  loop_->set_target_place(std::nullopt);
  for (const auto& t : space_->scene().tools)
    if (t.choice.tool + "/" + t.choice.surface == loop_->request().target) {
      loop_->set_target_place(t.region.mean);
      places.push_back(t.region.mean);
    }
  space_->set_overlay_places(std::move(places));
}

void DesignView::draw_overlay(ImDrawList* draw, const PlotFrame& frame, int ax, int ay) const {
  if (loop_) loop_->draw_overlay(draw, frame, ax, ay);
  const bool one_d = ax == ay;
  const auto at = [&](const Eigen::VectorXd& p) { return frame.to_screen(p[ax], one_d ? 0.0 : p[ay]); };
  for (std::size_t t : targets_) draw->AddCircle(at(space_->scene().tools[t].region.mean), 12.0f, IM_COL32(255, 80, 80, 255), 24, 2.5f);
  if (search_) {
    for (std::size_t i = 0; i < search_->evaluated.size(); ++i) draw->PathLineTo(at(search_->evaluated[i].placement.mean));
    draw->PathStroke(IM_COL32(255, 255, 255, 120), 0, 1.0f);
    for (const auto& c : search_->evaluated) draw->AddCircleFilled(at(c.placement.mean), 2.0f, IM_COL32(255, 255, 255, 160));
  }
  if (!placement_) return;
  const auto region = model::space::gaussian_region(placement_->mean, placement_->covariance, {0.68, 0.95});
  for (std::size_t k = 0; k < region.radius.size(); ++k) {
    const auto e = model::space::plane_ellipse(region, k, ax, one_d ? ax : ay);
    draw_ellipse(draw, frame, placement_->mean[ax], one_d ? 0.0 : placement_->mean[ay], e.semi_axis_1,
                 one_d ? 0.0 : e.semi_axis_2, e.angle_rad, IM_COL32(255, 255, 255, k == 0 ? 220 : 110), 1.5f);
  }
  draw_marker(draw, at(placement_->mean), Marker::diamond, 6.0f, IM_COL32(255, 255, 255, 255), true);
}

}  // namespace nibrig::ui::panel
