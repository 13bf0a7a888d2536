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

PrintedTip printed_tip_of(const std::string& catalog_material,
                          const mechanics::MaterialTable& materials) {
  try {
    return printed_tip_of(catalog_material);
  } catch (const std::invalid_argument&) {
  }
  try {
    return {materials.find(catalog_material).name, 0.0, true};
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(
        "printed tool material '" + catalog_material +
        "' has no design: not one of the paper's (vero, DM95, DM85, teflon), and " + e.what());
  }
}

bool has_printed_design(const std::string& catalog_material,
                        const mechanics::MaterialTable& materials) {
  try {
    printed_tip_of(catalog_material, materials);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
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
  const mechanics::Material& tip_material = materials.find(tip.material);
  const bool insert = !tip.whole_tool && tip_material.name != materials.find(body->second).name &&
                      tip.insert_length > 0;
  geometry.tip_insert_length = insert ? tip.insert_length : 0.0;
  mechanics::validate(geometry);
  design.shape = geometry;

  design.region_materials.clear();
  design.region_materials["body"] = tip.whole_tool ? tip_material.name : body->second;
  if (insert) design.region_materials["tip"] = tip.material;
  design.damping = tip.whole_tool && tip_material.damping
                       ? *tip_material.damping
                       : mechanics::design_damping(template_design, materials).first;

  design.tip.point = mechanics::default_tip(geometry).point;  // the apex moved with the diameter
  design.name = "printed " + (insert ? tip.material + " tip" : design.region_materials["body"]) +
                ", " + tip_label(tip_diameter_m);
  return design;
}

}  // namespace nibrig::model::forcing
