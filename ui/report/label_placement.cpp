#include "ui/report/label_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace nibrig::ui::report::detail {

namespace {

// Area two boxes share (0 when apart), after growing a by `margin` on every side so that labels
// keep a little air between them.
double shared_area(const Box& a, const Box& b, double margin) {
  const double w = std::min(a.x1 + margin, b.x1) - std::max(a.x0 - margin, b.x0);
  const double h = std::min(a.y1 + margin, b.y1) - std::max(a.y0 - margin, b.y0);
  return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

// How far a box reaches outside the bounds, summed over its sides (0 inside).
double outside(const Box& box, const Box& bounds) {
  return std::max(0.0, bounds.x0 - box.x0) + std::max(0.0, box.x1 - bounds.x1) +
         std::max(0.0, bounds.y0 - box.y0) + std::max(0.0, box.y1 - bounds.y1);
}

// Moves a box the least distance that brings it inside the bounds (as far as it fits).
Box shifted_inside(Box box, const Box& bounds) {
  const double dx = std::max(0.0, bounds.x0 - box.x0) - std::max(0.0, box.x1 - bounds.x1);
  const double dy = std::max(0.0, bounds.y0 - box.y0) - std::max(0.0, box.y1 - bounds.y1);
  return {box.x0 + dx, box.y0 + dy, box.x1 + dx, box.y1 + dy};
}

Box marker_box(const LabelRequest& r, double radius) {
  return {r.x - radius, r.y - radius, r.x + radius, r.y + radius};
}

}  // namespace

Box candidate_box(const LabelRequest& r, const PlacementOptions& options, int candidate) {
  const bool far = candidate >= near_candidates;
  // The far ring clears the near one by about a line of text, so that a leader line shows.
  const double d = options.marker_radius + options.gap + (far ? options.gap + 1.2 * r.height : 0.0);
  // Diagonal spots sit at the same distance from the marker as the straight ones, roughly.
  const double diagonal = 0.75 * d;
  const double w = r.width, h = r.height;
  switch (candidate % near_candidates) {
    case 0:
      return {r.x + d, r.y - 0.5 * h, r.x + d + w, r.y + 0.5 * h};
    case 1:
      return {r.x - d - w, r.y - 0.5 * h, r.x - d, r.y + 0.5 * h};
    case 2:
      return {r.x - 0.5 * w, r.y + d, r.x + 0.5 * w, r.y + d + h};
    case 3:
      return {r.x - 0.5 * w, r.y - d - h, r.x + 0.5 * w, r.y - d};
    case 4:
      return {r.x + diagonal, r.y + diagonal, r.x + diagonal + w, r.y + diagonal + h};
    case 5:
      return {r.x - diagonal - w, r.y + diagonal, r.x - diagonal, r.y + diagonal + h};
    case 6:
      return {r.x + diagonal, r.y - diagonal - h, r.x + diagonal + w, r.y - diagonal};
    default:
      return {r.x - diagonal - w, r.y - diagonal - h, r.x - diagonal, r.y - diagonal};
  }
}

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests,
                                      const PlacementOptions& options) {
  const std::size_t n = requests.size();
  std::vector<Box> markers;
  for (const auto& r : requests) markers.push_back(marker_box(r, options.marker_radius));

  // Crowding: how many other markers lie within reach of a point's label.
  std::vector<int> crowd(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double reach =
        requests[i].width + 2.0 * (options.marker_radius + options.gap) + requests[i].height;
    for (std::size_t j = 0; j < n; ++j) {
      if (j != i &&
          std::hypot(requests[j].x - requests[i].x, requests[j].y - requests[i].y) < reach)
        ++crowd[i];
    }
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (requests[a].first != requests[b].first) return requests[a].first;
    return crowd[a] > crowd[b];
  });

  std::vector<PlacedLabel> out(n);
  std::vector<Box> placed;
  for (std::size_t i : order) {
    const auto& r = requests[i];
    if (r.width <= 0.0) continue;
    const double air = 0.15 * r.height;
    // Compared in this order: inside the bounds, fewest things covered, least area covered, the
    // earlier spot.
    using Cost = std::tuple<double, int, double, int>;
    Cost best{INFINITY, 0, 0.0, 0};
    Box best_box{};
    for (int c = 0; c < label_candidates; ++c) {
      const Box box = candidate_box(r, options, c);
      int covered = 0;
      double area = 0.0;
      for (const auto* set : {&placed, &markers}) {
        for (const auto& other : *set) {
          const double a = shared_area(box, other, air);
          covered += a > 0.0;
          area += a;
        }
      }
      const Cost cost{outside(box, options.bounds), covered, area, c};
      if (cost < best) best = cost, best_box = box;
    }
    const bool clean = std::get<1>(best) == 0;
    if (options.skip_overlapping && !clean && !r.first) continue;
    out[i].placed = true;
    const int spot = std::get<3>(best) % near_candidates;
    out[i].leader = std::get<3>(best) >= near_candidates;
    out[i].just = spot == 2 || spot == 3 ? 0.5 : (spot == 1 || spot == 5 || spot == 7 ? 1.0 : 0.0);
    out[i].box = shifted_inside(best_box, options.bounds);
    placed.push_back(out[i].box);
  }
  return out;
}

Leader leader_line(const LabelRequest& r, const Box& box, double marker_radius) {
  // To the nearest point of the box, from where that direction leaves the marker.
  const double tx = std::clamp(r.x, box.x0, box.x1);
  const double ty = std::clamp(r.y, box.y0, box.y1);
  const double length = std::hypot(tx - r.x, ty - r.y);
  if (length <= marker_radius) return {tx, ty, tx, ty};
  const double ux = (tx - r.x) / length, uy = (ty - r.y) / length;
  return {r.x + ux * marker_radius, r.y + uy * marker_radius, tx, ty};
}

}  // namespace nibrig::ui::report::detail
