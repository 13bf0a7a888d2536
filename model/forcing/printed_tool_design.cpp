#include "model/forcing/printed_tool_design.hpp"

#include <cmath>
#include <stdexcept>

#include "model/forcing/forcing_model.hpp"
#include "model/mechanics/design_model.hpp"

namespace nibrig::model::forcing {

namespace {

constexpr const char* kVeroClear = "VeroClear-Piovarci2018";

}  // namespace

PrintedTip printed_tip_of(const std::string& catalog_material) {
  if (catalog_material == "vero" || catalog_material == "teflon") return {kVeroClear, 0.0};
  if (catalog_material == "DM95" || catalog_material == "DM85")
    return {catalog_material, kPrintedTipInsertLength};
  throw std::invalid_argument("printed tool material '" + catalog_material +
                              "' has no design (known: vero, DM95, DM85, teflon)");
}

mechanics::Design printed_tool_design(const PrintedTip& tip, double tip_diameter_m,
                                      const mechanics::Design& template_design,
                                      const mechanics::MaterialTable& materials) {
  const auto* stylus = std::get_if<mechanics::StylusGeometry>(&template_design.shape);
  if (stylus == nullptr)
    throw std::invalid_argument("printed tool design: template '" + template_design.name +
                                "' is not a parametric stylus");
  const auto body = template_design.region_materials.find("body");
  if (body == template_design.region_materials.end())
    throw std::invalid_argument("printed tool design: template '" + template_design.name +
                                "' names no material for region \"body\"");
  if (!(std::isfinite(tip_diameter_m) && tip_diameter_m > 0))
    throw std::invalid_argument("printed tool design: tip diameter must be a positive length");

  mechanics::Design design = template_design;
  mechanics::StylusGeometry geometry = *stylus;
  geometry.tip_diameter = tip_diameter_m;
  const bool insert = materials.find(tip.material).name != materials.find(body->second).name &&
                      tip.insert_length > 0;
  geometry.tip_insert_length = insert ? tip.insert_length : 0.0;
  mechanics::validate(geometry);
  design.shape = geometry;

  design.region_materials.clear();
  design.region_materials["body"] = body->second;
  if (insert) design.region_materials["tip"] = tip.material;
  design.damping = mechanics::design_damping(template_design, materials).first;

  design.tip.point = mechanics::default_tip(geometry).point;  // the apex moved with the diameter
  design.name = "printed " + (insert ? tip.material + " tip" : body->second) + ", " +
                tip_label(tip_diameter_m);
  return design;
}

}  // namespace nibrig::model::forcing
