// A new surface's forcing F_S(f, v) calibrated from a few tools the fitted model already knows,
// measured on it: their |H|, t_d and m_μ are held, so each tool gives one estimate of ln F per cell
// (speed, frequency), ln M − ln|H| − ln t_d − ln m_μ, and the calibration is their mean, exactly as
// the full fit recovers F for fixed curves (forcing_fit.hpp).
//
// Uncertainty: the standard error of that mean, s/√n per cell, with s² the tools' variance about
// their mean pooled over the cell's neighbours at the same speed (kSurfaceSePoolHz either side).
// One cell's variance from two or three tools has one or two degrees of freedom and would swing
// by a factor of several from bin to bin; the spectra are smooth over a few bins and so is the
// tools' disagreement (it is mostly where their resonances differ), so neighbours share it.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/forcing_model.hpp"

namespace nibrig::model::forcing {

// Half the width of the window a cell's variance is pooled over: half a knot interval of the
// material and tip curves, narrower than any feature those curves can follow.
inline constexpr double kSurfaceSePoolHz = 25.0;

struct SurfaceCalibration {
  ForcingModel model;  // the input, with the surface's forcing (and its errors, from 2 tools) added
  std::string surface;
  std::vector<std::string> tools;
  // ln F per [speed][frequency], and its standard error: empty with a single tool, which gives
  // the forcing but no spread to tell its error.
  std::vector<std::vector<double>> log_forcing, log_forcing_se;
  double rms_se_db = 0.0;  // RMS over the cells of the standard error, in dB (0 with one tool)
  // How far the calibrated surface is from the tools it was calibrated on (dB RMS), and per tool.
  double residual_rms_db = 0.0;
  std::vector<ExemplarFit> tool_fits;
};

// `tools` are exemplars on `surface` (one per tool) with their responses, of tips and materials
// the model has curves for, on its grid. Throws std::invalid_argument naming the tool or surface:
// no tools, a tool on another surface or twice, an unknown tip or material, off the grid, the
// surface already in the model (a calibration adds a surface under a new name), a cell no tool
// measured a positive amplitude in.
SurfaceCalibration calibrate_surface(const ForcingModel& model,
                                     std::span<const ForcingExemplar> tools,
                                     const std::string& surface);

}  // namespace nibrig::model::forcing
