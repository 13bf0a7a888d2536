// The regions' surfaces of a two-material stylus as the FEM meshed it: closed, wound outward, the
// interface shared, and enclosing what the geometry says.
#include "model/mechanics/region_surface.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "model/mechanics/shape_builders.hpp"
#include "tests/model/mechanics/mesh_volume.hpp"

namespace nibrig::model::mechanics {
namespace {

using std::numbers::pi;

StylusGeometry two_material_stylus() {
  StylusGeometry g;
  g.tip_diameter = 0.0027;
  g.tip_insert_length = 0.006;
  return g;
}

using testing::corner_volume;

class RegionSurface : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mesh_ = new TetMesh(mesh_stylus(two_material_stylus(), 0.003));
    surfaces_ = new std::vector<io::SurfaceMesh>(region_surfaces(*mesh_));
  }
  static void TearDownTestSuite() {
    delete surfaces_;
    delete mesh_;
  }
  static TetMesh* mesh_;
  static std::vector<io::SurfaceMesh>* surfaces_;
};
TetMesh* RegionSurface::mesh_ = nullptr;
std::vector<io::SurfaceMesh>* RegionSurface::surfaces_ = nullptr;

TEST_F(RegionSurface, EachRegionIsClosedAndEveryEdgeRunsBothWays) {
  ASSERT_EQ(surfaces_->size(), mesh_->region_names.size());
  for (std::size_t r = 0; r < surfaces_->size(); ++r) {
    const auto& s = (*surfaces_)[r];
    EXPECT_EQ(s.name, mesh_->region_names[r]);
    // Closed and consistently wound: every directed edge once, and its reverse once.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : s.triangles)
      for (int k = 0; k < 3; ++k) ++directed[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
    for (const auto& [edge, uses] : directed) {
      ASSERT_EQ(uses, 1) << s.name << " edge " << edge.first << "-" << edge.second;
      ASSERT_EQ(directed.count({edge.second, edge.first}), 1u) << s.name << " open at " << edge.first;
    }
    EXPECT_GT(enclosed_volume(s), 0.0) << s.name << " is wound inward";
  }
}

// Between two bounds that need no tolerance: the surface passes through the corner and edge nodes
// on the curved boundary, so it encloses at least the corner-node polyhedron, and, inscribed in a
// convex shape, at most the shape itself (cylinder, cone and hemisphere of the geometry).
TEST_F(RegionSurface, TheVolumeLiesBetweenTheCornerPolyhedronAndTheTrueShape) {
  const auto g = two_material_stylus();
  const double r_body = g.body_diameter / 2, r_tip = g.tip_diameter / 2;
  const double exact = pi * r_body * r_body * g.body_length +
                       pi * g.taper_length / 3 * (r_body * r_body + r_body * r_tip + r_tip * r_tip) +
                       2.0 / 3.0 * pi * r_tip * r_tip * r_tip;
  double total = 0;
  for (std::size_t r = 0; r < surfaces_->size(); ++r) {
    const double v = enclosed_volume((*surfaces_)[r]);
    EXPECT_GE(v, corner_volume(*mesh_, static_cast<int>(r))) << (*surfaces_)[r].name;
    total += v;
  }
  EXPECT_LE(total, exact);
  EXPECT_GT(total, 0.97 * exact);  // the cylinder's own facets cut under 3 % at 8 elements a circle
}

// Body and tip meet face to face: every triangle of the tip's surface on the cut plane is one of
// the body's, wound the other way.
TEST_F(RegionSurface, BodyAndTipShareTheirInterfaceWithOppositeWinding) {
  ASSERT_EQ(surfaces_->size(), 2u);
  using Corner = std::array<double, 3>;
  std::set<std::array<Corner, 3>> body_triangles;
  const auto& body = (*surfaces_)[mesh_->region_names[0] == "body" ? 0 : 1];
  const auto& tip = (*surfaces_)[mesh_->region_names[0] == "body" ? 1 : 0];
  for (const auto& t : body.triangles) body_triangles.insert({body.vertices[t[0]], body.vertices[t[1]], body.vertices[t[2]]});
  std::size_t shared = 0;
  for (const auto& t : tip.triangles) {
    const Corner a = tip.vertices[t[0]], b = tip.vertices[t[1]], c = tip.vertices[t[2]];
    const bool reversed = body_triangles.count({a, c, b}) + body_triangles.count({c, b, a}) + body_triangles.count({b, a, c});
    const bool same = body_triangles.count({a, b, c}) + body_triangles.count({b, c, a}) + body_triangles.count({c, a, b});
    EXPECT_FALSE(same) << "a shared triangle wound the same way in both regions";
    shared += reversed ? 1 : 0;
  }
  EXPECT_GT(shared, 0u);
  // The interface is the cut plane, 6 mm back from the apex.
  const double cut = two_material_stylus().overall_length() - 0.006;
  std::size_t on_cut = 0;
  for (const auto& v : tip.vertices) on_cut += std::abs(v[0] - cut) < 1e-9 ? 1 : 0;
  EXPECT_GT(on_cut, 3u);
}

TEST(RegionSurfaceRefusal, AMeshWithoutTetrahedraIsRefused) {
  EXPECT_THROW(region_surfaces(TetMesh{}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::mechanics
