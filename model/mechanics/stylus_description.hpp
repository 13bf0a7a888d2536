// A stylus design as a designer writes it (design.json): the shape (the paper's bar, a parametric
// stylus, or a mesh file), a material per region, damping, and where the tip is driven and the
// sensor reads. Everything in SI units; every default is stated here.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <variant>

#include "model/mechanics/material_table.hpp"
#include "model/mechanics/mesh_import.hpp"
#include "model/mechanics/shape_builders.hpp"
#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

struct MeshFileShape {
  std::filesystem::path path;  // absolute, or relative to the design file when read from one
  double unit_scale = 0.001;  // metres per file unit: STL and STEP files are usually in millimetres
  // Nodes inside this box (metres) are clamped; when absent the file must carry a "clamp" group.
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> clamp_box;
};

using Shape = std::variant<BarGeometry, StylusGeometry, MeshFileShape>;

// A point on or in the body and a unit direction: the tip force's line of action, or the sensor's
// measuring axis.
struct Probe {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

struct Design {
  std::string name;
  Shape shape;
  std::map<std::string, std::string> region_materials;  // region name → material name
  // When absent, the damping of the material of region "body" (or the only region) is used.
  std::optional<RayleighDamping> damping;
  Probe tip, sensor;
  double mesh_size = 0.003;  // m
  int modes = 32;
};

// Defaults for the parametric shapes, stated once:
//  bar: tip = the middle of the free end, pushed along z (the preload of Sec. 5.1); sensor = top
//       face on the centre line 20 mm from the free end, axis z (the paper does not say where its
//       accelerometer sat: this is our assumption).
//  stylus: tip = the apex, force along y (the drag of the paper across the surface); sensor = the
//       body's surface 10 mm in front of the grip, axis y (the rig's accelerometer is on the tool,
//       just outside the holder: our assumption).
Probe default_tip(const BarGeometry& bar);
Probe default_sensor(const BarGeometry& bar);
Probe default_tip(const StylusGeometry& stylus);
Probe default_sensor(const StylusGeometry& stylus);

// An inline bar (no design file) as a whole design: the defaults above for tip and sensor, the
// one region "body" of `material`, 12 modes and bar_mesh_size. Named "bar <length in mm> mm".
// Throws what validate(bar) throws.
Design bar_design(const BarGeometry& bar, const std::string& material);

// Elements as thick as the bar: the first three bending frequencies are then within 0.1 % of the
// converged ones (demo: cantilever_convergence.csv) at a modest cost. No finer than a
// hundredth of the free length, so that a very thin bar does not mesh into millions of elements.
double bar_mesh_size(const BarGeometry& bar);

// Format "nibrig-design", version 1 (FORMATS.md, "Stylus design"). Checks that every material named
// exists in `materials` and that directions are non-zero (they are normalised). Throws
// io::FormatError naming the file and field.
Design read_design(const std::filesystem::path& file, const MaterialTable& materials);

// The design's mesh with its "clamp" node set (throws std::invalid_argument when the clamp is empty
// or a region has no material).
TetMesh mesh_design(const Design& design);

// The material of a mesh region: as the design names it, or, for a region the design does not
// name, the design's only material (a mesh file's regions are known only once it is meshed).
// Throws std::invalid_argument naming the design and region when the design names several.
const std::string& material_of_region(const Design& design, const std::string& region);

}  // namespace nibrig::model::mechanics
