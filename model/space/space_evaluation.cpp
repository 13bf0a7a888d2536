#include "model/space/space_evaluation.hpp"

#include <algorithm>
#include <optional>
#include <regex>
#include <string>

#include "model/io/catalog_file.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/fit.hpp"
#include "model/space/space_inputs.hpp"

namespace nibrig::model::space {

namespace {

// The trailing number of every name ("i0464" → 464), or nothing when any name has none.
std::optional<std::vector<double>> numbers_in_names(const std::vector<std::string>& names) {
  static const std::regex trailing_number("([0-9]+)$");
  std::vector<double> numbers;
  for (const auto& n : names) {
    std::smatch m;
    if (!std::regex_search(n, m, trailing_number)) return std::nullopt;
    numbers.push_back(std::stod(m[1].str()));
  }
  return numbers;
}

}  // namespace

SpaceEvaluation evaluate_space(const SpaceFile& space, const std::filesystem::path& space_file,
                               const io::TripletSet& judged, const std::filesystem::path& judged_file,
                               const std::filesystem::path& catalog) {
  StimulusLocator locator(space, space_file, catalog);
  const std::vector<QueryPrediction> predicted = predict_queries(space, judged, locator, judged_file);
  std::vector<double> mean;
  for (const auto& x : predicted) mean.push_back(x.p);
  SpaceEvaluation out;
  out.scores = score_predictions(mean, judged.triplets);
  for (const auto& name : judged.stimuli) out.placed_from_descriptors += locator.placed(name);
  return out;
}

Validation validate_space_file(const std::filesystem::path& judgments,
                               const std::filesystem::path& descriptors,
                               const DimensionScanOptions& scan,
                               const numeric::Progress& progress) {
  return validate_space(io::read_triplets(judgments), descriptors, scan, progress);
}

Validation validate_space(io::TripletSet judgments, const std::filesystem::path& descriptors,
                          const DimensionScanOptions& scan, const numeric::Progress& progress) {
  if (scan.dims.empty() || scan.lambdas.empty() || scan.models.empty())
    throw std::invalid_argument("a validation needs at least one number of dimensions, weight and model");
  const double max_lambda = *std::max_element(scan.lambdas.begin(), scan.lambdas.end());
  const std::size_t max_dims = *std::max_element(scan.dims.begin(), scan.dims.end());
  if (max_lambda > 0 && descriptors.empty())
    throw std::invalid_argument("weights (lambdas) above 0 need a catalog of descriptors");
  const SpaceInputs in = space_inputs(std::move(judgments), {}, max_dims, 0.0);
  std::optional<io::Catalog> catalog;
  if (!descriptors.empty()) catalog = io::read_catalog(descriptors);
  std::function<Eigen::MatrixXd(std::size_t)> descriptor_table;
  if (catalog)
    descriptor_table = [&](std::size_t dims) {
      return descriptors_for_stimuli(*catalog, descriptors, in.judgments.stimuli, dims).values;
    };
  Validation out;
  out.triplets = in.problem.triplets.size();
  out.responses = io::response_count(in.judgments);
  out.points = scan_dimensions(in.problem, descriptor_table, scan, progress);
  const auto numbers = numbers_in_names(in.judgments.stimuli);
  if (numbers && std::find(scan.dims.begin(), scan.dims.end(), 1u) != scan.dims.end()) {
    SpaceProblem one = in.problem;
    one.dims = 1;
    const Eigen::MatrixXd q = fit_space(one, scan.cross_validation.fit).coordinates;
    out.rank_correlation_with_names = spearman({q.data(), q.data() + q.size()}, *numbers);
  }
  return out;
}

}  // namespace nibrig::model::space
