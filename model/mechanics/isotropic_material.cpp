#include "model/mechanics/isotropic_material.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nibrig::model::mechanics {
namespace {

[[noreturn]] void fail(const IsotropicMaterial& m, const std::string& what, double value,
                       const char* unit) {
  std::ostringstream s;
  s << "material '" << m.name << "': " << what << ", got " << value << unit;
  throw std::invalid_argument(s.str());
}

}  // namespace

void validate(const IsotropicMaterial& m) {
  if (!std::isfinite(m.youngs_modulus) || m.youngs_modulus <= 0.0)
    fail(m, "Young's modulus must be positive and finite", m.youngs_modulus, " Pa");
  if (!std::isfinite(m.poisson_ratio) || m.poisson_ratio <= -1.0 || m.poisson_ratio >= 0.5)
    fail(m, "Poisson ratio must lie in (-1, 0.5)", m.poisson_ratio, "");
  if (!std::isfinite(m.density) || m.density <= 0.0)
    fail(m, "density must be positive and finite", m.density, " kg/m^3");
}

LameParameters lame_parameters(const IsotropicMaterial& m) {
  const double e = m.youngs_modulus, nu = m.poisson_ratio;
  return {e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), e / (2.0 * (1.0 + nu))};
}

}  // namespace nibrig::model::mechanics
