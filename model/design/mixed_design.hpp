// The stylus a design point describes, for the mechanics: the printed tools' template with the
// point's tip diameter and, for a mix, a tip insert of the mixed material. Dithered multi-material
// prints are modelled by the rule of mixtures on every elastic constant and the density (E, ν, ρ
// linear in the fractions; the paper interpolates "material parameters" linearly, Sec. 5.3). That
// is an assumption: a dithered composite of a stiff and a soft phase can be softer than the linear
// rule says (the Reuss bound), and no measurement here tells which.
#pragma once

#include "model/design/design_point.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"

namespace nibrig::model::design {

struct MixedDesign {
  mechanics::Design design;
  // `materials` with the mixed tip material added when the point is a mix (the design names it).
  mechanics::MaterialTable materials;
};

// One material: exactly the design of the fitted printed tool (forcing::printed_tool_design). A
// mix: a kPrintedTipInsertLength insert of the mixed material when any material of the mix is
// printed as an insert (DM95, DM85), else the whole tool of the mixed material (vero and teflon
// print the same VeroClear, so their mix is the VeroClear tool). Any other material of `materials`
// (a lab's) is the whole tool of it, and is never mixed. Throws std::invalid_argument for a
// material without a printed design, a lab's material in a mix, or an invalid point.
MixedDesign mixed_design(const DesignPoint& point, const mechanics::Design& template_design,
                         const mechanics::MaterialTable& materials);

// The design point of a designer's own stylus file: its tip diameter (a parametric stylus) and the
// catalog material of its tip (region "tip", else "body"): VeroClear-Piovarci2018 is "vero", DM95
// and DM85 are themselves; a stylus of one other material throughout is that material, by its
// table name (a lab's, printed whole). Throws std::invalid_argument naming the design for another
// shape or a tip of another material than its body's that is none of the paper's.
DesignPoint design_point_of(const mechanics::Design& design);

}  // namespace nibrig::model::design
