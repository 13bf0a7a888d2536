// A rig as a person asks for it — "the simulated rig with vero2 on office", "the USB controller
// NR-0001 with the accelerometer on input 1 of Scarlett", "replay this session" — opened the same
// way for every face, with its speed profile.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "model/io/rig_session_json.hpp"
#include "rig/accelerometer_input.hpp"
#include "rig/rig.hpp"
#include "rig/speed_profile.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::model::design {
class ToolSounds;
}

namespace nibrig::rig {

enum class RigKind { simulated, usb, replay };

// The ranges every face holds a rig request to (the command line's options are checked against the
// same numbers). A capture shorter than one sensor block says nothing; the longest is the longest
// profile. The paper's arm pressed with 2.2 N; a hundredth of a newton is a pen resting on paper,
// and 50 N breaks a tip.
inline constexpr double kShortestCaptureSeconds = 0.01;
inline constexpr double kLightestLoadN = 0.01;
inline constexpr double kHeaviestLoadN = 50.0;
// An accelerometer's m/s² at full scale (`calibrate --accelerometer`): 0.001 g to 100 000 g, the
// range a session's reader holds session.json to (model/io/rig_session_json.hpp).
inline constexpr double kLeastAccelerometerM_s2 = model::io::session_json::kLeastAccelerometerM_s2PerUnit;
inline constexpr double kMostAccelerometerM_s2 = model::io::session_json::kMostAccelerometerM_s2PerUnit;

// Throw std::invalid_argument "<who>: <value>: expected ..." for a value outside those ranges (or
// not finite); `who` is the option or argument that set it ("--load", "load"), or empty for the
// value alone (a refusal whose face names it).
void check_capture_seconds(double seconds, const std::string& who);
void check_load(double load_N, const std::string& who);
void check_accelerometer_scale(double m_s2_per_full_scale, const std::string& who);

struct RigRequest {
  RigKind kind = RigKind::simulated;
  // What is mounted: required for the simulated rig (it simulates it); for the others, what the
  // session will say (a replayed session knows its own).
  std::string tool, surface;
  double load_N = rt::kReferenceNormalForce;
  std::uint64_t seed = 1;  // the simulated rig's noise
  // 1 = real time; k > 1 = k times faster; 0 = as fast as it computes (simulated and replay rigs).
  double speedup = 1.0;
  std::filesystem::path replay;  // a session folder, or a paper recording (replay rig)
  std::filesystem::path replay_friction;  // a paper friction recording played beside `replay`
  std::string usb_serial;        // empty: the only controller on the bus
  std::string input_api;         // the accelerometer's audio back end (USB rig); empty: any
  std::string input_device;      // the accelerometer's audio input (USB rig)
  unsigned input_channel = 1;    // 1-based
  double accelerometer_m_s2_per_full_scale = kDefaultAccelerometerM_s2;
};

// Why a rig job (a capture, a comparison) cannot start: which part of the request is at fault (a
// face names its own option or argument for it) and, in what(), the value and what was expected,
// without the field's name.
class RigRequestRefused : public std::invalid_argument {
 public:
  enum class Field {
    rig,            // no rig named
    tool,           // the simulated rig's tool: missing, or unknown to the catalog
    surface,        // the simulated rig's surface: missing, or unknown to the catalog
    load,           // outside kLightestLoadN..kHeaviestLoadN
    speedup,        // neither 0 nor within the pacer's range
    accelerometer,  // the USB rig's scale, outside its range
    input_channel,  // the USB rig's input channel: 0, or beyond playback::kMostOutputChannels
    replay,         // a replay of nothing
    profile,        // an unknown profile, or one a replayed rig cannot run
    seconds,        // a length outside kShortestCaptureSeconds..kMaxProfileSeconds
    simulate,       // what to simulate: unknown, or unsaid on a rig that does not know its tool
  };
  RigRequestRefused(Field field, const std::string& what);
  Field field() const noexcept { return field_; }

 private:
  Field field_;
};

// "rig", "tool", "surface", "load", "speedup", "accelerometer", "input_channel", "replay",
// "profile", "seconds", "simulate": the Python arguments' names.
const char* field_name(RigRequestRefused::Field field);

// Everything about the request that can be refused without opening a device or reading a file:
// what its kind needs and the ranges above. Throws RigRequestRefused.
void check_rig_request(const RigRequest& request);

// Opens the rig, after check_rig_request. `sounds` makes the simulated tool (a catalog pairing or a
// design point) and gives the catalog's μ for it; it is used only by the simulated rig. Throws
// std::invalid_argument for a request that cannot be met (RigRequestRefused; what a session's
// reader throws for a broken one) and std::runtime_error when a device is missing (naming what was
// found instead).
std::unique_ptr<Rig> open_rig(const RigRequest& request, model::design::ToolSounds& sounds);

// "steps" (the paper's protocol: 3 sweeps of six 2 s steps over 17-250 mm/s, 42 s), "sweep" (the
// user study's 3 s sweep, two periods) or a CSV file (rig/speed_profile.hpp); `seconds` cuts or
// repeats it (checked as check_capture_seconds does). Throws RigRequestRefused (profile, seconds);
// FormatError naming a broken file.
SpeedProfile profile_named(const std::string& name_or_file, std::optional<double> seconds);

// The profile a rig is to run, checked before it opens: `profile` (empty: `default_profile`) cut or
// repeated to `seconds`; nullopt for a replayed rig, which runs what it recorded and refuses
// another. Throws RigRequestRefused (profile, seconds) and what profile_named throws.
std::optional<SpeedProfile> profile_to_run(const RigRequest& request, const std::string& profile,
                                           const std::string& default_profile,
                                           std::optional<double> seconds);

// A rig opened with the profile it is to run, as every face opens one (profile_to_run's, or a
// replay's own cut to `seconds`). Throws what open_rig and profile_to_run throw.
struct OpenedRig {
  std::unique_ptr<Rig> rig;
  SpeedProfile profile;
};
OpenedRig open_rig_with_profile(const RigRequest& request, model::design::ToolSounds& sounds,
                                const std::string& profile, const std::string& default_profile,
                                std::optional<double> seconds);
// The same with the profile already checked (profile_to_run's `asked`), for a face that checked it
// before opening anything.
OpenedRig open_rig_running(const RigRequest& request, model::design::ToolSounds& sounds,
                           std::optional<SpeedProfile> asked, std::optional<double> seconds);

// What a comparison simulates beside the rig: `asked` (a tool id or design point), else what the
// rig says is mounted, on `surface`, else the mounted one. Throws std::invalid_argument when the
// rig does not know what is mounted and nothing was asked.
struct SimulatedChoice {
  std::string tool, surface;
};
SimulatedChoice simulated_choice(const RigDescription& rig, const std::string& asked_tool,
                                 const std::string& asked_surface);

}  // namespace nibrig::rig
