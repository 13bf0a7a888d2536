#include "model/measure/friction.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/measure/effective_sample_size.hpp"
#include "model/measure/order_statistics.hpp"

namespace nibrig::model::measure {

namespace {

constexpr double kSmoothingS = 0.05;
constexpr double kEnterFraction = 0.50;
constexpr double kLeaveFraction = 0.25;
constexpr double kFrictionEdgeFraction = 0.10;
constexpr double kBridgeS = 0.5;
constexpr double kMinContactS = 1.0;
constexpr double kSettleS = 1.0;
constexpr double kMinRelativeStep = 0.05;
constexpr double kZ95 = 1.959963984540054;

void check_rate(double fs) {
  if (!(fs > 0.0) || !std::isfinite(fs)) {
    throw std::invalid_argument("friction: sample rate must be positive and finite");
  }
}

std::vector<double> moving_mean(std::span<const double> x, std::size_t width) {
  std::vector<double> prefix(x.size() + 1, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) prefix[i + 1] = prefix[i] + x[i];
  std::vector<double> out(x.size());
  const std::size_t half = width / 2;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t a = i >= half ? i - half : 0;
    const std::size_t b = std::min(x.size(), a + width);
    out[i] = (prefix[b] - prefix[a]) / static_cast<double>(b - a);
  }
  return out;
}

struct Interval {
  double mean = 0.0;
  double low = 0.0;
  double high = 0.0;
  double effective = 0.0;
};

// Mean of `values` with a 95 % interval: SE = sqrt(var(residuals) · τ / n), τ the integrated
// autocorrelation time of the noise (in samples).
Interval mean_with_interval(std::span<const double> values, std::span<const double> residuals,
                            double tau) {
  Interval r;
  const double n = static_cast<double>(values.size());
  r.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  const double rbar = std::accumulate(residuals.begin(), residuals.end(), 0.0) / n;
  double var = 0.0;
  for (double e : residuals) var += (e - rbar) * (e - rbar) / n;
  const double se = std::sqrt(var * tau / n);
  r.low = r.mean - kZ95 * se;
  r.high = r.mean + kZ95 * se;
  r.effective = n / tau;
  return r;
}

}  // namespace

ContactRegion detect_contact(std::span<const double> force, double fs) {
  check_rate(fs);
  if (static_cast<double>(force.size()) < 2.0 * fs) {
    throw std::invalid_argument("detect_contact: need at least 2 s of samples, got " +
                                std::to_string(force.size()));
  }
  for (double v : force) {
    if (!std::isfinite(v)) throw std::invalid_argument("detect_contact: non-finite force sample");
  }
  const auto width =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kSmoothingS * fs)));
  std::vector<double> y = moving_mean(force, width);
  const double mid = 0.5 * (quantile(y, 0.02) + quantile(y, 0.98));
  std::vector<double> low, high;
  for (double v : y) (v < mid ? low : high).push_back(v);
  if (low.empty() || high.empty())
    throw std::runtime_error("detect_contact: the force is constant");
  double baseline = median(low);
  double plateau = median(high);
  // Contact is the level farther from zero: work on the sign that makes it the upper one.
  const double sign = std::abs(plateau) >= std::abs(baseline) ? 1.0 : -1.0;
  if (sign < 0) std::swap(baseline, plateau);
  for (double& v : y) v *= sign;
  const double step = sign * (plateau - baseline);
  if (!(step > kMinRelativeStep * std::max(std::abs(plateau), std::abs(baseline)))) {
    throw std::runtime_error("detect_contact: no contact level stands out from the baseline");
  }
  const double b = sign * baseline;
  const double enter = b + kEnterFraction * step;
  const double leave = b + kLeaveFraction * step;

  struct Run {
    std::size_t begin, end;
  };
  std::vector<Run> runs;
  bool in = false;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!in && y[i] > enter) {
      runs.push_back({i, y.size()});
      in = true;
    } else if (in && y[i] < leave) {
      runs.back().end = i;
      in = false;
    }
  }
  const auto bridge = static_cast<std::size_t>(kBridgeS * fs);
  std::vector<Run> merged;
  for (const Run& r : runs) {
    if (!merged.empty() && r.begin - merged.back().end < bridge) {
      merged.back().end = r.end;
    } else {
      merged.push_back(r);
    }
  }
  const auto min_length = static_cast<std::size_t>(kMinContactS * fs);
  const Run* best = nullptr;
  for (const Run& r : merged) {
    if (r.end - r.begin >= min_length &&
        (best == nullptr || r.end - r.begin > best->end - best->begin)) {
      best = &r;
    }
  }
  if (best == nullptr) throw std::runtime_error("detect_contact: no contact lasts 1 s");

  const double edge = b + kFrictionEdgeFraction * step;
  ContactRegion c;
  c.begin = best->begin;
  while (c.begin > 0 && y[c.begin - 1] > edge) --c.begin;
  c.end = best->end;
  while (c.end < y.size() && y[c.end] > edge) ++c.end;
  c.baseline_N = baseline;
  c.plateau_N = plateau;
  return c;
}

