// The work of `nibrig experiment run|report` (registered in cmd_experiment.cpp): a triplet study
// with a person at the terminal or a simulated participant, on the actuator or the turntable, and
// its report. The study itself is model/study; its start and presenters are rig/study/study_start and
// rig/study/*_presenter.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "rig/accelerometer_input.hpp"
#include "ui/cli/device_options.hpp"

namespace nibrig::ui::cli {

struct ExperimentRunOptions {
  std::filesystem::path stimuli;  // required for a new study; on --resume the study's own
  std::string mode = "actuator";
  std::string participant;
  std::filesystem::path simulate;  // a space: a simulated participant answers, nothing is played
  double lapse_rate = 0.0;
  double pace = 0.0;  // with --simulate: wait its response times divided by this; 0: no waiting
  std::optional<std::uint64_t> seed;
  std::string plan = "two-stage";  // two-stage, adaptive, or a trial list file
  std::size_t trials = 0, practice = 3, break_every = 100, dims = 2;
  bool resume = false;
  bool simulated_rig = false;
  std::optional<double> rig_speedup;  // none: real time for a person, as fast as it computes with --simulate
  std::optional<std::string> usb;  // rig mode with the USB controller ("" = the only one)
  std::string input_api, input;   // its accelerometer's audio input
  unsigned input_channel = 1;
  double accelerometer = rig::kDefaultAccelerometerM_s2;
  std::filesystem::path instructions, consent;
  std::filesystem::path catalog, design, forcing_model;
  DeviceOptions device;
  std::string actuator;
  std::filesystem::path output;  // the study folder
};
void run_experiment(const ExperimentRunOptions& options, unsigned threads);

struct ExperimentReportOptions {
  std::filesystem::path study, output;  // output: default study/report
  std::filesystem::path space;          // the space a validation study tests
  std::filesystem::path catalog;
  bool all_judgments = false;
  int bootstrap = 200, starts = 16;
  unsigned seed = 1;
};
void run_experiment_report(const ExperimentReportOptions& options, unsigned threads);

}  // namespace nibrig::ui::cli
