// Meshes for the mechanics tests, generated with Gmsh: a box (bars, cantilevers, patches) and a
// round rod with a hemispherical end (curved isoparametric elements). Both have the node set
// "clamp" on their face x = 0.
#pragma once

#include <Eigen/Core>

#include "model/mechanics/tet_mesh.hpp"

namespace nibrig::model::mechanics::test {

// The box [0, size.x] × [0, size.y] × [0, size.z] (m), elements of at most mesh_size (m).
TetMesh box_mesh(const Eigen::Vector3d& size, double mesh_size);

// A cylinder of the given radius along x from 0 to `length`, closed at x = length by a hemisphere
// (total length length + radius), elements of at most mesh_size (m).
TetMesh rod_mesh(double radius, double length, double mesh_size);

}  // namespace nibrig::model::mechanics::test
