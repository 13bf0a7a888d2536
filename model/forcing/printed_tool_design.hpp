// The stylus design behind a printed tool of the catalog (material × tip diameter): the forcing fit
// needs each tool's simulated response H(f), and the catalog holds only the tool's material name
// and tip size. This turns those into a mechanics::Design derived from one template stylus.
#pragma once

#include <string>

#include "model/mechanics/stylus_description.hpp"

namespace nibrig::model::forcing {

// Length of a soft tip insert, measured back from the apex: the bundled two-material design
// assets/designs/stylus_vero_dm85tip_4mm.json (hemisphere and part of the taper). The paper does
// not give it; a test keeps this constant and that file in agreement.
inline constexpr double kPrintedTipInsertLength = 0.006;  // m

// How a catalog material is printed: the material (a name in assets/materials.json) of the tip
// insert and the insert's length; insert_length = 0 means the whole tool is the body material.
// whole_tool: the whole tool, body and tip, is `material` (a lab's one-material print).
struct PrintedTip {
  std::string material;
  double insert_length = 0.0;  // m
  bool whole_tool = false;
};

// The catalog's printed materials:
//  "vero"   the whole tool in VeroClear as the paper fitted it (VeroClear-Piovarci2018: E 0.45 GPa,
//           Rayleigh stiffness 1.25e-3 s, from the ring-down of Sec. 5.1), no insert;
//  "DM95", "DM85"  a VeroClear body with a kPrintedTipInsertLength tip insert of that Digital
//           Material (assets/materials.json: E estimated from the Shore A hardness, an estimate);
//  "teflon" a VeroClear tool whose tip is wrapped in PTFE tape. The tape (tens of µm) is not
//           modelled: the design is the VeroClear one, and whatever the tape does to the contact
//           is absorbed by the fitted material curve m(f) of "teflon". That is an assumption.
// Throws std::invalid_argument naming the material for any other name (commercial and real tools
// have no design).
PrintedTip printed_tip_of(const std::string& catalog_material);

// The paper's materials as above; any other name a material of `materials` (a lab's own, or a
// bundled one such as PLA) printed as the whole tool, as an FDM or SLA printer makes a stylus of
// one material. Throws std::invalid_argument naming the material and what the table knows.
PrintedTip printed_tip_of(const std::string& catalog_material,
                          const mechanics::MaterialTable& materials);

// Whether printed_tip_of(catalog_material, materials) has a design for it.
bool has_printed_design(const std::string& catalog_material,
                        const mechanics::MaterialTable& materials);

// `template_design` must be a parametric stylus ("kind": "stylus"): its body (length, diameter,
// taper, grip), body material, mesh size, mode count and sensor are kept (assumptions stated in
// that file and in mechanics/stylus_description.hpp: 10 mm × 120 mm body, 15 mm taper, 30 mm grip,
// sensor on the surface 10 mm in front of the grip). The tip diameter becomes `tip_diameter_m`, the
// tip insert becomes `tip` (no insert when its material is the body's), the tip probe moves to the
// new apex with the template's force direction, and the damping is fixed to the template's (its
// own, else its body material's): Rayleigh damping must be one for the whole body to keep modes
// uncoupled, and the soft materials' own damping is not known. A whole-tool print is the template
// in `tip.material` throughout, damped as that material when its table entry has damping (a
// ring-down calibration gives it), else as the template. Throws std::invalid_argument for a
// template that is not a stylus or has no "body" material, and for a non-positive diameter.
mechanics::Design printed_tool_design(const PrintedTip& tip, double tip_diameter_m,
                                      const mechanics::Design& template_design,
                                      const mechanics::MaterialTable& materials);

}  // namespace nibrig::model::forcing
