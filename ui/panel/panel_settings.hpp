// What the panel remembers between runs: the view it showed, the actuator's device, the space it
// had open, the stroke, the rig's choices and the experiment's study folder and stimulus list. Kept as JSON in $XDG_CONFIG_HOME/nibrig/panel.json
// (else ~/.config/nibrig/panel.json), written atomically when the panel closes; a file that cannot
// be read is reported in the window and the defaults are used (never a crash).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "ui/panel/panel.hpp"
#include "ui/panel/rig_view.hpp"

namespace nibrig::ui::panel {

struct PanelSettings {
  View view = View::space;
  std::optional<DeviceRequest> device;
  std::filesystem::path space;
  StrokeChoice stroke;
  RigChoice rig;
  // The experiment view's study folder and stimulus list: a study runs over days, one
  // participant a start, and the form had come back empty each time.
  std::string study, stimuli;
  // Where a file was last chosen in a dialog: where the next start's dialogs open.
  std::filesystem::path dialog_folder;
  std::string printer;  // the design view's export printer (empty: none)
};

// $NIBRIG_PANEL_SETTINGS, else $XDG_CONFIG_HOME/nibrig/panel.json, else ~/.config/nibrig/panel.json.
std::filesystem::path panel_settings_file();
// The settings in `file`; defaults when it does not exist. Throws std::runtime_error naming the
// file and what is wrong in it.
PanelSettings read_panel_settings(const std::filesystem::path& file);
void write_panel_settings(const std::filesystem::path& file, const PanelSettings& settings);

// What a panel shows of `settings` once it runs (the view, the stroke every view plays, the rig's
// choice; the device and space are PanelSetup's), and what it would remember now.
void apply_panel_settings(Panel& panel, const PanelSettings& settings);
PanelSettings panel_settings_of(Panel& panel);

}  // namespace nibrig::ui::panel
