// A point in the space of printable designs (Sec. 5.3): a mix of the printed materials (the
// fraction of each, as a multi-material printer dithers them) and a tip diameter. Written on the
// command line as "DM85:0.25,vero:0.75,tip=1mm"; a single material may omit its fraction ("vero,
// tip=2mm"). Material names are the catalog's (vero, DM95, DM85, teflon).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace nibrig::model::design {

struct MaterialShare {
  std::string material;
  double fraction = 1.0;
};

struct DesignPoint {
  std::vector<MaterialShare> mix;  // fractions in [0, 1] adding up to 1, each material once
  double tip_diameter_m = 0.0;

  // The fraction of `material` in the mix (0 when absent).
  double fraction_of(const std::string& material) const;
};

// How far from 1 the fractions of a mix may add up (rounding in a hand-written spec).
inline constexpr double kMixSumTolerance = 1e-6;

// The smallest share of a material a typed mix may give: the print sheet names mixes in whole per
// cent, so a share below half a per cent prints as "0 %" — a material the printer is told to load
// for nothing it can dither. A fraction of 0 drops the material.
inline constexpr double kSmallestMixFraction = 0.005;

// Throws std::invalid_argument saying what is wrong and where in `text`: an entry that is neither
// "material[:fraction]" nor "tip=<number>mm", a fraction outside [0, 1] or above 0 and below
// kSmallestMixFraction, fractions that do not add
// up to 1 (giving their sum), a material named twice, no material, no tip or a tip that is not a
// positive length. Entries with fraction 0 are dropped.
DesignPoint parse_design_point(std::string_view text);

// The catalog's name of a printed material (vero, DM95, DM85, teflon) for a name typed in any case
// or as the material table's full name ("dm85" -> "DM85", "VeroClear-Piovarci2018" -> "vero"); any
// other name is returned as typed, for the forcing model to refuse naming the materials it has.
// parse_design_point applies it to every material.
std::string catalog_material_name(std::string_view typed);

// The same checks on a point built in code.
void validate(const DesignPoint& point);

// "DM85:0.25,vero:0.75,tip=1mm": parse_design_point reads it back to the same point.
std::string to_string(const DesignPoint& point);

// For people: fractions and tip to 3 significant digits ("vero:0.0477,DM85:0.952,tip=3.86mm"); a
// design a printer dithers in steps of a few per cent needs no more. Files keep to_string.
std::string label(const DesignPoint& point);

// The point a fraction `lambda` of the way from a to b: every material's fraction and the tip
// diameter interpolated linearly (the paper's line between two designs, Sec. 6.2).
DesignPoint interpolate(const DesignPoint& a, const DesignPoint& b, double lambda);

}  // namespace nibrig::model::design
