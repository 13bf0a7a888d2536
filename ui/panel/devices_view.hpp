// View 5, devices: the audio API, device and output channel by name, the period; what runs, in
// words read at a glance (the period and the output latency in ms, the callback's load as a share
// of the period, the xruns of the last minute) and the device losses; the actuator calibration in
// use; the chain's round trip, measured on request (RoundTripSection); the USB rig controllers on
// the bus. Once a stream is open the form shows what it runs (a back end may impose its own period:
// JACK its server's), not what was asked. Listing devices probes servers (JACK may take a second),
// so it runs in the background when asked.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "playback/audio_devices.hpp"
#include "rig/pen/pen_input.hpp"
#include "rig/usb/usb_device_list.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/panel_audio.hpp"
#include "ui/panel/round_trip_section.hpp"
#include "ui/panel/stream_monitor.hpp"

namespace nibrig::ui::panel {

struct DeviceListing {
  std::vector<playback::ApiDevices> apis;
  std::vector<rig::usb::RigControllerInfo> controllers;
  std::string usb_problem;
  std::vector<rig::pen::TabletInfo> tablets;
  std::string tablet_problem;  // why none could be read, when none were
};

// What the view shows of the stream that runs, as last drawn.
struct RunningStream {
  std::string api, device;
  unsigned sample_rate = 0, period_frames = 0;
  double period_ms = 0.0;
  // The output latency: as the back end reports it, or, when it reports none, one period (the
  // least a block waits between being rendered and being heard).
  long latency_frames = 0;
  bool latency_reported = false;
  double latency_ms = 0.0;
  std::optional<StreamLoad> load;  // nullopt until blocks ran within the window
  RecentXruns xruns;
};

class DevicesView {
 public:
  explicit DevicesView(PanelAudio& audio);
  void draw();
  void refresh();
  DeviceRequest& request() { return request_; }
  // The request as the form shows it (what to remember between runs).
  DeviceRequest shown_request() const;
  void set_request(const DeviceRequest& request);
  // Opens request() on the audition; the error, if any, is shown.
  void open();
  const std::string& error() const { return error_; }
  const std::optional<DeviceListing>& listing() const { return listing_; }
  const std::optional<RunningStream>& running() const { return running_; }
  RoundTripSection& round_trip() { return round_trip_; }
  const RoundTripSection& round_trip() const { return round_trip_; }
  bool measuring() const { return round_trip_.running(); }
  // Reads the stream's counters into running() (the view does when drawn; the panel every frame
  // otherwise, so that "xruns in the last minute" covers the minute, whichever view was shown).
  void sample();

 private:
  void draw_listing();
  void draw_stream();
  void show_what_runs(const playback::StreamInfo& info);  // into the form, once per stream opened

  PanelAudio& audio_;
  DeviceRequest request_;
  std::unique_ptr<BackgroundJob<DeviceListing>> job_;
  std::optional<DeviceListing> listing_;
  std::string error_;
  char api_[32] = "", device_[128] = "", actuator_[512] = "";
  // The stream the form last showed (api, device, rate, period).
  std::optional<std::tuple<std::string, std::string, unsigned, unsigned>> shown_stream_;
  StreamMonitor monitor_;
  std::optional<RunningStream> running_;
  RoundTripSection round_trip_;
  std::chrono::steady_clock::time_point created_ = std::chrono::steady_clock::now();
};

}  // namespace nibrig::ui::panel
