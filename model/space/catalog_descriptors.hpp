// The physical descriptors the axes of a space are tied to (Sec. 4.5), read from a tool catalog:
// axis 1 the Coulomb friction coefficient μ; axis 2 the perceptually weighted mean vibration; for
// D ≥ 3 dimensions, axes 2..D the D − 1 uniform band energies of the weighted vibration instead.
// Vibration enters as log10: perceived vibration intensity grows with the logarithm of amplitude
// far more nearly than linearly, and on a linear scale the loudest tool alone would set the
// correlation.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"

namespace nibrig::model::space {

// The first descriptor of every space: the Coulomb friction coefficient μ.
inline constexpr const char* kFrictionDescriptor = "friction_mu";

struct DescriptorTable {
  std::vector<std::string> names;  // one per column
  std::vector<std::string> rows;   // stimulus (pairing) names, "tool/surface"
  Eigen::MatrixXd values;          // rows × names
};

// The descriptor names for a D-dimensional space (D descriptors); D from 1 to 6 (the catalog holds
// band energies for up to 5 bands). Throws std::invalid_argument otherwise.
std::vector<std::string> paper_descriptor_names(std::size_t dims);

// Every name paper_descriptor_names gives for any dimension, each once: μ, the weighted mean, then
// the band energies by band count (16 names).
std::vector<std::string> all_paper_descriptor_names();

// The stimulus named "tool/surface" is the catalog pairing of those ids. Throws io::FormatError
// naming `catalog_file` and the stimulus when a stimulus has no such pairing, or its pairing lacks
// friction or vibration descriptors, or a value is not positive where a logarithm is taken.
DescriptorTable descriptors_for_stimuli(const io::Catalog& catalog,
                                        const std::filesystem::path& catalog_file,
                                        const std::vector<std::string>& stimuli, std::size_t dims);

// Every pairing of the catalog that has both friction and vibration, in catalog order.
DescriptorTable descriptors_of_catalog(const io::Catalog& catalog,
                                       const std::filesystem::path& catalog_file, std::size_t dims);

// "tool/surface"
std::string pairing_name(const io::Pairing& pairing);

}  // namespace nibrig::model::space
