#include "model/mechanics/shape_builders.hpp"

#include <gmsh.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "model/mechanics/gmsh_session.hpp"

namespace nibrig::model::mechanics {
namespace {

constexpr double kNodeTolerance = 1e-9;  // m: far below any element, far above rounding

void require(bool ok, const std::string& shape, const std::string& field, const std::string& why) {
  if (!ok) throw std::invalid_argument(shape + " " + field + ": " + why);
}

// Every length of a shape lies between these: a printer resolves no finer than about 16 µm, and
// no stylus or test bar is a metre long (the CLI's --bar has the same bound). Beyond them Gmsh's
// geometry kernel throws or runs for minutes.
constexpr double kShortestLength = 1e-5;  // m
constexpr double kLongestLength = 1.0;    // m

void require_positive(double value, const std::string& shape, const std::string& field) {
  std::ostringstream got;
  got << "must be a length between " << kShortestLength << " and " << kLongestLength
      << " m, got " << value;
  require(std::isfinite(value) && value >= kShortestLength && value <= kLongestLength, shape,
          field, got.str());
}

// What a solve's peak memory was measured at (`nibrig predict` on the bundled stylus at 1 mm:
// about 81,600 elements by the estimate below, 2.31 GB peak; at 1.5 and 3 mm 0.57 and 0.14 GB).
constexpr double kMeasuredElements = 81600;
constexpr double kMeasuredPeakBytes = 2.22e9;  // above the process's own 0.09 GB
constexpr double kProcessBytes = 0.09e9;

// About six tetrahedra fill an element-sized cube of the shape's bounding box (m^3).
double elements_estimate(double box_volume, double mesh_size) {
  return 6 * box_volume / (mesh_size * mesh_size * mesh_size);
}

// The mesh is bounded by what the FEM solves in the memory it may use: a finer mesh was refused
// only past two million elements, which needs some 150 GB; one at 0.35 mm ran for minutes at 4 GB
// and more before it could fail.
void require_mesh_size(double mesh_size, double box_volume, const std::string& shape, double memory_bytes) {
  std::ostringstream why;
  if (!(std::isfinite(mesh_size) && mesh_size >= kShortestLength && mesh_size <= kLongestLength)) {
    why << "mesh size must be a length between " << kShortestLength << " and " << kLongestLength
        << " m, got " << mesh_size;
    throw std::invalid_argument(why.str());
  }
  const double elements = elements_estimate(box_volume, mesh_size);
  const double needed = fem_peak_bytes(elements);
  if (needed > memory_bytes) {
    const double most = kMeasuredElements *
                        std::pow(std::max(memory_bytes - kProcessBytes, 0.0) / kMeasuredPeakBytes, 0.75);
    why.precision(3);
    why << "mesh size " << mesh_size << " m would cut the " << shape << " into about " << elements
        << " elements, whose solve needs about " << needed / 1e9 << " GB, more than the "
        << memory_bytes / 1e9 << " GB it may use (half this machine's memory); choose at least "
        << std::cbrt(6 * box_volume / most) << " m";
    throw std::invalid_argument(why.str());
  }
}

int single_volume(const gmsh::vectorpair& out, const std::string& what) {
  std::vector<int> volumes;
  for (const auto& [dim, tag] : out)
    if (dim == 3) volumes.push_back(tag);
  if (volumes.size() != 1)
    throw std::runtime_error(what + ": expected one solid, OpenCASCADE made " +
                             std::to_string(volumes.size()));
  return volumes.front();
}

int fuse_volumes(int a, int b) {
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::fuse({{3, a}}, {{3, b}}, out, map);
  return single_volume(out, "fusing the stylus parts");
}

// Splits `volume` by the planes x = cuts[i] (ascending) into pieces that share conforming faces.
std::vector<int> split_along_x(int volume, const std::vector<double>& cuts, double extent) {
  std::vector<int> pieces;
  int rest = volume;
  for (double x : cuts) {
    gmsh::vectorpair copy, back, front;
    std::vector<gmsh::vectorpair> map;
    gmsh::model::occ::copy({{3, rest}}, copy);
    const int below =
        gmsh::model::occ::addBox(-extent, -extent, -extent, x + extent, 2 * extent, 2 * extent);
    const int below_copy =
        gmsh::model::occ::addBox(-extent, -extent, -extent, x + extent, 2 * extent, 2 * extent);
    gmsh::model::occ::intersect(copy, {{3, below}}, back, map);
    gmsh::model::occ::cut({{3, rest}}, {{3, below_copy}}, front, map);
    pieces.push_back(single_volume(back, "cutting the stylus"));
    rest = single_volume(front, "cutting the stylus");
  }
  pieces.push_back(rest);
  if (pieces.size() > 1) {
    gmsh::vectorpair objects, tools, out;
    std::vector<gmsh::vectorpair> map;
    objects.push_back({3, pieces.front()});
    for (std::size_t i = 1; i < pieces.size(); ++i) tools.push_back({3, pieces[i]});
    gmsh::model::occ::fragment(objects, tools, out, map);
    pieces.clear();
    for (const auto& m : map) pieces.push_back(single_volume(m, "joining the stylus pieces"));
  }
  return pieces;
}

void name_region(const std::string& name, const std::vector<int>& volumes) {
  if (volumes.empty()) return;
  const int group = gmsh::model::addPhysicalGroup(3, volumes);
  gmsh::model::setPhysicalName(3, group, name);
}

}  // namespace

double fem_peak_bytes(double elements) {
  // Above some 20,000 elements the measured peaks grow as elements^(4/3), the fill of a sparse
  // factorisation of a 3-D mesh ordered by nested dissection.
  return kProcessBytes + kMeasuredPeakBytes * std::pow(elements / kMeasuredElements, 4.0 / 3.0);
}

double fem_memory_budget_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? 0.5 * static_cast<double>(pages) * static_cast<double>(page) : 4e9;
}

