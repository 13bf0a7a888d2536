// The devices a command lists, as JSON for `--json FILE`: audio APIs with their devices, pen
// tablets, rig controllers and bootloaders waiting, each field what the printed line shows.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "playback/audio_devices.hpp"
#include "rig/pen/pen_input.hpp"
#include "rig/usb/bootloader_port.hpp"
#include "rig/usb/usb_device_list.hpp"

namespace nibrig::ui::cli {

nlohmann::json audio_devices_json(const std::vector<playback::ApiDevices>& apis);
// `why`: the reason there are none when the input devices could not be read, else empty.
nlohmann::json tablets_json(const std::vector<rig::pen::TabletInfo>& tablets,
                            const std::string& why);
nlohmann::json rig_controllers_json(const std::vector<rig::usb::RigControllerInfo>& controllers);
nlohmann::json serial_ports_json(const std::vector<rig::usb::SerialPort>& ports);

}  // namespace nibrig::ui::cli
