// nibrig-panel's contents: the five views as tabs of one full-window ImGui window, an error line
// that shows what went wrong in a file or a device (never a crash), and the files a person opens.
// Everything here runs on the UI thread and only draws and dispatches: loading, fitting, making
// sounds and the rig run on worker threads (background_job.hpp), the sound on the audio thread.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "model/space/descriptor_map.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/design_view.hpp"
#include "ui/panel/panel_audio.hpp"
#include "ui/panel/space_scene.hpp"
#include "ui/panel/space_view.hpp"

namespace nibrig::ui::panel {

class RigView;
class PadView;
class DevicesView;

enum class View { space, design, rig, pad, devices };
std::optional<View> view_named(std::string_view name);
const char* view_name(View view);

struct PanelSetup {
  std::filesystem::path catalog;  // empty: the bundled one
  std::filesystem::path space;    // empty: the default (computed on first start, then cached)
  std::filesystem::path forcing;  // empty: the default
  std::optional<DeviceRequest> device;  // opened at start; none: play nowhere until chosen
  bool start_rig = false;               // the rig view's run starts at once
  DesignSettings design;                // how finely the design view solves its grid
};

class Panel {
 public:
  explicit Panel(PanelSetup setup);
  ~Panel();

  // One frame's widgets, filling the display.
  void draw();
  void show(View view);
  View current() const { return current_; }
  // True once nothing is loading in the background for the view shown (screenshots wait for it).
  bool settled() const;
  const std::string& error() const { return error_; }
  // Shown in the error line until something else goes wrong (e.g. a settings file that could not
  // be read).
  void set_error(std::string error) { error_ = std::move(error); }
  // The space file open now (empty: none yet).
  const std::filesystem::path& space_file() const { return space_file_; }
  // The status line under the views: the device and its state, what plays, the stroke.
  std::string status_line() const;

  SpaceView& space_view() { return *space_view_; }
  PanelAudio& audio() { return *audio_; }
  RigView& rig_view() { return *rig_view_; }
  DesignView& design_view() { return *design_view_; }
  PadView& pad_view() { return *pad_view_; }
  DevicesView& devices_view() { return *devices_view_; }
  const DevicesView& devices_view() const { return *devices_view_; }

 private:
  void load_space(const std::filesystem::path& file);
  void load_default_space();
  void poll_jobs();
  void draw_menu();
  void draw_status();

  PanelSetup setup_;
  std::filesystem::path space_file_;
  std::unique_ptr<PanelAudio> audio_;
  std::unique_ptr<SpaceView> space_view_;
  std::unique_ptr<RigView> rig_view_;
  std::unique_ptr<PadView> pad_view_;
  std::unique_ptr<DevicesView> devices_view_;
  std::unique_ptr<BackgroundJob<LoadedSpace>> space_job_;
  std::unique_ptr<DesignView> design_view_;
  View current_ = View::space;
  std::optional<View> requested_;
  std::string error_;
  char open_path_[512] = {};
};

}  // namespace nibrig::ui::panel
