// View 5, devices: the audio API, device and output channel by name, the period; what was opened,
// the callback's load, xruns and device losses; the actuator calibration in use; the USB rig
// controllers on the bus. Listing devices probes servers (JACK may take a second), so it runs in
// the background when asked.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "playback/audio_devices.hpp"
#include "rig/usb/usb_device_list.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/panel_audio.hpp"

namespace nibrig::ui::panel {

struct DeviceListing {
  std::vector<playback::ApiDevices> apis;
  std::vector<rig::usb::RigControllerInfo> controllers;
  std::string usb_problem;
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

 private:
  void draw_listing();
  void draw_stream();

  PanelAudio& audio_;
  DeviceRequest request_;
  std::unique_ptr<BackgroundJob<DeviceListing>> job_;
  std::optional<DeviceListing> listing_;
  std::string error_;
  char api_[32] = "", device_[128] = "", actuator_[512] = "";
};

}  // namespace nibrig::ui::panel
