#include "ui/cli/space_figures.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

#include "model/space/bootstrap.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::cli {

namespace space = model::space;

void write_space_plot(const space::SpaceFile& s, const std::vector<PlacedTool>& placed,
                      const std::string& title, const std::filesystem::path& png) {
  report::write_scatter_plot(figures::space_scatter(s, placed, title), png);
}

void write_dimension_scan_plot(const std::vector<space::DimensionScanPoint>& points,
                               const std::string& title, const std::filesystem::path& png) {
  std::map<double, int> lambdas;
  for (const auto& p : points) lambdas[p.lambda] = 0;
  report::LinePlot plot;
  plot.title = title;
  plot.y_label = "held-out error |#gDp| (%)";
  std::set<std::string> models;
  for (const auto& p : points) models.insert(space::family_name(p.model));
  const auto add = [](report::LineSeries& line, double x, const space::DimensionScanPoint& p) {
    line.x.push_back(x);
    line.y.push_back(100 * p.mean_error);
    line.y_low.push_back(100 * (p.mean_error - p.sd_error));
    line.y_high.push_back(100 * (p.mean_error + p.sd_error));
  };
  // One line per judgment model (or per λ when one model), or per dimension and model over λ.
  std::map<std::string, report::LineSeries> lines;
  std::vector<std::string> order;
  for (const auto& p : points) {
    const std::string model = models.size() > 1 ? space::family_name(p.model) : "";
    const std::string key = lambdas.size() == 1
                                ? (model.empty() ? fmt::format("#gl = {:g}", p.lambda) : model)
                                : std::to_string(p.dims) + "-D" + (model.empty() ? "" : " " + model);
    if (!lines.count(key)) order.push_back(key), lines[key].label = key;
    add(lines[key], lambdas.size() == 1 ? static_cast<double>(p.dims) : p.lambda, p);
  }
  plot.x_label = lambdas.size() == 1 ? "dimensions" : "#gl";
  for (const auto& key : order) plot.series.push_back(lines[key]);
  report::write_line_plot(plot, png);
}

}  // namespace nibrig::ui::cli
