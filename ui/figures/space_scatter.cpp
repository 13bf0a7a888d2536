#include "ui/figures/space_scatter.hpp"

#include <fmt/format.h>

#include "model/space/bootstrap.hpp"

namespace nibrig::ui::figures {

namespace space = model::space;

namespace {

std::string group_of(const std::string& name) {
  const auto slash = name.rfind('/');
  return slash == std::string::npos ? std::string() : name.substr(slash + 1);
}

report::Ellipse ellipse_at(const Eigen::VectorXd& centre, const space::PlaneEllipse& e,
                           bool one_dimensional) {
  report::Ellipse out{centre(0), one_dimensional ? 0.0 : centre(1), e.semi_axis_1, e.semi_axis_2,
                      e.angle_rad};
  return out;
}

}  // namespace

report::ScatterPlot space_scatter(const space::SpaceFile& s, const std::vector<PlacedTool>& placed,
                                  const std::string& title) {
  const bool one_d = s.coordinates.rows() == 1;
  report::ScatterPlot plot;
  plot.title = title;
  plot.x_label = s.descriptor_names.empty() ? "axis 1" : "axis 1 (" + s.descriptor_names[0] + ")";
  plot.y_label = one_d ? "" : s.descriptor_names.size() < 2 ? "axis 2"
                                                            : "axis 2 (" + s.descriptor_names[1] + ")";
  plot.equal_axes = !one_d;
  // Bootstrap levels and the placement ellipses share the styles: 68 % and 95 %.
  std::vector<double> levels = s.region_levels.empty() ? std::vector<double>{0.68, 0.95}
                                                       : s.region_levels;
  for (double l : levels) plot.region_labels.push_back(fmt::format("{:g} %", 100 * l));
  for (std::size_t i = 0; i < s.stimuli.size(); ++i) {
    const Eigen::VectorXd q = s.coordinates.col(static_cast<Eigen::Index>(i));
    report::ScatterPoint p{s.stimuli[i], q(0), one_d ? 0.0 : q(1), group_of(s.stimuli[i]), {}, false};
    if (!s.regions.empty())
      for (std::size_t k = 0; k < s.region_levels.size(); ++k)
        p.regions.push_back(ellipse_at(q, space::plane_ellipse(s.regions[i], k), one_d));
    plot.points.push_back(p);
  }
  for (const auto& t : placed) {
    report::ScatterPoint p{t.name, t.placement.mean(0), one_d ? 0.0 : t.placement.mean(1),
                           t.group.empty() ? group_of(t.name) : t.group, {}, true};
    if (!t.regions) {
      plot.points.push_back(p);
      continue;
    }
    const space::ConfidenceRegion region =
        space::gaussian_region(t.placement.mean, t.placement.covariance, levels);
    for (std::size_t k = 0; k < levels.size(); ++k)
      p.regions.push_back(ellipse_at(t.placement.mean, space::plane_ellipse(region, k), one_d));
    plot.points.push_back(p);
  }
  return plot;
}

}  // namespace nibrig::ui::figures
