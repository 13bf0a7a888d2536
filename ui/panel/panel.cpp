#include "ui/panel/panel.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <stop_token>
#include <string>
#include <vector>

#include "model/design/default_forcing.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/forcing_store.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/user_cache.hpp"
#include "model/space/space_fit_file.hpp"
#include "ui/panel/devices_view.hpp"
#include "ui/panel/experiment_view.hpp"
#include "ui/panel/pad_view.hpp"
#include "ui/panel/rig_view.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace {

// The error line's height before it scrolls: a long error is read whole, without pushing the views
// off a small window.
constexpr int kErrorLines = 3;
// Room kept right of the status line for its A, B, C buttons.
constexpr float kStatusButtons = 90.0f;

constexpr View kViews[] = {View::space, View::design,  View::rig,
                           View::pad,   View::devices, View::experiment};

std::filesystem::path sessions_folder() {
  const char* data = std::getenv("XDG_DATA_HOME");
  const char* home = std::getenv("HOME");
  const std::filesystem::path base =
      data && *data ? std::filesystem::path(data)
                    : std::filesystem::path(home && *home ? home : ".") / ".local" / "share";
  return base / "nibrig" / "sessions";
}

// Where a file dialog starts: the folder of the file in use, else the working folder.
std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.empty() ? file : file.parent_path();
}

// A fit's two steps (the starts, then the bootstrap's refits) as the two halves of one bar.
std::vector<std::string> fit_steps(const model::space::SpaceFitSettings& s) {
  std::vector<std::string> steps;
  if (s.choose_model) steps.push_back(model::space::kChoiceStep);
  steps.push_back(model::space::kFitStep);
  if (s.bootstrap > 0) steps.push_back(model::space::kBootstrapStep);
  return steps;
}

model::space::StepProgress fit_progress(JobControl& control, std::vector<std::string> steps) {
  auto report = step_reporter(control, "");
  return [&control, report, steps](const std::string& step, std::size_t done, std::size_t total) {
    report(step + ": " + std::to_string(done) + " of " + std::to_string(total), done, total);
    // Each step that runs takes an equal share of the bar, in the order they run.
    const auto at = std::find(steps.begin(), steps.end(), step);
    if (steps.size() < 2 || at == steps.end()) return;
    const double part = total ? static_cast<double>(done) / static_cast<double>(total) : 0.0;
    control.progress((static_cast<double>(at - steps.begin()) + part) /
                     static_cast<double>(steps.size()));
  };
}

}  // namespace

std::optional<View> view_named(std::string_view name) {
  for (View v : kViews)
    if (name == view_name(v)) return v;
  return std::nullopt;
}

const char* view_name(View view) {
  switch (view) {
    case View::space:
      return "space";
    case View::design:
      return "design";
    case View::rig:
      return "rig";
    case View::pad:
      return "pad";
    case View::devices:
      return "devices";
    case View::experiment:
      return "experiment";
  }
  return "space";
}

Panel::Panel(PanelSetup setup) : setup_(std::move(setup)) {
  model::design::ToolSoundOptions sounds;
  sounds.catalog = setup_.catalog;
  sounds.forcing_model = setup_.forcing;
  audio_ = std::make_unique<PanelAudio>(sounds);
  space_view_ = std::make_unique<SpaceView>(
      SpaceScene{}, [this](const std::vector<ToolChoice>& tools) { audio_->play(tools); });
  space_view_->share_stroke(&audio_->stroke(), [this] { audio_->stroke_changed(); });
  rig_view_ = std::make_unique<RigView>(setup_.catalog, setup_.forcing, sessions_folder());
  rig_view_->play_through(audio_.get());
  pad_view_ = std::make_unique<PadView>(*audio_);
  design_view_ =
      std::make_unique<DesignView>(*audio_, setup_.catalog, setup_.forcing, setup_.design);
  devices_view_ = std::make_unique<DevicesView>(*audio_);
  experiment_view_ = std::make_unique<ExperimentView>(
      *audio_,
      [this] {
        model::design::ToolSoundOptions options;
        options.catalog = setup_.catalog;
        options.forcing_model = setup_.forcing;
        return options;
      },
      [this] {
        const rig::RigRequest request = rig_request_of(rig_view_->choice());
        if (request.kind == rig::RigKind::replay)
          throw std::invalid_argument(
              "a study in rig mode needs the simulated or the USB rig: choose one in the rig view");
        return request;
      });
  if (setup_.device) {
    devices_view_->set_request(*setup_.device);
    if (const std::string e = audio_->open(*setup_.device); !e.empty()) errors_.report(e);
  }
  if (!setup_.space.empty())
    load_space(setup_.space);
  else
    load_default_space();
  if (!setup_.loop.empty()) open_design_loop(setup_.loop);
  if (setup_.start_rig) {
    rig_view_->choice().speedup = 8.0f;
    rig_view_->start();
  }
}

