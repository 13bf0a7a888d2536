// Prints already recorded, standing in for printing them: the paper's grid of VeroClear, DM85 and
// DM95 at 1, 2 and 4 mm was recorded on the turntable (vibration) and on the force sensor
// (friction) in separate runs. A design loop replaying them proposes only these designs, and each
// round's print is their two recordings replayed on the rig (rig/replay_rig.hpp), so the loop runs
// on real measurements.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"

namespace nibrig::rig {

struct RecordedPrint {
  model::design::DesignPoint design;  // one material at one tip
  std::filesystem::path vibration;    // arm_[plain_]<material>_<tip>_<surface>.csv[.gz]
  std::filesystem::path friction;     // <material><tip>_<surface>_<load>N_<lever>_<rep>.csv[.gz]
};

// Every print of `materials` recorded on `surface` under `folder` (searched through), with both
// its recordings; a design recorded twice takes the first file by path, the friction run the
// lowest repetition. Nail and pen-holder variants are other designs and are left out. Sorted by
// material as given, then tip. Throws std::invalid_argument naming the folder, the surface and
// the file names expected when none is found, or when `folder` is not a folder.
std::vector<RecordedPrint> find_recorded_prints(const std::filesystem::path& folder,
                                                const std::string& surface,
                                                const std::vector<std::string>& materials);

std::vector<model::design::DesignPoint> designs_of(const std::vector<RecordedPrint>& prints);

}  // namespace nibrig::rig
