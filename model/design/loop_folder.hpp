// A design loop's folder: what the loop was asked (loop.json) and each round in round-N/: its
// design and prediction (round.json), the print's files (print/), the rig's session of it
// (session/), the measurement analysed from it (measurement.json: a catalog of one pairing) and the
// forcing model refitted with it (forcing.json). Every file is written whole or not at all, so a
// loop killed at any point reads back to its last completed step (loop_session.hpp resumes it).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/design/design_loop.hpp"
#include "model/design/design_point.hpp"

namespace nibrig::model::design {

inline constexpr int kDefaultLoopRounds = 6;
inline constexpr int kMostLoopRounds = 50;

// What the loop was asked: loop.json.
struct LoopRequest {
  std::string target;   // "tool/surface", judged in the space or placed from the catalog
  std::string surface;  // the surface the stylus is for
  std::filesystem::path space_file;
  std::filesystem::path catalog_file;  // empty: the bundled one
  std::string forcing;                 // a forcing file or a lab's stored model; empty: the default
  std::string printer;                 // a printer profile for the prints' files; empty: none
  std::string first_material = "vero", second_material = "DM85";  // the range's mix
  NextPrintRule rule = kDefaultNextPrintRule;
  int max_rounds = kDefaultLoopRounds;
  // The only designs the loop may print (empty: any in the range), e.g. prints recorded already
  // (rig/recorded_prints.hpp). The catalog's own measurements of them on the loop's surface are
  // left out of its starting model, so that it learns them from its prints and not twice.
  std::vector<DesignPoint> candidates;
};

struct LoopMeasuredRecord {
  double distance = 0.0, distance_sd = 0.0;
  Eigen::VectorXd position;     // the placement's mean
  Eigen::VectorXd descriptors;  // the space map's, in its order
};

// One round: round-N/round.json.
struct LoopRoundRecord {
  int number = 0;
  DesignPoint design;
  double predicted_distance = 0.0, predicted_distance_sd = 0.0, chance_within = 0.0;
  Eigen::VectorXd predicted_position;
  std::optional<LoopMeasuredRecord> measured;
  std::string
      stopped;  // why the loop stopped after this round (describe(LoopStop)); empty: it goes on
};

std::filesystem::path loop_request_file(const std::filesystem::path& folder);
std::filesystem::path round_folder(const std::filesystem::path& folder, int round);
std::filesystem::path round_file(const std::filesystem::path& folder, int round);
std::filesystem::path round_print_file(const std::filesystem::path& folder,
                                       int round);  // print/stylus.3mf
std::filesystem::path round_session_folder(const std::filesystem::path& folder, int round);
std::filesystem::path round_measurement_file(const std::filesystem::path& folder, int round);
std::filesystem::path round_forcing_file(const std::filesystem::path& folder, int round);

// Throws std::invalid_argument naming what a new loop lacks or has wrong (no target, surface or
// space; rounds outside 1 to kMostLoopRounds; one material twice in the mix; a candidate of
// another material). Every face's check.
void check_loop_request(const LoopRequest& request);

// Throw std::runtime_error naming the file when it cannot be written.
void write_loop_request(const std::filesystem::path& folder, const LoopRequest& request);
void write_round(const std::filesystem::path& folder, const LoopRoundRecord& round);

// Throw io::FormatError naming the file and field for a file that does not read as one.
LoopRequest read_loop_request(const std::filesystem::path& folder);
// round-1, round-2, ... while their round.json exists; a round folder without one (the loop was
// killed while it was made) ends the list.
std::vector<LoopRoundRecord> read_rounds(const std::filesystem::path& folder);

}  // namespace nibrig::model::design
