#include "model/design/mixed_design.hpp"

#include <algorithm>
#include <stdexcept>
#include <variant>

#include "model/forcing/printed_tool_design.hpp"

namespace nibrig::model::design {

MixedDesign mixed_design(const DesignPoint& point, const mechanics::Design& template_design,
                         const mechanics::MaterialTable& materials) {
  validate(point);
  std::vector<forcing::PrintedTip> tips;
  for (const auto& share : point.mix)
    tips.push_back(forcing::printed_tip_of(share.material, materials));
  if (point.mix.size() == 1)  // one printed material: the fitted tools' design
    return {forcing::printed_tool_design(tips.front(), point.tip_diameter_m, template_design,
                                         materials),
            materials};
  for (std::size_t i = 0; i < tips.size(); ++i)
    if (tips[i].whole_tool)
      throw std::invalid_argument(
          "design point '" + to_string(point) + "': '" + point.mix[i].material +
          "' prints as a whole tool of one material and is not mixed (a mix is of the "
          "paper's PolyJet materials: vero, DM95, DM85)");
  const bool any_insert = std::any_of(tips.begin(), tips.end(), [](const forcing::PrintedTip& tip) {
    return tip.insert_length > 0;
  });
  if (!any_insert)  // vero and teflon print the same VeroClear tool
    return {forcing::printed_tool_design(tips.front(), point.tip_diameter_m, template_design,
                                         materials),
            materials};

  mechanics::Material mixed;
  mixed.name = "mix " + to_string(point);
  mixed.basis = "fitted";
  mixed.source = "rule of mixtures (E, Poisson ratio, density linear in the fractions) of";
  for (std::size_t i = 0; i < point.mix.size(); ++i) {
    const auto& share = point.mix[i];
    const mechanics::Material& m = materials.find(tips[i].material);
    mixed.youngs_modulus += share.fraction * m.youngs_modulus;
    mixed.poisson_ratio += share.fraction * m.poisson_ratio;
    mixed.density += share.fraction * m.density;
    mixed.source += " " + m.name;
    mixed.basis =
        mechanics::least_calibrated(mixed.basis, m.basis);  // as calibrated as its least part
  }
  mechanics::validate(mixed);
  std::vector<mechanics::Material> all = materials.materials();
  all.push_back(mixed);
  MixedDesign result{{}, mechanics::MaterialTable(std::move(all))};
  result.design =
      forcing::printed_tool_design({mixed.name, forcing::kPrintedTipInsertLength},
                                   point.tip_diameter_m, template_design, result.materials);
  return result;
}

DesignPoint design_point_of(const mechanics::Design& design) {
  const auto* stylus = std::get_if<mechanics::StylusGeometry>(&design.shape);
  if (stylus == nullptr)
    throw std::invalid_argument("design '" + design.name +
                                "' is not a parametric stylus, so its tip diameter is unknown");
  auto region = design.region_materials.find("tip");
  if (region == design.region_materials.end()) region = design.region_materials.find("body");
  if (region == design.region_materials.end())
    throw std::invalid_argument("design '" + design.name + "' names no tip or body material");
  std::string material;
  for (const char* printed : {"vero", "DM95", "DM85"})
    if (forcing::printed_tip_of(printed).material == region->second) material = printed;
  // A stylus of one material throughout is that material printed whole: a lab's, by its table name.
  const bool one_material =
      std::all_of(design.region_materials.begin(), design.region_materials.end(),
                  [&](const auto& r) { return r.second == region->second; });
  if (material.empty() && one_material) material = region->second;
  if (material.empty())
    throw std::invalid_argument(
        "design '" + design.name + "': its tip material '" + region->second +
        "' is not a printed material of the forcing model "
        "(VeroClear-Piovarci2018, DM95, DM85) and the stylus is not of one material "
        "(a lab's material prints as the whole tool)");
  return {{{material, 1.0}}, stylus->tip_diameter};
}

}  // namespace nibrig::model::design
