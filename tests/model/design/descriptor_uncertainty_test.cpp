// A predicted tool's descriptor error: the friction errors of middle tips and the second moments
// computed by hand on small tables, and a predicted tool placed with it as the space's map says.
#include "model/design/descriptor_uncertainty.hpp"

#include <gtest/gtest.h>

#include <random>

#include "model/design/design_search.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/descriptor_map.hpp"

namespace nibrig::model::design {
namespace {

io::Catalog friction_catalog() {
  io::Catalog c;
  auto tool = [&](std::string id, std::string material, double tip, std::string surface,
                  double mu) {
    if (std::none_of(c.tools.begin(), c.tools.end(), [&](const auto& t) { return t.id == id; }))
      c.tools.push_back({id, id, "printed", material, tip});
    io::Pairing p;
    p.tool = id;
    p.surface = surface;
    p.friction = io::FrictionDescriptor{};
    p.friction->mu = mu;
    c.pairings.push_back(p);
  };
  tool("vero1", "vero", 0.001, "office", 0.10);
  tool("vero2", "vero", 0.002, "office", 0.13);
  tool("vero4", "vero", 0.004, "office", 0.16);
  tool("vero2_nail1", "vero", 0.002, "office", 9.0);  // a worn variant: never used
  tool("DM851", "DM85", 0.001, "office", 0.50);       // no middle tip of DM85
  tool("DM854", "DM85", 0.004, "office", 0.80);
  tool("vero1", "vero", 0.001, "glass", 0.20);  // two tips on glass: no middle either
  tool("vero2", "vero", 0.002, "glass", 0.30);
  c.tools.push_back({"pencil", "pencil", "real", "graphite", 0.001});
  io::Pairing pencil;
  pencil.tool = "pencil";
  pencil.surface = "office";
  pencil.friction = io::FrictionDescriptor{};
  pencil.friction->mu = 0.3;
  c.pairings.push_back(pencil);
  return c;
}

TEST(DescriptorUncertainty, FrictionErrorsAreThoseOfTheMiddleTipsOnly) {
  const auto errors = friction_interpolation_errors(friction_catalog());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].tool, "vero2");
  EXPECT_EQ(errors[0].surface, "office");
  // 2 mm lies a third of the way from 1 to 4 mm: 0.10 + (0.16 − 0.10)/3 = 0.12, measured 0.13.
  EXPECT_NEAR(errors[0].error, -0.01, 1e-15);
}

forcing::DescriptorError vibration_error(double mean, double scale) {
  forcing::DescriptorError e{"t", "s", mean, {}};
  for (int k = forcing::kMinDescriptorBands; k <= forcing::kMaxDescriptorBands; ++k)
    for (int j = 0; j < k; ++j) e.log10_band_energies[k].push_back(scale * (j + 1));
  return e;
}

TEST(DescriptorUncertainty, TheCovarianceIsTheSecondMomentAboutZero) {
  const std::vector<forcing::DescriptorError> vibration{vibration_error(0.1, 0.01),
                                                        vibration_error(-0.3, -0.02)};
  const std::vector<FrictionInterpolationError> friction{{"a", "s", 0.01}, {"b", "s", -0.03}};
  const auto c = descriptor_error_covariance(vibration, friction);
  EXPECT_EQ(c.names, space::all_paper_descriptor_names());
  EXPECT_EQ(c.vibration_samples, 2u);
  EXPECT_EQ(c.friction_samples, 2u);
  const auto two_d = c.block(space::paper_descriptor_names(2));  // μ, weighted mean
  EXPECT_NEAR(two_d(0, 0), (0.01 * 0.01 + 0.03 * 0.03) / 2, 1e-15);
  EXPECT_NEAR(two_d(1, 1), (0.1 * 0.1 + 0.3 * 0.3) / 2, 1e-15);  // not centred: the bias counts
  EXPECT_EQ(two_d(0, 1), 0.0);  // friction and vibration errors: different tools
  // Three bands (a 4-D space): band j is scale·(j + 1) in both samples.
  const auto four_d = c.block(space::paper_descriptor_names(4));
  for (Eigen::Index i = 1; i < 4; ++i)
    for (Eigen::Index j = 1; j < 4; ++j)
      EXPECT_NEAR(four_d(i, j), (0.01 * 0.01 + 0.02 * 0.02) * i * j / 2, 1e-15) << i << j;
  // The weighted mean against band 1 of 2: (0.1 · 0.01 + (−0.3) · (−0.02)) / 2.
  const auto cross =
      c.block({space::paper_descriptor_names(2)[1], space::paper_descriptor_names(3)[1]});
  EXPECT_NEAR(cross(0, 1), (0.1 * 0.01 + 0.3 * 0.02) / 2, 1e-15);
  EXPECT_EQ(cross(0, 1), cross(1, 0));
  // A measured μ has no interpolation error.
  EXPECT_EQ(c.without_friction().block(space::paper_descriptor_names(2))(0, 0), 0.0);
  EXPECT_EQ(c.without_friction().block(space::paper_descriptor_names(2))(1, 1), two_d(1, 1));
}

