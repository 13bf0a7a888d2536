// nibrig.audition: one to three tools played live on an audio device chosen by API and name, their
// speed and force set while they play, A, B or C selected, as `nibrig audition` and the panel do
// through a playback::LiveAudition. No call waits for the audio thread: a command the engine's
// queue cannot take yet is held by the audition and handed over by a pump thread of this face.
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>
#include <thread>

#include "model/design/tool_sound.hpp"
#include "model/numeric/cancellation.hpp"
#include "playback/actuator_file.hpp"
#include "playback/actuator_store.hpp"
#include "playback/audio_devices.hpp"
#include "playback/live_audition.hpp"
#include "playback/offline_render.hpp"
#include "rt/reference_load.hpp"
#include "rt/stroke_request.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/submodules.hpp"
#include "ui/python/tool_sound_options.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
using namespace std::chrono_literals;

namespace {

constexpr std::size_t kSlots = 3;  // A/B or the three of a triplet
constexpr double kDefaultForceN = rt::kReferenceNormalForce;  // the paper's recordings
constexpr double kDefaultSpeedM_s = 0.1;                      // a steady stroke, mid sweep

char letter_of(std::size_t slot) { return static_cast<char>('A' + slot); }

// A live contact is held to the ranges a rendered stroke is (playback/offline_render.hpp), as the
// command line's --speed and --force are: 1e308 m/s once played.
void check_speed(double speed_m_s) {
  rt::StrokeRequest request;
  request.speed_m_s = speed_m_s;
  playback::check_stroke_request(request);
}
void check_force(double force_n) {
  rt::StrokeRequest request;
  request.force_n = force_n;
  playback::check_stroke_request(request);
}

struct PlayerOptions {
  std::string api, device;
  unsigned channel = 1, rate = 0, period = 256;
  std::string name;
  std::optional<std::string> actuator;
};

class Player {
 public:
  explicit Player(const PlayerOptions& o) {
    ReleasedGil unlocked;
    const auto settings = playback::output_settings_for(o.api, o.device, o.rate, o.period, o.channel, o.name);
    rt::EngineSettings engine;
    engine.sample_rate_hz = settings.sample_rate;
    engine.slots = kSlots;
    audition_ = std::make_unique<playback::LiveAudition>(engine);
    if (o.actuator) {
      const auto calibration = playback::read_actuator_file(playback::find_actuator(*o.actuator));
      audition_->use_actuator(calibration, calibration.name);
    }
    audition_->open(settings);
    pump_ = std::jthread([this](std::stop_token stop) {
      while (!stop.stop_requested()) {
        {
          std::lock_guard lock(mutex_);
          if (audition_) audition_->pump();
        }
        std::this_thread::sleep_for(10ms);
      }
    });
  }
  ~Player() { close(); }
  Player(const Player&) = delete;
  Player& operator=(const Player&) = delete;

