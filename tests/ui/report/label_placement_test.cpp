// Label placement as geometry: a label goes to the preferred free spot, moves away from markers and
// the plot's edge, goes further out with a leader line when its neighbours crowd it, and in a crowd
// is left out rather than drawn over something.
#include "ui/report/label_placement.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::ui::report::detail {
namespace {

constexpr double radius = 4.5, gap = 4.0;

PlacementOptions options(bool skip = false) {
  return {radius, gap, Box{0.0, 0.0, 1000.0, 600.0}, skip};
}

bool overlap(const Box& a, const Box& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

Box marker(const LabelRequest& r) {
  return {r.x - radius, r.y - radius, r.x + radius, r.y + radius};
}

TEST(ReportLabelPlacement, ALonePointIsLabelledOnItsRight) {
  const auto placed = place_labels({{500.0, 300.0, 80.0, 14.0}}, options());
  ASSERT_TRUE(placed[0].placed);
  EXPECT_FALSE(placed[0].leader);
  EXPECT_DOUBLE_EQ(placed[0].just, 0.0);
  EXPECT_DOUBLE_EQ(placed[0].box.x0, 500.0 + radius + gap);
  EXPECT_DOUBLE_EQ(placed[0].box.width(), 80.0);
  EXPECT_DOUBLE_EQ(0.5 * (placed[0].box.y0 + placed[0].box.y1), 300.0);  // centred on the point
}

TEST(ReportLabelPlacement, APointAtTheRightEdgeIsLabelledOnItsLeft) {
  const auto placed = place_labels({{980.0, 300.0, 80.0, 14.0}}, options());
  ASSERT_TRUE(placed[0].placed);
  EXPECT_DOUBLE_EQ(placed[0].box.x1, 980.0 - radius - gap);
  EXPECT_DOUBLE_EQ(placed[0].just, 1.0);  // anchored at the end that faces the point
}

TEST(ReportLabelPlacement, ALabelKeepsOffItsNeighboursMarker) {
  // The neighbour's marker sits where the right-hand label would go; the left is free.
  const std::vector<LabelRequest> requests = {{500.0, 300.0, 80.0, 14.0},
                                              {560.0, 300.0, 0.0, 14.0}};
  const auto placed = place_labels(requests, options());
  ASSERT_TRUE(placed[0].placed);
  EXPECT_FALSE(placed[1].placed);  // no text, no label
  EXPECT_FALSE(overlap(placed[0].box, marker(requests[1])));
  EXPECT_LT(placed[0].box.x1, 500.0);
}

// A point whose eight near spots are all covered by markers around it, with the far ring free.
std::vector<LabelRequest> hemmed_in(double label_width) {
  std::vector<LabelRequest> r = {{500.0, 300.0, label_width, 14.0}};
  for (int c = 0; c < near_candidates; ++c) {
    const Box b = candidate_box(r[0], options(), c);
    r.push_back({0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1), 0.0, 14.0});
  }
  return r;
}

TEST(ReportLabelPlacement, AHemmedInPointIsLabelledFurtherOutWithALeader) {
  const auto requests = hemmed_in(30.0);
  const auto placed = place_labels(requests, options());
  ASSERT_TRUE(placed[0].placed);
  EXPECT_TRUE(placed[0].leader);
  for (std::size_t i = 0; i < requests.size(); ++i)
    EXPECT_FALSE(overlap(placed[0].box, marker(requests[i]))) << "covers marker " << i;
  // The leader starts on the marker's edge and ends on the label's box.
  const auto l = leader_line(requests[0], placed[0].box, radius);
  EXPECT_NEAR(std::hypot(l.x0 - 500.0, l.y0 - 300.0), radius, 1e-9);
  const auto& b = placed[0].box;
  const bool on_edge = std::abs(l.x1 - b.x0) < 1e-9 || std::abs(l.x1 - b.x1) < 1e-9 ||
                       std::abs(l.y1 - b.y0) < 1e-9 || std::abs(l.y1 - b.y1) < 1e-9;
  EXPECT_TRUE(on_edge);
}

TEST(ReportLabelPlacement, InACrowdALabelThatCannotBeFreeIsLeftOut) {
  // A point in a field of markers 12 px apart: every spot of a 100 px label covers some of them.
  std::vector<LabelRequest> requests = {{500.0, 300.0, 100.0, 14.0}};
  for (int i = -30; i <= 30; ++i) {
    for (int j = -6; j <= 6; ++j) {
      if (i != 0 || j != 0) requests.push_back({500.0 + 12.0 * i, 300.0 + 12.0 * j, 0.0, 14.0});
    }
  }
  EXPECT_FALSE(place_labels(requests, options(true))[0].placed);
  // Without the crowd rule the label is drawn anyway, over some markers.
  const auto forced = place_labels(requests, options(false));
  ASSERT_TRUE(forced[0].placed);
  int covered = 0;
  for (std::size_t i = 1; i < requests.size(); ++i)
    covered += overlap(forced[0].box, marker(requests[i]));
  EXPECT_GE(covered, 1);
}

TEST(ReportLabelPlacement, LabelsStayInsideTheBounds) {
  // Corners and edges: each label must find a spot inside the 1000×600 box.
  const std::vector<LabelRequest> requests = {{2.0, 2.0, 120.0, 14.0},
                                              {998.0, 598.0, 120.0, 14.0},
                                              {2.0, 598.0, 120.0, 14.0},
                                              {998.0, 2.0, 120.0, 14.0},
                                              {500.0, 598.0, 120.0, 14.0}};
  const auto placed = place_labels(requests, options(true));
  for (std::size_t i = 0; i < placed.size(); ++i) {
    ASSERT_TRUE(placed[i].placed) << i;
    const auto& b = placed[i].box;
    EXPECT_GE(b.x0, 0.0) << i;
    EXPECT_LE(b.x1, 1000.0) << i;
    EXPECT_GE(b.y0, 0.0) << i;
    EXPECT_LE(b.y1, 600.0) << i;
  }
}

}  // namespace
}  // namespace nibrig::ui::report::detail
