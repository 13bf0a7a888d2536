// What calibrating a new material or surface against a fitted forcing model starts from: the
// prints' measured spectra with the factors the model already knows divided out, in log amplitude,
// on the model's grid. Shared by material_calibration and surface_calibration, so that both check
// a print against the model the same way and name it the same way when it does not fit.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/forcing_model.hpp"

namespace nibrig::model::forcing {

// ln M − ln|H| − Σ(the known log factors) per [speed][frequency] of the model; NaN where the
// measured amplitude (or a held factor) is ≤ 0 and has no logarithm.
using LogCells = std::vector<std::vector<double>>;

// "DM951 on glass".
std::string print_name(const ForcingExemplar& print);

// Throws std::invalid_argument, starting with `what` and naming the print, when its spectrum is not
// on the model's frequencies and speeds or its response is not one finite value > 0 per frequency.
void check_print_grid(const ForcingModel& model, const ForcingExemplar& print,
                      const std::string& what);

// ln M − ln|H| of a print on the model's grid (check_print_grid first); NaN where M ≤ 0.
LogCells print_log_data(const ForcingExemplar& print);

// The RMS in dB of the finite values of `residuals` (one LogCells per print), and per print.
struct CalibrationResiduals {
  double rms_db = 0.0;
  std::vector<ExemplarFit> per_print;
};
CalibrationResiduals residual_summary(std::span<const ForcingExemplar> prints,
                                      const std::vector<LogCells>& residuals);

// The exemplars of `material`, only those with a tip among `tips_m` when it is not empty. Throws
// std::invalid_argument naming the material, or the tip, that no exemplar has.
std::vector<ForcingExemplar> prints_of_material(std::span<const ForcingExemplar> exemplars,
                                                const std::string& material,
                                                std::span<const double> tips_m = {});

// The exemplars on `surface`, only those of the tools named when `tools` is not empty. Throws
// std::invalid_argument naming the surface, or a tool not measured on it.
std::vector<ForcingExemplar> tools_on_surface(std::span<const ForcingExemplar> exemplars,
                                              const std::string& surface,
                                              std::span<const std::string> tools = {});

// Each exemplar predicted by `model` (its |H| on its surface, with its tip and material) against
// its measurement: RMS of 20·log10(predicted/measured) over the cells. Throws what
// ForcingModel::predict throws for a surface, tip or material the model lacks.
std::vector<ExemplarFit> prediction_errors(const ForcingModel& model,
                                           std::span<const ForcingExemplar> exemplars);

// The exemplars of `material` a calibration did not use (`used`), on surfaces `model` has,
// predicted by it: how well a calibration from a few prints predicts the material's others.
std::vector<ExemplarFit> unused_print_errors(const ForcingModel& model, std::span<const ForcingExemplar> exemplars,
                                             const std::string& material, std::span<const ForcingExemplar> used);

}  // namespace nibrig::model::forcing
