// What a PrusaSlicer G-code says it printed: its settings block, and the filament its extruding
// moves lay down by feature. For the tests that slice nibrig's exports with the real slicer.
#pragma once

#include <map>
#include <sstream>
#include <string>

namespace nibrig::test {

// "; key = value" of a G-code's settings block (PrusaSlicer writes it at the end).
inline std::map<std::string, std::string> gcode_settings(const std::string& gcode) {
  std::map<std::string, std::string> out;
  std::istringstream in(gcode);
  for (std::string l; std::getline(in, l);) {
    if (l.rfind("; ", 0) != 0) continue;
    const auto eq = l.find(" = ");
    if (eq != std::string::npos) out[l.substr(2, eq - 2)] = l.substr(eq + 3);
  }
  return out;
}

// Filament (mm of it) pushed by extruding moves (with X or Y), by the ;TYPE: of the feature they
// print: absolute E (M82) reset by G92, or relative (M83). Retractions and primes move E alone and
// are left out, so the sum is what was laid down.
inline std::map<std::string, double> gcode_filament_by_feature(const std::string& gcode) {
  std::map<std::string, double> mm;
  std::istringstream in(gcode);
  std::string type = "none";
  double e = 0.0;
  bool relative = false;
  for (std::string l; std::getline(in, l);) {
    if (l.rfind(";TYPE:", 0) == 0) {
      type = l.substr(6);
      continue;
    }
    l = l.substr(0, l.find(';'));
    std::istringstream words(l);
    std::string command;
    if (!(words >> command)) continue;
    if (command == "M83") relative = true;
    if (command == "M82") relative = false;
    if (command != "G1" && command != "G0" && command != "G92") continue;
    bool xy = false, has_e = false;
    double new_e = 0.0;
    for (std::string w; words >> w;) {
      if (w[0] == 'X' || w[0] == 'Y') xy = true;
      if (w[0] == 'E') has_e = true, new_e = std::stod(w.substr(1));
    }
    if (!has_e) continue;
    if (command == "G92") {
      e = new_e;
      continue;
    }
    const double pushed = relative ? new_e : new_e - e;
    if (!relative) e = new_e;
    if (pushed > 0 && xy) mm[type] += pushed;
  }
  return mm;
}

}  // namespace nibrig::test
