// The velocity-binned magnitude spectrum of a tool on a surface: the common currency between
// measurement (model/measure), the tool catalog (model/io/catalog), prediction (model/forcing) and plots.
#pragma once

#include <vector>

namespace nibrig::model::io {

// amplitude_m_s2[s][f] is the single-sided amplitude (peak, m/s^2) at frequencies_hz[f] while the tip
// moves at speeds_m_s[s]. In JSON files the speeds are written as `speeds_mm_s` (mm/s), see catalog.hpp.
struct VelocitySpectrum {
  std::vector<double> frequencies_hz;
  std::vector<double> speeds_m_s;
  std::vector<std::vector<double>> amplitude_m_s2;
};

}  // namespace nibrig::model::io