void validate_mesh_size(double mesh_size) {
  require_mesh_size(mesh_size, 0.0, "shape", fem_memory_budget_bytes());
}
void validate_mesh_size(const BarGeometry& bar, double mesh_size, double memory_bytes) {
  require_mesh_size(mesh_size, bar.length * bar.width * bar.thickness, "bar", memory_bytes);
}
void validate_mesh_size(const StylusGeometry& s, double mesh_size, double memory_bytes) {
  require_mesh_size(mesh_size, s.overall_length() * s.body_diameter * s.body_diameter, "stylus", memory_bytes);
}

void validate(const BarGeometry& bar) {
  const std::string shape = "bar";
  require_positive(bar.length, shape, "length");
  require_positive(bar.width, shape, "width");
  require_positive(bar.thickness, shape, "thickness");
  require(std::isfinite(bar.clamp_length) && bar.clamp_length >= 0, shape, "clamp length",
          "must be zero or a positive length in metres");
  require(bar.free_length() > 0, shape, "clamp length", "must be shorter than the bar");
  require(std::isfinite(bar.end_radius) && bar.end_radius >= 0 &&
              bar.end_radius <= bar.width / 2 + kNodeTolerance,
          shape, "end radius", "must lie between 0 and half the width");
  require(bar.end_radius <= bar.free_length(), shape, "end radius",
          "must not exceed the free length");
  if (bar.cutout) {
    require_positive(bar.cutout_radius, shape, "cutout radius");
    require_positive(bar.cutout_offset, shape, "cutout offset");
    require(bar.cutout_radius < bar.width / 2, shape, "cutout radius",
            "must leave material on both sides");
    require(bar.cutout_offset + bar.cutout_radius < bar.free_length(), shape, "cutout",
            "must lie within the free part of the bar");
    require(bar.cutout_offset > bar.cutout_radius, shape, "cutout",
            "must not cut through the free end");
  }
}

namespace {

TetMesh mesh_valid_bar(const BarGeometry& bar, double mesh_size) {
  const double L = bar.free_length(), w = bar.width, t = bar.thickness, r = bar.end_radius;
  GmshSession session("bar");
  namespace occ = gmsh::model::occ;
  const bool semicircle = r >= w / 2 - kNodeTolerance;
  int volume = occ::addBox(0, -w / 2, -t / 2, semicircle ? L - w / 2 : L, w, t);
  if (semicircle) {
    volume = fuse_volumes(volume, occ::addCylinder(L - w / 2, 0, -t / 2, 0, 0, t, w / 2));
  } else if (r > 0) {
    // Asked of the OpenCASCADE kernel directly: a second synchronize of the model would make
    // Gmsh 4.8 drop (and leak) the entities of the first.
    gmsh::vectorpair end_edges;  // the two edges along z at the free end's corners
    occ::getEntitiesInBoundingBox(L - 1e-7, -w, -t, L + 1e-7, w, t, end_edges, 1);
    std::vector<int> corner_edges;
    for (const auto& [dim, tag] : end_edges) {
      double xmin, ymin, zmin, xmax, ymax, zmax;
      occ::getBoundingBox(dim, tag, xmin, ymin, zmin, xmax, ymax, zmax);
      if (zmax - zmin > t / 2) corner_edges.push_back(tag);
    }
    gmsh::vectorpair out;
    occ::fillet({volume}, corner_edges, {r}, out);
    volume = single_volume(out, "rounding the bar's end");
  }
  if (bar.cutout) {
    gmsh::vectorpair out;
    std::vector<gmsh::vectorpair> map;
    occ::cut({{3, volume}},
             {{3, occ::addCylinder(L - bar.cutout_offset, 0, -t, 0, 0, 2 * t, bar.cutout_radius)}},
             out, map);
    volume = single_volume(out, "cutting the bar's hole");
  }
  occ::synchronize();
  name_region("body", {volume});
  // Through the thickness a 2 mm bar needs at least two quadratic elements to bend accurately;
  // the caller's size governs the rest.
  generate_quadratic_tets(mesh_size, std::min(mesh_size, t) / 4);
  session.throw_if_failed("meshing the bar");
  TetMesh mesh = tet_mesh_from_gmsh("body");
  mesh.node_sets["clamp"] = nodes_in_box(mesh, {-1, -1, -1}, {0, 1, 1});
  return mesh;
}

}  // namespace

