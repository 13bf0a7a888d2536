#include "model/mechanics/design_model.hpp"

#include <chrono>
#include <stdexcept>
#include <tuple>

#include "model/mechanics/modal_model_builder.hpp"
#include "model/mechanics/point_probe.hpp"

namespace nibrig::model::mechanics {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <typename Stage>
auto naming_design(const Design& design, Stage&& stage) {
  try {
    return stage();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    if (what.find("design '") == 0) throw;
    throw std::invalid_argument("design '" + design.name + "': " + what);
  }
}

}  // namespace

std::pair<RayleighDamping, std::string> design_damping(const Design& design,
                                                       const MaterialTable& materials) {
  if (design.damping) return {*design.damping, "the design"};
  auto body = design.region_materials.find("body");
  if (body == design.region_materials.end() && design.region_materials.size() == 1)
    body = design.region_materials.begin();
  if (body != design.region_materials.end()) {
    const Material& material = materials.find(body->second);
    if (material.damping) return {*material.damping, "material '" + material.name + "'"};
  }
  return {RayleighDamping{}, "none (undamped)"};
}

DesignModel build_design_model(const Design& design, const MaterialTable& materials) {
  DesignModel model;
  model.design = design;
  std::tie(model.damping, model.damping_source) = design_damping(design, materials);

  auto start = std::chrono::steady_clock::now();
  model.mesh = naming_design(design, [&] { return mesh_design(design); });
  model.seconds.meshing_s = seconds_since(start);
  // Before the expensive stages: a tip or sensor off the body is a mistake in the design file.
  const PointLocator locator = naming_design(design, [&] { return PointLocator(model.mesh); });
  naming_design(design, [&] { return locator.locate(design.tip.point); });
  naming_design(design, [&] { return locator.locate(design.sensor.point); });

  std::vector<IsotropicMaterial> elastic;
  for (const auto& region : model.mesh.region_names) {
    model.region_materials.push_back(materials.find(material_of_region(design, region)));
    elastic.push_back(elastic_part(model.region_materials.back()));
  }
  start = std::chrono::steady_clock::now();
  const FemSystem system =
      naming_design(design, [&] { return assemble(model.mesh, elastic, {"clamp"}); });
  model.free_dofs = system.free_dofs();
  model.seconds.assembly_s = seconds_since(start);

  start = std::chrono::steady_clock::now();
  ModalOptions options;
  options.modes = design.modes;
  model.modes = naming_design(design, [&] { return compute_modes(system, options); });
  model.seconds.modes_s = seconds_since(start);

  const ModalProbe probe{design.tip.point, design.tip.direction, design.sensor.point,
                         design.sensor.direction};
  model.modal = naming_design(design, [&] {
    return build_modal_model(locator, model.modes, model.damping.mass, model.damping.stiffness,
                             probe);
  });
  return model;
}

}  // namespace nibrig::model::mechanics
