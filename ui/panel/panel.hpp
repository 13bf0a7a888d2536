// nibrig-panel's contents: the six views as tabs of one full-window ImGui window, an error line
// that shows what went wrong in a file or a device (never a crash), the files a person opens and
// saves (spaces, catalogs, forcing models, designs; a space fitted from judgments), and the keys.
// Everything here runs on the UI thread and only draws and dispatches: loading, fitting, making
// sounds and the rig run on worker threads (background_job.hpp), the sound on the audio thread.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "model/space/descriptor_map.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/design_view.hpp"
#include "ui/panel/error_line.hpp"
#include "ui/panel/file_dialog.hpp"
#include "ui/panel/panel_audio.hpp"
#include "ui/panel/space_fit_form.hpp"
#include "ui/panel/space_scene.hpp"
#include "ui/panel/space_view.hpp"

namespace nibrig::ui::panel {

class RigView;
class PadView;
class DevicesView;
class ExperimentView;

enum class View { space, design, rig, pad, devices, experiment };
std::optional<View> view_named(std::string_view name);
const char* view_name(View view);

struct PanelSetup {
  std::filesystem::path catalog;        // empty: the bundled one
  std::filesystem::path space;          // empty: the default (computed on first start, then cached)
  std::filesystem::path forcing;        // empty: the default
  std::optional<DeviceRequest> device;  // opened at start; none: play nowhere until chosen
  bool start_rig = false;               // the rig view's run starts at once
  DesignSettings design;                // how finely the design view solves its grid
  std::filesystem::path loop;  // a design loop's folder shown in the design view; empty: none
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
  // The error line: what went wrong last, until something succeeds or the person moves to
  // another view (then empty); every error stays in errors().history() (Help > Errors).
  const std::string& error() const { return errors_.current(); }
  const ErrorLine& errors() const { return errors_; }
  // Shown in the error line (e.g. a settings file that could not be read).
  void set_error(std::string error) { errors_.report(std::move(error)); }
  // The space file open now (empty: none yet, the default, or a fit not saved).
  const std::filesystem::path& space_file() const { return space_file_; }
  // The space shown, as a file holds it (none until one has loaded).
  const std::optional<model::space::SpaceFile>& shown_space() const { return space_; }
  // The catalog and forcing model in use (empty: the bundled catalog, the demo's forcing model).
  const std::filesystem::path& catalog_file() const { return setup_.catalog; }
  const std::filesystem::path& forcing_file() const { return setup_.forcing; }

  // What the File menu does. Each returns at once: reading, fitting and writing run in the
  // background, and what goes wrong shows in the error line. A catalog or forcing model is read
  // whole before it replaces the one in use, so a bad file changes nothing.
  void open_space(const std::filesystem::path& file) { load_space(file); }
  void open_default_space() { load_default_space(); }
  void fit_space(const SpaceFitRequest& request);
  void save_space(const std::filesystem::path& file);
  void open_catalog(const std::filesystem::path& file);
  void open_forcing(const std::filesystem::path& file);
  // A forcing model the lab keeps by name (forcing calibrate-material --save): what the File menu's
  // "Stored forcing model" lists (model::forcing::stored_forcing_models).
  void open_stored_forcing(const std::string& name);
  void save_forcing(const std::filesystem::path& file);
  void open_design(const std::filesystem::path& file);
  // A design loop's rounds over the Design view's space (its folder or loop.json).
  void open_design_loop(const std::filesystem::path& file);
  void save_design(const std::filesystem::path& file);
  void export_stylus(const std::filesystem::path& file);
  // True while a file is being read, written or a space fitted.
  bool busy() const { return space_job_ != nullptr || file_job_ != nullptr; }
  // The last thing a file operation said ("wrote …"), shown in the status line.
  const std::string& notice() const { return notice_; }
  FileDialog& file_dialog() { return files_; }
  SpaceFitRequest& fit_request() { return fit_request_; }

  // The keys (also listed under Help): A, B, C switch between the tools compared; space stops what
  // plays or plays the chosen tools again; ctrl+1…6 show a view; ctrl+O opens a space. Not while
  // a text field has the keyboard.
  void handle_keys();
  // The status line under the views: the device and its state, what plays, the stroke.
  std::string status_line() const;

