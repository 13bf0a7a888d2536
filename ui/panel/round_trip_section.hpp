// The devices view's round-trip measurement: impulses through the output the form names and back on
// an input (playback::measure_round_trips, what `nibrig latency` runs), on a background job, and
// its figures per period as a table. The UI thread only starts, polls and draws.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "imgui.h"
#include "playback/round_trip_run.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/panel_audio.hpp"

namespace nibrig::ui::panel {

// What the section's form holds besides the output (which is the devices view's).
struct RoundTripRequest {
  std::string input_device;  // by name; empty: the output's device
  unsigned input_channel = 1;
  std::vector<unsigned> periods{64};
  int impulses = 50;
  double interval_ms = 250.0;
};

// "64, 128,256" -> {64, 128, 256}. Throws std::invalid_argument naming the field and the entry
// that is not a period in frames (1 to 65536).
std::vector<unsigned> parse_periods(const std::string& text);

class RoundTripSection {
 public:
  // Its longest field label: the view that holds the section leaves room for it.
  static constexpr const char* kWidestLabel = "input device (by name)";
  RoundTripSection();
  // The section's widgets; `output` is the devices view's form (api, device, output channel).
  void draw(const DeviceRequest& output);
  // Starts the measurement on a job; nothing while one runs. The form's periods are used as typed.
  void start(const DeviceRequest& output);
  bool running() const { return job_ != nullptr; }
  const RoundTripRequest& request() const { return request_; }
  // Fills the form (what to remember between runs, or what a test types).
  void set_request(const RoundTripRequest& request);
  // The last measurement's figures, one entry per period (empty before the first).
  const std::vector<playback::RoundTripResult>& results() const { return results_; }
  const std::string& error() const { return error_; }
  // The table's cells as last drawn, a row per period: what a person reads.
  const std::vector<std::vector<std::string>>& shown_rows() const { return shown_rows_; }
  // What the bar shows while measuring (0-1): the periods done, and within one the time its
  // impulses take (impulses × interval), since the measurement reports only whole periods.
  double shown_progress() const;
  // Why no impulse came back, when a period found none (else empty): what to connect.
  std::string hint() const;
  // Where the measure button was last drawn (screen pixels), for a test to click.
  std::optional<ImVec2> measure_button() const { return measure_button_; }

 private:
  void poll();
  void draw_table();

  RoundTripRequest request_;
  char input_device_[128] = "", periods_[64] = "64";
  std::unique_ptr<BackgroundJob<std::vector<playback::RoundTripResult>>> job_;
  RoundTripRequest measuring_;  // the request job_ runs
  DeviceRequest measured_output_;  // its output, for the hint
  std::chrono::steady_clock::time_point started_, period_started_;
  double periods_done_ = 0.0;  // job_->progress() when period_started_ was taken
  std::vector<playback::RoundTripResult> results_;
  std::string error_;
  std::vector<std::vector<std::string>> shown_rows_;
  std::optional<ImVec2> measure_button_;
};

}  // namespace nibrig::ui::panel