Panel::~Panel() {
  // The views that play stop using the audio before it goes.
  experiment_view_.reset();
  design_view_.reset();
  retired_designs_.clear();
  pad_view_.reset();
}

void Panel::load_space(const std::filesystem::path& file) {
  space_file_ = file;
  showing_default_ = false;
  space_job_ = std::make_unique<BackgroundJob<LoadedSpace>>(
      "loading the space", [file, catalog = setup_.catalog](JobControl& control) {
        control.message("reading " + file.string());
        return load_space_file(file, catalog);
      });
}

void Panel::load_default_space() {
  space_file_.clear();
  showing_default_ = true;
  space_job_ = std::make_unique<BackgroundJob<LoadedSpace>>(
      "the default space", [catalog = setup_.catalog](JobControl& control) {
        model::design::DefaultsOptions options;
        options.catalog = catalog;
        options.stop = control.stop_token();
        options.progress = step_reporter(control, "the default space (computed once, then kept): ");
        return panel::load_default_space(options);
      });
}

void Panel::fit_space(const SpaceFitRequest& r) {
  space_file_.clear();
  showing_default_ = false;
  space_job_ = std::make_unique<BackgroundJob<LoadedSpace>>(
      "fitting a space", [r, catalog = setup_.catalog](JobControl& control) {
        control.message("reading " + r.judgments.string());
        const std::filesystem::path descriptors =
            r.descriptors ? model::io::or_default(catalog, model::io::default_catalog)
                          : std::filesystem::path();
        const auto inputs = model::space::read_space_inputs(r.judgments, descriptors,
                                                            static_cast<std::size_t>(r.dims),
                                                            r.descriptors ? r.lambda : 0.0);
        model::space::SpaceFitSettings settings;
        settings.starts = r.starts;
        settings.seed = static_cast<unsigned>(r.seed);
        settings.bootstrap = r.bootstrap;
        settings.choose_model = r.model == "auto";
        if (!settings.choose_model) settings.model = model::space::parse_family(r.model);
        settings.stop = control.stop_token();
        auto fitted = model::space::fit_space_file(inputs, r.judgments, descriptors, settings,
                                                   fit_progress(control, fit_steps(settings)));
        auto loaded =
            loaded_space_of(std::move(fitted.file), catalog,
                            "space fitted to " + r.judgments.filename().string() + " (not saved)");
        loaded.warnings = std::move(fitted.warnings);
        return loaded;
      });
}

void Panel::file_job(std::string title, std::function<Apply(JobControl&)> work) {
  if (file_job_) {
    errors_.report("wait for " + file_job_->title() + " to finish");
    return;
  }
  notice_.clear();
  file_job_ = std::make_unique<BackgroundJob<Apply>>(std::move(title), std::move(work));
}

void Panel::save_space(const std::filesystem::path& file) {
  if (!space_) {
    errors_.report("there is no space to save yet");
    return;
  }
  file_job("saving the space", [space = *space_, file](JobControl&) -> Apply {
    model::space::write_space_file(file, space);
    return [file](Panel& p) {
      p.space_file_ = file;
      p.showing_default_ = false;
      p.notice_ = "wrote " + file.string();
    };
  });
}

void Panel::open_catalog(const std::filesystem::path& file) {
  file_job("opening the catalog", [file, forcing = setup_.forcing](JobControl& control) -> Apply {
    control.message("reading " + file.string());
    model::design::ToolSoundOptions options;
    options.catalog = file;
    options.forcing_model = forcing;
    auto sounds = std::make_shared<model::design::ToolSounds>(
        options);  // reads the catalog, or throws naming it
    return [sounds, file, forcing](Panel& p) {
      p.use_sources(sounds, file, forcing);
      p.notice_ = "the catalog is " + file.string();
    };
  });
}

