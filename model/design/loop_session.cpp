#include "model/design/loop_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "model/catalog/catalog_builder.hpp"
#include "model/design/design_grid_file.hpp"
#include "model/design/design_search.hpp"
#include "model/design/print_discrepancy.hpp"
#include "model/design/printability.hpp"
#include "model/design/stylus_export.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/io/format_error.hpp"
#include "model/space/space_inputs.hpp"

namespace nibrig::model::design {

namespace fs = std::filesystem;

namespace {

// The tip the early check of a printer prints the mix's materials at, before the model says its
// tips: the paper's reference tip, within every printer's smallest.
constexpr double kReferenceTipForPrinterCheck = 0.002;

LoopStop stop_named(const std::string& text) {
  for (const LoopStop s :
       {LoopStop::within_threshold, LoopStop::no_closer_design, LoopStop::round_limit})
    if (describe(s) == text) return s;
  return LoopStop::none;
}

// Each reason `printer` cannot make `point`, as its export would refuse it.
std::vector<std::string> refusals(const io::PrinterProfile& printer,
                                  const forcing::ForcingInputOptions& options,
                                  const DesignPoint& point) {
  StylusPrint print = stylus_print(options, point);
  print.printer = printer;
  return print_refusals(printer, print);
}

// The designs of the loop's range `printer` makes at `tips`: with a printer that cannot mix, each
// of the mix's materials alone at each tip it prints; nullopt with one that mixes (the range's
// ends are checked: a material it lacks leaves nothing of the line). Throws std::invalid_argument
// naming the printer and why when it makes none.
std::optional<std::vector<DesignPoint>> printable_range(const io::PrinterProfile& printer,
                                                        const forcing::ForcingInputOptions& options,
                                                        const LoopRequest& r,
                                                        const std::vector<double>& tips) {
  if (printer.mixes_materials) {
    const std::string why =
        unprintable_line(printer, DesignPoint{{{r.first_material, 1.0}}, tips.front()},
                         DesignPoint{{{r.second_material, 1.0}}, tips.front()});
    if (!why.empty()) throw std::invalid_argument("printer " + printer.name + ": " + why);
    return std::nullopt;
  }
  std::vector<DesignPoint> out;
  std::string why;
  for (const auto& material : {r.first_material, r.second_material})
    for (const double tip : tips) {
      const DesignPoint point{{{material, 1.0}}, tip};
      const auto reasons = refusals(printer, options, point);
      if (reasons.empty())
        out.push_back(point);
      else if (why.empty())
        why = label(point) + ": " + reasons.front();
    }
  if (out.empty())
    throw std::invalid_argument("printer " + printer.name + " cannot mix " + r.first_material +
                                " and " + r.second_material + ", nor print either alone (" + why +
                                "): give a mix with a material it prints");
  return out;
}

}  // namespace

std::unique_ptr<LoopSession> LoopSession::open(const fs::path& folder,
                                               std::optional<LoopRequest> request,
                                               const numeric::StepProgress& progress) {
  return open_folder(folder, std::move(request), std::nullopt, progress);
}

std::unique_ptr<LoopSession> LoopSession::resume_with_rounds(
    const fs::path& folder, int max_rounds, const numeric::StepProgress& progress) {
  return open_folder(folder, std::nullopt, max_rounds, progress);
}

std::unique_ptr<LoopSession> LoopSession::open_folder(const fs::path& folder,
                                                      std::optional<LoopRequest> request,
                                                      std::optional<int> max_rounds,
                                                      const numeric::StepProgress& progress) {
  std::unique_ptr<LoopSession> s(new LoopSession);
  s->folder_ = folder;
  if (fs::exists(folder) && !fs::is_directory(folder))
    throw std::invalid_argument(folder.string() + " is a file: a design loop's folder is a folder");
  const bool exists = fs::exists(loop_request_file(folder));
  if (request) {
    if (exists)
      throw std::invalid_argument(folder.string() +
                                  " holds a design loop already: resume it, or give a new folder");
    if (fs::exists(folder) && !fs::is_empty(folder))
      throw std::invalid_argument(folder.string() +
                                  " is not empty: a new design loop needs a new or empty folder");
    check_loop_request(*request);
    s->request_ = std::move(*request);
  } else {
    if (!exists)
      throw std::invalid_argument(folder.string() +
                                  " holds no design loop (no loop.json) to resume");
    s->request_ = read_loop_request(folder);
    s->rounds_ = read_rounds(folder);
    if (max_rounds) {
      const auto done = static_cast<int>(s->rounds_.size());
      if (*max_rounds < done)
        throw std::invalid_argument(
            fmt::format("rounds: {}: the loop has made {} rounds already; expected {} to {}",
                        *max_rounds, done, std::max(done, 1), kMostLoopRounds));
      s->request_.max_rounds = *max_rounds;
      check_loop_request(s->request_);
    }
  }
  s->load(progress);
  if (!exists || max_rounds) write_loop_request(folder, s->request_);

  // The measured rounds taken in again, in order; only the last may await its measurement.
  for (std::size_t k = 0; k < s->rounds_.size(); ++k) {
    const int n = s->rounds_[k].number;
    const fs::path measurement = round_measurement_file(folder, n);
    if (!fs::exists(measurement)) {
      if (k + 1 < s->rounds_.size())
        throw io::FormatError(measurement, "round " + std::to_string(n),
                              "is missing, yet round " + std::to_string(n + 1) + " follows it");
      break;
    }
    const io::Catalog one = io::read_catalog(measurement);
    if (one.pairings.size() != 1)
      throw io::FormatError(measurement, "pairings", "one pairing expected: the round's print");
    // A record without its measurement was written before the loop was killed: made again.
    s->take_in(n, one.pairings.front(), !s->rounds_[k].measured.has_value());
  }
  if (!s->rounds_.empty()) s->stopped_ = stop_named(s->rounds_.back().stopped);
  // Stopped at a limit now raised: it goes on, and its last record no longer says it stopped.
  if (s->stopped_ == LoopStop::round_limit &&
      static_cast<int>(s->rounds_.size()) < s->request_.max_rounds) {
    s->stopped_ = LoopStop::none;
    s->rounds_.back().stopped.clear();
    write_round(folder, s->rounds_.back());
  }
  return s;
}

void LoopSession::load(const numeric::StepProgress& progress) {
  const LoopRequest& r = request_;
  space_ = space::read_space_file(r.space_file);
  if (!space_.descriptor_map)
    throw std::invalid_argument(
        r.space_file.string() +
        " has no descriptor map (fit it with --descriptors): prints and designs are "
        "placed from their descriptors");
  if (!r.printer.empty()) printer_ = io::find_printer_profile(r.printer);
  forcing::ForcingInputOptions options;
  options.catalog = r.catalog_file;
  // What the printer cannot make is refused before anything is solved: the loop's own candidates,
  // or (on a printer that cannot mix) a mix neither of whose materials it prints alone.
  if (printer_) {
    for (const auto& c : r.candidates)
      if (const auto reasons = refusals(*printer_, options, c); !reasons.empty())
        throw std::invalid_argument("printer " + printer_->name + " cannot print the candidate " +
                                    label(c) + ": " + reasons.front());
    if (r.candidates.empty())
      printable_range(*printer_, options, r, {kReferenceTipForPrinterCheck});
  }
  const auto designs = numeric::step_progress(progress, "printed tools' responses", 0);
  forcing_inputs_ = forcing::load_forcing_inputs(
      options, [&](const forcing::DesignResponse&, std::size_t done, std::size_t total) {
        if (designs) designs(done, total);
      });
  if (r.candidates.empty()) {
    inputs_ = load_prediction_inputs(options, r.forcing);
  } else {
    // The candidates' own measurements on the surface leave the start: the loop learns them from
    // its prints. The default model is fitted again without them; a given model is taken as it is.
    std::erase_if(forcing_inputs_.exemplars, [&](const forcing::ForcingExemplar& e) {
      if (e.surface != r.surface || !e.mix.empty()) return false;
      const DesignPoint measured{{{e.material, 1.0}}, e.tip_diameter_m};
      return std::any_of(r.candidates.begin(), r.candidates.end(),
                         [&](const DesignPoint& c) { return same_design(c, measured); });
    });
    std::optional<forcing::ForcingModel> start;
    if (r.forcing.empty()) start = forcing::fit_forcing_for_prediction(forcing_inputs_).model;
    inputs_ = load_prediction_inputs(options, r.forcing, start);
  }
  space::StimulusLocator locator(space_, r.space_file, inputs_->catalog_file);
  space::Placement target;
  try {
    target = locator.locate(r.target, r.space_file);
  } catch (const std::exception& e) {
    throw std::invalid_argument("target '" + r.target + "' cannot be placed: " + e.what());
  }
  const auto& model = inputs_->model;
  const GridAxes axes = even_axes(r.first_material, r.second_material, kDefaultFractionPoints,
                                  model.tip_log_gain.begin()->first,
                                  model.tip_log_gain.rbegin()->first, kDefaultTipPoints);
  std::optional<std::vector<DesignPoint>> printable;
  if (printer_ && r.candidates.empty())
    printable = printable_range(*printer_, options, r, axes.tips_m);
  grid_ = cached_design_response_grid(*inputs_, axes, progress);

  LoopSetup setup;
  setup.inputs = inputs_.get();
  setup.catalog_exemplars = forcing_inputs_.exemplars;
  setup.grid = &grid_;
  setup.map = &*space_.descriptor_map;
  setup.target = target;
  setup.surface = r.surface;
  setup.range.first_material = r.first_material;
  setup.range.second_material = r.second_material;
  setup.range.min_tip_m = axes.tips_m.front();
  setup.range.max_tip_m = axes.tips_m.back();
  // A printer that cannot mix makes each material alone at the grid's tips: the loop prints those.
  setup.candidates = printable ? *printable : r.candidates;
  setup.rule = r.rule;
  setup.threshold =
      just_noticeable_distance(space_.model, static_cast<std::size_t>(space_.coordinates.rows()));
  setup.measurement_noise =
      measurement_descriptor_noise(inputs_->catalog, space_.descriptor_map->descriptor_names);
  setup.max_rounds = r.max_rounds;
  loop_ = std::make_unique<LoopModel>(setup);
}

std::optional<int> LoopSession::awaiting_measurement() const {
  if (rounds_.empty() || rounds_.back().measured) return std::nullopt;
  return rounds_.back().number;
}

std::optional<int> LoopSession::advance() {
  if (awaiting_measurement())
    throw std::logic_error(
        fmt::format("round {} awaits its print's measurement", *awaiting_measurement()));
  if (stopped_ != LoopStop::none) return std::nullopt;
  const auto stop_here = [&](LoopStop why) {
    stopped_ = why;
    rounds_.back().stopped = describe(why);
    write_round(folder_, rounds_.back());
    return std::nullopt;
  };
  if (const LoopStop why = loop_->stop(nullptr); why != LoopStop::none) return stop_here(why);
  const Proposal proposal = loop_->propose();
  if (const LoopStop why = loop_->stop(&proposal); why != LoopStop::none) return stop_here(why);

  LoopRoundRecord round;
  round.number = static_cast<int>(rounds_.size()) + 1;
  round.design = proposal.next.candidate.point;
  round.predicted_distance = proposal.next.candidate.distance;
  round.predicted_distance_sd = proposal.next.candidate.distance_sd;
  round.chance_within = proposal.next.chance_within;
  round.predicted_position = proposal.next.candidate.placement.mean;
  // The print's files first, the record last: a round whose record exists has its files.
  StylusPrint print = stylus_print(inputs_->setup, round.design);
  print.printer = printer_;
  if (printer_) check_printable(*printer_, print);
  write_stylus_files(round_print_file(folder_, round.number), print);
  write_round(folder_, round);
  rounds_.push_back(std::move(round));
  return rounds_.back().number;
}

void LoopSession::take_in(int round, const io::Pairing& measured, bool write) {
  LoopRoundRecord& record = rounds_.at(static_cast<std::size_t>(round - 1));
  loop_->add_print(record.design, measured);
  const MeasuredPlacement& placed = loop_->prints().back().placement;
  record.measured = LoopMeasuredRecord{placed.distance, placed.distance_sd, placed.placement.mean,
                                       placed.descriptors};
  if (!write) return;
  forcing::write_forcing_model(round_forcing_file(folder_, round), loop_->model());
  write_round(folder_, record);
}

void LoopSession::take_measurement(const io::Pairing& measured) {
  const auto round = awaiting_measurement();
  if (!round) throw std::logic_error("no round awaits a measurement");
  if (measured.surface != request_.surface)
    throw std::invalid_argument(
        fmt::format("the print was measured on '{}', the loop designs for '{}'", measured.surface,
                    request_.surface));
  if (!measured.friction || !measured.vibration)
    throw std::invalid_argument("the print's measurement needs both friction and vibration");
  io::Catalog one;
  io::ToolEntry tool;
  tool.id = measured.tool;
  tool.name =
      "design loop round " + std::to_string(*round) + ": " + to_string(rounds_.back().design);
  tool.kind = "printed";
  tool.material =
      rounds_.back().design.mix.size() == 1 ? rounds_.back().design.mix.front().material : "mix";
  tool.tip_diameter_m = rounds_.back().design.tip_diameter_m;
  one.tools.push_back(tool);
  one.surfaces.push_back({measured.surface, measured.surface});
  one.pairings.push_back(measured);
  one.pairings.back().tool = tool.id;
  io::write_catalog(round_measurement_file(folder_, *round), one);
  take_in(*round, measured, true);
}

io::Pairing LoopSession::analyse_session(const fs::path& session) const {
  catalog::FoundRecordings found;
  found.files.push_back({session, catalog::RecordingKind::session});
  const catalog::CatalogBuild build = catalog::build_catalog(found, *inputs_->threshold, {}, 1);
  if (build.catalog.pairings.size() != 1)
    throw std::invalid_argument(session.string() + ": one tool on one surface expected, found " +
                                std::to_string(build.catalog.pairings.size()) + " pairings");
  return build.catalog.pairings.front();
}

}  // namespace nibrig::model::design
