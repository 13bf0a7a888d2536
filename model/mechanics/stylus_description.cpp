#include "model/mechanics/stylus_description.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"

namespace nibrig::model::mechanics {
namespace {

namespace jf = io::json_fields;
using nlohmann::json;

// Reads the optional members of one JSON object into fields, refusing keys it does not know (a
// misspelt "tip_diamter" must not silently fall back to the default).
class ObjectReader {
 public:
  ObjectReader(const json& object, const std::filesystem::path& file, std::string path)
      : object_(jf::as_object(object, file, path)), file_(file), path_(std::move(path)) {}

  void number(const std::string& key, double& field) {
    known_.insert(key);
    if (object_.contains(key)) field = jf::number_member(object_, key, file_, path_);
  }
  void boolean(const std::string& key, bool& field) {
    known_.insert(key);
    if (!object_.contains(key)) return;
    const json& value = object_.at(key);
    if (!value.is_boolean())
      throw io::FormatError(file_, jf::place(jf::member_path(path_, key)),
                            "expected true or false");
    field = value.get<bool>();
  }
  void vector3(const std::string& key, Eigen::Vector3d& field) {
    known_.insert(key);
    if (!object_.contains(key)) return;
    const std::string at = jf::member_path(path_, key);
    const auto values = jf::as_number_array(object_.at(key), file_, at);
    if (values.size() != 3)
      throw io::FormatError(file_, jf::place(at), "expected three numbers [x, y, z]");
    field = {values[0], values[1], values[2]};
  }
  void string(const std::string& key, std::string& field) {
    known_.insert(key);
    if (object_.contains(key)) field = jf::string_member(object_, key, file_, path_);
  }
  // A key read elsewhere (a nested object) that must not count as unknown.
  void nested(const std::string& key) { known_.insert(key); }

  void reject_unknown() const {
    for (const auto& [key, value] : object_.items()) {
      if (known_.count(key)) continue;
      std::string known;
      for (const auto& k : known_) known += (known.empty() ? "" : ", ") + k;
      throw io::FormatError(file_, jf::place(jf::member_path(path_, key)),
                            "unknown field (known here: " + known + ")");
    }
  }

 private:
  const json& object_;
  const std::filesystem::path& file_;
  std::string path_;
  std::set<std::string> known_;
};

BarGeometry read_bar(ObjectReader& r) {
  BarGeometry bar;
  r.number("length", bar.length);
  r.number("width", bar.width);
  r.number("thickness", bar.thickness);
  r.number("clamp_length", bar.clamp_length);
  r.number("end_radius", bar.end_radius);
  r.boolean("cutout", bar.cutout);
  r.number("cutout_radius", bar.cutout_radius);
  r.number("cutout_offset", bar.cutout_offset);
  return bar;
}

StylusGeometry read_stylus(ObjectReader& r) {
  StylusGeometry s;
  r.number("body_length", s.body_length);
  r.number("body_diameter", s.body_diameter);
  r.number("taper_length", s.taper_length);
  r.number("tip_diameter", s.tip_diameter);
  r.number("tip_insert_length", s.tip_insert_length);
  r.number("grip_length", s.grip_length);
  return s;
}

MeshFileShape read_file_shape(ObjectReader& r, const json& shape,
                              const std::filesystem::path& file) {
  MeshFileShape m;
  std::string path;
  r.string("path", path);
  if (path.empty())
    throw io::FormatError(file, jf::place("shape.path"), "expected the mesh file's path");
  m.path = std::filesystem::path(path).is_absolute() ? std::filesystem::path(path)
                                                     : file.parent_path() / path;
  r.number("unit_scale", m.unit_scale);
  if (!(m.unit_scale > 0))
    throw io::FormatError(file, jf::place("shape.unit_scale"), "expected metres per file unit > 0");
  r.nested("clamp_box");
  if (shape.contains("clamp_box")) {
    ObjectReader box(shape.at("clamp_box"), file, "shape.clamp_box");
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::nan("")), hi = lo;
    box.vector3("min", lo);
    box.vector3("max", hi);
    box.reject_unknown();
    if (!lo.allFinite() || !hi.allFinite() || (lo.array() > hi.array()).any())
      throw io::FormatError(file, jf::place("shape.clamp_box"),
                            "expected \"min\" and \"max\" corners with min <= max");
    m.clamp_box = std::make_pair(lo, hi);
  }
  return m;
}

Probe read_probe(const json& root, const std::string& key, const std::string& direction_key,
                 Probe probe, const std::filesystem::path& file) {
  if (!root.contains(key)) return probe;
  ObjectReader r(root.at(key), file, key);
  r.vector3("point", probe.point);
  r.vector3(direction_key, probe.direction);
  r.reject_unknown();
  if (!(probe.direction.norm() > 0))
    throw io::FormatError(file, jf::place(key + "." + direction_key),
                          "expected a non-zero direction");
  probe.direction.normalize();
  return probe;
}

}  // namespace

Probe default_tip(const BarGeometry& bar) {
  return {{bar.free_length(), 0, 0}, Eigen::Vector3d::UnitZ()};
}
Probe default_sensor(const BarGeometry& bar) {
  return {{bar.free_length() - 0.020, 0, bar.thickness / 2}, Eigen::Vector3d::UnitZ()};
}
Design bar_design(const BarGeometry& bar, const std::string& material) {
  validate(bar);
  Design design;
  design.name = "bar " + std::to_string(bar.length * 1e3).substr(0, 5) + " mm";
  design.shape = bar;
  design.tip = default_tip(bar);
  design.sensor = default_sensor(bar);
  design.mesh_size = bar_mesh_size(bar);
  design.modes = 12;
  design.region_materials["body"] = material;
  return design;
}

