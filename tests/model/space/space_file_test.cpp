#include "model/space/space_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::space {
namespace {

SpaceFile example() {
  SpaceFile s;
  s.stimuli = {"a/x", "b/x", "c/x", "d/x", "e/x"};
  s.coordinates = Eigen::MatrixXd::Random(2, 5);
  s.model.scale = 2.0 / 3.0;
  s.lambda = 0.5;
  s.descriptor_names = {"mu", "log10_vib"};
  s.descriptors = Eigen::MatrixXd::Random(5, 2);
  s.descriptor_source = "catalog.json";
  s.descriptor_map = fit_descriptor_map(s.coordinates, s.descriptors, s.descriptor_names);
  s.region_levels = {0.68, 0.95};
  for (int i = 0; i < 5; ++i)
    s.regions.push_back({Eigen::Vector2d(i, -i), Eigen::Matrix2d{{1.0, 0.1}, {0.1, 2.0}}, {1.5, 2.4}});
  s.bootstrap_resamples = 100;
  return s;
}

TEST(SpaceFile, DescriptorsMapAndRegionsSurviveARoundTrip) {
  const auto dir = nibrig::test::scratch_dir("space_file");
  const SpaceFile s = example();
  write_space_file(dir / "space.json", s);
  const SpaceFile r = read_space_file(dir / "space.json");
  EXPECT_TRUE(r.coordinates.isApprox(s.coordinates, 1e-14));
  EXPECT_EQ(r.descriptor_names, s.descriptor_names);
  EXPECT_TRUE(r.descriptors.isApprox(s.descriptors, 1e-14));
  ASSERT_TRUE(r.descriptor_map.has_value());
  const Eigen::Vector2d x(0.2, -0.1);
  const Placement a = place_from_descriptors(*s.descriptor_map, x);
  const Placement b = place_from_descriptors(*r.descriptor_map, x);
  EXPECT_TRUE(a.mean.isApprox(b.mean, 1e-12));  // JSON keeps doubles to 17 digits
  EXPECT_TRUE(a.covariance.isApprox(b.covariance, 1e-12));
  ASSERT_EQ(r.regions.size(), 5u);
  EXPECT_EQ(r.regions[3].radius, s.regions[3].radius);
  EXPECT_TRUE(r.regions[3].covariance.isApprox(s.regions[3].covariance));
  EXPECT_EQ(r.bootstrap_resamples, 100);
}

TEST(SpaceFile, ARegionOfTheWrongShapeIsNamed) {
  const auto dir = nibrig::test::scratch_dir("space_file_bad");
  SpaceFile s = example();
  s.regions[2].covariance = Eigen::Matrix3d::Identity();
  write_space_file(dir / "space.json", s);
  try {
    read_space_file(dir / "space.json");
    FAIL() << "a 3x3 covariance in a 2-D space was accepted";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("bootstrap.regions[2].covariance"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::space
