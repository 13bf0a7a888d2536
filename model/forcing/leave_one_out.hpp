// Leave-one-out validation of the forcing model (the paper's Fig. 12): each chosen exemplar is
// removed, the model is fitted to the rest, and the exemplar is predicted from the training's F_S,
// t and m and its own simulated response H. The error is what a designer would see for a tool
// that was never measured.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/descriptor_error.hpp"
#include "model/forcing/forcing_fit.hpp"

namespace nibrig::model::forcing {

struct HeldOutResult {
  std::string tool, surface;
  bool predictable = false;
  std::string reason;  // why not, when !predictable
  // RMS over every bin and speed of 20·log10(predicted/measured), and per speed (model speeds).
  double rms_db = 0.0;
  std::vector<double> rms_db_by_speed;
  // The same error of a model-free baseline: the held-out tool predicted as the geometric mean of
  // the other tools measured on its surface. Tells how much t, m and H add over "this surface
  // sounds like this".
  double baseline_rms_db = 0.0;
  std::size_t training_exemplars = 0;
  // How far the prediction's perceptual descriptors are from the measured ones, when a threshold
  // curve was given to weigh them.
  std::optional<DescriptorError> descriptor_error;
};

struct LeaveOneOutSummary {
  std::size_t predicted = 0, not_predictable = 0;
  double mean_rms_db = 0.0, median_rms_db = 0.0, max_rms_db = 0.0;
  double mean_baseline_rms_db = 0.0;
  // RMS over the predicted exemplars of log10(predicted / measured) of the perceptually weighted
  // mean vibration, when a threshold was given (0 otherwise).
  double weighted_mean_rms_log10 = 0.0;
  std::vector<std::size_t> worst;  // indices into the results, worst first, at most three
};

struct LeaveOneOut {
  std::vector<HeldOutResult> results;  // in the order of `held_out`
  LeaveOneOutSummary summary;
};

// Holds out exemplars[held_out[k]] in turn (every other exemplar trains). An exemplar whose
// surface, tip or material no other exemplar shares, or without which a curve of the training set
// is not identifiable, is reported as not predictable with the reason (fit_problems), never
// skipped silently. With a threshold curve, each prediction's descriptor error is computed too.
// Throws std::invalid_argument for an index out of range.
LeaveOneOut leave_one_out(std::span<const ForcingExemplar> exemplars,
                          std::span<const std::size_t> held_out,
                          const ForcingFitOptions& options = {},
                          const measure::ThresholdCurve* threshold = nullptr);

// Every exemplar held out in turn (results[k] is exemplars[k]): the paper's tools or any other
// subset is then summarize() of their results, without refitting.
LeaveOneOut leave_every_one_out(std::span<const ForcingExemplar> exemplars,
                                const measure::ThresholdCurve* threshold = nullptr,
                                const ForcingFitOptions& options = {});

// The summary of any set of held-out results (worst: indices into `results`), as leave_one_out
// gives for its own.
LeaveOneOutSummary summarize(std::span<const HeldOutResult> results);

// The descriptor errors of the predictable results that have one, in order.
std::vector<DescriptorError> descriptor_errors(const LeaveOneOut& loo);

// The descriptor errors of every exemplar that can be held out (all of them in turn; those that
// cannot be predicted are left out, as leave_one_out says why). What a predicted tool's placement
// uncertainty is estimated from, computed when the model is fitted because it needs each
// exemplar's measured spectrum and response.
std::vector<DescriptorError> held_out_descriptor_errors(std::span<const ForcingExemplar> exemplars,
                                                        const measure::ThresholdCurve& threshold,
                                                        const ForcingFitOptions& options = {});

// Error of a predicted against a measured spectrum on the same grid: RMS of 20·log10(p/m) over all
// bins and speeds, and per speed; bins where either is ≤ 0 are left out. Throws
// std::invalid_argument when the grids differ or no bin is usable.
struct SpectrumError {
  double rms_db = 0.0;
  std::vector<double> rms_db_by_speed;
};
SpectrumError log_spectrum_error(const io::VelocitySpectrum& predicted,
                                 const io::VelocitySpectrum& measured);

}  // namespace nibrig::model::forcing