double bar_mesh_size(const BarGeometry& bar) {
  return std::max(bar.thickness, bar.free_length() / 100);
}

Probe default_tip(const StylusGeometry& s) { return {s.apex(), Eigen::Vector3d::UnitY()}; }
Probe default_sensor(const StylusGeometry& s) {
  return {{s.grip_length + 0.010, s.body_diameter / 2, 0}, Eigen::Vector3d::UnitY()};
}

Design read_design(const std::filesystem::path& file, const MaterialTable& materials) {
  const json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, "nibrig-design", 1);
  Design design;
  design.name =
      root.contains("name") ? jf::string_member(root, "name", file, "") : file.stem().string();

  const json& shape = jf::member(root, "shape", file, "");
  ObjectReader shape_reader(shape, file, "shape");
  std::string kind;
  shape_reader.string("kind", kind);
  Probe tip, sensor;
  try {
    if (kind == "bar") {
      const BarGeometry bar = read_bar(shape_reader);
      validate(bar);
      design.shape = bar;
      tip = default_tip(bar), sensor = default_sensor(bar);
    } else if (kind == "stylus") {
      const StylusGeometry stylus = read_stylus(shape_reader);
      validate(stylus);
      design.shape = stylus;
      tip = default_tip(stylus), sensor = default_sensor(stylus);
    } else if (kind == "file") {
      design.shape = read_file_shape(shape_reader, shape, file);
      if (!root.contains("tip") || !root.contains("sensor"))
        throw io::FormatError(file, jf::place(root.contains("tip") ? "sensor" : "tip"),
                              "a design from a mesh file must say where its tip and sensor are");
    } else {
      throw io::FormatError(file, jf::place("shape.kind"),
                            "expected \"bar\", \"stylus\" or \"file\", got \"" + kind + "\"");
    }
  } catch (const std::invalid_argument& e) {  // an impossible shape: say which field of the file
    throw io::FormatError(file, jf::place("shape"), e.what());
  }
  shape_reader.reject_unknown();

  const json& region_materials =
      jf::as_object(jf::member(root, "materials", file, ""), file, "materials");
  for (const auto& [region, material] : region_materials.items()) {
    const std::string at = jf::member_path("materials", region);
    const std::string name = jf::as_string(material, file, at);
    try {
      materials.find(name);
    } catch (const std::invalid_argument& e) {
      throw io::FormatError(file, jf::place(at), e.what());
    }
    design.region_materials[region] = name;
  }
  if (design.region_materials.empty())
    throw io::FormatError(file, jf::place("materials"), "expected at least one region");

  if (root.contains("damping")) {
    ObjectReader r(root.at("damping"), file, "damping");
    RayleighDamping d;
    r.number("rayleigh_mass", d.mass);
    r.number("rayleigh_stiffness", d.stiffness);
    r.reject_unknown();
    if (d.mass < 0 || d.stiffness < 0)
      throw io::FormatError(file, jf::place("damping"),
                            "Rayleigh coefficients must not be negative");
    design.damping = d;
  }
  design.tip = read_probe(root, "tip", "direction", tip, file);
  design.sensor = read_probe(root, "sensor", "axis", sensor, file);
  if (root.contains("mesh_size")) {
    design.mesh_size = jf::number_member(root, "mesh_size", file, "");
  }
  try {
    std::visit(
        [&](const auto& shape) {
          if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, MeshFileShape>)
            validate_mesh_size(design.mesh_size);
          else
            validate_mesh_size(shape, design.mesh_size);
        },
        design.shape);
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, jf::place("mesh_size"), e.what());
  }
  if (root.contains("modes"))
    design.modes = static_cast<int>(jf::as_integer(root.at("modes"), file, "modes", 1, 1000));

  std::set<std::string> known{"format", "version", "name",      "shape", "materials", "damping",
                              "tip",    "sensor",  "mesh_size", "modes", "comment"};
  for (const auto& [key, value] : root.items())
    if (!known.count(key)) throw io::FormatError(file, jf::place(key), "unknown field");
  return design;
}

TetMesh mesh_design(const Design& design) {
  TetMesh mesh = std::visit(
      [&](const auto& shape) -> TetMesh {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, BarGeometry>) {
          return mesh_bar(shape, design.mesh_size);
        } else if constexpr (std::is_same_v<T, StylusGeometry>) {
          return mesh_stylus(shape, design.mesh_size);
        } else {
          TetMesh imported = import_mesh_file(shape.path, {shape.unit_scale, design.mesh_size});
          if (shape.clamp_box)
            imported.node_sets["clamp"] =
                nodes_in_box(imported, shape.clamp_box->first, shape.clamp_box->second);
          return imported;
        }
      },
      design.shape);
  const auto clamp = mesh.node_sets.find("clamp");
  if (clamp == mesh.node_sets.end() || clamp->second.empty())
    throw std::invalid_argument(
        "design '" + design.name +
        "': the mesh has no clamped region (no node in the clamp box or \"clamp\" group); "
        "an unclamped stylus would float freely");
  for (const auto& region : mesh.region_names) material_of_region(design, region);
  return mesh;
}

const std::string& material_of_region(const Design& design, const std::string& region) {
  const auto it = design.region_materials.find(region);
  if (it != design.region_materials.end()) return it->second;
  if (design.region_materials.size() == 1) return design.region_materials.begin()->second;
  throw std::invalid_argument("design '" + design.name + "': mesh region '" + region +
                              "' has no material, and the design names more than one");
}

}  // namespace nibrig::model::mechanics
