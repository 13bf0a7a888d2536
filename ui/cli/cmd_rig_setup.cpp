// `nibrig rig calibrate` and `nibrig rig flash`: setting up a rig controller a lab has built. The
// work is rig/usb's (calibrate_controller, flash_firmware); this file holds the options, the
// prompts at the terminal and the printing.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "rig/usb/controller_calibration.hpp"
#include "rig/usb/firmware_flash.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/device_json.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {
namespace {

struct RigCalibrateOptions {
  std::string serial;  // the controller; empty: the only one
  bool zero = false;
  std::string normal_weight, tangential_weight;  // with units, parsed by rig::usb::parse_weight_N
  std::optional<double> lever, radius_mm, counts_per_revolution;
  std::optional<std::string> new_serial;
  bool yes = false;
  double seconds = 1.0;
  std::filesystem::path json;
};

struct RigFlashOptions {
  std::string serial;
  std::string port;
  std::string hex;
  std::filesystem::path json;
};

void print_rig_calibration(const char* label, const rig::usb::ForceCalibration& c) {
  std::printf("%s: normal %.6g counts/N, tangential %.6g counts/N, lever factor %.6g\n", label,
              c.normal_counts_per_N, c.tangential_counts_per_N, c.lever_factor);
}

void print_rig_force_reading(const char* channel, const std::optional<rig::usb::ForceReading>& r, double known_N) {
  if (!r) return;
  std::printf("%s channel: read %.4f N (spread %.4f N, %zu frames) with %.4f N on it\n", channel, r->mean_N,
              r->std_dev_N, r->frames, known_N);
}

nlohmann::json force_calibration_json(const rig::usb::ForceCalibration& c) {
  return {{"normal_counts_per_N", c.normal_counts_per_N},
          {"tangential_counts_per_N", c.tangential_counts_per_N},
          {"lever_factor", c.lever_factor}};
}

nlohmann::json force_reading_json(const std::optional<rig::usb::ForceReading>& r,
                                  const std::optional<double>& known_N) {
  if (!r) return nullptr;
  return {{"known_N", *known_N},
          {"read_N", r->mean_N},
          {"spread_N", r->std_dev_N},
          {"frames", r->frames}};
}

// What `rig calibrate` prints, as numbers (ui/cli/README.md, "Output files").
nlohmann::json rig_calibration_json(const rig::usb::ControllerCalibrationResult& result,
                                    const rig::usb::ControllerCalibrationSteps& steps) {
  nlohmann::json geometry = nullptr;
  if (result.geometry)
    geometry = {{"counts_per_revolution", result.geometry->counts_per_revolution},
                {"track_radius_mm", result.geometry->track_radius_m * 1000.0}};
  return {{"controller",
           {{"serial", result.identity.serial},
            {"protocol_version", rig::usb::version_text(result.identity.protocol_version)},
            {"firmware", result.identity.firmware}}},
          {"normal", force_reading_json(result.normal, steps.normal_weight_N)},
          {"tangential", force_reading_json(result.tangential, steps.tangential_weight_N)},
          {"before", force_calibration_json(result.before)},
          {"after", force_calibration_json(result.after)},
          {"geometry", geometry}};
}

void calibrate_rig_controller(const RigCalibrateOptions& o) {
  rig::usb::ControllerCalibrationSteps steps;
  steps.zero = o.zero;
  try {
    if (!o.normal_weight.empty()) steps.normal_weight_N = rig::usb::parse_weight_N(o.normal_weight, "--normal-weight");
    if (!o.tangential_weight.empty()) {
      steps.tangential_weight_N = rig::usb::parse_weight_N(o.tangential_weight, "--tangential-weight");
    }
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());
  }
  steps.lever_factor = o.lever;
  if (o.radius_mm) steps.track_radius_m = *o.radius_mm / 1000.0;
  steps.counts_per_revolution = o.counts_per_revolution;
  if (o.new_serial) {
    if (const std::string problem = rig::usb::serial_problem(*o.new_serial); !problem.empty()) {
      throw CLI::ValidationError("--serial", problem);
    }
    steps.serial = o.new_serial;
  }
  steps.average_s = o.seconds;
  if (!steps.zero && !steps.normal_weight_N && !steps.tangential_weight_N && !steps.lever_factor &&
      !steps.track_radius_m && !steps.counts_per_revolution && !steps.serial) {
    throw CLI::ValidationError(
        "nothing to do: give --zero, --normal-weight, --tangential-weight, --lever, --radius, --counts-per-rev "
        "or --serial");
  }
  rig::usb::UsbRigController::Options controller;
  controller.serial = o.serial;
  rig::usb::UsbRigController rig(controller);
  const bool yes = o.yes;
  const auto prompt = [yes](const std::string& instruction) {
    if (yes) {
      std::printf("%s (--yes: not waiting)\n", instruction.c_str());
      std::fflush(stdout);
      return;
    }
    std::printf("%s, then press Enter. ", instruction.c_str());
    std::fflush(stdout);
    std::string line;
    if (!std::getline(std::cin, line)) {
      throw std::runtime_error("the terminal closed before \"" + instruction +
                               "\" was confirmed; give --yes to run without waiting");
    }
  };
  const auto result = rig::usb::calibrate_controller(rig, steps, prompt);
  std::printf("rig controller %s (protocol %s, firmware %s)\n", result.identity.serial.c_str(),
              rig::usb::version_text(result.identity.protocol_version).c_str(), result.identity.firmware.c_str());
  print_rig_force_reading("normal", result.normal, steps.normal_weight_N.value_or(0.0));
  print_rig_force_reading("tangential", result.tangential, steps.tangential_weight_N.value_or(0.0));
  print_rig_calibration("before", result.before);
  print_rig_calibration("now on the device", result.after);
  if (result.geometry) {
    std::printf("geometry on the device: %.6g encoder counts per revolution, track radius %.3f mm\n",
                result.geometry->counts_per_revolution, result.geometry->track_radius_m * 1000.0);
  }
  write_json_numbers(o.json, rig_calibration_json(result, steps));
}