  void play(const std::vector<std::string>& tools, const std::string& surface, const std::optional<double>& speed,
            const std::optional<double>& force, const std::optional<std::filesystem::path>& trajectory, bool sweep,
            std::uint64_t seed, const std::optional<std::filesystem::path>& catalog,
            const std::optional<std::filesystem::path>& stylus, const std::optional<std::filesystem::path>& forcing,
            const py::object& progress) {
    open_or_throw();
    if (tools.empty() || tools.size() > kSlots)
      throw std::invalid_argument("tools names " + std::to_string(tools.size()) + "; expected one to three tools (A, B, C)");
    if (speed && (trajectory || sweep))
      throw std::invalid_argument("speed is for a constant stroke; give speed, trajectory or sweep, not two");
    if (trajectory && sweep) throw std::invalid_argument("trajectory and sweep are two strokes; give one");
    if (speed) check_speed(*speed);
    if (force) check_force(*force);
    std::vector<model::design::ToolSound> sounds;
    std::optional<rt::Stroke> stroke;
    run_long_call(
        [&](std::stop_token stop, const Report& report) {
          const auto options = tool_sound_options(catalog, stylus, forcing, stop, report);
          model::design::ToolSounds made(options);
          for (const auto& tool : tools) made.check(tool, surface);  // before any meshing or fitting
          for (const auto& tool : tools) sounds.push_back(made.sound(tool, surface));
          if (trajectory || sweep) {
            rt::StrokeRequest request;
            request.trajectory = trajectory.value_or(std::filesystem::path());
            request.force_n = force;
            stroke = rt::make_stroke(request);
          }
        },
        progress);
    std::lock_guard lock(mutex_);
    open_or_throw();
    for (std::size_t slot = 0; slot < kSlots; ++slot) loaded_[slot] = slot < tools.size();
    for (std::size_t slot = 0; slot < sounds.size(); ++slot) audition_->load(slot, sounds[slot], seed + slot);
    audition_->select(0);
    force_n_ = force.value_or(kDefaultForceN);
    if (stroke) {
      stroke_ = stroke->description;
      audition_->attach(std::move(stroke->source));
    } else {
      speed_m_s_ = speed.value_or(kDefaultSpeedM_s);
      contact_locked();
    }
  }

  void set_speed(double speed) {
    check_speed(speed);
    std::lock_guard lock(mutex_);
    open_or_throw();
    speed_m_s_ = speed;
    contact_locked();
  }
  void set_force(double force) {
    check_force(force);
    std::lock_guard lock(mutex_);
    open_or_throw();
    force_n_ = force;
    contact_locked();
  }
  std::optional<double> speed() const { return stroke_.empty() ? std::optional(speed_m_s_) : std::nullopt; }
  double force() const { return force_n_; }
  std::string stroke() const {
    if (!stroke_.empty()) return stroke_;
    char words[64];
    std::snprintf(words, sizeof words, "live contact %.0f mm/s, %.2f N", speed_m_s_ * 1e3, force_n_);
    return words;
  }

  void select(std::size_t slot) {
    std::lock_guard lock(mutex_);
    open_or_throw();
    if (slot >= kSlots) throw std::invalid_argument("slot " + std::to_string(slot) + " is out of range; expected 0-2 or 'A'-'C'");
    if (!loaded_[slot])
      throw std::invalid_argument(std::string("slot ") + letter_of(slot) + " holds no tool: play() gave fewer tools");
    audition_->select(slot);
  }
  void select_letter(const std::string& letter) {
    if (letter.size() != 1 || std::toupper(static_cast<unsigned char>(letter[0])) < 'A' ||
        std::toupper(static_cast<unsigned char>(letter[0])) > 'C')
      throw std::invalid_argument("slot '" + letter + "' is not one of 'A', 'B', 'C'");
    select(static_cast<std::size_t>(std::toupper(static_cast<unsigned char>(letter[0])) - 'A'));
  }
  std::string selected() const {
    std::lock_guard lock(mutex_);
    return std::string(1, letter_of(audition_ ? audition_->selected() : 0));
  }
  std::vector<std::string> names() {
    std::lock_guard lock(mutex_);
    std::vector<std::string> out;
    if (!audition_) return out;
    for (std::size_t slot = 0; slot < kSlots; ++slot)
      if (loaded_[slot]) out.push_back(audition_->names()[slot]);
    return out;
  }

  // The tools fall silent (the contact stops, ramped over a block); the device stays open.
  void stop() {
    std::lock_guard lock(mutex_);
    open_or_throw();
    stroke_.clear();
    speed_m_s_ = 0.0;
    force_n_ = 0.0;
    contact_locked();
  }

  void close() {
    std::unique_ptr<playback::LiveAudition> closing;
    {
      std::lock_guard lock(mutex_);
      closing.swap(audition_);
    }
    if (!closing) return;
    pump_.request_stop();
    ReleasedGil unlocked;
    if (pump_.joinable()) pump_.join();
    closing->close();
  }

