// How closely the rig repeats a measurement, from the catalog itself: the paper's nail-test prints
// DM85{1,2,4}_nail1 and _nail2 are one print recorded twice on note paper, so the RMS dB difference
// of their spectra is the measurement's repeatability (the paper's 2.3 dB), the floor under any
// prediction's error and the bar a calibration's uncertainty is held to.
#pragma once

#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"

namespace nibrig::model::forcing {

struct Repeatability {
  double rms_db = 0.0;             // the mean over the pairs of their RMS dB difference
  std::vector<std::string> pairs;  // "DM851_nail1 / DM851_nail2 on note: 2.41 dB"
};

// Every "<print>_nail1" with a "<print>_nail2" on the same surface, both with spectra, is a pair.
// Throws std::invalid_argument when the catalog holds no such pair.
Repeatability nail_pair_repeatability(const io::Catalog& catalog);

}  // namespace nibrig::model::forcing
