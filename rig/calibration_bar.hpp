// The ring-down bar of the paper's Sec. 5.1 (210 × 20 × 2 mm, rounded end R10, an R5 hole 10 mm
// from it, clamped over 30 mm) as a printed part in a lab's material on a lab's printer: the first
// step of calibrating a material from prints. Its solid, the refusals a printer gives it, and the
// FEM design the ring-down fit (model/mechanics/ring_down.hpp) simulates it by, all from one
// BarGeometry so that what is printed is what is fitted.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/io/printer_profile.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "rig/printed_parts.hpp"

namespace nibrig::rig {

struct CalibrationBar {
  model::mechanics::BarGeometry geometry;  // the paper's bar by default
  std::string material;                    // the material table's name, as the printer lists it
  double preload = 0.05;                   // m: the paper pulls the free end 5 cm aside
};

// The bar of `material` as `materials` names it (any case), the paper's length unless `length_m` is
// given (checked with the geometry when the bar is written). Throws what MaterialTable::find throws
// for a material the table lacks.
CalibrationBar calibration_bar_of(const std::string& material,
                                  const model::mechanics::MaterialTable& materials,
                                  std::optional<double> length_m = std::nullopt);

// The FEM design the fit uses: model::mechanics::bar_design, its tip the middle of the free end and
// its sensor on the centre line 20 mm from that end, axis through the thickness.
model::mechanics::Design calibration_bar_design(const CalibrationBar& bar);

// Where the design's sensor and tip sit on the printed bar, in the print's frame: x from the
// clamped (square) end, y across from the centre line, z up from the bed. Metres.
Eigen::Vector3d bar_sensor_on_print(const CalibrationBar& bar);
Eigen::Vector3d bar_tip_on_print(const CalibrationBar& bar);

// The bar lying flat (thickness along z, the clamped end at x = 0): its layers then run along the
// bar, so the ring-down measures the in-plane modulus, the one a stylus lying on the bed bends
// with. The print settings are the profile's. Throws what validate(BarGeometry) throws.
PrintedPart calibration_bar_part(const CalibrationBar& bar,
                                 const model::io::PrinterProfile& printer);

// Why `printer` cannot make the bar, in words (empty when it can): a material it does not list, a
// bar longer than its bed (naming the longest that fits), a thickness or the hole's rim below its
// smallest feature.
std::vector<std::string> calibration_bar_refusals(const model::io::PrinterProfile& printer,
                                                  const CalibrationBar& bar);

}  // namespace nibrig::rig
