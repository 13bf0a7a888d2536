#include "model/design/mixed_design.hpp"

#include <algorithm>
#include <stdexcept>
#include <variant>

#include "model/forcing/printed_tool_design.hpp"

namespace nibrig::model::design {

MixedDesign mixed_design(const DesignPoint& point, const mechanics::Design& template_design,
                         const mechanics::MaterialTable& materials) {
  validate(point);
  const bool any_insert = std::any_of(point.mix.begin(), point.mix.end(), [](const auto& share) {
    return forcing::printed_tip_of(share.material).insert_length > 0;
  });
  if (point.mix.size() == 1 || !any_insert)  // one printed material: the fitted tools' design
    return {forcing::printed_tool_design(forcing::printed_tip_of(point.mix.front().material),
                                         point.tip_diameter_m, template_design, materials),
            materials};

  mechanics::Material mixed;
  mixed.name = "mix " + to_string(point);
  mixed.basis = "fitted";
  mixed.source = "rule of mixtures (E, Poisson ratio, density linear in the fractions) of";
  for (const auto& share : point.mix) {
    const mechanics::Material& m = materials.find(forcing::printed_tip_of(share.material).material);
    mixed.youngs_modulus += share.fraction * m.youngs_modulus;
    mixed.poisson_ratio += share.fraction * m.poisson_ratio;
    mixed.density += share.fraction * m.density;
    mixed.source += " " + m.name;
    mixed.basis = mechanics::least_calibrated(mixed.basis, m.basis);  // as calibrated as its least part
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
  if (material.empty())
    throw std::invalid_argument("design '" + design.name + "': its tip material '" +
                                region->second +
                                "' is not a printed material of the forcing model "
                                "(VeroClear-Piovarci2018, DM95, DM85)");
  return {{{material, 1.0}}, stylus->tip_diameter};
}

}  // namespace nibrig::model::design