void Panel::open_forcing(const std::filesystem::path& file) {
  file_job("opening the forcing model",
           [file, catalog = setup_.catalog](JobControl& control) -> Apply {
             control.message("reading " + file.string());
             model::forcing::read_forcing_model(file);  // the whole file checked before it is used
             model::design::ToolSoundOptions options;
             options.catalog = catalog;
             options.forcing_model = file;
             auto sounds = std::make_shared<model::design::ToolSounds>(options);
             return [sounds, file, catalog](Panel& p) {
               p.use_sources(sounds, catalog, file);
               p.notice_ = "the forcing model is " + file.string();
             };
           });
}

void Panel::open_stored_forcing(const std::string& name) {
  try {
    open_forcing(model::forcing::find_forcing_model(name));
  } catch (const std::invalid_argument& e) {
    errors_.report(e.what());
  }
}

void Panel::save_forcing(const std::filesystem::path& file) {
  file_job(
      "saving the forcing model",
      [file, forcing = setup_.forcing, catalog = setup_.catalog](JobControl& control) -> Apply {
        if (!forcing.empty()) {
          model::forcing::write_forcing_model(file, model::forcing::read_forcing_model(forcing));
        } else {  // the demo's, from the user cache (fitted there first if it is not yet)
          model::design::DefaultsOptions defaults;
          defaults.catalog = catalog;
          defaults.progress = step_reporter(control, "the default forcing model: ");
          model::forcing::write_forcing_model(file,
                                              model::design::default_forcing_model(defaults).value);
        }
        return [file](Panel& p) { p.notice_ = "wrote " + file.string(); };
      });
}

void Panel::open_design(const std::filesystem::path& file) {
  if (const std::string e = design_view_->open_prediction(file); !e.empty()) {
    errors_.report(e);
    return;
  }
  errors_.clear();
  notice_ = "the design of " + file.string();
  show(View::design);
}

void Panel::open_design_loop(const std::filesystem::path& file) {
  if (const std::string e = design_view_->open_loop(file); !e.empty()) {
    errors_.report(e);
    return;
  }
  errors_.clear();
  notice_ = "the design loop of " + design_view_->loop()->folder().string();
  show(View::design);
}

void Panel::save_design(const std::filesystem::path& file) {
  if (const std::string e = design_view_->save_prediction(file); !e.empty()) {
    errors_.report(e);
  } else {
    errors_.clear();
    notice_ = "wrote " + file.string();
  }
}

void Panel::export_stylus(const std::filesystem::path& file) {
  auto work = design_view_->stylus_export(file, space_);
  if (!work) {
    errors_.report("there is no design to export yet (the grid is not ready)");
    return;
  }
  file_job("exporting the stylus", [work = std::move(work), file](JobControl&) -> Apply {
    work();
    return [file](Panel& p) {
      p.notice_ = "wrote " + file.string() + ", the STLs and the print sheet beside it";
    };
  });
}

void Panel::use_sources(std::shared_ptr<model::design::ToolSounds> sounds,
                        std::filesystem::path catalog, std::filesystem::path forcing) {
  setup_.catalog = std::move(catalog);
  setup_.forcing = std::move(forcing);
  audio_->use_sounds(std::move(sounds));
  rig_view_->set_files(setup_.catalog, setup_.forcing);
  // The design view's grid depends on both: it starts again. The old one stops its work on its
  // own thread and goes once that has ended (the UI does not wait for a FEM solve).
  design_view_->stop_work();
  retired_designs_.push_back(std::move(design_view_));
  design_view_ =
      std::make_unique<DesignView>(*audio_, setup_.catalog, setup_.forcing, setup_.design);
  // The tools of the space are placed from the catalog: placed again.
  if (!space_file_.empty())
    load_space(space_file_);
  else if (showing_default_ || !space_)
    load_default_space();
  else
    space_job_ = std::make_unique<BackgroundJob<LoadedSpace>>(
        "placing the tools", [space = *space_, catalog = setup_.catalog](JobControl&) {
          return loaded_space_of(space, catalog, "space fitted here (not saved)");
        });
}

