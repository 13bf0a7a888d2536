// A linear, isotropic, homogeneous elastic material as the FEM needs it: Young's modulus, Poisson
// ratio and density in SI units, their validation, and the Lamé parameters the element stiffness
// is written in.
#pragma once

#include <string>

namespace nibrig::model::mechanics {

struct IsotropicMaterial {
  std::string name;             // for messages, e.g. "VeroClear"
  double youngs_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;   // ν, dimensionless
  double density = 0.0;         // ρ, kg/m³
};

// Throws std::invalid_argument naming the material and the field when E ≤ 0, ν ∉ (−1, 0.5),
// ρ ≤ 0 or any value is not finite. ν = 0.5 (incompressible) is rejected because λ diverges and a
// displacement-only element locks; ν ≤ −1 makes the material unstable.
void validate(const IsotropicMaterial& material);

// λ = Eν / ((1+ν)(1−2ν)), μ = E / (2(1+ν)), both Pa. Assumes a validated material.
struct LameParameters {
  double lambda = 0.0;
  double mu = 0.0;
};
LameParameters lame_parameters(const IsotropicMaterial& material);

}  // namespace nibrig::model::mechanics
