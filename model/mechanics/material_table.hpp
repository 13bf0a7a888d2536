// The table of isotropic materials a design may name (assets/materials.json): elastic constants,
// optional Rayleigh damping and where every number comes from. Reading checks every value's range
// and names the file and field of anything wrong.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/mechanics/isotropic_material.hpp"

namespace nibrig::model::mechanics {

struct RayleighDamping {
  double mass = 0.0;       // α, 1/s
  double stiffness = 0.0;  // λ, s
};

struct Material {
  std::string name;
  double youngs_modulus = 0.0;  // Pa
  double poisson_ratio = 0.0;
  double density = 0.0;  // kg/m³
  std::optional<RayleighDamping> damping;
  // Where the numbers stand: "fitted" to measurements of prints, a "datasheet"'s (until calibrated),
  // an "estimate" (e.g. from a Shore hardness); empty when a table does not say.
  std::string basis;
  std::string source;
  // A lab's own material: the bundled one its prints are made of (what a printer loads for it; its
  // calibration's "printed_as"). Empty: the material itself.
  std::string printed_as;
  // A ring-down calibration's standard deviations of E (Pa) and of the Rayleigh stiffness term
  // (s), and their correlation: how sure the lab's entry is, which predictions carry.
  std::optional<double> youngs_modulus_sd, rayleigh_stiffness_sd;
  double modulus_damping_correlation = 0.0;
};

// "fitted", "datasheet", "estimate": what a table's `basis` may say.
bool is_material_basis(const std::string& basis);

// Of two bases, the less calibrated (estimate < datasheet < fitted; an unstated one is the least):
// what a mix or a design of several materials stands on.
std::string least_calibrated(const std::string& a, const std::string& b);

// For people: "datasheet values, not calibrated", "fitted to prints", "an estimate", "basis not
// stated".
std::string describe_basis(const Material& material);
std::string describe_basis(const std::string& basis);

class MaterialTable {
 public:
  MaterialTable() = default;
  explicit MaterialTable(std::vector<Material> materials);

  const std::vector<Material>& materials() const { return materials_; }
  // Case-insensitive; throws std::invalid_argument listing the known names, and where they were
  // looked for, when there is none.
  const Material& find(const std::string& name) const;

  // Where the materials come from ("assets/materials.json", "the lab's folder …"), for find's error.
  const std::vector<std::string>& looked_in() const { return looked_in_; }
  void set_looked_in(std::vector<std::string> places) { looked_in_ = std::move(places); }

 private:
  std::vector<Material> materials_;
  std::vector<std::string> looked_in_;
};

// The elastic constants the FEM needs.
IsotropicMaterial elastic_part(const Material& material);

// Throws std::invalid_argument naming the material and field: the elastic constants as
// validate(IsotropicMaterial) checks them, negative damping, anything not finite.
void validate(const Material& material);

// Format "nibrig-materials", version 1 (`basis` optional): the file alone. Throws io::FormatError
// naming the file and field.
MaterialTable read_material_file(const std::filesystem::path& file);
// The same from the file's parsed `root` (`file` names it in errors), for a reader that needs the
// file's other fields too.
MaterialTable material_table_from_json(const nlohmann::json& root,
                                       const std::filesystem::path& file);

// The file's materials, then the lab's own calibrated ones (lab_materials.hpp: the user store's
// materials folder), so that every command that takes a material by name finds a lab's. On a name in
// both, the file's wins. Throws what read_material_file throws, for the file or a lab file.
MaterialTable read_material_table(const std::filesystem::path& file);

}  // namespace nibrig::model::mechanics
