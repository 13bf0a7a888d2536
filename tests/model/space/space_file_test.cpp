#include "model/space/space_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

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

// A space kept as text (a pickled one) comes back bit for bit: every double printed to round trip.
TEST(SpaceFile, ItsTextReadsBackExactlyAndBrokenTextIsNamed) {
  const SpaceFile s = example();
  const SpaceFile r = parse_space_file(space_file_text(s, "pickled space"), "pickled space");
  EXPECT_EQ(r.coordinates, s.coordinates);
  EXPECT_EQ(r.model.scale, s.model.scale);
  EXPECT_EQ(r.descriptor_map->coefficients, s.descriptor_map->coefficients);
  EXPECT_EQ(r.regions[2].covariance, s.regions[2].covariance);
  try {
    parse_space_file("{\"format\": \"nibrig-catalog\"}", "pickled space");
    ADD_FAILURE() << "another format was read as a space";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("pickled space"), std::string::npos) << e.what();
  }
}

TEST(SpaceFile, TheJudgmentModelItsChoiceAndAnOlderFileWithoutOneRead) {
  const auto dir = nibrig::test::scratch_dir("space_file_model");
  SpaceFile s = example();
  s.model.family = {Link::student_t, true, true};
  s.model.lapse = 0.031;
  s.model.log_noise = Eigen::VectorXd::LinSpaced(5, -0.4, 0.6);
  s.model_reason = "5-fold cross-validation of 12 models";
  s.model_scores = {{"probit", 0.52, 0.81, 0.7, 0.2}, {"student-t+lapse+noise", 0.5, 0.83, 0.71, 0.19}};
  write_space_file(dir / "space.json", s);
  const SpaceFile r = read_space_file(dir / "space.json");
  EXPECT_EQ(r.model.family, s.model.family);
  EXPECT_EQ(r.model.lapse, 0.031);
  EXPECT_TRUE(r.model.log_noise.isApprox(s.model.log_noise, 1e-15));
  EXPECT_EQ(r.model_reason, s.model_reason);
  ASSERT_EQ(r.model_scores.size(), 2u);
  EXPECT_EQ(r.model_scores[1].family, "student-t+lapse+noise");
  EXPECT_EQ(r.model_scores[1].majority_agreement, 0.83);

  // A space written before judgment models existed holds the paper's.
  nlohmann::json old = nlohmann::json::parse(std::ifstream(dir / "space.json"));
  old.erase("judgment_model");
  std::ofstream(dir / "old.json") << old.dump();
  EXPECT_EQ(read_space_file(dir / "old.json").model.family, kPaperModel);
  // A noise too few, and an unknown family, are named with their place.
  old["judgment_model"] = {{"family", "probit+noise"}, {"lapse", 0.0}, {"log_noise", {0.1, 0.2}}};
  std::ofstream(dir / "short.json") << old.dump();
  try {
    read_space_file(dir / "short.json");
    FAIL() << "two noises for five stimuli were accepted";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("judgment_model.log_noise"), std::string::npos) << e.what();
  }
  old["judgment_model"] = {{"family", "cauchy"}, {"lapse", 0.0}};
  std::ofstream(dir / "unknown.json") << old.dump();
  try {
    read_space_file(dir / "unknown.json");
    FAIL() << "an unknown family was accepted";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("judgment_model.family"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("student-t+lapse+noise"), std::string::npos) << e.what();
  }
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

// A damaged or hand-edited space is refused where a number means nothing: a coordinate of 1e300
// would give p_first = nan in `space predict`, and `dims` must match the coordinates.
TEST(SpaceFile, DimsAndCoordinatesOutsideTheirMeaningAreNamed) {
  const auto dir = nibrig::test::scratch_dir("space_file_bounds");
  write_space_file(dir / "space.json", example());
  std::ifstream in(dir / "space.json");
  const nlohmann::json good = nlohmann::json::parse(in);
  const struct {
    std::function<void(nlohmann::json&)> edit;
    std::string field;
  } cases[] = {
      {[](nlohmann::json& j) { j["coordinates"][1][0] = 1e300; }, "coordinates[1][0]"},
      {[](nlohmann::json& j) { j["coordinates"][0][1] = -5e3; }, "coordinates[0][1]"},
      {[](nlohmann::json& j) { j["dims"] = -5; }, "dims"},
      {[](nlohmann::json& j) { j["dims"] = 2.5; }, "dims"},
      {[](nlohmann::json& j) { j["dims"] = 1e20; }, "dims"},
      {[](nlohmann::json& j) { j["dims"] = 3; }, "dims"},  // the points have 2
      {[](nlohmann::json& j) { j["lambda"] = 1e308; }, "lambda"},
  };
  for (const auto& c : cases) {
    nlohmann::json j = good;
    c.edit(j);
    std::ofstream(dir / "bad.json") << j.dump(2);
    try {
      read_space_file(dir / "bad.json");
      ADD_FAILURE() << "accepted a bad " << c.field;
    } catch (const io::FormatError& e) {
      EXPECT_NE(std::string(e.what()).find("field '" + c.field + "'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace nibrig::model::space