  // How many commands wait for the engine's queue (the pump hands them over every 10 ms).
  std::size_t pending() {
    std::lock_guard lock(mutex_);
    return audition_ ? audition_->pump() : 0;
  }

  std::string status() const {
    std::lock_guard lock(mutex_);
    if (!audition_) return "closed";
    return audition_->output_status() == playback::OutputStatus::lost ? "lost" : "running";
  }
  std::string problem() const {
    std::lock_guard lock(mutex_);
    return audition_ ? audition_->last_problem() : "";
  }

  py::dict stream() const {
    std::lock_guard lock(mutex_);
    py::dict d;
    if (!audition_) return d;
    const auto info = *audition_->stream_info();
    d["api"] = info.api, d["device"] = info.device, d["rate_hz"] = info.sample_rate;
    d["period_frames"] = info.period_frames, d["output_channels"] = info.output_channels;
    d["latency_frames"] = info.latency_frames;
    d["actuator"] = audition_->actuator();
    return d;
  }

  py::dict stats() const {
    std::lock_guard lock(mutex_);
    py::dict d;
    if (!audition_) return d;
    const auto e = audition_->engine_stats();
    const auto o = *audition_->output_stats();
    d["callbacks"] = o.callbacks, d["frames"] = o.frames, d["underflows"] = o.output_underflows;
    d["losses"] = o.losses, d["reconnects"] = o.reconnects;
    d["engine_overruns"] = e.overruns, d["peak_output"] = e.peak_output, d["limited_samples"] = e.limited_samples;
    d["callback_median_s"] = e.callback_time_quantile(0.5);
    d["callback_p99_s"] = e.callback_time_quantile(0.99);
    d["callback_max_s"] = e.max_callback_s;
    return d;
  }

 private:
  void open_or_throw() const {
    if (!audition_) throw std::invalid_argument("this player is closed; open another");
  }
  void contact_locked() { audition_->set_contact(speed_m_s_, force_n_); }

  mutable std::mutex mutex_;  // between Python's calls and the pump; neither holds it while waiting on audio
  std::unique_ptr<playback::LiveAudition> audition_;
  std::array<bool, kSlots> loaded_{};
  double speed_m_s_ = 0.0, force_n_ = kDefaultForceN;
  std::string stroke_;  // the attached stroke, in words; empty: a live contact
  std::jthread pump_;
};

py::list device_list(const std::optional<std::string>& api) {
  std::vector<playback::ApiDevices> apis;
  {
    ReleasedGil unlocked;
    if (api) {
      apis.push_back(playback::list_devices(*api));
    } else {
      apis = playback::list_devices();
    }
  }
  py::list out;
  for (const auto& a : apis) {
    py::list devices;
    for (const auto& d : a.devices) {
      py::dict device;
      device["name"] = d.name, device["outputs"] = d.output_channels, device["inputs"] = d.input_channels;
      device["rates_hz"] = d.sample_rates, device["preferred_rate_hz"] = d.preferred_sample_rate;
      device["default_output"] = d.default_output, device["default_input"] = d.default_input;
      devices.append(device);
    }
    py::dict entry;
    entry["api"] = a.api, entry["name"] = a.display_name, entry["available"] = a.available;
    entry["unavailable_reason"] = a.unavailable_reason, entry["devices"] = devices;
    out.append(entry);
  }
  return out;
}

}  // namespace

