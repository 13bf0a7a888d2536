// `nibrig pen calibrate`: a pen's pressure curve measured with a kitchen scale (the pen pressed on
// it at a few loads, each held while the person presses Enter) or on the rig's force sensor
// (`--rig`, the loads read from it), and stored by the pen's name, where `audition --pen` and the
// panel's pad find it.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <iostream>
#include <mutex>

#include "rig/pen/pen_calibration.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/pen/pen_force_file.hpp"
#include "rig/pen/pen_input.hpp"
#include "rig/pen/pen_load.hpp"
#include "rig/pen/pen_rig_load.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {
namespace {

struct PenCalibrateOptions {
  std::string name;
  std::string tablet;
  std::vector<std::string> loads{"100g", "200g", "400g"};
  bool rig = false;  // the loads from the rig's normal-force sensor instead
  std::string serial;
  unsigned holds = 4;
  std::filesystem::path output;
};

// Each of o.holds loads as the rig's sensor reads it, the pen pressed on the sensor a little harder
// each time.
void pen_calibrate_on_rig(const PenCalibrateOptions& o, rig::pen::PenInput& input, rig::pen::PenCalibrator& calibrator,
                          std::mutex& mutex) {
  rig::pen::RigLoadReader rig(o.serial);
  std::printf("pen '%s' on \"%s\", loads from the rig %s: press the pen's tip straight down on the rig's "
              "force sensor, a little harder at each hold, hold it steady, and press Enter\n",
              o.name.c_str(), input.tablet().name.c_str(), rig.serial().c_str());
  const double window = rig::pen::PenCalibrationSettings{}.window_s;
  for (unsigned i = 0; i < o.holds; ++i) {
    while (true) {
      std::printf("hold %u of %u - Enter when steady: ", i + 1, o.holds);
      std::fflush(stdout);
      std::string line;
      if (!std::getline(std::cin, line)) throw std::runtime_error("pen calibrate: input ended before every load was held");
      if (input.removed()) throw std::runtime_error("pen calibrate: the tablet was unplugged");
      try {
        const double now = rig::pen::pen_clock_now_s();
        const double load = rig.load_n(now, window);
        std::lock_guard lock(mutex);
        const auto hold = calibrator.hold(load, now);
        std::printf("held: %.3f N, pressure %.4f (sd %.4f, %zu reports)\n", load, hold.pressure, hold.pressure_sd,
                    hold.samples);
        break;
      } catch (const rig::pen::PenCalibrationRefusal& e) {
        std::printf("not taken: %s; again\n", e.what());
      }
    }
  }
}

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
  if (o.rig) {
    if (o.holds < 3) throw CLI::ValidationError("--holds", "needs at least three holds for a curve");
    rig::pen::PenInput input(o.tablet, rig::pen::PenEvents{[&](const rig::pen::PenSample& s) {
                                                             std::lock_guard lock(mutex);
                                                             calibrator.add(s);
                                                           },
                                                           {}});
    pen_calibrate_on_rig(o, input, calibrator, mutex);
    store_pen_calibration(o, input.tablet().name, "the rig's normal-force sensor", calibrator, mutex);
    return;
  }
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
      "calibrate", "Measure a pen's pressure curve (pressure to newtons) on a kitchen scale or the rig and store it");
  cal->add_option("--name", c->name, "The pen's name, which `audition --pen-name` finds it by")->required();
  cal->add_option("--tablet", c->tablet, "The tablet, by (part of) its name (default: the first)");
  auto* load = cal->add_option("--load", c->loads, "The loads held, in order (e.g. 100g, 1.5N); at least three")
                   ->capture_default_str();
  cal->add_option("--holds", c->holds, "With --rig: how many holds, each pressed a little harder")->capture_default_str();
  cal->add_flag("--rig", c->rig,
                "Take each load from the USB rig's normal-force sensor (the pen pressed on it) instead of --load")
      ->excludes(load);
  cal->add_option("--serial", c->serial, "With --rig: the rig controller's serial (default: the only one)");
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