void Panel::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || files_.is_open()) return;
  // ImGui 1.86's GLFW back end indexes io.KeysDown by GLFW's key codes.
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl) {
    for (int k = 0; k < 6; ++k)
      if (pressed(GLFW_KEY_1 + k)) show(kViews[k]);
    if (pressed(GLFW_KEY_O))
      files_.open("Open a space", FileDialog::Mode::open, {".json"}, folder_of(space_file_),
                  [this](const std::filesystem::path& f) { open_space(f); });
    return;
  }
  for (int k = 0; k < 3; ++k)
    if (pressed(GLFW_KEY_A + k)) audio_->select(static_cast<std::size_t>(k));
  if (pressed(GLFW_KEY_SPACE)) audio_->stop();
  if (pressed(GLFW_KEY_F12)) frame_times_window_ = !frame_times_window_;
  // Enter plays again what the status line says it does: the tools chosen in the space view, or
  // else what is loaded (a space opened since forgets the choice, not what was compared).
  if (pressed(GLFW_KEY_ENTER)) {
    if (!space_view_->chosen().empty())
      space_view_->play_chosen();
    else
      audio_->play_again();
  }
}

void Panel::show(View view) { requested_ = view; }

bool Panel::settled() const {
  switch (current_) {
    case View::space:
      return !space_job_ && !audio_->making_sounds();
    case View::rig:
      return !rig_view_->running() || rig_view_->progress() >= 0.5;
    case View::devices:
      return devices_view_->listing().has_value();
    case View::experiment:
      return experiment_view_->stage() != ExperimentView::Stage::preparing;
    case View::design:
      return !space_job_ && design_view_->ready() && !design_view_->preparing() &&
             !design_view_->measuring_error();
    case View::pad:
      return !file_job_;
    default:
      return true;
  }
}

void Panel::poll_jobs() {
  audio_->poll();
  std::erase_if(retired_designs_, [](const auto& view) { return !view->working(); });
  if (space_job_ && space_job_->done()) {
    if (auto loaded = space_job_->take_result()) {
      errors_.clear();
      if (!fallback_reason_.empty())
        errors_.report(fallback_reason_ + " (the default space is shown instead)");
      fallback_reason_.clear();
      for (const auto& w : loaded->warnings) errors_.report(w);
      design_view_->set_space(loaded->scene, loaded->map);
      space_view_->set_scene(std::move(loaded->scene));
      space_ = std::move(loaded->file);
      shown_space_file_ = space_file_;
      space_job_.reset();
    } else {
      const std::string failed = space_job_->error();
      const bool was_default = showing_default_;
      space_job_.reset();
      errors_.report(failed);
      // The space shown stays the one remembered: a file that failed is not opened next start.
      space_file_ = shown_space_file_;
      // Nothing shown (a remembered or given file that no longer reads): the default is computed,
      // as the empty view says it will be.
      if (!space_ && !was_default) {
        fallback_reason_ = failed;
        load_default_space();
      }
    }
  }
  if (file_job_ && file_job_->done()) {
    auto apply = file_job_->take_result();
    const std::string failed = file_job_->error();
    file_job_.reset();
    if (apply && *apply) {
      errors_.clear();
      (*apply)(*this);
    } else {
      errors_.report(failed);
    }
  }
}