TEST(DescriptorUncertainty, RefusesWhatItCannotEstimate) {
  EXPECT_THROW(descriptor_error_covariance({}, {}), std::invalid_argument);
  const std::vector<forcing::DescriptorError> vibration{vibration_error(0.1, 0.01)};
  const auto c = descriptor_error_covariance(vibration, {});
  EXPECT_EQ(c.friction_samples, 0u);
  EXPECT_EQ(c.block(space::paper_descriptor_names(1))(0, 0), 0.0);
  try {
    c.block({"loudness"});
    ADD_FAILURE() << "an unknown descriptor was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("loudness"), std::string::npos) << e.what();
  }
}

TEST(DescriptorUncertainty, APredictedToolIsPlacedWithItsErrorThroughTheMap) {
  // A 2-D space whose map is fitted to random coordinates over (μ, log10 weighted mean).
  std::mt19937_64 generator(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::Index n = 12;
  Eigen::MatrixXd descriptors(n, 2), coordinates(2, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    descriptors.row(i) << 0.2 + 0.05 * normal(generator), -1.0 + 0.1 * normal(generator);
    coordinates.col(i) << 20 * descriptors(i, 0) + 0.1 * normal(generator),
        10 * descriptors(i, 1) + 0.1 * normal(generator);
  }
  const auto map =
      space::fit_descriptor_map(coordinates, descriptors, space::paper_descriptor_names(2));
  PredictedTool tool;
  tool.point = parse_design_point("vero:0.5,DM85:0.5,tip=2mm");
  tool.surface = "office";
  tool.mu = 0.21;
  tool.vibration.weighted_mean = std::pow(10.0, -0.95);
  const space::Placement measured_like = place_predicted(map, tool);
  const std::vector<forcing::DescriptorError> vibration{vibration_error(0.05, 0.01),
                                                        vibration_error(-0.04, 0.02)};
  const std::vector<FrictionInterpolationError> friction{{"a", "s", 0.01}};
  tool.descriptor_errors = descriptor_error_covariance(vibration, friction);
  const space::Placement predicted = place_predicted(map, tool);
  EXPECT_TRUE(predicted.mean.isApprox(measured_like.mean, 1e-15));
  // Each axis gains its own descriptor's error: axis 1 ≈ 20·sd(μ), axis 2 ≈ 10·sd(log10 mean)
  // (the map's slopes), up to the small cross slopes the noise leaves.
  const double mu_variance = 0.01 * 0.01, mean_variance = (0.05 * 0.05 + 0.04 * 0.04) / 2;
  EXPECT_NEAR(predicted.covariance(0, 0) - measured_like.covariance(0, 0), 400 * mu_variance,
              0.05 * 400 * mu_variance);
  EXPECT_NEAR(predicted.covariance(1, 1) - measured_like.covariance(1, 1), 100 * mean_variance,
              0.05 * 100 * mean_variance);
  // Exactly the map's J·Σ·Jᵀ.
  const Eigen::MatrixXd jacobian =
      map.coefficients.rightCols(2) * map.descriptor_scale.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd added =
      jacobian * tool.descriptor_errors.block(map.descriptor_names) * jacobian.transpose();
  EXPECT_TRUE((predicted.covariance - measured_like.covariance).isApprox(added, 1e-12));
}

}  // namespace
}  // namespace nibrig::model::design
