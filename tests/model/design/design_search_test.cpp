// The searches against objectives whose minimum is known, checked against a brute-force scan of a
// fine grid (the independent reference); no FEM is involved.
#include "model/design/design_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/model/design/search_objective.hpp"

namespace nibrig::model::design {
namespace {

using search_testing::objective;

TEST(DesignSearch, TheLineSearchFindsTheMinimumABruteForceScanFinds) {
  // Along vero 1 mm → DM85 4 mm, λ sets the fraction to λ and the tip to 1 + 3λ mm. Two dips: a
  // shallow one near λ = 0.15 and the deeper one at λ = 0.62, which the scan must not miss.
  const auto f = [](double fraction, double) {
    return std::min(0.5 + 4 * std::pow(fraction - 0.15, 2), 0.2 + 3 * std::pow(fraction - 0.62, 2));
  };
  const auto result = line_search(parse_design_point("vero,tip=1mm"),
                                  parse_design_point("DM85,tip=4mm"), objective(f));
  double brute = 0, brute_value = 1e9;
  for (int k = 0; k <= 100000; ++k) {
    const double l = k / 100000.0;
    if (f(l, 0) < brute_value) brute_value = f(l, 0), brute = l;
  }
  EXPECT_NEAR(result.best().point.fraction_of("DM85"), brute, 0.01);
  EXPECT_NEAR(result.best().point.tip_diameter_m, 0.001 + 0.003 * brute, 0.0003);
  EXPECT_NEAR(result.best().distance, brute_value, 1e-3);
  // The path starts with the scan from a to b, and the ranking is by distance.
  EXPECT_DOUBLE_EQ(result.evaluated.front().point.fraction_of("vero"), 1.0);
  EXPECT_DOUBLE_EQ(result.evaluated[8].point.fraction_of("DM85"), 1.0);
  for (std::size_t k = 1; k < result.ranked.size(); ++k)
    EXPECT_LE(result.evaluated[result.ranked[k - 1]].distance,
              result.evaluated[result.ranked[k]].distance);
  EXPECT_LT(result.evaluated.size(), 30u);  // 9 scan points and a few golden sections
}

TEST(DesignSearch, TheRangeSearchFindsTheMinimumOfTheWholeRange) {
  const auto f = [](double fraction, double tip_mm) {
    return std::hypot(fraction - 0.6, 0.4 * (tip_mm - 2.7));
  };
  const auto result = range_search(objective(f));
  // The first grid has steps of 0.25 and 1 mm, two refinements quarter them: the optimum is found
  // within half a final step.
  EXPECT_NEAR(result.best().point.fraction_of("DM85"), 0.6, 0.0625 / 2 + 1e-9);
  EXPECT_NEAR(result.best().point.tip_diameter_m * 1e3, 2.7, 0.25 / 2 + 1e-9);
  // Every candidate is a valid design inside the range.
  for (const auto& c : result.evaluated) {
    EXPECT_NO_THROW(validate(c.point));
    EXPECT_GE(c.point.tip_diameter_m, 0.001 - 1e-12);
    EXPECT_LE(c.point.tip_diameter_m, 0.004 + 1e-12);
  }
}

// Every progress call, and a check that its candidate is the one the search just kept.
struct ProgressLog {
  std::vector<std::size_t> done, totals;
  std::vector<double> distances;
  SearchProgress callback() {
    return [this](const Candidate& c, std::size_t d, std::size_t total) {
      done.push_back(d);
      totals.push_back(total);
      distances.push_back(c.distance);
    };
  }
  // One call per candidate evaluated, in order, with a total fixed before the first.
  void expect_one_call_per_candidate(const SearchResult& result) const {
    ASSERT_EQ(done.size(), result.evaluated.size());
    for (std::size_t k = 0; k < done.size(); ++k) {
      EXPECT_EQ(done[k], k + 1);  // the searches are sequential: counts arrive in order
      EXPECT_EQ(totals[k], totals.front());
      EXPECT_EQ(distances[k], result.evaluated[k].distance);
    }
    EXPECT_LE(done.size(), totals.front());  // the total is a bound the search never exceeds
  }
};

bool same_search(const SearchResult& a, const SearchResult& b) {
  if (a.ranked != b.ranked || a.evaluated.size() != b.evaluated.size()) return false;
  for (std::size_t k = 0; k < a.evaluated.size(); ++k)
    if (a.evaluated[k].distance != b.evaluated[k].distance) return false;
  return true;
}

TEST(DesignSearch, TheLineSearchReportsEachCandidateAndReachesItsTotal) {
  // The deeper dip at λ = 0.62 lies inside the line: the golden section brackets two full scan
  // steps, the widest bracket, so the search evaluates exactly its announced total.
  const auto f = objective([](double fraction, double) {
    return std::min(0.5 + 4 * std::pow(fraction - 0.15, 2), 0.2 + 3 * std::pow(fraction - 0.62, 2));
  });
  const auto a = parse_design_point("vero,tip=1mm"), b = parse_design_point("DM85,tip=4mm");
  ProgressLog log;
  const auto watched = line_search(a, b, f, {}, log.callback());
  log.expect_one_call_per_candidate(watched);
  EXPECT_EQ(log.done.back(), log.totals.back());
  EXPECT_TRUE(same_search(watched, line_search(a, b, f)));  // watching changes nothing
}

TEST(DesignSearch, TheRangeSearchReportsEachCandidateAndStopsShortAtAnEdge) {
  // An interior optimum: every refinement evaluates all 8 neighbours, 5 × 4 + 2 × 8 = 36.
  const auto inside = objective([](double fraction, double tip_mm) {
    return std::hypot(fraction - 0.6, 0.4 * (tip_mm - 2.7));
  });
  ProgressLog log;
  const auto watched = range_search(inside, {}, log.callback());
  log.expect_one_call_per_candidate(watched);
  EXPECT_EQ(log.totals.front(), 36u);
  EXPECT_EQ(log.done.back(), 36u);
  EXPECT_TRUE(same_search(watched, range_search(inside)));
  // The optimum in a corner (pure vero, 1 mm): neighbours outside the range are skipped, so the
  // count ends below the announced total, which stays fixed.
  const auto corner = objective([](double fraction, double tip_mm) { return fraction + tip_mm; });
  ProgressLog edge;
  const auto at_edge = range_search(corner, {}, edge.callback());
  edge.expect_one_call_per_candidate(at_edge);
  EXPECT_LT(edge.done.back(), 36u);
}

TEST(DesignSearch, RefusesSearchesThatCannotBeMade) {
  const auto f = objective([](double, double) { return 0.0; });
  EXPECT_THROW(line_search(parse_design_point("vero,tip=1mm"), parse_design_point("DM85,tip=4mm"),
                           f, {1, 0.01, {}}),
               std::invalid_argument);
  RangeSearchOptions same;
  same.second_material = "vero";
  EXPECT_THROW(range_search(f, same), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::design
