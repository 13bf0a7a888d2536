// The design search as a face asks for it, without a face: each refusal names its field and comes
// before the targets are asked for (a face's space file read) or any prediction, and a search
// through the request is the search design_search.hpp's functions make of the same fields. The
// candidates are predicted from a hand-made response grid: milliseconds each, no FEM.
#include "model/design/design_search_request.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "model/numeric/cancellation.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "tests/model/design/synthetic_design_grid.hpp"

namespace nibrig::model::design {
namespace {

using Field = DesignSearchField;

// Six of the grid's designs placed at coordinates linear in their standardised descriptors, with a
// small scatter so that the fit has residuals: a 2-D space the grid's predictions lie in.
space::DescriptorMap space_of(const Predict& predict) {
  space::DescriptorMap names_only;
  names_only.descriptor_names = space::paper_descriptor_names(2);
  const std::vector<std::string> designs = {
      "vero,tip=1.5mm", "vero,tip=3mm", "DM85:0.5,vero:0.5,tip=1.5mm", "DM85:0.5,vero:0.5,tip=3mm",
      "DM85,tip=1.5mm", "DM85,tip=3mm"};
  Eigen::MatrixXd x(designs.size(), 2);
  for (std::size_t k = 0; k < designs.size(); ++k)
    x.row(static_cast<Eigen::Index>(k)) =
        predicted_descriptors(names_only, predict(parse_design_point(designs[k]))).transpose();
  const Eigen::RowVectorXd mean = x.colwise().mean();
  const Eigen::RowVectorXd sd =
      ((x.rowwise() - mean).array().square().colwise().sum() / 5.0).sqrt();
  Eigen::MatrixXd coordinates =
      ((x.rowwise() - mean).array().rowwise() / sd.array()).matrix().transpose();
  for (Eigen::Index k = 0; k < coordinates.cols(); ++k)
    coordinates(k % 2, k) += k % 3 == 0 ? 0.05 : -0.03;
  return space::fit_descriptor_map(coordinates, x, names_only.descriptor_names);
}

struct GridWorld {
  std::unique_ptr<PredictionInputs> inputs = grid_testing::hand_made_inputs();
  DesignResponseGrid grid = grid_testing::synthetic_grid();
  Predict predict = grid_predictor(inputs->setup, grid, "office");
  space::DescriptorMap map = space_of(predict);
  // Where two designs of the grid lie: targets the searches can come near.
  space::Placement near_mix =
      place_predicted(map, predict(parse_design_point("DM85:0.6,vero:0.4,tip=2.7mm")));
  space::Placement near_vero =
      place_predicted(map, predict(parse_design_point("DM85:0.2,vero:0.8,tip=1.2mm")));
  double min_tip_m = grid.axes.tips_m.front(), max_tip_m = grid.axes.tips_m.back();
  int targets_asked = 0;