void Panel::draw_menu() {
  if (!ImGui::BeginMenuBar()) return;
  using Mode = FileDialog::Mode;
  const auto chosen = [this](void (Panel::*action)(const std::filesystem::path&)) {
    return [this, action](const std::filesystem::path& f) { (this->*action)(f); };
  };
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open space...", "Ctrl+O"))
      files_.open("Open a space", Mode::open, {".json"}, folder_of(space_file_),
                  chosen(&Panel::open_space));
    if (ImGui::MenuItem("The default space")) load_default_space();
    if (ImGui::MenuItem("Fit a space from judgments...")) fit_window_ = true;
    if (ImGui::MenuItem("Save space as...", nullptr, false, space_.has_value()))
      files_.open("Save the space", Mode::save, {".json"}, folder_of(space_file_),
                  chosen(&Panel::save_space));
    ImGui::Separator();
    if (ImGui::MenuItem("Open catalog..."))
      files_.open("Open a catalog", Mode::open, {".json", ".json.gz"}, folder_of(setup_.catalog),
                  chosen(&Panel::open_catalog));
    if (ImGui::MenuItem("Open forcing model..."))
      files_.open("Open a forcing model", Mode::open, {".json"}, folder_of(setup_.forcing),
                  chosen(&Panel::open_forcing));
    if (ImGui::BeginMenu("Stored forcing model")) {
      if (ImGui::IsWindowAppearing()) stored_forcing_ = model::forcing::stored_forcing_models();
      if (stored_forcing_.empty())
        ImGui::TextDisabled("none yet: forcing calibrate-material --save NAME");
      for (const auto& name : stored_forcing_)
        if (ImGui::MenuItem(name.c_str(), nullptr,
                            setup_.forcing == model::forcing::forcing_store_path(name)))
          open_stored_forcing(name);
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Save forcing model as..."))
      files_.open("Save the forcing model", Mode::save, {".json"}, folder_of(setup_.forcing),
                  chosen(&Panel::save_forcing));
    ImGui::Separator();
    if (ImGui::MenuItem("Open design...", nullptr, false, design_view_->ready()))
      files_.open("Open a design (a prediction file)", Mode::open, {".json"}, {},
                  chosen(&Panel::open_design));
    if (ImGui::MenuItem("Open design loop..."))
      files_.open("Open a design loop (its loop.json)", Mode::open, {"loop.json"}, {},
                  chosen(&Panel::open_design_loop));
    if (ImGui::MenuItem("Save design as...", nullptr, false, design_view_->predicted().has_value()))
      files_.open("Save the design (a prediction file)", Mode::save, {".json"}, {},
                  chosen(&Panel::save_design));
    if (ImGui::MenuItem("Export stylus for printing...", nullptr, false,
                        design_view_->predicted().has_value()))
      files_.open("Export the stylus (3MF, an STL per region beside it)", Mode::save, {".3mf"}, {},
                  chosen(&Panel::export_stylus));
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Keys")) keys_window_ = true;
    if (ImGui::MenuItem("Errors")) errors_window_ = true;
    ImGui::MenuItem("Frame times", "F12", &frame_times_window_);
    ImGui::EndMenu();
  }
  ImGui::EndMenuBar();
}

void Panel::draw_fit_window() {
  if (!fit_window_) return;
  ImGui::SetNextWindowSize({560.0f, 0.0f}, ImGuiCond_Appearing);
  if (ImGui::Begin("Fit a space from judgments", &fit_window_)) {
    ImGui::TextWrapped(
        "Triplet judgments (ours, Lagunas et al. or Salmon's CSV). The fit runs in the background; "
        "the space it makes is shown, and File > Save space as keeps it.");
    if (space_fit_form(fit_request_, files_)) fit_space(fit_request_);
  }
  ImGui::End();
}

std::string Panel::status_line() const {
  const auto& audition = audio_->audition();
  std::string device = "no device";
  if (const auto info = audition.stream_info()) {
    device = info->api + " " + info->device;
    if (audition.output_status() == playback::OutputStatus::lost)
      device += ": LOST (" + audition.last_problem() + "), looking for it";
  }
  // The slot heard is marked; the others are loaded, a key away.
  const auto sounding = audio_->sounding();
  std::string playing;
  for (std::size_t i = 0; i < audio_->playing().size(); ++i) {
    const bool heard = sounding && audition.selected() == i;
    playing += std::string(i ? ", " : "") + static_cast<char>('A' + i) + ": " + audio_->names()[i] +
               (heard ? " (sounding)" : "");
  }
  if (playing.empty())
    playing = "nothing loaded";
  else if (!sounding)
    playing = "stopped (" + playing + "; Enter plays again)";
  const std::string moving = audio_->stroke_description();
  const std::string stroke = moving == "stopped" ? "stroke: " + audio_->chosen_stroke_description()
                             : moving == "the pad" ? "moved by the pad"
                                                   : "stroke: " + moving;
  // The rig's simulation on the actuator is a second output: said here too while it runs.
  std::string rig;
  if (rig_view_->running())
    if (const std::string line = rig_view_->actuator_line(); !line.empty()) rig = " | rig: " + line;
  return device + " | " + playing + " | " + stroke + rig;
}