void add_audition_module(py::module_ m) {
  const std::string player_doc = fmt::format(
      "Loads one to three tools (catalog names or design points) into A, B, C on a surface and "
      "plays A: a live "
      "contact at speed m/s (default {:g}) and force N (default {:g}, the paper's), or a drawing's "
      "trajectory, "
      "or the rig's sweep (sweep=True). Building a design's sound may fit the forcing model once: "
      "progress (step, done, total); the GIL is released; Ctrl-C stops it.",
      kDefaultSpeedM_s, kDefaultForceN);
  py::class_<Player>(
      m, "Player",
      "One to three tools played live on an audio device: slots A, B, C, one heard at a time")
      .def(py::init([](const std::optional<std::string>& api,
                       const std::optional<std::string>& device, unsigned channel, unsigned rate,
                       unsigned period, const std::string& name,
                       const std::optional<std::string>& actuator) {
             return std::make_unique<Player>(
                 PlayerOptions{api.value_or(""), device.value_or(""), channel, rate, period, name, actuator});
           }),
           py::arg("api") = py::none(), py::arg("device") = py::none(), py::kw_only(),
           py::arg("channel") = 1u, py::arg("rate") = 0u, py::arg("period") = 256u,
           py::arg("name") = "nibrig-python", py::arg("actuator") = py::none(),
           "Opens a device by API ('jack', 'alsa', 'pulse'; None: the first with an output) and "
           "name (exact, or "
           "a unique part; None: the API's default), playing silence until play(). channel: "
           "1-based output; "
           "rate in Hz (0: the device's own; JACK: the server's); period in frames (JACK uses its "
           "server's); "
           "name: the JACK client's; actuator: a calibration by name or file (`nibrig calibrate`), "
           "its inverse "
           "filter then applied. Raises OSError naming what was asked when the device is not "
           "there.")
      .def("play", &Player::play, py::arg("tools"), py::arg("surface"), py::kw_only(),
           py::arg("speed") = py::none(), py::arg("force") = py::none(),
           py::arg("trajectory") = py::none(), py::arg("sweep") = false, py::arg("seed") = 1u,
           py::arg("catalog") = py::none(), py::arg("stylus") = py::none(),
           py::arg("forcing") = py::none(), py::arg("progress") = py::none(), player_doc.c_str())
      .def_property("speed", &Player::speed, &Player::set_speed,
                    "The live contact's speed, m/s (None while a trajectory or sweep moves the "
                    "tools); setting it "
                    "replaces that stroke with a live contact, ramped over one block")
      .def_property("force", &Player::force, &Player::set_force,
                    "The live contact's normal force, N")
      .def_property_readonly("stroke", &Player::stroke, "What moves the tools, in words")
      .def("select", &Player::select_letter, py::arg("slot"),
           "Crossfades to slot 'A', 'B' or 'C' (20 ms)")
      .def("select", &Player::select, py::arg("slot"), "Crossfades to slot 0, 1 or 2 (20 ms)")
      .def_property_readonly("selected", &Player::selected, "The slot heard: 'A', 'B' or 'C'")
      .def_property_readonly("names", &Player::names,
                             "The tools in A, B, C as the engine names them")
      .def("stop", &Player::stop,
           "The tools fall silent (contact speed and force 0); the device stays open")
      .def("close", &Player::close, "Closes the device; the player cannot play again")
      .def_property_readonly(
          "pending", &Player::pending,
          "Commands held until the engine's queue takes them (handed over every 10 ms)")
      .def_property_readonly("status", &Player::status,
                             "'running', 'lost' (looked for again every 200 ms) or 'closed'")
      .def_property_readonly("problem", &Player::problem,
                             "Why the device was last lost; '' while nothing went wrong")
      .def_property_readonly("stream", &Player::stream,
                             "What was opened: api, device, rate_hz, period_frames, "
                             "output_channels, latency_frames, actuator")
      .def_property_readonly(
          "stats", &Player::stats,
          "callbacks, frames, underflows, losses, reconnects, engine_overruns, peak_output (full "
          "scale 1), limited_samples, callback_median_s / _p99_s / _max_s")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](Player& p, const py::args&) { p.close(); });

  m.def("devices", &device_list, py::arg("api") = py::none(),
        "Every audio API compiled in with its devices (or one API): api, name, available, unavailable_reason, "
        "devices (name, outputs, inputs, rates_hz, preferred_rate_hz, default_output, default_input)");
}

}  // namespace nibrig::ui::python
