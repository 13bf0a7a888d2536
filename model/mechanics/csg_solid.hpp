// A solid made of boxes and cylinders, added then cut away (constructive solid geometry), turned
// into the closed, outward-wound surface a printer takes by Gmsh's OpenCASCADE kernel: the
// printable parts of the rig are such solids, as the stylus is a parametric shape. Metres.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/io/surface_mesh.hpp"

namespace nibrig::model::mechanics {

struct CsgBox {
  Eigen::Vector3d lo, hi;  // opposite corners, lo < hi on every axis
};

struct CsgCylinder {
  Eigen::Vector3d base;  // centre of one end face
  Eigen::Vector3d axis;  // from that end to the other: direction and length
  double radius = 0.0;
};

// The solid is the union of `boxes` and `cylinders` less the union of `box_cuts` and
// `cylinder_cuts`: it must come out as one piece.
struct CsgSolid {
  std::vector<CsgBox> boxes;
  std::vector<CsgCylinder> cylinders;
  std::vector<CsgBox> box_cuts;
  std::vector<CsgCylinder> cylinder_cuts;
};

struct CsgMeshing {
  // The longest triangle edge on flat faces: a flat face's triangles cost a file and nothing else.
  double max_edge = 4e-3;
  // Facets around a full circle. A hole's polygon lies inside its circle, so a printed hole comes
  // out smaller by the sagitta r·(1 − cos(π/n)): at 64, 0.12 % of its radius (11 µm on a 19 mm
  // bearing seat), under a tenth of the 0.2 mm an FDM printer's own error takes off a hole.
  int segments_per_circle = 64;
};

// Throws std::invalid_argument naming `name` and the primitive (its list and index) for a box
// with lo ≥ hi on an axis, a cylinder with no length or radius, or a solid with nothing added.
void validate(const CsgSolid& solid, const std::string& name);

// The solid's boundary, named `name`, as Gmsh meshes its faces: every edge shared by exactly two
// triangles (checked), wound counter-clockwise seen from outside.
// Throws std::runtime_error naming `name` when OpenCASCADE does not make one solid of it or Gmsh
// cannot mesh it.
io::SurfaceMesh csg_surface(const CsgSolid& solid, const std::string& name,
                            const CsgMeshing& meshing = {});

}  // namespace nibrig::model::mechanics
