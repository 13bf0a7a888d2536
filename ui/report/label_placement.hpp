// Where the labels of a scatter plot go: beside their points, each at the candidate spot that
// covers the fewest labels and markers already placed. Pure page geometry (pixels, origin bottom
// left), kept apart from drawing so that it can be reasoned about and tested without PLplot.
#pragma once

#include <vector>

#include "ui/report/chart_parts.hpp"

namespace nibrig::ui::report::detail {

struct LabelRequest {
  double x, y;           // the marker's centre
  double width, height;  // the label's box; width 0 means no label
  bool first = false;    // placed before the others and never left out (what a figure is about)
};

struct PlacementOptions {
  double marker_radius;  // every marker is kept clear as a square of this half-width
  double gap;            // between a marker's edge and the nearest label
  Box bounds;            // labels stay inside (the plot box)
  // Leave out a label whose best spot still covers something (a crowded plot) instead of placing
  // it over another label or a marker.
  bool skip_overlapping = false;
};

// Spots beside a point, in order of preference: right, left, above, below, the four diagonals,
// then the same eight further out, where a leader line joins the label to its point.
constexpr int label_candidates = 16;
constexpr int near_candidates = 8;
Box candidate_box(const LabelRequest& request, const PlacementOptions& options, int candidate);

struct PlacedLabel {
  bool placed = false;
  bool leader = false;  // far from its point: draw a leader line
  Box box{};
  // Where the text is anchored in the box: 0 its start at the left edge (a label right of its
  // point), 1 its end at the right edge (left of the point), 0.5 centred (above or below). The box
  // is sized from an estimate of the text width that errs wide: anchored on the side facing the
  // point, the text stays close to it.
  double just = 0.0;
};

// One entry per request (not placed when width is 0, or skipped in a crowd). Labels asked `first`
// are placed before the others; then the most crowded point first, so that the points with the fewest free spots choose before their
// neighbours take them; ties between spots go to the earlier spot in the order above.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests,
                                      const PlacementOptions& options);

// Where a leader line from the marker's edge to the label box ends: {x0, y0, x1, y1}.
struct Leader {
  double x0, y0, x1, y1;
};
Leader leader_line(const LabelRequest& request, const Box& box, double marker_radius);

}  // namespace nibrig::ui::report::detail
