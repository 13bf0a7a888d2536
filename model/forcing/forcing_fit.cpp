#include "model/forcing/forcing_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "model/forcing/hermite_curve.hpp"

namespace nibrig::model::forcing {

namespace {

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Which free curve (a block of knot values) each exemplar's tip and material use, and with what
// weight: 1 for a tool of one material at a fitted tip; a mix's fractions, and an interpolated
// tip's two linear weights. The reference tip and material are pinned at zero and own no block.
struct Layout {
  using Weights = std::vector<std::pair<std::size_t, double>>;  // (index, weight)
  std::vector<double> knots;
  std::vector<double> tips;  // distinct fitted diameters, ascending, the reference among them
  std::vector<std::string> materials;  // distinct names, sorted, the reference among them
  std::vector<std::optional<std::size_t>> tip_block, material_block;  // per tip / material
  std::vector<Weights> exemplar_tip, exemplar_material;               // per exemplar
  std::size_t blocks = 0;
  std::vector<std::string> block_names;  // "tip 1 mm", "material 'DM85'"

  std::size_t knot_count() const { return knots.size(); }
  std::size_t unknowns() const { return blocks * knots.size(); }
  // (block, weight) of every free curve exemplar e's ln t + ln m sums.
  Weights blocks_of(std::size_t e) const {
    Weights out;
    for (const auto& [t, w] : exemplar_tip[e])
      if (tip_block[t]) out.emplace_back(*tip_block[t], w);
    for (const auto& [m, w] : exemplar_material[e])
      if (material_block[m]) out.emplace_back(*material_block[m], w);
    return out;
  }
  bool uses(std::size_t e, std::size_t block) const {
    const auto b = blocks_of(e);
    return std::any_of(b.begin(), b.end(),
                       [&](const auto& bw) { return bw.first == block && bw.second != 0; });
  }
};

std::vector<std::pair<std::string, double>> shares_of(const ForcingExemplar& e) {
  if (e.mix.empty()) return {{e.material, 1.0}};
  return e.mix;
}

// The two fitted tips around `d` and their weights, linear in the diameter (as
// design::interpolated_log_gain weighs them); empty when d lies outside the fitted tips.
Layout::Weights tip_weights(const std::vector<double>& tips, double d) {
  for (std::size_t t = 0; t < tips.size(); ++t)
    if (same_tip(tips[t], d)) return {{t, 1.0}};
  const auto upper = std::lower_bound(tips.begin(), tips.end(), d);
  if (upper == tips.begin() || upper == tips.end()) return {};
  const auto j = static_cast<std::size_t>(upper - tips.begin());
  const double w = (d - tips[j - 1]) / (tips[j] - tips[j - 1]);
  return {{j - 1, 1.0 - w}, {j, w}};
}

Layout make_layout(std::span<const ForcingExemplar> exemplars, const ForcingFitOptions& options) {
  Layout layout;
  layout.knots = options.knot_frequencies_hz.empty() ? default_knot_frequencies()
                                                     : options.knot_frequencies_hz;
  layout.tips.push_back(options.reference_tip_diameter_m);
  std::set<std::string> materials{options.reference_material};
  for (const auto& e : exemplars) {
    for (const auto& [m, f] : shares_of(e)) materials.insert(m);
    if (e.tip_interpolated) continue;
    const bool known = std::any_of(layout.tips.begin(), layout.tips.end(),
                                   [&](double d) { return same_tip(d, e.tip_diameter_m); });
    if (!known) layout.tips.push_back(e.tip_diameter_m);
  }
  std::sort(layout.tips.begin(), layout.tips.end());
  layout.materials.assign(materials.begin(), materials.end());
  for (double d : layout.tips) {
    const bool reference = same_tip(d, options.reference_tip_diameter_m);
    layout.tip_block.push_back(reference ? std::nullopt : std::optional(layout.blocks++));
    if (!reference) layout.block_names.push_back("tip " + tip_label(d));
  }
  for (const auto& m : layout.materials) {
    const bool reference = m == options.reference_material;
    layout.material_block.push_back(reference ? std::nullopt : std::optional(layout.blocks++));
    if (!reference) layout.block_names.push_back("material '" + m + "'");
  }
  for (const auto& e : exemplars) {
    layout.exemplar_tip.push_back(tip_weights(layout.tips, e.tip_diameter_m));
    Layout::Weights shares;
    for (const auto& [m, f] : shares_of(e))
      shares.emplace_back(
          static_cast<std::size_t>(std::find(layout.materials.begin(), layout.materials.end(), m) -
                                   layout.materials.begin()),
          f);
    layout.exemplar_material.push_back(std::move(shares));
  }
  return layout;
}

std::string exemplar_name(const ForcingExemplar& e) { return e.tool + " on " + e.surface; }

// Shapes and values that the fit needs: one grid for all, |H| > 0 and finite, amplitudes finite.
std::vector<std::string> data_problems(std::span<const ForcingExemplar> exemplars,
                                       const std::vector<double>& knots) {
  std::vector<std::string> problems;
  if (exemplars.empty()) return {"no exemplars to fit"};
  const auto& grid = exemplars.front().measured;
  for (const auto& e : exemplars) {
    const std::string name = exemplar_name(e);
    if (!(std::isfinite(e.tip_diameter_m) && e.tip_diameter_m > 0))
      problems.push_back(name + ": tip diameter must be a positive length");
    double sum = 0.0;
    for (const auto& [m, f] : e.mix) {
      if (!(std::isfinite(f) && f > 0 && f <= 1))
        problems.push_back(name + ": the fraction of '" + m + "' must lie in (0, 1]");
      sum += f;
    }
    if (!e.mix.empty() && std::abs(sum - 1.0) > 1e-6)
      problems.push_back(name + ": its mix's fractions add up to " + std::to_string(sum) +
                         ", not 1");
    if (!io::same_grid(e.measured, grid)) {
      problems.push_back(name + ": its frequencies or speeds differ from those of " +
                         exemplar_name(exemplars.front()));
      continue;
    }
    if (e.measured.amplitude_m_s2.size() != grid.speeds_m_s.size())
      problems.push_back(name + ": one amplitude row per speed expected");
    for (const auto& row : e.measured.amplitude_m_s2)
      if (row.size() != grid.frequencies_hz.size() ||
          !std::all_of(row.begin(), row.end(), [](double a) { return std::isfinite(a); })) {
        problems.push_back(name + ": every amplitude row needs one finite value per frequency");
        break;
      }
    if (e.response_magnitude.size() != grid.frequencies_hz.size())
      problems.push_back(name + ": its response has " +
                         std::to_string(e.response_magnitude.size()) + " values for " +
                         std::to_string(grid.frequencies_hz.size()) + " frequencies");
    else if (!std::all_of(e.response_magnitude.begin(), e.response_magnitude.end(),
                          [](double h) { return std::isfinite(h) && h > 0; }))
      problems.push_back(name + ": its response magnitude must be finite and > 0 everywhere");
  }
  if (!grid.frequencies_hz.empty() &&
      (grid.frequencies_hz.front() < knots.front() || grid.frequencies_hz.back() > knots.back())) {
    std::ostringstream out;
    out << "the spectra span " << grid.frequencies_hz.front() << "-" << grid.frequencies_hz.back()
        << " Hz, beyond the knots " << knots.front() << "-" << knots.back() << " Hz";
    problems.push_back(out.str());
  }
  return problems;
}

std::map<std::string, std::vector<std::size_t>> by_surface(
    std::span<const ForcingExemplar> exemplars) {
  std::map<std::string, std::vector<std::size_t>> surfaces;
  for (std::size_t e = 0; e < exemplars.size(); ++e) surfaces[exemplars[e].surface].push_back(e);
  return surfaces;
}

// Per knot, the data identify exactly the differences of ln t + ln m between exemplars that share
// a surface (the cell's own ln F absorbs the rest). A curve is identifiable when its unit vector
// lies in the span of those differences.
std::vector<std::string> identifiability_problems(std::span<const ForcingExemplar> exemplars,
                                                  const Layout& layout,
                                                  const ForcingFitOptions& options) {
  if (layout.blocks == 0) return {};
  const auto surfaces = by_surface(exemplars);
  std::vector<Eigen::RowVectorXd> rows;
  auto indicator = [&](std::size_t e) {
    Eigen::RowVectorXd x = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(layout.blocks));
    for (const auto& [b, weight] : layout.blocks_of(e)) x(static_cast<Eigen::Index>(b)) += weight;
    return x;
  };
  for (const auto& [surface, members] : surfaces)
    for (std::size_t k = 1; k < members.size(); ++k)
      rows.push_back(indicator(members[k]) - indicator(members[0]));
  Eigen::MatrixXd d(static_cast<Eigen::Index>(rows.size()),
                    static_cast<Eigen::Index>(layout.blocks));
  for (std::size_t r = 0; r < rows.size(); ++r) d.row(static_cast<Eigen::Index>(r)) = rows[r];
  const auto rank_of = [](const Eigen::MatrixXd& m) {
    if (m.rows() == 0) return Eigen::Index{0};
    Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
    lu.setThreshold(1e-9);
    return lu.rank();
  };
  const Eigen::Index base = rank_of(d);

