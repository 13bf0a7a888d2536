#include "model/design/design_response_grid.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <exception>
#include <sstream>
#include <stdexcept>

#include "model/design/tip_bracket.hpp"
#include "model/numeric/cancellation.hpp"
#include "model/numeric/parallel_for.hpp"

namespace nibrig::model::design {

namespace {

std::string grid_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void check_axis(const std::vector<double>& values, const std::string& name, double min, double max,
                const std::string& range) {
  if (values.size() < 2)
    throw std::invalid_argument("design grid: the " + name + " axis needs at least 2 nodes, has " +
                                std::to_string(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!(values[k] >= min && values[k] <= max))
      throw std::invalid_argument("design grid: " + name + "[" + std::to_string(k) + "] is " +
                                  grid_number(values[k]) + ", expected " + range);
    if (k > 0 && !(values[k] > values[k - 1]))
      throw std::invalid_argument("design grid: " + name + "[" + std::to_string(k) + "] is " +
                                  grid_number(values[k]) + ", expected more than the previous " +
                                  grid_number(values[k - 1]) + " (strictly increasing)");
  }
}

// Where x lies on an axis: the cell's lower node and the weight of its upper one.
struct AxisPosition {
  std::size_t lower = 0;
  double weight = 0.0;
};

AxisPosition locate(const std::vector<double>& nodes, double x, const std::string& what,
                    double unit, const std::string& unit_name) {
  const double lo = nodes.front(), hi = nodes.back();
  // Within a part in 1e12 of the range counts as on the edge: a slider's end value computed as
  // min + (max − min)·1 may miss the last node by an ulp.
  const double slack = 1e-12 * (hi - lo);
  if (!(x >= lo - slack && x <= hi + slack)) {
    const bool below = x < lo;
    throw std::invalid_argument(
        "the design grid's " + what + " " + grid_number(x / unit) + unit_name + " is " +
        grid_number(std::abs(x - (below ? lo : hi)) / unit) + unit_name + (below ? " below" : " above") +
        " its range " + grid_number(lo / unit) + unit_name + " to " + grid_number(hi / unit) + unit_name +
        ": nothing outside the grid is extrapolated");
  }
  x = std::clamp(x, lo, hi);  // only the slack above: no more than rounding
  std::size_t i = 0;
  while (i + 2 < nodes.size() && x > nodes[i + 1]) ++i;
  return {i, (x - nodes[i]) / (nodes[i + 1] - nodes[i])};
}

bool gain_jumps(double a, double b, double scale_a, double scale_b) {
  const bool significant_a = std::abs(a) > kSignificantGain * scale_a;
  const bool significant_b = std::abs(b) > kSignificantGain * scale_b;
  if (!significant_a && !significant_b) return false;
  if (significant_a != significant_b) return true;  // one vanishes where the other is heard
  if ((a > 0) != (b > 0)) return true;
  const double ratio = std::abs(a) / std::abs(b);
  return ratio > kGainJump || ratio < 1.0 / kGainJump;
}

double largest_gain(const modal::ModalModel& m) {
  double largest = 0.0;
  for (std::size_t k = 0; k < m.size(); ++k)
    largest = std::max(largest, std::abs(m.input[k] * m.output[k]));
  return largest;
}

std::size_t jumps_between(const SimulatedResponse& a, const SimulatedResponse& b) {
  const double scale_a = largest_gain(a.modal), scale_b = largest_gain(b.modal);
  std::size_t jumps = 0;
  for (std::size_t k = 0; k < std::min(a.modal.size(), b.modal.size()); ++k)
    jumps += gain_jumps(a.modal.input[k] * a.modal.output[k], b.modal.input[k] * b.modal.output[k],
                        scale_a, scale_b);
  return jumps;
}

// Every other node of an axis, both ends kept: n/2 + 1 of n. For odd n the indices 0, 2, .., n − 1;
// for even n each index k·(n − 1)/(m − 1) rounded half up, distinct since that step is at least 1.
std::vector<double> coarse_axis_nodes(const std::vector<double>& fine) {
  const std::size_t n = fine.size(), m = n / 2 + 1;
  std::vector<double> coarse;
  for (std::size_t k = 0; k < m; ++k)
    coarse.push_back(fine[(2 * k * (n - 1) + (m - 1)) / (2 * (m - 1))]);
  return coarse;
}

// Where `value` is in `axis` exactly, or nullopt.
std::optional<std::size_t> exact_axis_index(const std::vector<double>& axis, double value) {
  const auto at = std::find(axis.begin(), axis.end(), value);
  if (at == axis.end()) return std::nullopt;
  return static_cast<std::size_t>(at - axis.begin());
}

}  // namespace

GridAxes coarse_axes(const GridAxes& fine) {
  validate(fine);
  return {fine.material_a, fine.material_b, coarse_axis_nodes(fine.fractions),
          coarse_axis_nodes(fine.tips_m)};
}

GridAxes even_axes(const std::string& material_a, const std::string& material_b,
                   std::size_t fraction_points, double min_tip_m, double max_tip_m,
                   std::size_t tip_points) {
  GridAxes axes{material_a, material_b, {}, {}};
  auto even = [](double lo, double hi, std::size_t n) {
    std::vector<double> v;
    for (std::size_t k = 0; k < n; ++k)
      v.push_back(k + 1 == n ? hi : lo + (hi - lo) * static_cast<double>(k) / (n - 1.0));
    return v;
  };
  axes.fractions = even(0.0, 1.0, fraction_points);
  axes.tips_m = even(min_tip_m, max_tip_m, tip_points);
  validate(axes);
  return axes;
}

void validate(const GridAxes& axes) {
  if (axes.material_a.empty() || axes.material_b.empty())
    throw std::invalid_argument("design grid: both materials must be named");
  if (axes.material_a == axes.material_b)
    throw std::invalid_argument("design grid: the two materials are both '" + axes.material_a +
                                "'; a mix needs two");
  check_axis(axes.fractions, "fraction", 0.0, 1.0, "a fraction in [0, 1]");
  check_axis(axes.tips_m, "tip", 1e-9, 1.0, "a tip diameter in metres, above 0 and below 1 m");
}

DesignPoint grid_point(const GridAxes& axes, double fraction, double tip_m) {
  DesignPoint point;
  point.tip_diameter_m = tip_m;
  if (fraction < 1.0) point.mix.push_back({axes.material_a, 1.0 - fraction});
  if (fraction > 0.0) point.mix.push_back({axes.material_b, fraction});
  validate(point);
  return point;
}

double solved_mesh_size(const PredictionSetup& setup) {
  return setup.mesh_size > 0 ? setup.mesh_size : setup.template_design.mesh_size;
}

int solved_modes(const PredictionSetup& setup) {
  return setup.modes > 0 ? setup.modes : setup.template_design.modes;
}

void validate(const DesignResponseGrid& grid, const std::string& where) {
  validate(grid.axes);
  const std::size_t count = grid.axes.fractions.size() * grid.axes.tips_m.size();
  auto refuse = [&](const std::string& what) {
    throw std::invalid_argument(where + ": " + what);
  };
  if (grid.nodes.size() != count)
    refuse("expected " + std::to_string(count) + " nodes (fractions × tips), found " +
           std::to_string(grid.nodes.size()));
  if (grid.frequencies_hz.empty()) refuse("no frequencies");
  if (grid.modes <= 0) refuse("expected a positive mode count");
  for (std::size_t n = 0; n < count; ++n) {
    const auto& node = grid.nodes[n];
    const std::string at =
        "node " + std::to_string(n) + " (" +
        to_string(grid_point(grid.axes, grid.axes.fractions[n / grid.axes.tips_m.size()],
                             grid.axes.tips_m[n % grid.axes.tips_m.size()])) +
        ")";
    if (node.response_magnitude.size() != grid.frequencies_hz.size())
      refuse(at + ": expected |H| at " + std::to_string(grid.frequencies_hz.size()) +
             " frequencies, found " + std::to_string(node.response_magnitude.size()));
    for (double h : node.response_magnitude)
      if (!(h > 0 && std::isfinite(h))) refuse(at + ": |H| " + grid_number(h) + ", expected > 0");
    const auto& m = node.modal;
    if (m.size() != static_cast<std::size_t>(grid.modes) || m.zeta.size() != m.size() ||
        m.input.size() != m.size() || m.output.size() != m.size())
      refuse(at + ": expected " + std::to_string(grid.modes) + " modes with ω, ζ, b and c each");
    for (std::size_t k = 0; k < m.size(); ++k)
      if (!(m.omega[k] > 0 && std::isfinite(m.omega[k]) && m.zeta[k] >= 0 &&
            std::isfinite(m.zeta[k]) && std::isfinite(m.input[k]) && std::isfinite(m.output[k])) ||
          (k > 0 && m.omega[k] < m.omega[k - 1]))
        refuse(at + ": mode " + std::to_string(k) +
               " expected ω > 0 ascending, ζ ≥ 0, finite b and c");
  }
}

std::size_t count_mode_jumps(const DesignResponseGrid& grid) {
  const std::size_t nf = grid.axes.fractions.size(), nt = grid.axes.tips_m.size();
  std::size_t jumps = 0;
  for (std::size_t i = 0; i < nf; ++i)
    for (std::size_t j = 0; j < nt; ++j) {
      if (i + 1 < nf) jumps += jumps_between(grid.node(i, j), grid.node(i + 1, j));
      if (j + 1 < nt) jumps += jumps_between(grid.node(i, j), grid.node(i, j + 1));
    }
  return jumps;
}

DesignResponseGrid compute_design_response_grid(const PredictionSetup& setup, const GridAxes& axes,
                                                const numeric::Progress& progress,
                                                std::stop_token stop, unsigned threads,
                                                const DesignResponseGrid* known) {
  validate(axes);
  if (setup.model == nullptr)
    throw std::invalid_argument("design grid: the setup needs a forcing model (its frequencies)");
  // The cheap refusal first: a tip range the forcing model cannot scale fails before any FEM.
  const std::vector<double> tips = fitted_tips(*setup.model);
  bracket_tip(tips, axes.tips_m.front(), "the design grid's smallest tip against the forcing "
                                         "model's tip curves");
  bracket_tip(tips, axes.tips_m.back(), "the design grid's largest tip against the forcing "
                                        "model's tip curves");
  DesignResponseGrid grid;
  grid.axes = axes;
  grid.frequencies_hz = setup.model->frequencies_hz;
  grid.mesh_size_m = solved_mesh_size(setup);
  grid.modes = solved_modes(setup);
  const std::size_t nt = axes.tips_m.size();
  const std::size_t count = axes.fractions.size() * nt;
  grid.nodes.resize(count);
  // A known node is the same solve only when everything the solve depends on and the grid records
  // is the same: the materials, mesh size, mode count, and the frequencies |H| is given at.
  if (known != nullptr) validate(*known, "the known design grid");
  const bool reusable = known != nullptr && known->axes.material_a == axes.material_a &&
                        known->axes.material_b == axes.material_b &&
                        known->mesh_size_m == grid.mesh_size_m && known->modes == grid.modes &&
                        known->frequencies_hz == grid.frequencies_hz;
  std::vector<std::size_t> to_solve;
  for (std::size_t n = 0; n < count; ++n) {
    const auto i =
        reusable ? exact_axis_index(known->axes.fractions, axes.fractions[n / nt]) : std::nullopt;
    const auto j =
        reusable ? exact_axis_index(known->axes.tips_m, axes.tips_m[n % nt]) : std::nullopt;
    if (i && j)
      grid.nodes[n] = known->node(*i, *j);
    else
      to_solve.push_back(n);
  }
  numeric::ProgressCounter counter(progress, to_solve.size());
  numeric::parallel_for(to_solve.size(), threads, [&](std::size_t k) {
    if (stop.stop_requested()) return;
    const std::size_t n = to_solve[k];
    const DesignPoint point = grid_point(axes, axes.fractions[n / nt], axes.tips_m[n % nt]);
    try {
      grid.nodes[n] = simulate_response(setup, point);
    } catch (const std::exception& e) {
      throw std::runtime_error("design grid node " + to_string(point) + ": " + e.what());
    }
    counter.finished();
  });
  numeric::throw_if_cancelled(stop, "design grid");
  validate(grid, "the computed design grid");
  grid.mode_jumps = count_mode_jumps(grid);
  if (grid.mode_jumps > 0)
    spdlog::info(
        "design grid {}-{}: {} rank-matched modes change gain sign or tenfold between neighbouring "
        "nodes (modes crossing in frequency); they are blended, not followed (see "
        "design_response_grid.hpp)",
        axes.material_a, axes.material_b, grid.mode_jumps);
  return grid;
}

SimulatedResponse interpolate_response(const DesignResponseGrid& grid, double fraction,
                                       double tip_m) {
  const AxisPosition a = locate(grid.axes.fractions, fraction, "fraction of " + grid.axes.material_b,
                                1.0, "");
  const AxisPosition t = locate(grid.axes.tips_m, tip_m, "tip diameter", 1e-3, " mm");
  const std::array<const SimulatedResponse*, 4> corner{
      &grid.node(a.lower, t.lower), &grid.node(a.lower, t.lower + 1),
      &grid.node(a.lower + 1, t.lower), &grid.node(a.lower + 1, t.lower + 1)};
  const std::array<double, 4> w{(1 - a.weight) * (1 - t.weight), (1 - a.weight) * t.weight,
                                a.weight * (1 - t.weight), a.weight * t.weight};
  SimulatedResponse out;
  // The design a slider shows: its nearest node's, a name for people only.
  out.design_name = corner[std::max_element(w.begin(), w.end()) - w.begin()]->design_name;
  const std::size_t nh = grid.frequencies_hz.size();
  out.response_magnitude.assign(nh, 0.0);
  for (std::size_t j = 0; j < nh; ++j) {
    double log_h = 0.0;
    for (std::size_t c = 0; c < 4; ++c) log_h += w[c] * std::log(corner[c]->response_magnitude[j]);
    out.response_magnitude[j] = std::exp(log_h);
  }
  const std::size_t modes = static_cast<std::size_t>(grid.modes);
  auto& m = out.modal;
  m.omega.assign(modes, 0.0);
  m.zeta.assign(modes, 0.0);
  m.input.assign(modes, 0.0);
  m.output.assign(modes, 0.0);
  for (std::size_t k = 0; k < modes; ++k) {
    double log_omega = 0.0, zeta = 0.0, gain = 0.0;
    for (std::size_t c = 0; c < 4; ++c) {
      const auto& cm = corner[c]->modal;
      log_omega += w[c] * std::log(cm.omega[k]);
      zeta += w[c] * cm.zeta[k];
      gain += w[c] * cm.input[k] * cm.output[k];
    }
    m.omega[k] = std::exp(log_omega);
    m.zeta[k] = zeta;
    m.input[k] = std::sqrt(std::abs(gain));
    m.output[k] = gain < 0 ? -m.input[k] : m.input[k];
  }
  // A weighted mean of ascending lists is ascending, but exp(log) may round two equal ω apart by
  // an ulp the wrong way; the modal model's checks want them ascending.
  for (std::size_t k = 1; k < modes; ++k) m.omega[k] = std::max(m.omega[k], m.omega[k - 1]);
  return out;
}

PredictedTool predict_from_grid(const PredictionSetup& setup, const DesignResponseGrid& grid,
                                double fraction, double tip_m, const std::string& surface) {
  if (setup.model == nullptr || setup.model->frequencies_hz != grid.frequencies_hz)
    throw std::invalid_argument(
        "the design grid's |H| is on other frequencies than the forcing model's: it was computed "
        "for another model; recompute it");
  SimulatedResponse response = interpolate_response(grid, fraction, tip_m);  // refuses outside
  const auto& axes = grid.axes;
  const DesignPoint point =
      grid_point(axes, std::clamp(fraction, axes.fractions.front(), axes.fractions.back()),
                 std::clamp(tip_m, axes.tips_m.front(), axes.tips_m.back()));
  return predict_from_response(setup, point, surface, std::move(response));
}

std::function<PredictedTool(const DesignPoint&)> grid_predictor(const PredictionSetup& setup,
                                                                const DesignResponseGrid& grid,
                                                                const std::string& surface) {
  return [&setup, &grid, surface](const DesignPoint& point) {
    for (const auto& share : point.mix)
      if (share.fraction > 0 && share.material != grid.axes.material_a && share.material != grid.axes.material_b)
        throw std::invalid_argument("design " + to_string(point) + ": the grid mixes only " + grid.axes.material_a +
                                    " and " + grid.axes.material_b + ", not " + share.material);
    return predict_from_grid(setup, grid, point.fraction_of(grid.axes.material_b), point.tip_diameter_m, surface);
  };
}

}  // namespace nibrig::model::design