void Panel::follow_error_view() {
  // An error is about what was being done in the view it came up in: once the person moves to
  // another view the line empties (Help > Errors keeps it), so that a catalog's error is not read
  // as the rig's or the pad's minutes later.
  if (errors_.current() != error_seen_) {
    error_seen_ = errors_.current();
    error_view_ =
        requested_.value_or(current_);  // an error reported as a view is asked for is that view's
  } else if (!error_seen_.empty() && current_ != error_view_) {
    errors_.clear();
    error_seen_.clear();
  }
}

void Panel::follow_audio_error() {
  const std::string& now = audio_->error();
  if (now == audio_error_seen_) return;
  if (!now.empty())
    errors_.report(now);
  else if (errors_.current() == audio_error_seen_)
    errors_.clear();  // the audio's problem is over
  audio_error_seen_ = now;
}

float Panel::status_height(const std::string& status) const {
  const float line = ImGui::GetFrameHeightWithSpacing();
  const float bars = static_cast<float>((space_job_ ? 1 : 0) + (file_job_ ? 1 : 0) +
                                        (audio_->making_sounds() ? 1 : 0));
  const float width = ImGui::GetContentRegionAvail().x;
  // The status line wraps (long tool names are read whole), the buttons A-C beside it.
  const float text = ImGui::CalcTextSize(status.c_str(), nullptr, false, width - kStatusButtons).y;
  return ImGui::GetStyle().ItemSpacing.y * 3.0f + line * (1.0f + bars) + text +
         errors_.height(width, kErrorLines);
}

void Panel::draw_status(const std::string& status) {
  ImGui::Separator();
  if (space_job_) {
    if (progress_with_cancel("space-job", static_cast<float>(space_job_->progress()),
                             space_job_->message().c_str()))
      space_job_.reset();
  }
  if (file_job_)
    ImGui::ProgressBar(static_cast<float>(file_job_->progress()), {-1.0f, 0.0f},
                       file_job_->message().c_str());
  if (audio_->making_sounds() &&
      progress_with_cancel("making-sounds", static_cast<float>(audio_->making_progress()),
                           audio_->making_message().c_str()))
    audio_->cancel_making();
  if (!errors_.current().empty())
    errors_.draw(kErrorLines);
  else if (!notice_.empty())
    ImGui::TextDisabled("%s", notice_.c_str());
  else
    ImGui::NewLine();
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + ImGui::GetContentRegionAvail().x -
                         kStatusButtons);
  ImGui::TextUnformatted(status.c_str());
  ImGui::PopTextWrapPos();
  if (audio_->playing().size() > 1) {
    const auto sounding = audio_->sounding();
    for (std::size_t i = 0; i < audio_->playing().size(); ++i) {
      ImGui::SameLine();
      const char label[2] = {static_cast<char>('A' + i), 0};
      const bool heard = sounding && audio_->audition().selected() == i;
      if (heard)
        ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
      if (ImGui::SmallButton(label)) audio_->select(i);
      if (heard) ImGui::PopStyleColor();
    }
  }
}

double Panel::idle_wait_s() const {
  const ImGuiIO& io = ImGui::GetIO();
  const bool pressed = io.MouseDown[0] || io.MouseDown[1] || io.MouseDown[2];
  if (pressed || ImGui::IsAnyItemActive() || experiment_view_->fullscreen() ||
      pad_view_->drawing() || pad_view_->replaying() || audio_->handing_over())
    return 0.0;
  if (rig_view_->running()) return current_ == View::rig ? 0.0 : kProgressRefresh_s;
  const bool working = space_job_ || file_job_ || audio_->making_sounds() ||
                       design_view_->preparing() || devices_view_->measuring() ||
                       design_view_->measuring_error() ||
                       experiment_view_->stage() == ExperimentView::Stage::preparing;
  return working ? kProgressRefresh_s : kIdleRefresh_s;
}

