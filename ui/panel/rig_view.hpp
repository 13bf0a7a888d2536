// View 3, the rig: measured | simulated | difference spectrograms scrolling while a rig runs its
// profile (the simulated rig, a replayed session, or the USB controller when one is plugged in),
// the speed and force traces, and the live comparison's distance per speed. The run is
// rig::run_comparison on a worker thread; the analysis thread's rows reach the UI through a feed
// that the worker fills and the UI empties each frame (neither ever waits on the audio thread).
// While the rig runs, the simulation can play on the actuator (rig::ActuatorPlayer, on the device
// the panel plays on), turned on and off as it runs.
#pragma once

#include <atomic>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "rig/comparison_run.hpp"
#include "rig/rig_request.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/panel_audio.hpp"
#include "ui/panel/waterfall.hpp"

namespace nibrig::ui::panel {

struct RigChoice {
  int kind = 0;  // 0 simulated, 1 replay, 2 USB
  std::string tool = "vero2", surface = "office";  // mounted (simulated rig) and simulated
  std::string simulated_tool;                      // empty: the mounted one
  std::string profile = "sweep";                   // steps | sweep | a CSV file
  float seconds = 12.0f;                           // 0: the profile's own length
  std::string replay;                              // a session folder or paper recording
  std::string usb_serial;
  std::string input_api, input_device;
  int input_channel = 1;
  float speedup = 1.0f;  // the simulated and replay rigs: 1 = real time
  bool play_on_actuator = false;  // the simulation plays on the actuator while the rig runs
};

// The rig the choice names, as rig::open_rig takes it (the rig view's run, the experiment's rig mode).
rig::RigRequest rig_request_of(const RigChoice& choice);

// What the worker hands the UI, under a mutex held only to copy.
struct RigFeed {
  std::mutex mutex;
  std::vector<double> frequencies_hz;
  std::vector<float> measured_db, simulated_db;  // new rows × frequencies_hz.size()
  std::deque<float> speed_mm_s, force_n;  // the newest frames, decimated to 100 Hz
  std::optional<rig::ComparisonTable> table;
  rig::CaptureProgress progress;
  std::string rig_name, simulated_name;
  bool actuator_playing = false;
  std::string actuator_state;  // what the actuator plays, or why it does not
};

class RigView {
 public:
  RigView(std::filesystem::path catalog, std::filesystem::path forcing, std::filesystem::path sessions);
  ~RigView();

  void draw();
  void start();
  void stop();
  // The catalog and forcing model of the next run (a run going on keeps its own).
  void set_files(std::filesystem::path catalog, std::filesystem::path forcing) {
    catalog_ = std::move(catalog);
    forcing_ = std::move(forcing);
  }
  // The simulation plays on `audio`'s device and actuator calibration, as they are when a run
  // starts, and `audio` falls silent when the actuator plays the simulation. Null: it plays nowhere.
  void play_through(PanelAudio* audio) { audio_ = audio; }
  bool running() const { return job_ && !job_->done(); }
  // Of the run going on (0 before the capture starts), or 1 after it.
  double progress() const { return job_ ? job_->progress() : 1.0; }
  RigChoice& choice() { return choice_; }
  const std::string& error() const { return error_; }
  // What the view says of the last run once it ended: its session folder, and why it ended early.
  const std::string& finished() const { return finished_; }
  // The speed trace as drawn (mm/s at 100 Hz, the newest last).
  const std::vector<float>& speed_trace() const { return speed_mm_s_; }
  // Whether the run's simulation plays on the actuator now, and what it plays or why it does not.
  bool actuator_playing() const { return actuator_playing_; }
  const std::string& actuator_state() const { return actuator_state_; }
  // What a person is told of the actuator, for this view and the status line: what the player's
  // own stream does (playing, or not heard while its device is lost: a dead JACK server). Empty when
  // the simulation is not asked to play. `heard` says which.
  std::string actuator_line(bool* heard = nullptr) const;
  // For tests: the waterfalls (null before the first rows) and the last table.
  const Waterfall* measured() const { return measured_.get(); }
  const Waterfall* simulated() const { return simulated_.get(); }
  const Waterfall* difference() const { return difference_.get(); }
  const std::optional<rig::ComparisonTable>& table() const { return table_; }
  const std::vector<double>& shown_frequencies() const { return shown_hz_; }
  // Where waterfall i (measured, simulated, difference) was last drawn on the screen.
  std::pair<ImVec2, ImVec2> waterfall_rect(int i) const { return rects_[i]; }
  // Takes what the worker fed since the last frame (draw() calls it).
  void take_feed();

 private:
  void draw_controls();
  void draw_waterfalls();
  void draw_traces();
  void draw_table();
  // Hands the play choice to the run, silencing the audition when it turns on.
  void follow_play_choice();

  std::filesystem::path catalog_, forcing_, sessions_;
  RigChoice choice_;
  std::shared_ptr<RigFeed> feed_ = std::make_shared<RigFeed>();
  std::shared_ptr<std::atomic<bool>> play_wanted_ = std::make_shared<std::atomic<bool>>(false);
  PanelAudio* audio_ = nullptr;
  std::unique_ptr<BackgroundJob<rig::ComparisonRun>> job_;
  std::unique_ptr<Waterfall> measured_, simulated_, difference_;
  std::pair<ImVec2, ImVec2> rects_[3];
  std::vector<double> shown_hz_;  // the frequencies the waterfalls show (≤ 1 kHz)
  std::vector<float> speed_mm_s_, force_n_;
  std::optional<rig::ComparisonTable> table_;
  rig::CaptureProgress progress_;
  std::string rig_name_, simulated_name_, error_, finished_;
  bool actuator_playing_ = false;
  std::string actuator_state_;
};

}  // namespace nibrig::ui::panel
