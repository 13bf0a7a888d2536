// A design loop's rounds in the Design view (model/design/loop_folder.hpp): the measured prints as
// a path in the space in round order, each round's prediction beside its measurement (the line
// between them is what the model missed), and the next print, the round awaiting its measurement.
// Read from the loop's folder, which `nibrig design loop` and nibrig.design.loop write, and read
// again as they write it, so a loop running elsewhere is followed round by round.
#pragma once

#include <imgui.h>

#include <Eigen/Core>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/design/loop_folder.hpp"
#include "ui/panel/plot_frame.hpp"

namespace nibrig::ui::panel {

class LoopRounds {
 public:
  // Reads loop.json and every round. Throws what the readers throw (the file and field named).
  explicit LoopRounds(const std::filesystem::path& folder);

  const std::filesystem::path& folder() const { return folder_; }
  const model::design::LoopRequest& request() const { return request_; }
  const std::vector<model::design::LoopRoundRecord>& rounds() const { return rounds_; }
  // The round whose print awaits its measurement: the next print (none when every round is
  // measured).
  const model::design::LoopRoundRecord* next_print() const;
  const std::string& stopped() const;
  // Reads the folder again when one of its records changed since it was read (a new round, a
  // round measured, the loop stopped) and says whether it did. Looks at most every
  // kRefreshInterval, so a frame costs a few file stamps at most; a folder that no longer reads
  // (a record being replaced) keeps what was shown until the next look.
  bool refresh_if_changed();
  static constexpr std::chrono::milliseconds kRefreshInterval{500};
  // Where the loop's target lies in the space shown (a tool of its scene), when it is there.
  void set_target_place(std::optional<Eigen::VectorXd> place) { target_place_ = std::move(place); }

  // The path, predictions and next print on a space's plot (axes ax, ay; equal for a 1-D space).
  void draw_overlay(ImDrawList* draw, const PlotFrame& frame, int ax, int ay) const;
  // Round by round: design, predicted and measured distance; the next print; why it stopped.
  void draw_table() const;

 private:
  std::filesystem::path folder_;
  model::design::LoopRequest request_;
  std::vector<model::design::LoopRoundRecord> rounds_;
  std::optional<Eigen::VectorXd> target_place_;
  std::filesystem::file_time_type stamp_;
  std::chrono::steady_clock::time_point looked_;
};

}  // namespace nibrig::ui::panel
