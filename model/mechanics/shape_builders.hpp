// Parametric shapes meshed with Gmsh's OpenCASCADE kernel: the paper's validation bar (Sec. 5.1)
// and a stylus (cylindrical body, conical taper, hemispherical tip, optionally a tip of a second
// material). Each returns quadratic tetrahedra with material regions and the clamped node set.
#pragma once

#include <Eigen/Core>

#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics {

// The bar lies along +x from the clamp edge (x = 0) to its free end; y spans the width and z the
// thickness, both centred. Only the free part is meshed: a clamped section is held rigidly, so its
// material has no effect and the clamp is the face x = 0 (node set "clamp"). Region "body".
struct BarGeometry {
  double length = 0.210;  // whole bar, including the clamped section
  double width = 0.020;
  double thickness = 0.002;
  double clamp_length = 0.030;  // clamped over this much from the fixed end
  double end_radius =
      0.010;  // rounding of the free end's corners; width/2 is a semicircle, 0 square
  bool cutout = true;
  double cutout_radius = 0.005;
  double cutout_offset = 0.010;  // distance of the cutout's centre from the free end

  double free_length() const { return length - clamp_length; }
};

// Default: the paper's VeroClear bar (210 × 20 × 2 mm, rounded end R10, cutout R5 10 mm from the
// end, clamped over 30 mm). Throws std::invalid_argument naming the field that makes the shape
// impossible.
void validate(const BarGeometry& bar);
TetMesh mesh_bar(const BarGeometry& bar, double mesh_size);

// The stylus lies along +x from its back end (x = 0) to the tip's apex at x = overall_length().
// Regions: "body", and "tip" for the part within tip_insert_length of the apex when that is > 0.
// The holder clamps the back over grip_length (node set "clamp": every node with x ≤ grip_length).
struct StylusGeometry {
  double body_length = 0.120;  // cylindrical part
  double body_diameter = 0.010;
  double taper_length = 0.015;  // cone from the body's diameter down to the tip's
  double tip_diameter = 0.002;  // hemispherical tip
  double tip_insert_length = 0.0;
  double grip_length = 0.030;

  double overall_length() const { return body_length + taper_length + tip_diameter / 2; }
  Eigen::Vector3d apex() const { return {overall_length(), 0.0, 0.0}; }
};

void validate(const StylusGeometry& stylus);
TetMesh mesh_stylus(const StylusGeometry& stylus, double mesh_size);

// The peak memory (bytes) of meshing and solving a shape cut into about `elements` tetrahedra, as
// measured for `nibrig predict`.
double fem_peak_bytes(double elements);
// What a solve may use: half this machine's physical memory.
double fem_memory_budget_bytes();

// Throws std::invalid_argument when `mesh_size` is not a length in [1e-5, 1] m, or would cut the
// shape so fine that its solve needs more than `memory_bytes` (the message gives the finest mesh
// size that fits).
void validate_mesh_size(double mesh_size);  // a shape not known yet: the bounds alone
void validate_mesh_size(const BarGeometry& bar, double mesh_size,
                        double memory_bytes = fem_memory_budget_bytes());
void validate_mesh_size(const StylusGeometry& stylus, double mesh_size,
                        double memory_bytes = fem_memory_budget_bytes());

// Every node inside the axis-aligned box [lo, hi] (inclusive, with a tolerance of 1e-9 m), sorted.
std::vector<int> nodes_in_box(const TetMesh& mesh, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi);

}  // namespace nibrig::model::mechanics
