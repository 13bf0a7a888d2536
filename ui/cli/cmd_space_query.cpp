// `nibrig space predict|evaluate|embed`: a fitted space answering questions about triplets and
// tools, including tools placed from their descriptors alone.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <iostream>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/design/prediction_file.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/prediction_scores.hpp"
#include "model/space/query_csv.hpp"
#include "model/space/space_evaluation.hpp"
#include "model/space/space_inputs.hpp"
#include "model/space/space_tools.hpp"
#include "ui/cli/output.hpp"
#include "ui/cli/space_commands.hpp"
#include "ui/cli/space_figures.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

void run_space_predict(const SpaceQueryOptions& o) {
  const space::SpaceFile s = space::read_space_file(o.space_file);
  const model::io::TripletSet queries = model::io::read_triplet_queries(o.queries);
  space::StimulusLocator locator(s, o.space_file, o.catalog);
  const std::vector<space::QueryPrediction> p = space::predict_queries(s, queries, locator, o.queries);
  const bool with_sd = !o.catalog.empty();
  if (o.output.empty()) {
    std::cout << space::prediction_csv_text(queries, p, with_sd);
  } else {
    ensure_folder(o.output.parent_path());
    space::write_prediction_csv(o.output, queries, p, with_sd);
    say_wrote(o.output);
  }
}

void run_space_evaluate(const SpaceQueryOptions& o) {
  const space::SpaceFile s = space::read_space_file(o.space_file);
  const model::io::TripletSet judged = model::io::read_triplets(o.queries);
  const space::SpaceEvaluation evaluation = space::evaluate_space(s, o.space_file, judged, o.queries, o.catalog);
  const space::PredictionScores& scores = evaluation.scores;
  const std::size_t placed = evaluation.placed_from_descriptors;
  std::cout << fmt::format("{} triplets, {} responses of {}; {} stimuli placed from descriptors\n",
                           scores.triplets, scores.responses, o.queries.filename().string(),
                           placed);
  std::cout << fmt::format(
      "majority answer predicted: {:g} of {:g} ({:.1f} %), z = {:.2f}, one-sided p = {:.2g}\n",
      scores.majority.agreements, scores.majority.trials, 100 * scores.majority.fraction,
      scores.majority.z, scores.majority.p_value);
  std::cout << fmt::format("individual answers predicted: {:.1f} % of {}\n",
                           100 * scores.individual.fraction, scores.responses);
  std::cout << fmt::format("mean |p_predicted - p_observed| = {:.1f} %\n",
                           100 * scores.mean_absolute_error);
  if (scores.probability_correlation)
    std::cout << fmt::format("Pearson r (predicted vs observed p) = {:.3f}, p = {:.2g}\n",
                             scores.probability_correlation->r,
                             scores.probability_correlation->p_value);
  else
    std::cout << "Pearson r (predicted vs observed p): not defined: "
              << scores.no_correlation_because << "\n";
  if (!o.output.empty()) {
    nlohmann::json j = {{"triplets", scores.triplets},
                        {"responses", scores.responses},
                        {"placed_from_descriptors", placed},
                        {"majority_agreements", scores.majority.agreements},
                        {"majority_trials", scores.majority.trials},
                        {"majority_z", scores.majority.z},
                        {"majority_p_value", scores.majority.p_value},
                        {"individual_agreement", scores.individual.fraction},
                        {"mean_absolute_error", scores.mean_absolute_error}};
    if (scores.probability_correlation) {
      j["pearson_r"] = scores.probability_correlation->r;
      j["pearson_p_value"] = scores.probability_correlation->p_value;
    }
    write_json_file(o.output, j);
    say_wrote(o.output);
  }
}

void run_space_embed(const SpaceEmbedOptions& o) {
  const space::SpaceFile s = space::read_space_file(o.space_file);
  if (!s.descriptor_map)
    throw std::invalid_argument(o.space_file.string() +
                                " has no descriptor map: fit it with --descriptors catalog.json");
  model::io::Catalog catalog = model::io::read_catalog(o.catalog);
  // A predicted tool's descriptor error, by its stimulus name, carried into its placement.
  space::DescriptorErrors descriptor_errors;
  if (!o.predicted.empty()) {
    const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
    for (const auto& file : o.predicted) {
      model::design::ReadPrediction read = model::design::read_prediction(file, threshold);
      if (read.descriptor_errors.empty())
        spdlog::warn("{} has no descriptor_error_covariance: placed as if measured", file.string());
      else
        try {
          descriptor_errors[space::pairing_name(read.pairing)] =
              read.descriptor_errors.block(s.descriptor_map->descriptor_names);
        } catch (const std::invalid_argument& e) {
          throw model::io::FormatError(
              file, model::io::json_fields::place("descriptor_error_covariance.names"), e.what());
        }
      catalog.tools.push_back(std::move(read.tool));
      catalog.pairings.push_back(std::move(read.pairing));
    }
  }
  const std::vector<space::PlacedPairing> placed =
      space::place_catalog(s, catalog, o.catalog, descriptor_errors);
  std::vector<PlacedTool> drawn;
  for (const auto& p : placed)
    if (!p.judged)
      drawn.push_back(
          {p.pairing, p.placement, p.kind == space::ToolKind::predicted ? "predicted" : "", true});
  std::cout << fmt::format("{} catalog pairings placed ({} of them judged in {})\n", placed.size(),
                           placed.size() - drawn.size(), o.space_file.filename().string());
  const auto dims = static_cast<std::size_t>(s.coordinates.rows());
  if (o.output.empty()) {
    std::cout << space::embed_csv_text(placed, dims);
  } else {
    ensure_folder(o.output.parent_path());
    space::write_embed_csv(o.output, placed, dims);
    say_wrote(o.output);
  }
  if (!o.plot.empty()) {
    ensure_folder(o.plot.parent_path());
    write_space_plot(s, drawn, "Tools placed from their descriptors", o.plot);
    say_wrote(o.plot);
  }
}

}  // namespace nibrig::ui::cli
