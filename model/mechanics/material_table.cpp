#include "model/mechanics/material_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/mechanics/lab_materials.hpp"

namespace nibrig::model::mechanics {
namespace {

namespace jf = io::json_fields;

bool same_name(const std::string& a, const std::string& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](unsigned char x, unsigned char y) {
    return std::tolower(x) == std::tolower(y);
  });
}

std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

MaterialTable::MaterialTable(std::vector<Material> materials) : materials_(std::move(materials)) {
  for (std::size_t i = 0; i < materials_.size(); ++i) {
    validate(materials_[i]);
    for (std::size_t j = 0; j < i; ++j)
      if (same_name(materials_[i].name, materials_[j].name))
        throw std::invalid_argument("material '" + materials_[i].name + "' is defined twice");
  }
}

const Material& MaterialTable::find(const std::string& name) const {
  for (const auto& m : materials_)
    if (same_name(m.name, name)) return m;
  std::string known;
  for (const auto& m : materials_) known += (known.empty() ? "" : ", ") + m.name;
  std::string places;
  for (const auto& p : looked_in_) places += (places.empty() ? "; looked in " : " and ") + p;
  throw std::invalid_argument("unknown material '" + name + "' (known: " + known + places + ")");
}

bool is_material_basis(const std::string& basis) {
  return basis == "fitted" || basis == "datasheet" || basis == "estimate";
}

std::string least_calibrated(const std::string& a, const std::string& b) {
  const auto rank = [](const std::string& basis) {
    return basis == "fitted" ? 3 : basis == "datasheet" ? 2 : basis == "estimate" ? 1 : 0;
  };
  return rank(b) < rank(a) ? b : a;
}

std::string describe_basis(const std::string& basis) {
  if (basis == "fitted") return "fitted to prints";
  if (basis == "datasheet") return "datasheet values, not calibrated";
  if (basis == "estimate") return "an estimate, not calibrated";
  return "basis not stated";
}

std::string describe_basis(const Material& material) { return describe_basis(material.basis); }

IsotropicMaterial elastic_part(const Material& m) {
  return {m.name, m.youngs_modulus, m.poisson_ratio, m.density};
}

void validate(const Material& m) {
  const std::string who = "material '" + m.name + "': ";
  if (m.name.empty()) throw std::invalid_argument("a material has no name");
  validate(elastic_part(m));
  if (!m.basis.empty() && !is_material_basis(m.basis))
    throw std::invalid_argument(who + "basis '" + m.basis + "' is not fitted, datasheet or estimate");
  if (m.damping) {
    if (!(std::isfinite(m.damping->mass) && m.damping->mass >= 0))
      throw std::invalid_argument(who + "Rayleigh mass coefficient must be zero or positive, got " +
                                  number_text(m.damping->mass) + " 1/s");
    if (!(std::isfinite(m.damping->stiffness) && m.damping->stiffness >= 0))
      throw std::invalid_argument(who +
                                  "Rayleigh stiffness coefficient must be zero or positive, got " +
                                  number_text(m.damping->stiffness) + " s");
  }
}

MaterialTable read_material_file(const std::filesystem::path& file) {
  return material_table_from_json(jf::parse_file(file), file);
}

MaterialTable material_table_from_json(const nlohmann::json& root,
                                       const std::filesystem::path& file) {
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, "nibrig-materials", 1);
  const auto& list = jf::as_array(jf::member(root, "materials", file, ""), file, "materials");
  std::vector<Material> materials;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = jf::element_path("materials", i);
    const auto& entry = jf::as_object(list[i], file, path);
    Material m;
    m.name = jf::string_member(entry, "name", file, path);
    m.youngs_modulus = jf::number_member(entry, "youngs_modulus", file, path);
    m.poisson_ratio = jf::number_member(entry, "poisson_ratio", file, path);
    m.density = jf::number_member(entry, "density", file, path);
    if (entry.contains("rayleigh_mass") || entry.contains("rayleigh_stiffness")) {
      RayleighDamping d;
      if (entry.contains("rayleigh_mass"))
        d.mass = jf::number_member(entry, "rayleigh_mass", file, path);
      if (entry.contains("rayleigh_stiffness"))
        d.stiffness = jf::number_member(entry, "rayleigh_stiffness", file, path);
      m.damping = d;
    }
    if (entry.contains("basis")) m.basis = jf::string_member(entry, "basis", file, path);
    m.source = jf::string_member(entry, "source", file, path);
    try {
      validate(m);
    } catch (const std::invalid_argument& e) {
      throw io::FormatError(file, jf::place(path), e.what());
    }
    materials.push_back(std::move(m));
  }
  try {
    MaterialTable table(std::move(materials));
    table.set_looked_in({file.string()});
    return table;
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, jf::place("materials"), e.what());
  }
}

MaterialTable read_material_table(const std::filesystem::path& file) {
  return with_lab_materials(read_material_file(file));
}

}  // namespace nibrig::model::mechanics