  std::vector<std::string> problems;
  for (std::size_t b = 0; b < layout.blocks; ++b) {
    Eigen::MatrixXd with(d.rows() + 1, d.cols());
    with.topRows(d.rows()) = d;
    with.row(d.rows()) = Eigen::RowVectorXd::Unit(d.cols(), static_cast<Eigen::Index>(b));
    if (rank_of(with) == base) continue;
    std::set<std::string> on, shared;
    for (std::size_t e = 0; e < exemplars.size(); ++e) {
      if (!layout.uses(e, b)) continue;
      on.insert(exemplars[e].surface);
      if (surfaces.at(exemplars[e].surface).size() > 1) shared.insert(exemplars[e].surface);
    }
    std::string problem = layout.block_names[b] + " is not identifiable: ";
    if (shared.empty())
      problem += "it was measured only on surfaces where no other tool was (" + joined(on) +
                 "), so its curve trades freely against that surface's forcing";
    else
      problem += "the tools that share its surfaces (" + joined(on) +
                 ") do not separate its curve from the surface forcing and the other curves";
    const bool tip = layout.block_names[b].rfind("tip", 0) == 0;
    const bool reference_seen = std::any_of(exemplars.begin(), exemplars.end(), [&](const auto& e) {
      return tip ? same_tip(e.tip_diameter_m, options.reference_tip_diameter_m)
                 : e.material == options.reference_material;
    });
    if (!reference_seen)
      problem +=
          tip ? " (no exemplar has the reference tip, " +
                    tip_label(options.reference_tip_diameter_m) + ")"
              : " (no exemplar has the reference material, '" + options.reference_material + "')";
    problems.push_back(problem);
  }
  return problems;
}

// Every cell (surface, speed, bin) needs one positive amplitude to give F a value.
std::vector<std::string> empty_cell_problems(std::span<const ForcingExemplar> exemplars) {
  std::vector<std::string> problems;
  const auto& grid = exemplars.front().measured;
  for (const auto& [surface, members] : by_surface(exemplars))
    for (std::size_t s = 0; s < grid.speeds_m_s.size(); ++s)
      for (std::size_t j = 0; j < grid.frequencies_hz.size(); ++j) {
        const bool any = std::any_of(members.begin(), members.end(), [&](std::size_t e) {
          return exemplars[e].measured.amplitude_m_s2[s][j] > 0;
        });
        if (!any) {
          std::ostringstream out;
          out << "surface " << surface << " at " << grid.speeds_m_s[s] * 1e3 << " mm/s, "
              << grid.frequencies_hz[j]
              << " Hz: no exemplar has a positive amplitude, so its forcing is undetermined";
          problems.push_back(out.str());
          return problems;  // one example is enough; the rest is the same story
        }
      }
  return problems;
}

// One cell's observations: the log data y = ln M − ln|H| and the exemplar of each.
struct Cell {
  std::vector<std::size_t> exemplars;
  std::vector<double> y;
};

Cell cell_of(std::span<const ForcingExemplar> exemplars, const std::vector<std::size_t>& members,
             std::size_t s, std::size_t j) {
  Cell cell;
  for (std::size_t e : members) {
    const double a = exemplars[e].measured.amplitude_m_s2[s][j];
    if (!(a > 0)) continue;
    cell.exemplars.push_back(e);
    cell.y.push_back(std::log(a) - std::log(exemplars[e].response_magnitude[j]));
  }
  return cell;
}

// ln t + ln m of exemplar e at a bin whose Hermite weights are `weights`, for knot values θ.
double curves_at(const Layout& layout, std::size_t e,
                 const std::vector<std::pair<std::size_t, double>>& weights,
                 const Eigen::VectorXd& theta) {
  double sum = 0.0;
  for (const auto& [b, weight] : layout.blocks_of(e))
    for (const auto& [k, w] : weights)
      sum += weight * w * theta(static_cast<Eigen::Index>(b * layout.knot_count() + k));
  return sum;
}

}  // namespace

