// View 4, the pad: draw with a tablet's pen, or with the mouse when there is none, and the stroke's
// speed and force drive the engine live (Engine::set_contact through PanelAudio), with the speed
// and force traces under the canvas and the tool and surface in use. The pen is read through
// libinput (PadPen): its speed in millimetres of the tablet, its force from its pressure curve. The
// mouse has no force (GLFW reports no pressure), so a slider gives it; its speed is the pointer's,
// in millimetres of the screen.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "imgui.h"
#include "model/io/paper_drawing.hpp"
#include "rt/reference_load.hpp"
#include "ui/panel/file_dialog.hpp"
#include "ui/panel/pad_pen.hpp"
#include "ui/panel/panel_audio.hpp"

namespace nibrig::ui::panel {

class PadView {
 public:
  explicit PadView(PanelAudio& audio);
  void draw();
  // The speed (mm/s) and force (N) the pad last sent and whether a stroke is being drawn; the
  // traces, one value a frame.
  double speed_mm_s() const { return speed_mm_s_; }
  double force_n() const { return sent_force_n_; }
  bool drawing() const { return drawing_; }
  // Where "Replay a stroke..." was last drawn (screen pixels: min, max), for a test to measure.
  std::pair<ImVec2, ImVec2> replay_button() const { return replay_button_; }
  const std::deque<float>& trace() const { return trace_; }
  const std::deque<float>& force_trace() const { return force_trace_; }
  PadPen& pen() { return pen_; }
  // A recorded stroke (the paper's drawing format: an artist's, or one `audition --pen --record`
  // kept) replayed as the pad's input, in real time: its speed and force to the engine, its path on
  // the canvas. Returns the reader's error, if any (nothing changes then).
  std::string replay(const std::filesystem::path& file);
  bool replaying() const { return replay_.has_value(); }
  // Millimetres per screen pixel: 25.4 / the screen's dots per inch (96 unless set).
  void set_mm_per_pixel(double mm) { mm_per_pixel_ = mm; }
  // The tool the pad plays; loads it (in the background) when it changes.
  void use_tool(const ToolChoice& tool);
  const ToolChoice& tool() const { return tool_; }

 private:
  void update_speed(bool down, ImVec2 position, double now_s);
  void follow_mouse(ImVec2 origin);
  void follow_pen(rig::pen::PenStylus& stylus, ImVec2 size);
  void draw_traces(ImDrawList* draw, ImVec2 at, float width);
  void follow_replay(ImVec2 size);

  PanelAudio& audio_;
  ToolChoice tool_{"cryon", "office"};
  bool loaded_ = false;
  float force_n_ = static_cast<float>(rt::kReferenceNormalForce);
  double mm_per_pixel_ = 25.4 / 96.0;
  bool drawing_ = false;
  ImVec2 last_{};
  double speed_mm_s_ = 0.0;
  // The last two pointer events while the pen is down (newest first) and how many there are.
  ImVec2 event_[2]{};
  double event_s_[2]{};
  int events_ = 0;
  std::vector<std::vector<ImVec2>> strokes_;  // in canvas coordinates
  std::pair<ImVec2, ImVec2> replay_button_{};
  std::deque<float> trace_;                   // speed per frame, the last 600
  std::deque<float> force_trace_;             // force per frame, the last 600
  double sent_force_n_ = 0.0;
  std::uint64_t pen_stroke_ = 0;  // the pen stroke the canvas's last stroke is
  PadPen pen_;
  struct Replay {
    model::io::DrawingTrajectory drawing;
    double x_min_m = 0.0, x_max_m = 0.0, y_min_m = 0.0, y_max_m = 0.0;  // its extent, for the canvas
    double started_s = -1.0;  // the pad's clock when its first frame drew it
    std::size_t next = 0;     // the first row not yet played
  };
  std::optional<Replay> replay_;
  FileDialog files_;
  std::string replay_error_;
  char tool_text_[64] = "cryon", surface_text_[64] = "office";
};

}  // namespace nibrig::ui::panel
