#include "model/mechanics/mode_report.hpp"

#include <cmath>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/mechanics/beam_theory.hpp"
#include "model/mechanics/mode_direction.hpp"
#include "model/modal/frequency_response.hpp"

namespace nibrig::model::mechanics {

const Material& body_material(const DesignModel& m) {
  for (std::size_t r = 0; r < m.mesh.region_names.size(); ++r)
    if (m.mesh.region_names[r] == "body") return m.region_materials[r];
  return m.region_materials.front();
}

nlohmann::json material_json(const Material& m) {
  return {{"name", m.name},
          {"youngs_modulus", m.youngs_modulus},
          {"poisson_ratio", m.poisson_ratio},
          {"density", m.density},
          {"source", m.source}};
}

nlohmann::json mode_report_json(const DesignModel& m) {
  nlohmann::json j;
  j["design"] = m.design.name;
  j["material"] = material_json(body_material(m));
  nlohmann::json regions = nlohmann::json::object();
  for (std::size_t r = 0; r < m.mesh.region_names.size(); ++r)
    regions[m.mesh.region_names[r]] = material_json(m.region_materials[r]);
  j["regions"] = regions;
  j["damping"] = {{"rayleigh_mass", m.damping.mass},
                  {"rayleigh_stiffness", m.damping.stiffness},
                  {"source", m.damping_source}};
  if (const auto* bar = std::get_if<BarGeometry>(&m.design.shape)) {
    j["free_length"] = bar->free_length();
    if (!bar->cutout && bar->end_radius == 0) {
      const auto& material = body_material(m);
      j["euler_bernoulli_bending_hz"] =
          cantilever_bending_frequencies(material.youngs_modulus, material.density,
                                               bar->free_length(), bar->width, bar->thickness, 3);
    }
    j["width"] = bar->width;
    j["thickness"] = bar->thickness;
    j["length"] = bar->length;
    j["clamp_length"] = bar->clamp_length;
    j["cutout"] = bar->cutout;
  }
  j["mesh"] = {{"nodes", m.mesh.nodes.cols()},
               {"elements", m.mesh.tets.size()},
               {"element", "10-node tetrahedron"},
               {"mesh_size", m.design.mesh_size},
               {"free_dofs", m.free_dofs}};
  j["tip"] = {
      {"point", {m.design.tip.point.x(), m.design.tip.point.y(), m.design.tip.point.z()}},
      {"direction",
       {m.design.tip.direction.x(), m.design.tip.direction.y(), m.design.tip.direction.z()}}};
  j["sensor"] = {
      {"point", {m.design.sensor.point.x(), m.design.sensor.point.y(), m.design.sensor.point.z()}},
      {"axis",
       {m.design.sensor.direction.x(), m.design.sensor.direction.y(),
        m.design.sensor.direction.z()}}};
  nlohmann::json modes = nlohmann::json::array();
  for (std::size_t i = 0; i < m.modal.size(); ++i)
    modes.push_back({{"frequency", m.modal.omega[i] / (2 * M_PI)},
                     {"damping_ratio", m.modal.zeta[i]},
                     {"tip_participation", m.modal.input[i]},
                     {"sensor_participation", m.modal.output[i]},
                     {"displacement_fractions",
                      displacement_fractions(m.modes.shapes.col(static_cast<Eigen::Index>(i)))}});
  j["modes"] = modes;
  const auto frequencies = modal::default_frequency_grid();
  const auto response = modal::frequency_response(m.modal, frequencies);
  nlohmann::json magnitude = nlohmann::json::array(), phase = nlohmann::json::array();
  for (const auto& h : response) magnitude.push_back(std::abs(h)), phase.push_back(std::arg(h));
  j["frequency_response"] = {
      {"frequencies_hz", frequencies}, {"magnitude_m_s2_per_N", magnitude}, {"phase_rad", phase}};
  j["seconds"] = {{"meshing", m.seconds.meshing_s},
                  {"assembly", m.seconds.assembly_s},
                  {"modes", m.seconds.modes_s}};
  return j;
}

void write_mode_report(const std::filesystem::path& file, const DesignModel& model) {
  io::write_file_atomically(file, io::json_text(mode_report_json(model), file));
}

}  // namespace nibrig::model::mechanics