void Panel::draw() {
  const auto start = std::chrono::steady_clock::now();
  draw_views();
  frame_ms_[frame_at_++ % kFrameTimes] =
      std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Panel::draw_views() {
  poll_jobs();
  follow_audio_error();
  space_view_->set_sounding(audio_->sounding());
  if (current_ != View::devices) devices_view_->sample();
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  if (experiment_view_->fullscreen()) {
    // A participant in session sees the study and nothing else: no menu, tabs, status or keys of
    // the other views.
    ImGui::SetNextWindowPos(viewport->WorkPos);
    ImGui::SetNextWindowSize(viewport->WorkSize);
    ImGui::Begin(
        "nibrig-experiment", nullptr,
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    experiment_view_->draw();
    ImGui::End();
    return;
  }
  handle_keys();
  ImGui::SetNextWindowPos(viewport->WorkPos);
  ImGui::SetNextWindowSize(viewport->WorkSize);
  ImGui::Begin("nibrig-panel", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_MenuBar |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings);
  draw_menu();
  follow_error_view();
  const std::string status = status_line();  // once a frame: laid out, then drawn
  const float status_height = this->status_height(status);
  last_status_height_ = status_height;
  if (ImGui::BeginTabBar("views")) {
    for (View v : kViews) {
      const bool select = requested_ && *requested_ == v;
      if (ImGui::BeginTabItem(view_name(v), nullptr, select ? ImGuiTabItemFlags_SetSelected : 0)) {
        current_ = v;
        ImGui::BeginChild("view", {0.0f, -status_height});
        switch (v) {
          case View::space:
            space_view_->draw();
            break;
          case View::design:
            design_view_->draw();
            break;
          case View::rig:
            rig_view_->draw();
            break;
          case View::pad:
            pad_view_->draw();
            break;
          case View::devices:
            devices_view_->draw();
            break;
          case View::experiment:
            experiment_view_->draw();
            break;
        }
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
    }
    ImGui::EndTabBar();
  }
  if (requested_ && current_ == *requested_) requested_.reset();
  draw_status(status);
  files_.draw();
  ImGui::End();
  draw_fit_window();
  draw_help_windows();
}

void Panel::draw_frame_times() {
  if (!frame_times_window_) return;
  const std::size_t n = std::min(frame_at_, kFrameTimes);
  float sum = 0.0f, worst = 0.0f;
  for (std::size_t i = 0; i < n; ++i) sum += frame_ms_[i], worst = std::max(worst, frame_ms_[i]);
  // Bottom left of the view, above the status block: the space view's side panel (the stroke's
  // controls) is on the right, where the readout had covered it. Placed each time it is shown.
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({viewport->WorkPos.x + 12.0f, viewport->WorkPos.y + viewport->WorkSize.y -
                                                            last_status_height_ - 12.0f},
                          ImGuiCond_Appearing, {0.0f, 1.0f});
  if (ImGui::Begin("Frame times", &frame_times_window_, ImGuiWindowFlags_AlwaysAutoResize)) {
    const float rate = ImGui::GetIO().Framerate;
    ImGui::Text("%.1f frames/s (%.1f ms apart)", rate, rate > 0.0f ? 1000.0f / rate : 0.0f);
    ImGui::Text("the panel's widgets: %.2f ms a frame (worst %.2f) over the last %zu",
                n ? sum / n : 0.0f, worst, n);
    const double wait = idle_wait_s();
    if (wait > 0.0)
      ImGui::Text("idle: drawn on input, else every %.1f s", wait);
    else
      ImGui::TextUnformatted("something moves: drawn at the display's rate");
  }
  ImGui::End();
}

void Panel::draw_help_windows() {
  errors_.draw_history(&errors_window_);
  draw_frame_times();
  if (keys_window_) {
    if (ImGui::Begin("Keys", &keys_window_, ImGuiWindowFlags_AlwaysAutoResize)) {
      ImGui::TextUnformatted(
          "A, B, C       switch between the tools compared\n"
          "Enter         play the chosen tools again\n"
          "Space         stop\n"
          "Ctrl+1 ... 6  space, design, rig, pad, devices, experiment\n"
          "Ctrl+O        open a space\n"
          "F12           frame times\n"
          "(not while a text field has the keyboard)");
    }
    ImGui::End();
  }
}

}  // namespace nibrig::ui::panel
