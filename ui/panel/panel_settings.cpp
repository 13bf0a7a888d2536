#include "ui/panel/panel_settings.hpp"

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/finite_output.hpp"
#include "ui/panel/devices_view.hpp"
#include "ui/panel/experiment_view.hpp"
#include "ui/panel/file_dialog.hpp"

namespace nibrig::ui::panel {

namespace {

using nlohmann::json;

template <typename T>
void take(const json& j, const char* key, T& value) {
  if (j.contains(key)) value = j.at(key).get<T>();
}

}  // namespace

std::filesystem::path panel_settings_file() {
  if (const char* f = std::getenv("NIBRIG_PANEL_SETTINGS"); f && *f) return f;
  if (const char* d = std::getenv("XDG_CONFIG_HOME"); d && *d) return std::filesystem::path(d) / "nibrig" / "panel.json";
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home && *home ? home : ".") / ".config" / "nibrig" / "panel.json";
}

PanelSettings read_panel_settings(const std::filesystem::path& file) {
  PanelSettings s;
  if (!std::filesystem::exists(file)) return s;
  try {
    const json j = model::io::json_fields::parse_file(file);
    if (!j.is_object()) throw std::runtime_error("expected an object of settings");
    if (j.contains("view")) {
      const auto v = view_named(j.at("view").get<std::string>());
      if (!v) throw std::runtime_error("view '" + j.at("view").get<std::string>() + "' is none of the panel's");
      s.view = *v;
    }
    if (j.contains("device")) {
      const json& d = j.at("device");
      DeviceRequest r;
      take(d, "api", r.api);
      take(d, "device", r.device);
      take(d, "output_channel", r.output_channel);
      take(d, "period_frames", r.period_frames);
      s.device = r;
    }
    if (j.contains("space")) s.space = j.at("space").get<std::string>();
    if (j.contains("stroke")) {
      const json& t = j.at("stroke");
      take(t, "kind", s.stroke.kind);
      take(t, "speed_mm_s", s.stroke.speed_mm_s);
      take(t, "force_n", s.stroke.force_n);
      take(t, "trajectory", s.stroke.trajectory);
      if (s.stroke.kind < 0 || s.stroke.kind > 2) throw std::runtime_error("stroke kind must be 0, 1 or 2");
    }
    if (j.contains("experiment")) {
      const json& e = j.at("experiment");
      take(e, "study", s.study);
      take(e, "stimuli", s.stimuli);
    }
    if (j.contains("design")) take(j.at("design"), "printer", s.printer);
    if (j.contains("files")) {
      std::string folder;
      take(j.at("files"), "last_folder", folder);
      s.dialog_folder = folder;
    }
    if (j.contains("rig")) {
      const json& r = j.at("rig");
      take(r, "kind", s.rig.kind);
      take(r, "tool", s.rig.tool);
      take(r, "surface", s.rig.surface);
      take(r, "simulated_tool", s.rig.simulated_tool);
      take(r, "profile", s.rig.profile);
      take(r, "seconds", s.rig.seconds);
      take(r, "replay", s.rig.replay);
      take(r, "usb_serial", s.rig.usb_serial);
      take(r, "input_api", s.rig.input_api);
      take(r, "input_device", s.rig.input_device);
      take(r, "input_channel", s.rig.input_channel);
      take(r, "speedup", s.rig.speedup);
      take(r, "play_on_actuator", s.rig.play_on_actuator);
      if (s.rig.kind < 0 || s.rig.kind > 2) throw std::runtime_error("rig kind must be 0, 1 or 2");
    }
  } catch (const model::io::FormatError& e) {
    throw std::runtime_error(std::string(e.what()) + " (the defaults are used; the file is rewritten on exit)");
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what() + " (the defaults are used; the file is rewritten on exit)");
  }
  return s;
}

void write_panel_settings(const std::filesystem::path& file, const PanelSettings& s) {
  json j;
  j["format"] = "nibrig-panel-settings";
  j["view"] = view_name(s.view);
  if (s.device)
    j["device"] = {{"api", s.device->api},
                   {"device", s.device->device},
                   {"output_channel", s.device->output_channel},
                   {"period_frames", s.device->period_frames}};
  if (!s.space.empty()) j["space"] = s.space.string();
  j["stroke"] = {{"kind", s.stroke.kind},
                 {"speed_mm_s", s.stroke.speed_mm_s},
                 {"force_n", s.stroke.force_n},
                 {"trajectory", s.stroke.trajectory}};
  j["rig"] = {{"kind", s.rig.kind},           {"tool", s.rig.tool},
              {"surface", s.rig.surface},     {"simulated_tool", s.rig.simulated_tool},
              {"profile", s.rig.profile},     {"seconds", s.rig.seconds},
              {"replay", s.rig.replay},       {"usb_serial", s.rig.usb_serial},
              {"input_api", s.rig.input_api}, {"input_device", s.rig.input_device},
              {"input_channel", s.rig.input_channel}, {"speedup", s.rig.speedup},
              {"play_on_actuator", s.rig.play_on_actuator}};
  j["experiment"] = {{"study", s.study}, {"stimuli", s.stimuli}};
  j["files"] = {{"last_folder", s.dialog_folder.string()}};
  j["design"] = {{"printer", s.printer}};
  std::filesystem::create_directories(file.parent_path());
  model::io::write_file_atomically(file, model::io::json_text(j, file));
}

void apply_panel_settings(Panel& panel, const PanelSettings& settings) {
  panel.show(settings.view);
  panel.audio().stroke() = settings.stroke;
  panel.audio().stroke_changed();
  panel.rig_view().choice() = settings.rig;
  panel.experiment_view().form().study = settings.study;
  panel.experiment_view().form().stimuli = settings.stimuli;
  FileDialog::remember_last_folder(settings.dialog_folder);
  panel.design_view().set_printer(settings.printer);
}

PanelSettings panel_settings_of(Panel& panel) {
  PanelSettings kept;
  kept.view = panel.current();
  kept.device = panel.devices_view().shown_request();
  kept.space = panel.space_file();
  kept.stroke = panel.audio().stroke();
  kept.rig = panel.rig_view().choice();
  kept.study = panel.experiment_view().form().study;
  kept.stimuli = panel.experiment_view().form().stimuli;
  kept.dialog_folder = FileDialog::last_folder();
  kept.printer = panel.design_view().printer();
  return kept;
}

}  // namespace nibrig::ui::panel
