// The check of Sec. 5.3 on the material axis: predict the measured tools of one material from the
// others, as a mix of two fitted materials. The printed Digital Materials are themselves blends
// of rigid VeroClear and a rubber-like resin, DM95 holding more of the rigid phase than DM85, so
// "DM95 as a mix of VeroClear and DM85" is the nearest the data come to a measured interpolated
// print. Unlike the tip axis, the material effect is resolved by the data (DM85 against VeroClear
// is 3-5 standard errors at 50-150 Hz), so here the interpolation rule is actually put to a test.
//
// Which fraction? The one thing a designer knows of a material is its stiffness, so by default the
// fraction whose mix has the held-out material's Young's modulus under the rule of mixtures the
// mechanics uses (mixed_design.hpp) — the same prediction a designer would make for that mix.
// Beside it, the fraction the fitted curves themselves put the material at (a least-squares fit of
// its material curve on the line between the two), with its error: if the two disagree beyond the
// error, the mixing rule and the curve interpolation do not describe these materials together.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "model/design/interpolation_check.hpp"
#include "model/mechanics/material_table.hpp"

namespace nibrig::model::design {

// The fraction of `second` in a mix of `first` and `second` whose Young's modulus (the rule of
// mixtures, linear in the fractions, of their printed tip materials) equals that of `material`'s
// printed tip. Throws std::invalid_argument naming them when a material has no printed design, or
// when the modulus does not lie between the two (no mix of them has it).
double equal_modulus_fraction(const mechanics::MaterialTable& materials,
                              const std::string& material, const std::string& first,
                              const std::string& second);

struct MaterialHoldOut {
  forcing::ForcingModel model;  // fitted without the held-out material
  std::string material;
  std::string first, second;  // the mix's materials
  double second_fraction = 0.0;
  DesignPoint point_at(double tip_diameter_m) const;  // the mix (no zero share) at that tip
  // One per held-out exemplar, in input order: predicted as the mix at its own tip, against the
  // baselines (first alone, second alone) and the measured tools of the first and the second
  // material with its tip on its surface.
  std::vector<InterpolatedPrediction> predictions;
};

// Exemplars need their responses. Throws std::invalid_argument when no exemplar is of `material`,
// when it is one of the mix's, when the mix's fraction is outside [0, 1], or when the rest cannot
// be fitted (forcing::fit_problems, joined; the reference material must stay among them).
MaterialHoldOut hold_out_material(std::span<const forcing::ForcingExemplar> exemplars,
                                  const std::string& material, const std::string& first,
                                  const std::string& second, double second_fraction);

// From a fit of every exemplar (the held-out material included), per knot: the effect between the
// two (ln m_second − ln m_first), the held-out curve's departure from the mix's interpolation
// (ln m_material − ((1 − f) ln m_first + f ln m_second)), and the fraction f* that puts the
// held-out curve closest to that line over all knots (least squares) — each with its
// delete-one-tool jackknife standard error.
struct MaterialResolution {
  std::string material, first, second;
  double second_fraction = 0.0;
  std::vector<double> knot_frequencies_hz;
  std::vector<double> effect, effect_se;
  std::vector<double> deviation, deviation_se;
  double fitted_fraction = 0.0, fitted_fraction_se = 0.0;
  std::size_t tools = 0;
  std::size_t effect_resolved_knots() const;     // |effect| > 2 SE
  std::size_t deviation_resolved_knots() const;  // |deviation| > 2 SE
};
MaterialResolution material_resolution(const forcing::CurveJackknife& jackknife,
                                       const std::string& material, const std::string& first,
                                       const std::string& second, double second_fraction);

}  // namespace nibrig::model::design