  DesignSearchRequest request(std::vector<space::Placement> targets) {
    DesignSearchRequest r;
    r.targets = [this, targets] {
      ++targets_asked;
      DesignSearchTargets t{map, targets, {}};
      for (std::size_t k = 0; k < targets.size(); ++k)
        t.names.push_back("target " + std::to_string(k + 1));
      return t;
    };
    r.surface = "office";
    return r;
  }
};

GridWorld& world() {
  static GridWorld w;  // the inputs read and the map fitted once for the file
  return w;
}

Field refused_field(DesignSearchRequest request) {
  try {
    DesignSearch search(std::move(request));
  } catch (const DesignSearchRefused& e) {
    return e.field();
  }
  ADD_FAILURE() << "not refused";
  return Field::printer;
}

TEST(DesignSearchRequest, EachRefusableFieldIsRefusedByNameBeforeTheTargetsAreAskedFor) {
  auto& w = world();
  const auto line =
      std::pair{parse_design_point("vero,tip=1mm"), parse_design_point("DM85,tip=4mm")};
  const std::vector<std::pair<Field, std::function<void(DesignSearchRequest&)>>> cases = {
      {Field::min_tip, [](auto& r) { r.constraints.min_tip_m = 1e-9; }},
      {Field::max_tip, [](auto& r) { r.constraints.max_tip_m = 1.0; }},
      {Field::min_tip,
       [](auto& r) { r.constraints.min_tip_m = 0.003, r.constraints.max_tip_m = 0.002; }},
      {Field::allow,
       [](auto& r) {
         r.constraints.materials = {"vero", "vero"};
       }},
      {Field::cost,
       [](auto& r) {
         r.constraints.cost = {{"vero", -1.0}};
       }},
      {Field::max_cost, [](auto& r) { r.constraints.max_cost = 2.0; }},
      {Field::max_cost,
       [](auto& r) {
         r.constraints.cost = {{"vero", 1.0}};
         r.constraints.max_cost = std::nan("");
       }},
      {Field::surface, [](auto& r) { r.surface.clear(); }},
      {Field::between, [&](auto& r) { r.between = line, r.constraints.max_tip_m = 0.0005; }},
      {Field::between, [&](auto& r) { r.between = line, r.constraints.materials = {"steel"}; }},
      {Field::printer,
       [&](auto& r) {
         r.between = line;
         r.printer.emplace().materials = {"steel"};
       }},
      {Field::mix, [](auto& r) { r.second_material = "vero"; }},
      {Field::mix, [](auto& r) { r.first_material.clear(); }},
      {Field::mix, [](auto& r) { r.constraints.materials = {"DM95"}; }},
      {Field::targets, [](auto& r) { r.targets = nullptr; }},
  };
  for (const auto& [field, change] : cases) {
    auto request = w.request({w.near_mix});
    change(request);
    w.targets_asked = 0;
    EXPECT_EQ(refused_field(std::move(request)), field) << field_name(field);
    EXPECT_EQ(w.targets_asked, 0) << field_name(field)
                                  << ": refused before the targets are asked for";
  }
  try {
    parse_group_aim("nearest");
    ADD_FAILURE() << "an aim of 'nearest' accepted";
  } catch (const DesignSearchRefused& e) {
    EXPECT_EQ(e.field(), Field::aim);
  }
  EXPECT_EQ(parse_group_aim("mean"), space::GroupAim::mean);
}

// Through a design grid, a design it does not mix is refused by field, before any prediction.
TEST(DesignSearchRequest, ASearchThroughAGridRefusesDesignsItDoesNotMix) {
  auto& w = world();
  auto line = w.request({w.near_mix});
  line.between.emplace(parse_design_point("vero,tip=1mm"), parse_design_point("DM95,tip=4mm"));
  auto range = w.request({w.near_mix});
  range.second_material = "DM95";
  for (auto [request, field] : {std::pair{line, Field::between}, std::pair{range, Field::mix}}) {
    const DesignSearch search(std::move(request));
    try {
      search.run(*w.inputs, w.grid, {}, [](const Candidate& c, std::size_t, std::size_t) {
        ADD_FAILURE() << to_string(c.point) << " predicted";
      });
      ADD_FAILURE() << field_name(field) << " not refused";
    } catch (const DesignSearchRefused& e) {
      EXPECT_EQ(e.field(), field);
      EXPECT_NE(std::string(e.what()).find("DM95"), std::string::npos) << e.what();
    }
  }
}

TEST(DesignSearchRequest, TargetsWithoutAMapOrInAnotherSpaceAreRefusedByName) {
  auto& w = world();
  auto no_map = w.request({w.near_mix});
  no_map.targets = [] { return DesignSearchTargets{std::nullopt, {space::Placement{}}, {"t"}}; };
  EXPECT_EQ(refused_field(std::move(no_map)), Field::space);
  EXPECT_EQ(refused_field(w.request({})), Field::targets);
  space::Placement three_d{Eigen::VectorXd::Zero(3), Eigen::MatrixXd::Zero(3, 3)};
  EXPECT_EQ(refused_field(w.request({w.near_mix, three_d})), Field::targets);
  // A surface the forcing model lacks: refused when run, before the first prediction.
  auto glass = w.request({w.near_mix});
  glass.surface = "glass";
  const DesignSearch search(std::move(glass));
  try {
    search.run(*w.inputs);
    ADD_FAILURE() << "a surface the model lacks accepted";
  } catch (const DesignSearchRefused& e) {
    EXPECT_EQ(e.field(), Field::surface);
  }
}

TEST(DesignSearchRequest, TheFacesNamesAreTheMessagesNames) {
  // "min_tip_mm: 3 mm is above max_tip_mm, 2 mm": both fields in the face's words.
  auto request = world().request({world().near_mix});
  request.constraints.min_tip_m = 0.003, request.constraints.max_tip_m = 0.002;
  const DesignSearchNames names = [](Field f) { return std::string("<") + field_name(f) + ">"; };
  try {
    DesignSearch search(std::move(request), names);
    ADD_FAILURE() << "not refused";
  } catch (const DesignSearchRefused& e) {
    EXPECT_EQ(std::string(e.what()).rfind("<min_tip_mm>: ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("<max_tip_mm>"), std::string::npos) << e.what();
  }
}

TEST(DesignSearchRequest, ARangeSearchIsTheRangeSearchOfItsFields) {
  auto& w = world();
  auto request = w.request({w.near_mix});
  request.constraints.max_tip_m = 0.0035;
  request.constraints.cost = {{"vero", 1.0}, {"DM85", 3.0}};
  request.constraints.max_cost = 2.5;  // DM85 at most 0.75
  const DesignSearch search(std::move(request));
  std::size_t progressed = 0;
  const auto outcome =
      search.run(w.predict, w.min_tip_m, w.max_tip_m, {},
                 [&](const Candidate&, std::size_t, std::size_t) { ++progressed; });

  // The independent computation: range_search on the same evaluation and options, made by hand.
  RangeSearchOptions range;
  range.min_tip_m = w.min_tip_m, range.max_tip_m = w.max_tip_m;
  range.constraints = search.request().constraints;
  const auto direct = range_search(distance_to_target(w.predict, w.map, w.near_mix), range);
  // The same candidates in the same order, each with the same seeded draws for its sd: equal to
  // the last bit, so no tolerance is needed.
  ASSERT_EQ(outcome.result.evaluated.size(), direct.evaluated.size());
  EXPECT_EQ(to_string(outcome.result.best().point), to_string(direct.best().point));
  EXPECT_EQ(outcome.result.best().distance, direct.best().distance);
  EXPECT_EQ(outcome.result.best().distance_sd, direct.best().distance_sd);
  EXPECT_EQ(outcome.evaluations, direct.evaluated.size());
  EXPECT_EQ(progressed, direct.evaluated.size());
  EXPECT_TRUE(outcome.line_ends.empty());
  // The target is a design inside the allowed range (DM85 0.6, tip 2.7 mm): the optimum lies within
  // half a final step of it (fraction 0.75/16, tip 2.5 mm/12), 0.039 of the space's unit away in
  // this space; the bound is that with a margin of 2.5.
  EXPECT_LT(outcome.result.best().distance, 0.1);
  EXPECT_LE(outcome.result.best().point.fraction_of("DM85"), 0.75 + 1e-9);
  EXPECT_LE(outcome.result.best().point.tip_diameter_m, 0.0035 + 1e-12);
}

TEST(DesignSearchRequest, AGroupsLineSearchIsTheLineSearchOfItsFields) {
  auto& w = world();
  auto request = w.request({w.near_mix, w.near_vero});
  request.aim = space::GroupAim::mean;
  request.between =
      std::pair{parse_design_point("vero,tip=1mm"), parse_design_point("DM85,tip=4mm")};
  request.constraints.min_tip_m = 0.0015;
  const DesignSearch search(std::move(request));
  ASSERT_TRUE(search.group());
  const auto outcome = search.run(w.predict, w.min_tip_m, w.max_tip_m);

  LineSearchOptions line;
  line.constraints = search.request().constraints;
  const auto direct = line_search(
      search.request().between->first, search.request().between->second,
      distance_to_targets(w.predict, w.map, {w.near_mix, w.near_vero}, space::GroupAim::mean),
      line);
  ASSERT_EQ(outcome.result.evaluated.size(), direct.evaluated.size());
  for (std::size_t k = 0; k < direct.evaluated.size();
       ++k) {  // the same path, bit for bit as above
    EXPECT_EQ(to_string(outcome.result.evaluated[k].point), to_string(direct.evaluated[k].point));
    EXPECT_EQ(outcome.result.evaluated[k].distance, direct.evaluated[k].distance);
  }
  // The mean of the two targets' distances, each kept.
  const auto& best = outcome.result.best();
  ASSERT_EQ(best.target_distances.size(), 2u);
  EXPECT_NEAR(best.distance, (best.target_distances[0] + best.target_distances[1]) / 2, 1e-12);
  // The scan's ends are the ends of the segment the smallest tip allows: λ from 1/6 (1.5 mm) to 1.
  ASSERT_EQ(outcome.line_ends.size(), 2u);
  EXPECT_NEAR(outcome.result.evaluated[outcome.line_ends[0]].point.tip_diameter_m, 0.0015, 1e-9);
  EXPECT_NEAR(outcome.result.evaluated[outcome.line_ends[1]].point.tip_diameter_m, 0.004, 1e-9);
}

TEST(DesignSearchRequest, AStopBeforeTheFirstCandidatePredictsNothing) {
  auto& w = world();
  const DesignSearch search(w.request({w.near_mix}));
  std::stop_source stop;
  stop.request_stop();
  std::size_t progressed = 0;
  EXPECT_THROW(search.run(w.predict, w.min_tip_m, w.max_tip_m, stop.get_token(),
                          [&](const Candidate&, std::size_t, std::size_t) { ++progressed; }),
               numeric::Cancelled);
  EXPECT_EQ(progressed, 0u);
}

}  // namespace
}  // namespace nibrig::model::design