std::vector<std::string> fit_problems(std::span<const ForcingExemplar> exemplars,
                                      const ForcingFitOptions& options) {
  const std::vector<double> knots = options.knot_frequencies_hz.empty()
                                        ? default_knot_frequencies()
                                        : options.knot_frequencies_hz;
  auto problems = data_problems(exemplars, knots);
  if (!problems.empty()) return problems;
  const Layout layout = make_layout(exemplars, options);
  for (std::size_t e = 0; e < exemplars.size(); ++e)
    if (layout.exemplar_tip[e].empty())
      problems.push_back(
          exemplar_name(exemplars[e]) + ": its tip, " + tip_label(exemplars[e].tip_diameter_m) +
          ", lies outside the fitted tips (" + tip_label(layout.tips.front()) + " to " +
          tip_label(layout.tips.back()) + "), and is interpolated, not extrapolated");
  if (!problems.empty()) return problems;
  problems = identifiability_problems(exemplars, layout, options);
  for (auto& p : empty_cell_problems(exemplars)) problems.push_back(std::move(p));
  return problems;
}

ForcingModel fit_forcing_model(std::span<const ForcingExemplar> exemplars,
                               const ForcingFitOptions& options) {
  if (const auto problems = fit_problems(exemplars, options); !problems.empty()) {
    std::string what = "forcing fit: ";
    for (std::size_t k = 0; k < problems.size(); ++k) what += (k ? "; " : "") + problems[k];
    throw std::invalid_argument(what);
  }
  const Layout layout = make_layout(exemplars, options);
  const auto& grid = exemplars.front().measured;
  const std::size_t speeds = grid.speeds_m_s.size(), bins = grid.frequencies_hz.size();
  std::vector<std::vector<std::pair<std::size_t, double>>> weights;
  for (double f : grid.frequencies_hz) weights.push_back(hermite_weights(layout.knots, f));
  const auto surfaces = by_surface(exemplars);

  // Normal equations of the knots after F is eliminated: rows centred within their cell.
  const auto unknowns = static_cast<Eigen::Index>(layout.unknowns());
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(unknowns, unknowns);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  for (const auto& [surface, members] : surfaces)
    for (std::size_t s = 0; s < speeds; ++s)
      for (std::size_t j = 0; j < bins; ++j) {
        const Cell cell = cell_of(exemplars, members, s, j);
        if (cell.exemplars.size() < 2 || unknowns == 0) continue;
        // The unknowns this cell touches: the knots near f_j of every block its exemplars use.
        std::vector<Eigen::Index> columns;
        for (std::size_t e : cell.exemplars)
          for (const auto& [b, weight] : layout.blocks_of(e))
            for (const auto& [k, w] : weights[j])
              columns.push_back(static_cast<Eigen::Index>(b * layout.knot_count() + k));
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
        const auto n = static_cast<Eigen::Index>(cell.exemplars.size());
        Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(columns.size()));
        Eigen::VectorXd y(n);
        for (Eigen::Index i = 0; i < n; ++i) {
          const std::size_t e = cell.exemplars[static_cast<std::size_t>(i)];
          y(i) = cell.y[static_cast<std::size_t>(i)];
          for (const auto& [b, weight] : layout.blocks_of(e))
            for (const auto& [k, w] : weights[j]) {
              const auto global = static_cast<Eigen::Index>(b * layout.knot_count() + k);
              const auto local =
                  std::lower_bound(columns.begin(), columns.end(), global) - columns.begin();
              x(i, local) += weight * w;
            }
        }
        x.rowwise() -= x.colwise().mean();
        y.array() -= y.mean();
        const Eigen::MatrixXd xtx = x.transpose() * x;
        const Eigen::VectorXd xty = x.transpose() * y;
        for (std::size_t a = 0; a < columns.size(); ++a) {
          rhs(columns[a]) += xty(static_cast<Eigen::Index>(a));
          for (std::size_t c = 0; c < columns.size(); ++c)
            normal(columns[a], columns[c]) +=
                xtx(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(c));
        }
      }

  Eigen::VectorXd theta = Eigen::VectorXd::Zero(unknowns);
  if (unknowns > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(normal);
    // Relative to the largest pivot: a direction the data do not constrain leaves a pivot at
    // round-off level (~1e-15), a constrained one many orders above it.
    qr.setThreshold(1e-10);
    if (qr.rank() < unknowns)
      throw std::runtime_error("forcing fit: the normal equations of the knots have rank " +
                               std::to_string(qr.rank()) + " of " + std::to_string(unknowns) +
                               " (a knot interval without data?)");
    theta = qr.solve(rhs);
  }

  ForcingModel model;
  model.knot_frequencies_hz = layout.knots;
  model.reference_tip_diameter_m = options.reference_tip_diameter_m;
  model.reference_material = options.reference_material;
  model.frequencies_hz = grid.frequencies_hz;
  model.speeds_m_s = grid.speeds_m_s;
  auto curve = [&](const std::optional<std::size_t>& block) {
    std::vector<double> knots(layout.knot_count(), 0.0);
    if (block)
      for (std::size_t k = 0; k < knots.size(); ++k)
        knots[k] = theta(static_cast<Eigen::Index>(*block * layout.knot_count() + k));
    return knots;
  };
  for (std::size_t t = 0; t < layout.tips.size(); ++t)
    model.tip_log_gain[layout.tips[t]] = curve(layout.tip_block[t]);
  for (std::size_t m = 0; m < layout.materials.size(); ++m)
    model.material_log_gain[layout.materials[m]] = curve(layout.material_block[m]);

  // F from the cell means, and the residuals for the fit's quality.
  std::vector<double> squared_sum(exemplars.size(), 0.0);
  std::vector<std::size_t> counted(exemplars.size(), 0);
  double total = 0.0;
  for (const auto& [surface, members] : surfaces) {
    auto& forcing = model.surface_forcing[surface];
    forcing.assign(speeds, std::vector<double>(bins, 0.0));
    for (std::size_t s = 0; s < speeds; ++s)
      for (std::size_t j = 0; j < bins; ++j) {
        const Cell cell = cell_of(exemplars, members, s, j);
        model.skipped_nonpositive += members.size() - cell.exemplars.size();
        std::vector<double> detrended(cell.exemplars.size());
        double mean = 0.0;
        for (std::size_t i = 0; i < cell.exemplars.size(); ++i) {
          detrended[i] = cell.y[i] - curves_at(layout, cell.exemplars[i], weights[j], theta);
          mean += detrended[i];
        }
        mean /= static_cast<double>(cell.exemplars.size());
        forcing[s][j] = std::exp(mean);
        for (std::size_t i = 0; i < cell.exemplars.size(); ++i) {
          const double r = detrended[i] - mean;
          squared_sum[cell.exemplars[i]] += r * r;
          ++counted[cell.exemplars[i]];
          total += r * r;
          ++model.observations;
        }
      }
  }
  model.residual_rms_db = log_gain_to_db(
      std::sqrt(total / static_cast<double>(std::max<std::size_t>(model.observations, 1))));
  for (std::size_t e = 0; e < exemplars.size(); ++e)
    model.exemplar_fits.push_back(
        {exemplars[e].tool, exemplars[e].surface,
         log_gain_to_db(std::sqrt(squared_sum[e] /
                                  static_cast<double>(std::max<std::size_t>(counted[e], 1))))});
  return model;
}

}  // namespace nibrig::model::forcing