TetMesh mesh_bar(const BarGeometry& bar, double mesh_size) {
  validate(bar);
  validate_mesh_size(bar, mesh_size);
  return guard_gmsh("meshing the bar", [&] { return mesh_valid_bar(bar, mesh_size); });
}


void validate(const StylusGeometry& s) {
  const std::string shape = "stylus";
  require_positive(s.body_length, shape, "body length");
  require_positive(s.body_diameter, shape, "body diameter");
  require_positive(s.tip_diameter, shape, "tip diameter");
  require(std::isfinite(s.taper_length) && s.taper_length >= 0, shape, "taper length",
          "must be zero or a positive length in metres");
  require(s.tip_diameter <= s.body_diameter, shape, "tip diameter",
          "must not exceed the body diameter");
  require(s.taper_length > 0 || s.tip_diameter == s.body_diameter, shape, "taper length",
          "must be positive when the tip is narrower than the body");
  require_positive(s.grip_length, shape, "grip length");
  require(s.grip_length < s.body_length, shape, "grip length", "must be shorter than the body");
  require(std::isfinite(s.tip_insert_length) && s.tip_insert_length >= 0, shape,
          "tip insert length", "must be zero or a positive length in metres");
  require(s.overall_length() - s.tip_insert_length > s.grip_length, shape, "tip insert length",
          "must end before the grip");
}

namespace {

TetMesh mesh_valid_stylus(const StylusGeometry& s, double mesh_size) {
  GmshSession session("stylus");
  namespace occ = gmsh::model::occ;
  const double R = s.body_diameter / 2, r = s.tip_diameter / 2;
  const double tip_centre = s.body_length + s.taper_length;
  int volume = occ::addCylinder(0, 0, 0, s.body_length, 0, 0, R);
  if (s.taper_length > 0)
    volume = fuse_volumes(volume, occ::addCone(s.body_length, 0, 0, s.taper_length, 0, 0, R, r));
  volume = fuse_volumes(volume, occ::addSphere(tip_centre, 0, 0, r));

  std::vector<double> cuts{s.grip_length};
  if (s.tip_insert_length > 0) cuts.push_back(s.overall_length() - s.tip_insert_length);
  const std::vector<int> pieces = split_along_x(volume, cuts, 2 * s.overall_length());
  occ::synchronize();
  const bool has_tip = s.tip_insert_length > 0;
  std::vector<int> body(pieces.begin(), has_tip ? pieces.end() - 1 : pieces.end());
  name_region("body", body);
  if (has_tip) name_region("tip", {pieces.back()});

  generate_quadratic_tets(mesh_size, std::min(mesh_size, s.tip_diameter) / 6);
  session.throw_if_failed("meshing the stylus");
  TetMesh mesh = tet_mesh_from_gmsh("body");
  mesh.node_sets["clamp"] = nodes_in_box(mesh, {-1, -1, -1}, {s.grip_length, 1, 1});
  return mesh;
}

}  // namespace

TetMesh mesh_stylus(const StylusGeometry& s, double mesh_size) {
  validate(s);
  validate_mesh_size(s, mesh_size);
  return guard_gmsh("meshing the stylus", [&] { return mesh_valid_stylus(s, mesh_size); });
}


std::vector<int> nodes_in_box(const TetMesh& mesh, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi) {
  std::vector<int> inside;
  for (Eigen::Index i = 0; i < mesh.nodes.cols(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.col(i);
    if ((p.array() >= lo.array() - kNodeTolerance).all() &&
        (p.array() <= hi.array() + kNodeTolerance).all())
      inside.push_back(static_cast<int>(i));
  }
  return inside;
}

}  // namespace nibrig::model::mechanics
