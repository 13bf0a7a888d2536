// `nibrig pen calibrate`: a pen's pressure curve measured with a kitchen scale (the pen pressed on
// it at a few loads, each held while the person presses Enter) and stored by the pen's name, where
// `audition --pen` and the panel's pad find it.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <iostream>
#include <mutex>

#include "rig/pen/pen_calibration.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/pen/pen_force_file.hpp"
#include "rig/pen/pen_input.hpp"
#include "rig/pen/pen_load.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {
namespace {

struct PenCalibrateOptions {
  std::string name;
  std::string tablet;
  std::vector<std::string> loads{"100g", "200g", "400g"};
  std::filesystem::path output;
};

void store_pen_calibration(const PenCalibrateOptions& o, const std::string& tablet, const std::string& method,
                           const rig::pen::PenCalibrator& calibrator, std::mutex& mutex) {
  rig::pen::PenCalibration calibration;
  calibration.name = o.name;
  calibration.method = method + ", on \"" + tablet + "\"";
  {
    std::lock_guard lock(mutex);
    calibration.curve = calibrator.fit();
    calibration.holds = calibrator.holds();
  }
  const auto file = o.output.empty() ? rig::pen::pen_curve_path(o.name) : o.output;
  rig::pen::write_pen_file(file, calibration);
  std::printf("pressure curve of '%s':", o.name.c_str());
  for (const auto& p : calibration.curve.points()) std::printf(" %.4f→%.3f N", p.pressure, p.force_n);
  std::printf("\n");
  say_wrote(file);
}

void pen_calibrate(const PenCalibrateOptions& o) {
  std::mutex mutex;
  rig::pen::PenCalibrator calibrator;
  std::vector<double> loads_n;
  for (const auto& text : o.loads) {
    try {
      loads_n.push_back(rig::pen::parse_pen_load(text));
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--load", e.what());
    }
  }
  if (loads_n.size() < 3) throw CLI::ValidationError("--load", "needs at least three loads for a curve");
  rig::pen::PenInput input(o.tablet, rig::pen::PenEvents{[&](const rig::pen::PenSample& s) {
                                                           std::lock_guard lock(mutex);
                                                           calibrator.add(s);
                                                         },
                                                         {}});
  std::printf("pen '%s' on \"%s\": press the pen's tip straight down on the scale at each load, hold it "
              "steady, and press Enter while it reads the load\n",
              o.name.c_str(), input.tablet().name.c_str());
  for (std::size_t i = 0; i < loads_n.size(); ++i) {
    while (true) {
      std::printf("load %zu of %zu: %s (%.3f N) - Enter when steady: ", i + 1, loads_n.size(), o.loads[i].c_str(),
                  loads_n[i]);
      std::fflush(stdout);
      std::string line;
      if (!std::getline(std::cin, line)) throw std::runtime_error("pen calibrate: input ended before every load was held");
      if (input.removed()) throw std::runtime_error("pen calibrate: the tablet was unplugged");
      try {
        std::lock_guard lock(mutex);
        const auto hold = calibrator.hold(loads_n[i], rig::pen::pen_clock_now_s());
        std::printf("held: pressure %.4f (sd %.4f, %zu reports)\n", hold.pressure, hold.pressure_sd, hold.samples);
        break;
      } catch (const rig::pen::PenCalibrationRefusal& e) {
        std::printf("not taken: %s; again\n", e.what());
      }
    }
  }
  store_pen_calibration(o, input.tablet().name, "kitchen scale", calibrator, mutex);
}

}  // namespace

void add_pen_command(CLI::App& app, std::shared_ptr<const GlobalOptions> global) {
  auto* pen = app.add_subcommand("pen", "Pen tablets as the stylus: calibrate a pen's pressure to force");
  pen->require_subcommand(1);
  auto c = std::make_shared<PenCalibrateOptions>();
  auto* cal = pen->add_subcommand(
      "calibrate", "Measure a pen's pressure curve (pressure to newtons) on a kitchen scale and store it");
  cal->add_option("--name", c->name, "The pen's name, which `audition --pen-name` finds it by")->required();
  cal->add_option("--tablet", c->tablet, "The tablet, by (part of) its name (default: the first)");
  cal->add_option("--load", c->loads, "The loads held, in order (e.g. 100g, 1.5N); at least three")
      ->capture_default_str();
  cal->add_option("-o,--output", c->output, "Pen file to write (default: the pen store)");
  cal->footer("Curves are stored per pen name in $NIBRIG_PENS, else $XDG_DATA_HOME/nibrig/pens, else\n"
              "~/.local/share/nibrig/pens. A pen without one plays with the default curve (0 to 4.9 N\n"
              "over the pressure range). Reading tablets needs the `input` group.");
  cal->callback([c, global] {
    configure_logging(global->verbosity);
    pen_calibrate(*c);
  });
}

}  // namespace nibrig::ui::cli
