// The mode report (FORMATS.md, "Mode report"): a design's modal model as the JSON scripts read,
// with the material, mesh, probes, every mode and the sensor's frequency response.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "model/mechanics/design_model.hpp"

namespace nibrig::model::mechanics {

// The material of region "body", or of the first region.
const Material& body_material(const DesignModel& model);

// name, youngs_modulus, poisson_ratio, density, source.
nlohmann::json material_json(const Material& material);

// design, material (body_material's), regions, damping, free_length/width/thickness (bars; plain
// bars also euler_bernoulli_bending_hz), mesh, tip, sensor, modes[]{frequency (Hz),
// damping_ratio, tip_participation, sensor_participation, displacement_fractions [x, y, z]},
// frequency_response{frequencies_hz, magnitude_m_s2_per_N, phase_rad}, seconds.
nlohmann::json mode_report_json(const DesignModel& model);

// Written atomically (io::write_file_atomically); throws io::UnwritableOutput naming the field
// that is not finite, std::runtime_error naming the file when it cannot be written.
void write_mode_report(const std::filesystem::path& file, const DesignModel& model);

}  // namespace nibrig::model::mechanics
