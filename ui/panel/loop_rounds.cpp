#include "ui/panel/loop_rounds.hpp"

#include <algorithm>
#include <cstdio>

#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace design = model::design;

namespace {

const ImU32 kMeasuredColour = IM_COL32(120, 220, 140, 255);
const ImU32 kPredictedColour = IM_COL32(255, 255, 255, 190);
const ImU32 kNextColour = IM_COL32(255, 200, 60, 255);

// The newest write among the records a reader takes: loop.json and every round.json, the next
// round's included (it appears when the loop proposes it).
std::filesystem::file_time_type newest_record(const std::filesystem::path& folder,
                                              std::size_t rounds) {
  std::error_code error;
  auto newest = std::filesystem::last_write_time(design::loop_request_file(folder), error);
  for (std::size_t n = 1; n <= rounds + 1; ++n) {
    const auto t =
        std::filesystem::last_write_time(design::round_file(folder, static_cast<int>(n)), error);
    if (!error) newest = std::max(newest, t);
  }
  return newest;
}

}  // namespace

LoopRounds::LoopRounds(const std::filesystem::path& folder)
    : folder_(folder),
      request_(design::read_loop_request(folder)),
      rounds_(design::read_rounds(folder)),
      stamp_(newest_record(folder, rounds_.size())),
      looked_(std::chrono::steady_clock::now()) {}

bool LoopRounds::refresh_if_changed() {
  const auto now = std::chrono::steady_clock::now();
  if (now - looked_ < kRefreshInterval) return false;
  looked_ = now;
  const auto stamp = newest_record(folder_, rounds_.size());
  if (stamp == stamp_) return false;
  try {
    auto rounds = design::read_rounds(folder_);
    rounds_ = std::move(rounds);
  } catch (const std::exception&) {
    return false;  // read again at the next look
  }
  stamp_ = stamp;
  return true;
}

const design::LoopRoundRecord* LoopRounds::next_print() const {
  if (rounds_.empty() || rounds_.back().measured) return nullptr;
  return &rounds_.back();
}

const std::string& LoopRounds::stopped() const {
  static const std::string none;
  return rounds_.empty() ? none : rounds_.back().stopped;
}

void LoopRounds::draw_overlay(ImDrawList* draw, const PlotFrame& frame, int ax, int ay) const {
  const bool one_d = ax == ay;
  const auto at = [&](const Eigen::VectorXd& p) {
    return frame.to_screen(p[ax], one_d ? 0.0 : p[ay]);
  };
  // The measured prints in round order.
  for (const auto& r : rounds_)
    if (r.measured) draw->PathLineTo(at(r.measured->position));
  draw->PathStroke(kMeasuredColour, 0, 2.0f);
  char number[8];
  for (const auto& r : rounds_) {
    const ImVec2 predicted = at(r.predicted_position);
    if (r.measured) {
      const ImVec2 measured = at(r.measured->position);
      draw->AddLine(predicted, measured, kPredictedColour, 1.0f);
      draw_marker(draw, measured, Marker::circle, 5.0f, kMeasuredColour, true);
      std::snprintf(number, sizeof number, "%d", r.number);
      draw->AddText({measured.x + 6.0f, measured.y - 6.0f}, kMeasuredColour, number);
    }
    draw_marker(draw, predicted, Marker::circle, 5.0f, r.measured ? kPredictedColour : kNextColour,
                false);
  }
  if (target_place_ && target_place_->size() > std::max(ax, ay)) {
    const ImVec2 t = at(*target_place_);
    draw->AddCircle(t, 12.0f, kMeasuredColour, 24, 2.0f);
    draw->AddText({t.x + 14.0f, t.y - 6.0f}, kMeasuredColour, "target");
  }
  if (const auto* next = next_print()) {
    const ImVec2 p = at(next->predicted_position);
    draw->AddCircle(p, 10.0f, kNextColour, 24, 2.0f);
    draw->AddText({p.x + 12.0f, p.y - 6.0f}, kNextColour, "next print");
  }
}

void LoopRounds::draw_table() const {
  section("Design loop");
  ImGui::TextWrapped("%s on %s, %s: %s", request_.target.c_str(), request_.surface.c_str(),
                     design::rule_name(request_.rule).c_str(), folder_.string().c_str());
  if (ImGui::BeginTable("loop-rounds", 3,
                        ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("round: design");
    ImGui::TableSetupColumn("predicted");
    ImGui::TableSetupColumn("measured");
    ImGui::TableHeadersRow();
    for (const auto& r : rounds_) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%d: %s", r.number, design::label(r.design).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.2f ± %.2f", r.predicted_distance, r.predicted_distance_sd);
      ImGui::TableNextColumn();
      if (r.measured)
        ImGui::Text("%.2f ± %.2f", r.measured->distance, r.measured->distance_sd);
      else
        ImGui::TextColored({1.0f, 0.78f, 0.24f, 1.0f}, "next print");
    }
    ImGui::EndTable();
  }
  if (!stopped().empty())
    ImGui::TextWrapped("stopped: %s", stopped().c_str());
  else if (next_print())
    ImGui::TextWrapped("round %d awaits its print's measurement (design loop --resume)",
                       next_print()->number);
}

}  // namespace nibrig::ui::panel