void flash_rig_controller(const RigFlashOptions& o) {
  rig::usb::FirmwareFlashOptions options;
  options.serial = o.serial;
  if (!o.port.empty()) options.port = o.port;
  if (!o.hex.empty()) options.hex = o.hex;
  const auto result = rig::usb::flash_firmware(options, [](const std::string& step) {
    std::printf("%s\n", step.c_str());
    std::fflush(stdout);
  });
  std::printf("flashed %s; the rig controller is back: %s\n", result.hex.string().c_str(),
              rig::usb::describe(result.controller).c_str());
  write_json_numbers(o.json, {{"hex", result.hex.string()},
                              {"port", serial_ports_json({result.port}).front()},
                              {"controller", rig_controllers_json({result.controller}).front()}});
}

}  // namespace

void add_rig_setup_commands(CLI::App* rig_cmd, std::shared_ptr<const GlobalOptions> global) {
  auto c = std::make_shared<RigCalibrateOptions>();
  auto* cal = rig_cmd->add_subcommand(
      "calibrate",
      "Set up a USB rig controller: zero and calibrate its force channels with known weights, its lever, "
      "turntable geometry and serial; writes each to the device and prints what it holds");
  cal->add_option("--usb", c->serial, "The controller, by serial (default: the only one)");
  cal->add_flag("--zero", c->zero, "Zero both force channels with the tip lifted and no weight on the arm");
  cal->add_option("--normal-weight", c->normal_weight,
                  "Calibrate the normal channel with this weight on the tip: \"200g\", \"0.2kg\" or \"1.96N\"");
  cal->add_option("--tangential-weight", c->tangential_weight,
                  "Calibrate the tangential channel with this weight pulling the tip over a pulley");
  cal->add_option_function<double>("--lever", [c](const double& v) { c->lever = v; },
                                   "Lever factor: force at the tip / force at the sensor (kept by the weights' calibration)")
      ->check(in_range(1e-3, 1e3, "a lever factor"));
  cal->add_option_function<double>("--radius", [c](const double& v) { c->radius_mm = v; },
                                   "Track radius in mm: the circle the tip runs on (protocol 1.1)")
      ->check(in_range(1.0, 1000.0, "a radius in mm"));
  cal->add_option_function<double>("--counts-per-rev", [c](const double& v) { c->counts_per_revolution = v; },
                                   "Encoder counts per turntable revolution, all quadrature edges (protocol 1.1)")
      ->check(in_range(1.0, 1e7, "counts per revolution"));
  cal->add_option_function<std::string>("--serial", [c](const std::string& v) { c->new_serial = v; },
                                        "Give the controller this serial (up to 16 printable characters, no spaces)");
  cal->add_flag("--yes", c->yes, "Do not wait for Enter at each step: the arm is already as the step asks (scripts)");
  cal->add_option("--seconds", c->seconds, "Frames averaged for each weight, in seconds (default 1)")
      ->check(in_range(0.05, 60.0, "a length in seconds"));
  add_json_option(cal, c->json, "what the device holds and the readings");
  cal->callback([c, global] {
    configure_logging(global->verbosity);
    calibrate_rig_controller(*c);
  });

  auto f = std::make_shared<RigFlashOptions>();
  auto* fl = rig_cmd->add_subcommand(
      "flash",
      "Write the reference controller's firmware (rig/firmware) to its ATmega32U4 board through the board's "
      "bootloader with avrdude, and wait for it to come back");
  fl->add_option("--usb", f->serial, "The controller to flash, by serial (default: the only one)");
  fl->add_option("--port", f->port,
                 "The bootloader's serial port, when you pressed the board's reset button (e.g. /dev/ttyACM0); "
                 "without it the controller is asked into its bootloader");
  fl->add_option(
      "--hex", f->hex,
      "The firmware (default: $NIBRIG_FIRMWARE_HEX, else the installed "
      "share/nibrig/firmware/nibrig-rig.hex, else this build's rig/firmware/nibrig-rig.hex)");
  add_json_option(fl, f->json, "the controller as it came back");
  fl->callback([f, global] {
    configure_logging(global->verbosity);
    flash_rig_controller(*f);
  });
}

}  // namespace nibrig::ui::cli
