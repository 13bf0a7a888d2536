// From a design to its modal model: mesh, assemble, solve for the lowest modes, read them at the
// tip and sensor, apply Rayleigh damping. The one pipeline every user of the FEM shares (a stylus's
// modes, the ring-down fit, predicted designs); it records how long each stage took.
#pragma once

#include <vector>

#include "model/mechanics/fem_assembly.hpp"
#include "model/mechanics/isotropic_material.hpp"
#include "model/mechanics/modal_analysis.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::mechanics {

struct DesignModel {
  Design design;
  TetMesh mesh;
  std::vector<Material> region_materials;  // in the order of mesh.region_names
  RayleighDamping damping;
  std::string damping_source;  // "the design", "material 'X'", or "none (undamped)"
  Eigen::Index free_dofs = 0;
  ModalResult modes;
  modal::ModalModel modal;
  struct {
    double meshing_s = 0, assembly_s = 0, modes_s = 0;
  } seconds;
};

// The design's damping: its own when given, else that of the material of region "body" (or of the
// only region), else none (ζ = 0; the caller should say so). Second: where it came from.
std::pair<RayleighDamping, std::string> design_damping(const Design& design,
                                                       const MaterialTable& materials);

// Regions get their materials by material_of_region (stylus_description.hpp). Throws what the
// stages throw (bad shape, no clamp, unknown material, an unnamed region when the design names
// several materials, tip or sensor outside the body, modal solver failure), each naming the design.
DesignModel build_design_model(const Design& design, const MaterialTable& materials);

}  // namespace nibrig::model::mechanics
