#include "model/forcing/leave_one_out.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace nibrig::model::forcing {

namespace {

// Why `held` cannot be predicted from `training`, or "" when it can.
std::string unpredictable_reason(const ForcingExemplar& held,
                                 std::span<const ForcingExemplar> training,
                                 const ForcingFitOptions& options) {
  const auto shares = [&](auto&& same) {
    return std::any_of(training.begin(), training.end(), same);
  };
  if (!shares([&](const auto& e) { return e.surface == held.surface; }))
    return "no other tool was measured on " + held.surface + ", so its forcing is unknown";
  if (!shares([&](const auto& e) { return same_tip(e.tip_diameter_m, held.tip_diameter_m); }))
    return "no other exemplar has its " + tip_label(held.tip_diameter_m) +
           " tip, so its tip curve is unknown";
  if (!shares([&](const auto& e) { return e.material == held.material; }))
    return "no other exemplar is of material '" + held.material +
           "', so its material curve is unknown";
  const auto problems = fit_problems(training, options);
  if (!problems.empty()) {
    std::string reason = "without it the rest cannot be fitted: ";
    for (std::size_t k = 0; k < problems.size(); ++k) reason += (k ? "; " : "") + problems[k];
    return reason;
  }
  return "";
}

// The geometric mean of the training tools' spectra on the held-out tool's surface.
io::VelocitySpectrum surface_mean(const ForcingExemplar& held,
                                  std::span<const ForcingExemplar> training) {
  io::VelocitySpectrum mean{held.measured.frequencies_hz, held.measured.speeds_m_s, {}};
  for (std::size_t s = 0; s < held.measured.speeds_m_s.size(); ++s) {
    std::vector<double> row(held.measured.frequencies_hz.size(), 0.0);
    for (std::size_t j = 0; j < row.size(); ++j) {
      double sum = 0.0;
      std::size_t n = 0;
      for (const auto& e : training)
        if (e.surface == held.surface && e.measured.amplitude_m_s2[s][j] > 0) {
          sum += std::log(e.measured.amplitude_m_s2[s][j]);
          ++n;
        }
      row[j] = n > 0 ? std::exp(sum / static_cast<double>(n)) : 0.0;
    }
    mean.amplitude_m_s2.push_back(std::move(row));
  }
  return mean;
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

SpectrumError log_spectrum_error(const io::VelocitySpectrum& predicted,
                                 const io::VelocitySpectrum& measured) {
  if (predicted.amplitude_m_s2.size() != measured.amplitude_m_s2.size() ||
      predicted.frequencies_hz.size() != measured.frequencies_hz.size())
    throw std::invalid_argument("spectrum error: predicted and measured grids differ");
  SpectrumError error;
  double total = 0.0;
  std::size_t total_count = 0;
  const double db = 20.0 / std::log(10.0);
  for (std::size_t s = 0; s < measured.amplitude_m_s2.size(); ++s) {
    const auto& p = predicted.amplitude_m_s2[s];
    const auto& m = measured.amplitude_m_s2[s];
    if (p.size() != m.size())
      throw std::invalid_argument("spectrum error: predicted and measured grids differ");
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t j = 0; j < m.size(); ++j) {
      if (!(p[j] > 0 && m[j] > 0)) continue;
      const double d = db * std::log(p[j] / m[j]);
      sum += d * d;
      ++count;
    }
    error.rms_db_by_speed.push_back(count > 0 ? std::sqrt(sum / static_cast<double>(count))
                                              : std::numeric_limits<double>::quiet_NaN());
    total += sum;
    total_count += count;
  }
  if (total_count == 0)
    throw std::invalid_argument("spectrum error: no bin where both spectra are positive");
  error.rms_db = std::sqrt(total / static_cast<double>(total_count));
  return error;
}

LeaveOneOut leave_one_out(std::span<const ForcingExemplar> exemplars,
                          std::span<const std::size_t> held_out, const ForcingFitOptions& options,
                          const measure::ThresholdCurve* threshold) {
  LeaveOneOut out;
  for (std::size_t index : held_out) {
    if (index >= exemplars.size())
      throw std::invalid_argument("leave-one-out: exemplar index " + std::to_string(index) +
                                  " out of range (" + std::to_string(exemplars.size()) +
                                  " exemplars)");
    const ForcingExemplar& held = exemplars[index];
    std::vector<ForcingExemplar> training;
    for (std::size_t e = 0; e < exemplars.size(); ++e)
      if (e != index) training.push_back(exemplars[e]);

    HeldOutResult result;
    result.tool = held.tool;
    result.surface = held.surface;
    result.training_exemplars = training.size();
    result.reason = unpredictable_reason(held, training, options);
    if (result.reason.empty()) {
      const ForcingModel model = fit_forcing_model(training, options);
      const auto predicted =
          model.predict(held.response_magnitude, held.surface, held.tip_diameter_m, held.material);
      const SpectrumError error = log_spectrum_error(predicted, held.measured);
      result.predictable = true;
      result.rms_db = error.rms_db;
      result.rms_db_by_speed = error.rms_db_by_speed;
      result.baseline_rms_db =
          log_spectrum_error(surface_mean(held, training), held.measured).rms_db;
      if (threshold != nullptr)
        result.descriptor_error =
            descriptor_error(held.tool, held.surface, predicted, held.measured, *threshold);
    }
    out.results.push_back(std::move(result));
  }

  out.summary = summarize(out.results);
  return out;
}

LeaveOneOutSummary summarize(std::span<const HeldOutResult> results) {
  std::vector<double> errors, baselines;
  std::vector<std::size_t> order;
  double weighted_mean_squares = 0.0;
  for (std::size_t k = 0; k < results.size(); ++k) {
    if (!results[k].predictable) continue;
    errors.push_back(results[k].rms_db);
    baselines.push_back(results[k].baseline_rms_db);
    order.push_back(k);
    if (const auto& d = results[k].descriptor_error)
      weighted_mean_squares += d->log10_weighted_mean * d->log10_weighted_mean;
  }
  LeaveOneOutSummary summary;
  summary.predicted = errors.size();
  summary.not_predictable = results.size() - errors.size();
  if (!errors.empty()) {
    const double n = static_cast<double>(errors.size());
    summary.mean_rms_db = std::accumulate(errors.begin(), errors.end(), 0.0) / n;
    summary.mean_baseline_rms_db = std::accumulate(baselines.begin(), baselines.end(), 0.0) / n;
    summary.median_rms_db = median_of(errors);
    summary.weighted_mean_rms_log10 = std::sqrt(weighted_mean_squares / n);
    summary.max_rms_db = *std::max_element(errors.begin(), errors.end());
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return results[a].rms_db > results[b].rms_db;
    });
    order.resize(std::min<std::size_t>(order.size(), 3));
    summary.worst = order;
  }
  return summary;
}

std::vector<DescriptorError> descriptor_errors(const LeaveOneOut& loo) {
  std::vector<DescriptorError> errors;
  for (const auto& result : loo.results)
    if (result.descriptor_error) errors.push_back(*result.descriptor_error);
  return errors;
}

std::vector<DescriptorError> held_out_descriptor_errors(std::span<const ForcingExemplar> exemplars,
                                                        const measure::ThresholdCurve& threshold,
                                                        const ForcingFitOptions& options) {
  return descriptor_errors(leave_every_one_out(exemplars, &threshold, options));
}

LeaveOneOut leave_every_one_out(std::span<const ForcingExemplar> exemplars,
                                const measure::ThresholdCurve* threshold,
                                const ForcingFitOptions& options) {
  std::vector<std::size_t> every(exemplars.size());
  std::iota(every.begin(), every.end(), std::size_t{0});
  return leave_one_out(exemplars, every, options, threshold);
}

}  // namespace nibrig::model::forcing
