// What the mechanics commands and the demo report about a design's modal model: the JSON every
// script reads (documented keys) and safe file names for its figures.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "model/mechanics/design_model.hpp"

namespace nibrig::ui::cli {

// The material of region "body", or of the first region.
const model::mechanics::Material& body_material(const model::mechanics::DesignModel& model);

nlohmann::json material_json(const model::mechanics::Material& material);

// design, material{name, youngs_modulus, poisson_ratio, density, source}, regions, damping,
// free_length/width/thickness (bars; plain bars also euler_bernoulli_bending_hz), mesh, tip,
// sensor, modes[]{frequency (Hz), damping_ratio, tip_participation, sensor_participation,
// displacement_fractions [x, y, z]}, frequency_response{frequencies_hz,
// magnitude_m_s2_per_N, phase_rad}, seconds.
nlohmann::json modes_json(const model::mechanics::DesignModel& model);

// Letters and digits kept, everything else '_': "VeroClear stylus, 1 mm" ->
// "VeroClear_stylus__1_mm".
std::string file_stem(const std::string& name);

}  // namespace nibrig::ui::cli
