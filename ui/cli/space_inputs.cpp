#include "ui/cli/space_inputs.hpp"

#include <stdexcept>

#include "model/io/catalog_file.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

SpaceInputs read_space_inputs(const std::filesystem::path& judgments,
                              const std::filesystem::path& catalog, std::size_t dims,
                              double lambda) {
  if (lambda > 0 && catalog.empty())
    throw std::invalid_argument(
        "--lambda > 0 ties the axes to physical descriptors: give them with --descriptors "
        "catalog.json");
  if (lambda < 0) throw std::invalid_argument("--lambda must not be negative");
  SpaceInputs in;
  in.judgments = model::io::read_triplets(judgments);
  in.problem.dims = dims;
  in.problem.stimuli = in.judgments.stimuli.size();
  in.problem.triplets = in.judgments.triplets;
  in.problem.lambda = lambda;
  if (!catalog.empty()) {
    in.catalog_file = catalog;
    in.descriptors = space::descriptors_for_stimuli(model::io::read_catalog(catalog), catalog,
                                                    in.judgments.stimuli, dims);
    if (lambda > 0) in.problem.descriptors = in.descriptors->values;
  }
  space::validate(in.problem);
  return in;
}

SpaceLocator::SpaceLocator(const space::SpaceFile& space, const std::filesystem::path& space_file,
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
      throw std::invalid_argument(space_file.string() +
                                  " has no descriptor map (fit it with --descriptors) to place "
                                  "tools from " + catalog_file.string());
    catalog_ = model::io::read_catalog(catalog_file);
  }
}

const space::Placement& SpaceLocator::locate(const std::string& stimulus,
                                             const std::filesystem::path& query_file) {
  const auto it = known_.find(stimulus);
  if (it != known_.end()) return it->second;
  if (!catalog_)
    throw std::invalid_argument(query_file.string() + ": stimulus '" + stimulus + "' is not in " +
                                space_file_.string() +
                                " (a tool named \"tool/surface\" can be placed from its "
                                "descriptors with --catalog catalog.json)");
  const auto& map = *space_.descriptor_map;
  const space::DescriptorTable row = space::descriptors_for_stimuli(
      *catalog_, catalog_file_, {stimulus}, map.descriptor_names.size());
  if (row.names != map.descriptor_names)
    throw std::invalid_argument(space_file_.string() + ": its descriptor map uses descriptors " +
                                "that " + catalog_file_.string() + " does not provide");
  placed_[stimulus] = true;
  return known_[stimulus] =
             space::place_from_descriptors(map, row.values.row(0).transpose());
}

bool SpaceLocator::placed(const std::string& stimulus) const {
  const auto it = placed_.find(stimulus);
  return it != placed_.end() && it->second;
}

}  // namespace nibrig::ui::cli