  // How long the window may wait for input before the next frame (frame_pacing.hpp): 0 while
  // something moves (the rig's waterfall, a drag, the pad, a participant's session), a tenth of a
  // second while a job's progress is shown, else kIdleRefresh_s for the live readouts (the
  // device's state, the status line).
  static constexpr double kIdleRefresh_s = 1.0, kProgressRefresh_s = 0.1;
  double idle_wait_s() const;
  // The frame-time readout (Help > Frame times, or F12): frames per second and what the panel's
  // own widgets cost per frame.
  bool frame_times_shown() const { return frame_times_window_; }
  void show_frame_times(bool shown) { frame_times_window_ = shown; }

  SpaceView& space_view() { return *space_view_; }
  PanelAudio& audio() { return *audio_; }
  RigView& rig_view() { return *rig_view_; }
  DesignView& design_view() { return *design_view_; }
  PadView& pad_view() { return *pad_view_; }
  DevicesView& devices_view() { return *devices_view_; }
  const DevicesView& devices_view() const { return *devices_view_; }
  ExperimentView& experiment_view() { return *experiment_view_; }

 private:
  void load_space(const std::filesystem::path& file);
  void load_default_space();
  // Runs `work` in the background; what it returns is applied on the UI thread when done.
  using Apply = std::function<void(Panel&)>;
  void file_job(std::string title, std::function<Apply(JobControl&)> work);
  // Another catalog or forcing model: the views that use them start again with them.
  void use_sources(std::shared_ptr<model::design::ToolSounds> sounds, std::filesystem::path catalog,
                   std::filesystem::path forcing);
  void poll_jobs();
  void draw_menu();
  void draw_fit_window();
  void draw_status(const std::string& status);
  // Height the status block under the views takes this frame with `status` (it and the error line
  // wrap).
  float status_height(const std::string& status) const;
  void draw_help_windows();
  void draw_frame_times();
  void draw_views();
  // The audio's own error joins the error line when it changes.
  void follow_audio_error();
  // The error line moves on when the view does (see error_view_).
  void follow_error_view();

  PanelSetup setup_;
  std::filesystem::path space_file_;
  std::unique_ptr<PanelAudio> audio_;
  std::unique_ptr<SpaceView> space_view_;
  std::unique_ptr<RigView> rig_view_;
  std::unique_ptr<PadView> pad_view_;
  std::unique_ptr<DevicesView> devices_view_;
  std::unique_ptr<ExperimentView> experiment_view_;
  std::unique_ptr<BackgroundJob<LoadedSpace>> space_job_;
  std::unique_ptr<BackgroundJob<Apply>> file_job_;
  std::unique_ptr<DesignView> design_view_;
  std::vector<std::unique_ptr<DesignView>> retired_designs_;  // replaced, their work ending
  std::optional<model::space::SpaceFile> space_;              // the space shown, for Save space as
  View current_ = View::space;
  std::optional<View> requested_;
  ErrorLine errors_;
  std::string notice_, audio_error_seen_;
  std::vector<std::string> stored_forcing_;  // read as the File menu opens its list
  FileDialog files_;
  SpaceFitRequest fit_request_;
  bool showing_default_ = false;
  // The file of the space shown (space_file_ is the one asked for, until it fails to load), and
  // why the default is computed in place of a file that failed with nothing shown.
  std::filesystem::path shown_space_file_;
  std::string fallback_reason_;
  // The error line's error and the view it came up in: moving to another view moves on from it.
  std::string error_seen_;
  View error_view_ = View::space;
  bool fit_window_ = false, keys_window_ = false, errors_window_ = false,
       frame_times_window_ = false;
  // The panel's widget time per frame (ms), the last kFrameTimes frames, for the readout.
  static constexpr std::size_t kFrameTimes = 120;
  std::array<float, kFrameTimes> frame_ms_{};
  std::size_t frame_at_ = 0;
  float last_status_height_ =
      0.0f;  // the status block's, as last laid out: the readout sits above it
};

}  // namespace nibrig::ui::panel