FrictionFit fit_coulomb_friction(std::span<const double> force, double fs, double normal_load_N,
                                 const SweepAssumption& sweep) {
  if (!(normal_load_N > 0.0) || !std::isfinite(normal_load_N)) {
    throw std::invalid_argument("fit_coulomb_friction: normal load must be positive and finite");
  }
  if (sweep.speed_bins == 0) throw std::invalid_argument("fit_coulomb_friction: speed_bins is 0");
  FrictionFit fit;
  fit.contact = detect_contact(force, fs);
  const auto settle = static_cast<std::size_t>(std::lround(kSettleS * fs));
  fit.analysis_begin = fit.contact.begin + settle;
  fit.analysis_end = fit.contact.end > settle ? fit.contact.end - settle : 0;
  if (fit.analysis_end < fit.analysis_begin + 2 * sweep.speed_bins) {
    throw std::runtime_error(
        "fit_coulomb_friction: contact too short once 1 s is dropped at each end");
  }
  const std::size_t m = fit.analysis_end - fit.analysis_begin;
  fit.samples = m;

  // μ per sample, with the sensor's no-contact offset taken off (and the sign made positive when
  // the sensor reads friction as negative), and the assumed speed.
  const double sign = fit.contact.plateau_N >= fit.contact.baseline_N ? 1.0 : -1.0;
  const double n_minus_1 = static_cast<double>(std::max<std::size_t>(force.size(), 2) - 1);
  std::vector<double> mu(m), speed(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t s = fit.analysis_begin + i;
    mu[i] = sign * (force[s] - fit.contact.baseline_N) / normal_load_N;
    speed[i] = sweep.start_speed_m_s +
               (sweep.end_speed_m_s - sweep.start_speed_m_s) * static_cast<double>(s) / n_minus_1;
  }
  // Ordinary least squares μ = a + b v; with a constant speed the slope is 0 by definition.
  const double vbar = std::accumulate(speed.begin(), speed.end(), 0.0) / static_cast<double>(m);
  const double mbar = std::accumulate(mu.begin(), mu.end(), 0.0) / static_cast<double>(m);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    sxx += (speed[i] - vbar) * (speed[i] - vbar);
    sxy += (speed[i] - vbar) * (mu[i] - mbar);
  }
  fit.speed_slope_per_m_s = sxx > 0.0 ? sxy / sxx : 0.0;
  std::vector<double> residual(m);
  for (std::size_t i = 0; i < m; ++i) {
    residual[i] = mu[i] - mbar - fit.speed_slope_per_m_s * (speed[i] - vbar);
  }

  // One τ for the whole analysed part: the noise process is the same over the sweep, and a piece of
  // a few seconds holds too few correlation times to estimate τ on its own (at τ ≈ 0.1 s and 3 s
  // per piece its estimate would scatter by ±80 % and the piece intervals would undercover).
  const double tau = summarize_autocorrelation(residual).integrated_time_samples;
  const Interval all = mean_with_interval(mu, residual, tau);
  fit.mu = all.mean;
  fit.mu_ci_low = all.low;
  fit.mu_ci_high = all.high;
  fit.effective_samples = all.effective;

  for (std::size_t b = 0; b < sweep.speed_bins; ++b) {
    const std::size_t lo = m * b / sweep.speed_bins;
    const std::size_t hi = m * (b + 1) / sweep.speed_bins;
    const auto piece = std::span<const double>(mu).subspan(lo, hi - lo);
    const auto noise = std::span<const double>(residual).subspan(lo, hi - lo);
    const Interval r = mean_with_interval(piece, noise, tau);
    fit.speeds_m_s.push_back(std::accumulate(speed.begin() + static_cast<std::ptrdiff_t>(lo),
                                             speed.begin() + static_cast<std::ptrdiff_t>(hi), 0.0) /
                             static_cast<double>(hi - lo));
    fit.mu_by_speed.push_back(r.mean);
    fit.mu_by_speed_ci_low.push_back(r.low);
    fit.mu_by_speed_ci_high.push_back(r.high);
  }
  return fit;
}

double upstream_mu(std::span<const double> force, double normal_load_N) {
  constexpr std::size_t first = 4999;
  constexpr std::size_t last = 19999;  // inclusive
  if (force.size() <= last) {
    throw std::invalid_argument("upstream_mu: needs at least 20000 samples, got " +
                                std::to_string(force.size()));
  }
  if (!(normal_load_N > 0.0))
    throw std::invalid_argument("upstream_mu: normal load must be positive");
  const double sum = std::accumulate(force.begin() + first, force.begin() + last + 1, 0.0);
  return sum / static_cast<double>(last - first + 1) / normal_load_N;
}

}  // namespace nibrig::model::measure
