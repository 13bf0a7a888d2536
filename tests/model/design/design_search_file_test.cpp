// The design search's JSON written and read back: the optimum, the runners-up and the path hold
// every candidate's numbers bit for bit (nlohmann writes the digits that read back to the same
// double). The search runs on an objective whose distances are known; no FEM is involved.
#include "model/design/design_search_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "model/io/finite_output.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

SearchResult design_search_file_result() {
  const Evaluate evaluate = [](const DesignPoint& p) {
    Candidate c;
    c.point = p;
    const double fraction = p.fraction_of("DM85"), tip_mm = p.tip_diameter_m * 1e3;
    c.distance = 0.2 + 3 * std::pow(fraction - 0.62, 2);
    c.distance_sd = c.distance / 7;
    c.mu = 0.25 + fraction / 10;
    c.weighted_mean = 0.07 * tip_mm;
    c.placement.mean = Eigen::Vector2d(fraction - 0.5, tip_mm / 3);
    c.placement.covariance = Eigen::Matrix2d::Identity() * 0.01;
    c.target_distances = {c.distance, c.distance + 1};
    c.target_distance_sds = {c.distance_sd, c.distance_sd};
    return c;
  };
  return line_search(parse_design_point("vero,tip=1mm"), parse_design_point("DM85,tip=4mm"),
                     evaluate);
}

TEST(DesignSearchFile, RoundTripsTheOptimumRunnersUpAndPath) {
  const SearchResult result = design_search_file_result();
  const DesignSearchDescription description{"cryon/office",
                                            "glass",
                                            "along the line vero,tip=1mm -> DM85,tip=4mm",
                                            1.25,
                                            3,
                                            "space.json",
                                            {},
                                            {},
                                            {},
                                            {"cryon/office"},
                                            {}};
  const auto file = nibrig::test::scratch_dir("design_search_file") / "design_search.json";
  write_design_search(file, result, description);
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j, design_search_json(result, description));
  EXPECT_EQ(j.at("kind"), "design_search");
  EXPECT_EQ(j.at("target"), "cryon/office");
  EXPECT_EQ(j.at("surface"), "glass");
  EXPECT_EQ(j.at("space"), "space.json");
  EXPECT_EQ(j.at("placed"), nlohmann::json::array({"cryon/office"}));
  EXPECT_EQ(j.at("seconds").get<double>(), 1.25);

  const auto check = [](const nlohmann::json& c, const Candidate& expected) {
    EXPECT_EQ(c.at("design").get<std::string>(), to_string(expected.point));
    EXPECT_EQ(c.at("distance").get<double>(), expected.distance);
    EXPECT_EQ(c.at("distance_sd").get<double>(), expected.distance_sd);
    EXPECT_EQ(c.at("mu").get<double>(), expected.mu);
    EXPECT_EQ(c.at("weighted_mean").get<double>(), expected.weighted_mean);
    const auto coordinates = c.at("coordinates").get<std::vector<double>>();
    ASSERT_EQ(coordinates.size(), 2u);
    EXPECT_EQ(coordinates[0], expected.placement.mean(0));
    EXPECT_EQ(coordinates[1], expected.placement.mean(1));
    EXPECT_EQ(c.at("target_distances").get<std::vector<double>>(), expected.target_distances);
    EXPECT_EQ(c.at("target_distance_sds").get<std::vector<double>>(), expected.target_distance_sds);
  };
  check(j.at("optimum"), result.best());
  const auto runners = result.runners_up(3);
  ASSERT_EQ(j.at("runners_up").size(), runners.size());
  for (std::size_t k = 0; k < runners.size(); ++k)
    check(j.at("runners_up")[k], result.evaluated[runners[k]]);
  ASSERT_EQ(j.at("path").size(), result.evaluated.size());
  for (std::size_t k = 0; k < result.evaluated.size(); ++k)
    check(j.at("path")[k], result.evaluated[k]);

  // Without a space named the key is left out rather than written empty.
  DesignSearchDescription unnamed = description;
  unnamed.space.clear();
  EXPECT_FALSE(design_search_json(result, unnamed).contains("space"));
  EXPECT_FALSE(design_search_json(result, unnamed).contains("constraints"));

  // A group with constraints: its targets, aim and constraints, and each candidate's cost, the
  // fractions times the costs given.
  DesignSearchDescription group = description;
  group.targets = {"cryon/office", "pencil/office"};
  group.aim = "largest";
  group.constraints.max_tip_m = 0.003;
  group.constraints.cost = {{"vero", 1.0}, {"DM85", 3.0}};
  group.constraints.max_cost = 2.5;
  const auto g = design_search_json(result, group);
  EXPECT_EQ(g.at("targets").get<std::vector<std::string>>(), group.targets);
  EXPECT_EQ(g.at("aim"), "largest");
  EXPECT_DOUBLE_EQ(g.at("constraints").at("max_tip_mm").get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(g.at("constraints").at("max_cost").get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(g.at("constraints").at("cost").at("DM85").get<double>(), 3.0);
  const double f = result.best().point.fraction_of("DM85");
  EXPECT_NEAR(g.at("optimum").at("cost").get<double>(), (1 - f) * 1.0 + f * 3.0, 1e-12);

  // Through a grid: its error and solves, and per candidate whether the FEM solved it; a flag per
  // candidate or the file is refused.
  EXPECT_FALSE(j.contains("grid"));
  EXPECT_FALSE(j.at("path")[0].contains("fem_solved"));
  DesignSearchDescription guided = description;
  guided.guided = GuidedDescription{std::vector<bool>(result.evaluated.size(), false), 2.5e-4, 3};
  guided.guided->fem_solved[result.ranked.front()] = true;
  const auto on_grid = design_search_json(result, guided);
  EXPECT_EQ(on_grid.at("grid").at("error").get<double>(), 2.5e-4);
  EXPECT_EQ(on_grid.at("grid").at("fem_solves").get<std::size_t>(), 3u);
  for (std::size_t k = 0; k < result.evaluated.size(); ++k)
    EXPECT_EQ(on_grid.at("path")[k].at("fem_solved").get<bool>(), k == result.ranked.front()) << k;
  guided.guided->fem_solved.pop_back();
  EXPECT_THROW(design_search_json(result, guided), std::invalid_argument);
}

TEST(DesignSearchFile, RefusesANonFiniteDistanceNamingTheField) {
  SearchResult result = design_search_file_result();
  result.evaluated.back().distance_sd = std::nan("");
  const auto file = nibrig::test::scratch_dir("design_search_file_nan") / "broken.json";
  try {
    write_design_search(file, result,
                        {"cryon/office", "glass", "a line", 1.0, 4, "", {}, {}, {}, {}, {}});
    FAIL() << "wrote a NaN";
  } catch (const io::UnwritableOutput& e) {
    EXPECT_NE(std::string(e.what()).find("distance_sd"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace nibrig::model::design
