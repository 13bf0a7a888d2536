// The table of isotropic materials a design may name (assets/materials.json): elastic constants,
// optional Rayleigh damping and where every number comes from. Reading checks every value's range
// and names the file and field of anything wrong.
#pragma once

#include <filesystem>
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
  std::string source;
};

class MaterialTable {
 public:
  MaterialTable() = default;
  explicit MaterialTable(std::vector<Material> materials);

  const std::vector<Material>& materials() const { return materials_; }
  // Case-insensitive; throws std::invalid_argument listing the known names when there is none.
  const Material& find(const std::string& name) const;

 private:
  std::vector<Material> materials_;
};

// The elastic constants the FEM needs.
IsotropicMaterial elastic_part(const Material& material);

// Throws std::invalid_argument naming the material and field: the elastic constants as
// validate(IsotropicMaterial) checks them, negative damping, anything not finite.
void validate(const Material& material);

// Format "nibrig-materials", version 1. Throws io::FormatError naming the file and field.
MaterialTable read_material_table(const std::filesystem::path& file);

}  // namespace nibrig::model::mechanics
