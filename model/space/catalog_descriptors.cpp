#include "model/space/catalog_descriptors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "model/io/format_error.hpp"

namespace nibrig::model::space {
namespace {

constexpr std::size_t kMaxDims = 6;  // μ + up to 5 band energies

std::vector<double> descriptor_row(const io::Pairing& p, const std::filesystem::path& file,
                                   std::size_t dims) {
  const std::string place = "pairing '" + pairing_name(p) + "'";
  if (!p.friction || !p.vibration)
    throw io::FormatError(file, place,
                          std::string("has no ") + (p.friction ? "vibration" : "friction") +
                              " descriptor; a space's axes need both friction and vibration");
  std::vector<double> row{p.friction->mu};
  std::vector<double> vibration;
  if (dims == 2) {
    vibration.push_back(p.vibration->weighted_mean);
  } else if (dims >= 3) {
    const auto bands = p.vibration->band_energies.find(static_cast<int>(dims - 1));
    if (bands == p.vibration->band_energies.end())
      throw io::FormatError(file, place,
                            "has no " + std::to_string(dims - 1) + "-band vibration energies");
    vibration = bands->second;
  }
  for (double v : vibration) {
    if (!(v > 0.0))
      throw io::FormatError(file, place,
                            "has a vibration descriptor " + std::to_string(v) +
                                "; a positive value was expected (its logarithm is used)");
    row.push_back(std::log10(v));
  }
  return row;
}

DescriptorTable table(const std::vector<const io::Pairing*>& pairings,
                      const std::filesystem::path& file, std::size_t dims) {
  DescriptorTable t;
  t.names = paper_descriptor_names(dims);
  t.values.resize(static_cast<Eigen::Index>(pairings.size()), static_cast<Eigen::Index>(dims));
  for (std::size_t i = 0; i < pairings.size(); ++i) {
    const std::vector<double> row = descriptor_row(*pairings[i], file, dims);
    for (std::size_t j = 0; j < dims; ++j)
      t.values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = row[j];
    t.rows.push_back(pairing_name(*pairings[i]));
  }
  return t;
}

}  // namespace

std::string pairing_name(const io::Pairing& pairing) {
  return pairing.tool + "/" + pairing.surface;
}

std::vector<std::string> paper_descriptor_names(std::size_t dims) {
  if (dims < 1 || dims > kMaxDims)
    throw std::invalid_argument("descriptors exist for spaces of 1 to " + std::to_string(kMaxDims) +
                                " dimensions, not " + std::to_string(dims));
  std::vector<std::string> names{kFrictionDescriptor};
  if (dims == 2) names.push_back("log10_weighted_mean_vibration");
  for (std::size_t b = 1; dims >= 3 && b < dims; ++b)
    names.push_back("log10_band_" + std::to_string(b) + "_of_" + std::to_string(dims - 1) +
                    "_energy");
  return names;
}

std::vector<std::string> all_paper_descriptor_names() {
  std::vector<std::string> names;
  for (std::size_t dims = 1; dims <= kMaxDims; ++dims)
    for (auto& name : paper_descriptor_names(dims))
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

DescriptorTable descriptors_for_stimuli(const io::Catalog& catalog,
                                        const std::filesystem::path& catalog_file,
                                        const std::vector<std::string>& stimuli, std::size_t dims) {
  std::map<std::string, const io::Pairing*> by_name;
  for (const auto& p : catalog.pairings) by_name[pairing_name(p)] = &p;
  std::vector<const io::Pairing*> rows;
  for (const auto& s : stimuli) {
    const auto it = by_name.find(s);
    if (it == by_name.end())
      throw io::FormatError(catalog_file, "stimulus '" + s + "'",
                            "no pairing of that name; descriptor rows must match the judged "
                            "stimuli, named \"tool/surface\" by the catalog's ids");
    rows.push_back(it->second);
  }
  return table(rows, catalog_file, dims);
}

DescriptorTable descriptors_of_catalog(const io::Catalog& catalog,
                                       const std::filesystem::path& catalog_file,
                                       std::size_t dims) {
  std::vector<const io::Pairing*> rows;
  for (const auto& p : catalog.pairings)
    if (p.friction && p.vibration) rows.push_back(&p);
  return table(rows, catalog_file, dims);
}

}  // namespace nibrig::model::space
