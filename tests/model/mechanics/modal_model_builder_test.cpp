#include "model/mechanics/modal_model_builder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "tests/model/mechanics/box_mesh.hpp"

namespace nibrig::model::mechanics {
namespace {

using ::testing::HasSubstr;

constexpr double kBuilderLength = 0.18, kBuilderWidth = 0.02, kBuilderThickness = 0.002, kBuilderModulus = 0.45e9;

class CantileverModel : public ::testing::Test {
 protected:
  // ν = 0 so that beam theory is the exact thin limit (see modal_analysis_test.cpp); 12 modes of
  // the 8 mm mesh hold the first six thickness bendings.
  CantileverModel()
      : mesh_(test::box_mesh({kBuilderLength, kBuilderWidth, kBuilderThickness}, 8e-3)),
        system_(assemble(mesh_, {{"VeroClear", kBuilderModulus, 0.0, 1180.0}}, {"clamp"})),
        modes_(compute_modes(system_, options())),
        locator_(mesh_) {}

  static ModalOptions options() {
    ModalOptions o;
    o.modes = 12;
    return o;
  }

  TetMesh mesh_;
  FemSystem system_;
  ModalResult modes_;
  PointLocator locator_;
};

TEST_F(CantileverModel, ModalSumsGiveTheBeamsStaticCompliances) {
  ModalProbe probe;
  probe.tip = {kBuilderLength, kBuilderWidth / 2, kBuilderThickness / 2};  // middle of the free end
  probe.tip_direction = Eigen::Vector3d::UnitZ();
  probe.sensor = {kBuilderLength / 2, kBuilderWidth / 2, kBuilderThickness};  // mid-span, on the top face
  probe.sensor_axis = Eigen::Vector3d::UnitZ();
  const double alpha = 0.5, lambda = 1.25e-3;  // 1/s and s; the paper's fitted λ
  const modal::ModalModel model = build_modal_model(locator_, modes_, alpha, lambda, probe);
  ASSERT_EQ(model.size(), 12u);

  // A static force F at the tip along z deflects the tip by F Σ b_i²/ω_i² and mid-span by
  // F Σ c_i b_i/ω_i² (modal expansion of the static response, mass-normalised shapes). Beam theory:
  // L³/(3EI) and (L/2)²(3L − L/2)/(6EI) = 5L³/(48EI). The modes held here (six of the infinitely
  // many bendings) carry all but 0.03 % of the tip sum (Σ_n 4/(β_n L)⁴ = 1/3, and n > 5 adds
  // 1e-4 of it); shear adds 0.007 % and the 8 mm mesh is 0.03 % stiff in the first mode: 0.5 %
  // bounds them all with room, and a wrong normalisation or probe would be off by far more.
  const double ei = kBuilderModulus * kBuilderWidth * std::pow(kBuilderThickness, 3) / 12.0;
  double tip = 0.0, mid = 0.0;
  for (std::size_t i = 0; i < model.size(); ++i) {
    tip += model.input[i] * model.input[i] / (model.omega[i] * model.omega[i]);
    mid += model.output[i] * model.input[i] / (model.omega[i] * model.omega[i]);
  }
  const double tip_beam = std::pow(kBuilderLength, 3) / (3 * ei);
  const double mid_beam = 5 * std::pow(kBuilderLength, 3) / (48 * ei);
  EXPECT_NEAR(tip, tip_beam, 0.005 * tip_beam);
  EXPECT_NEAR(mid, mid_beam, 0.005 * mid_beam);

  for (std::size_t i = 0; i < model.size(); ++i) {
    EXPECT_EQ(model.omega[i], modes_.omega(static_cast<Eigen::Index>(i)));
    const double w = model.omega[i];
    EXPECT_NEAR(model.zeta[i], alpha / (2 * w) + lambda * w / 2, 1e-15 * (1 + model.zeta[i]));
  }
}

TEST_F(CantileverModel, BadProbesAndCoefficientsAreRejected) {
  ModalProbe good;
  good.tip = {kBuilderLength, kBuilderWidth / 2, kBuilderThickness / 2};
  good.sensor = {kBuilderLength / 2, kBuilderWidth / 2, kBuilderThickness};
  EXPECT_NO_THROW(build_modal_model(locator_, modes_, 0.0, 1e-3, good));

  ModalProbe p = good;
  p.tip_direction = {0.0, 0.0, 2.0};
  EXPECT_THAT([&] { build_modal_model(locator_, modes_, 0.0, 1e-3, p); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("tip direction")));
  p = good;
  p.sensor_axis = {0.0, 0.0, 0.0};
  EXPECT_THAT([&] { build_modal_model(locator_, modes_, 0.0, 1e-3, p); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("sensor axis")));
  EXPECT_THAT([&] { build_modal_model(locator_, modes_, 0.0, -1e-3, good); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("lambda")));
  p = good;
  p.tip = {kBuilderLength + 0.01, kBuilderWidth / 2, kBuilderThickness / 2};  // 10 mm past the end
  EXPECT_THAT([&] { build_modal_model(locator_, modes_, 0.0, 1e-3, p); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  HasSubstr("is outside the body: nearest surface is 10 mm away")));
}

}  // namespace
}  // namespace nibrig::model::mechanics
