// Leave-one-out validation of the forcing model (the paper's Fig. 12): each chosen exemplar is
// removed, the model is fitted to the rest, and the exemplar is predicted from the training's F_S,
// t and m and its own simulated response H. The error is what a designer would see for a tool
// that was never measured.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

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
};

struct LeaveOneOutSummary {
  std::size_t predicted = 0, not_predictable = 0;
  double mean_rms_db = 0.0, median_rms_db = 0.0, max_rms_db = 0.0;
  double mean_baseline_rms_db = 0.0;
  std::vector<std::size_t> worst;  // indices into the results, worst first, at most three
};

struct LeaveOneOut {
  std::vector<HeldOutResult> results;  // in the order of `held_out`
  LeaveOneOutSummary summary;
};

// Holds out exemplars[held_out[k]] in turn (every other exemplar trains). An exemplar whose
// surface, tip or material no other exemplar shares, or without which a curve of the training set
// is not identifiable, is reported as not predictable with the reason (fit_problems), never
// skipped silently. Throws std::invalid_argument for an index out of range.
LeaveOneOut leave_one_out(std::span<const ForcingExemplar> exemplars,
                          std::span<const std::size_t> held_out,
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
