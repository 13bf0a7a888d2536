// A design loop's rounds in the Design view (model/design/loop_folder.hpp): the measured prints as
// a path in the space in round order, each round's prediction beside its measurement (the line
// between them is what the model missed), and the next print, the round awaiting its measurement.
// Read from the loop's folder, which `nibrig design loop` and nibrig.design.loop write.
#pragma once

#include <imgui.h>

#include <Eigen/Core>
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
};

}  // namespace nibrig::ui::panel
