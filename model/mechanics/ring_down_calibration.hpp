// A material calibrated from a printed bar's ring-down: the fit of ring_down.hpp on the bar's FEM
// model (computed with the material's table values), its uncertainty (ring_down_uncertainty.hpp),
// and the fitted material a lab saves by name (lab_materials.hpp), with what it was fitted from.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "model/io/acceleration_trace.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/ring_down.hpp"
#include "model/mechanics/ring_down_uncertainty.hpp"

namespace nibrig::model::mechanics {

struct RingDownCalibrationOptions {
  std::string name;         // the fitted material's
  double preload = 0.05;    // m, as the bar was pulled aside
  bool calibrated = false;  // the trace is m/s² along the sensor axis: no gain fitted
  // What it was fitted from (recording, bar, printer, date): copied into the calibration record.
  nlohmann::json provenance = nlohmann::json::object();
};

struct RingDownCalibration {
  Material material;  // basis "fitted"; density and Poisson ratio are the reference's
  RingDownFit fit;
  RingDownUncertainty uncertainty;
  nlohmann::json calibration;  // the provenance, the fit and its uncertainty, for the lab's file
};

// Fits `trace` on `bar` (a DesignModel of one material, the reference) and makes the fitted
// material: E and the Rayleigh stiffness term fitted, the mass term held at the model's, density
// and Poisson ratio kept (the ring-down determines E/density, not either alone). Throws
// std::invalid_argument for an empty name, and what the fit and its uncertainty throw.
RingDownCalibration calibrate_ring_down(const DesignModel& bar, const io::AccelerationTrace& trace,
                                        const RingDownCalibrationOptions& options);

}  // namespace nibrig::model::mechanics
