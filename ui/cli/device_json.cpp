#include "ui/cli/device_json.hpp"

#include <fmt/format.h>

#include "rig/usb/usb_protocol.hpp"

namespace nibrig::ui::cli {

namespace {

// A missing value is null, never "" or 0, so a script cannot take it for one.
nlohmann::json text_or_null(const std::string& text) {
  return text.empty() ? nlohmann::json(nullptr) : nlohmann::json(text);
}

std::string usb_id(std::uint16_t vendor, std::uint16_t product) {
  return fmt::format("{:04x}:{:04x}", vendor, product);
}

}  // namespace

nlohmann::json audio_devices_json(const std::vector<playback::ApiDevices>& apis) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& api : apis) {
    nlohmann::json devices = nlohmann::json::array();
    for (const auto& d : api.devices)
      devices.push_back({{"name", d.name},
                         {"output_channels", d.output_channels},
                         {"input_channels", d.input_channels},
                         {"sample_rates_hz", d.sample_rates},
                         {"preferred_sample_rate_hz",
                          d.preferred_sample_rate == 0 ? nlohmann::json(nullptr)
                                                       : nlohmann::json(d.preferred_sample_rate)},
                         {"default_output", d.default_output},
                         {"default_input", d.default_input}});
    out.push_back({{"api", api.api},
                   {"display_name", api.display_name},
                   {"available", api.available},
                   {"unavailable_reason", text_or_null(api.unavailable_reason)},
                   {"devices", devices}});
  }
  return out;
}

nlohmann::json tablets_json(const std::vector<rig::pen::TabletInfo>& tablets,
                            const std::string& why) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& t : tablets)
    list.push_back(
        {{"name", t.name},
         {"model", text_or_null(t.model)},
         {"model_told_apart", t.model_told_apart},
         {"devnode", t.devnode},
         {"width_mm", t.width_mm > 0 ? nlohmann::json(t.width_mm) : nlohmann::json(nullptr)},
         {"height_mm", t.height_mm > 0 ? nlohmann::json(t.height_mm) : nlohmann::json(nullptr)},
         {"pressure", t.has_pressure},
         {"tilt", t.has_tilt}});
  return {{"tablets", list}, {"unreadable_reason", text_or_null(why)}};
}

nlohmann::json rig_controllers_json(const std::vector<rig::usb::RigControllerInfo>& controllers) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& c : controllers)
    out.push_back(
        {{"serial", text_or_null(c.serial)},
         {"bus", c.bus},
         {"address", c.address},
         {"protocol_version", c.protocol_version == 0
                                  ? nlohmann::json(nullptr)
                                  : nlohmann::json(rig::usb::version_text(c.protocol_version))},
         {"firmware", text_or_null(c.firmware)},
         {"problem", text_or_null(c.problem)}});
  return out;
}

nlohmann::json serial_ports_json(const std::vector<rig::usb::SerialPort>& ports) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : ports)
    out.push_back(
        {{"device", p.device},
         {"usb_id", p.vendor == 0 && p.product == 0 ? nlohmann::json(nullptr)
                                                    : nlohmann::json(usb_id(p.vendor, p.product))},
         {"board", text_or_null(p.board)}});
  return out;
}

}  // namespace nibrig::ui::cli
