#include "model/space/space_inputs.hpp"

#include <map>
#include <random>
#include <stdexcept>

#include "model/io/catalog_file.hpp"

namespace nibrig::model::space {

SpaceInputs read_space_inputs(const std::filesystem::path& judgments,
                              const std::filesystem::path& catalog, std::size_t dims,
                              double lambda) {
  return space_inputs(io::read_triplets(judgments), catalog, dims, lambda);
}

SpaceInputs space_inputs(io::TripletSet judgments, const std::filesystem::path& catalog,
                         std::size_t dims, double lambda) {
  if (lambda > 0 && catalog.empty())
    throw std::invalid_argument(
        "lambda > 0 ties the axes to physical descriptors: give them with a catalog of "
        "the judged tools' descriptors");
  if (lambda < 0) throw std::invalid_argument("lambda must not be negative");
  SpaceInputs in;
  in.judgments = std::move(judgments);
  in.problem.dims = dims;
  in.problem.stimuli = in.judgments.stimuli.size();
  in.problem.triplets = in.judgments.triplets;
  in.problem.lambda = lambda;
  if (!catalog.empty()) {
    in.catalog_file = catalog;
    in.descriptors = descriptors_for_stimuli(io::read_catalog(catalog), catalog,
                                                    in.judgments.stimuli, dims);
    if (lambda > 0) in.problem.descriptors = in.descriptors->values;
  }
  validate(in.problem);
  return in;
}

StimulusLocator::StimulusLocator(const SpaceFile& space, const std::filesystem::path& space_file,
                           const std::filesystem::path& catalog_file)
    : space_(space), space_file_(space_file), catalog_file_(catalog_file) {
  const auto dims = space.coordinates.rows();
  for (std::size_t i = 0; i < space.stimuli.size(); ++i) {
    known_[space.stimuli[i]] = {space.coordinates.col(static_cast<Eigen::Index>(i)),
                                Eigen::MatrixXd::Zero(dims, dims)};
    placed_[space.stimuli[i]] = false;
  }
  if (!catalog_file.empty()) {
    if (!space.descriptor_map)
      throw std::invalid_argument(
          space_file.string() +
          " has no descriptor map (fit it with a catalog's descriptors) to place "
          "tools from " +
          catalog_file.string());
    catalog_ = io::read_catalog(catalog_file);
  }
}

const Placement& StimulusLocator::locate(const std::string& stimulus,
                                             const std::filesystem::path& query_file) {
  const auto it = known_.find(stimulus);
  if (it != known_.end()) return it->second;
  if (!catalog_)
    throw std::invalid_argument(
        query_file.string() + ": stimulus '" + stimulus + "' is not in " + space_file_.string() +
        " (a tool named \"tool/surface\" is placed from its descriptors when a catalog is "
        "given)");
  const auto& map = *space_.descriptor_map;
  const DescriptorTable row = descriptors_for_stimuli(
      *catalog_, catalog_file_, {stimulus}, map.descriptor_names.size());
  if (row.names != map.descriptor_names)
    throw std::invalid_argument(space_file_.string() + ": its descriptor map uses descriptors " +
                                "that " + catalog_file_.string() + " does not provide");
  placed_[stimulus] = true;
  return known_[stimulus] =
             place_from_descriptors(map, row.values.row(0).transpose());
}

bool StimulusLocator::placed(const std::string& stimulus) const {
  const auto it = placed_.find(stimulus);
  return it != placed_.end() && it->second;
}

std::vector<QueryPrediction> predict_queries(const SpaceFile& space, const io::TripletSet& queries,
                                             StimulusLocator& locator,
                                             const std::filesystem::path& query_file) {
  std::mt19937_64 generator(1);
  std::vector<QueryPrediction> out;
  // A judged stimulus's own noise where the model has noises; a placed tool has the typical one.
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < space.stimuli.size(); ++i) index[space.stimuli[i]] = i;
  const auto log_sigma = [&](const io::Triplet& t) {
    const auto r = index.find(queries.stimuli[t.reference]), a = index.find(queries.stimuli[t.a]),
               b = index.find(queries.stimuli[t.b]);
    if (space.model.log_noise.size() == 0 || r == index.end() || a == index.end() || b == index.end())
      return typical_log_sigma(space.model);
    return triplet_log_sigma(space.model, r->second, a->second, b->second);
  };
  for (const auto& t : queries.triplets) {
    const auto& r = locator.locate(queries.stimuli[t.reference], query_file);
    const auto& a = locator.locate(queries.stimuli[t.a], query_file);
    const auto& b = locator.locate(queries.stimuli[t.b], query_file);
    if (r.covariance.isZero(0.0) && a.covariance.isZero(0.0) && b.covariance.isZero(0.0)) {
      out.push_back({probability_first(space.model, static_cast<std::size_t>(r.mean.size()), (a.mean - r.mean).norm(),
                                       (b.mean - r.mean).norm(), log_sigma(t)),
                     0.0});
    } else {
      const auto u = uncertain_probability_first(r, a, b, space.model, kUncertaintySamples, generator);
      out.push_back({u.mean, u.sd});
    }
  }
  return out;
}

}  // namespace nibrig::model::space
