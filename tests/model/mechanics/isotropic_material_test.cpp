#include "model/mechanics/isotropic_material.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace nibrig::model::mechanics {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string message_of(const IsotropicMaterial& m) {
  try {
    validate(m);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(IsotropicMaterial, RejectsEachBadFieldNamingMaterialAndField) {
  const IsotropicMaterial good{"VeroClear", 0.45e9, 0.35, 1180.0};
  EXPECT_NO_THROW(validate(good));

  IsotropicMaterial m = good;
  m.youngs_modulus = -1e9;
  EXPECT_THAT(message_of(m), AllOf(HasSubstr("material 'VeroClear'"), HasSubstr("Young's modulus"),
                                   HasSubstr("-1e+09 Pa")));
  m = good;
  m.youngs_modulus = 0.0;
  EXPECT_THAT(message_of(m), HasSubstr("Young's modulus"));
  m = good;
  m.poisson_ratio = 0.5;  // incompressible: λ diverges
  EXPECT_THAT(message_of(m), AllOf(HasSubstr("Poisson ratio"), HasSubstr("0.5")));
  m = good;
  m.poisson_ratio = -1.0;
  EXPECT_THAT(message_of(m), HasSubstr("Poisson ratio"));
  m = good;
  m.density = 0.0;
  EXPECT_THAT(message_of(m), AllOf(HasSubstr("VeroClear"), HasSubstr("density")));
  m = good;
  m.density = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(message_of(m), HasSubstr("density"));
  m = good;
  m.youngs_modulus = std::numeric_limits<double>::infinity();
  EXPECT_THAT(message_of(m), HasSubstr("Young's modulus"));
}

TEST(IsotropicMaterial, LameParametersOfSteelLikeMaterial) {
  // E = 200 GPa, ν = 0.25: μ = E/2.5 = 80 GPa and λ = Eν/((1.25)(0.5)) = 80 GPa, by hand.
  const LameParameters l = lame_parameters({"steel", 200e9, 0.25, 7800.0});
  EXPECT_NEAR(l.mu, 80e9, 1e-6);  // exact in binary up to one rounding of 80e9
  EXPECT_NEAR(l.lambda, 80e9, 1e-6);
}

}  // namespace
}  // namespace nibrig::model::mechanics
