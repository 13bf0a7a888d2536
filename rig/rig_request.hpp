// A rig as a person asks for it — "the simulated rig with vero2 on office", "the USB controller
// NR-0001 with the accelerometer on input 1 of Scarlett", "replay this session" — opened the same
// way for every face, with its speed profile.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
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
// not finite); `who` is the option or argument that set it ("--load", "load").
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

// Opens the rig, after checking the load and accelerometer scale as above (named "load" and
// "accelerometer"). `sounds` makes the simulated tool (a catalog pairing or a design point) and gives
// the catalog's μ for it; it is used only by the simulated rig. Throws std::invalid_argument for a
// request that cannot be met (naming what: an unknown tool, a missing session) and
// std::runtime_error when a device is missing (naming what was found instead).
std::unique_ptr<Rig> open_rig(const RigRequest& request, model::design::ToolSounds& sounds);

// "steps" (the paper's protocol: 3 sweeps of six 2 s steps over 17-250 mm/s, 42 s), "sweep" (the
// user study's 3 s sweep, two periods) or a CSV file (rig/speed_profile.hpp); `seconds` cuts or
// repeats it (checked as check_capture_seconds does, named "seconds"). Throws std::invalid_argument /
// FormatError naming the profile.
SpeedProfile profile_named(const std::string& name_or_file, std::optional<double> seconds);

// A rig opened with the profile it is to run, as every face opens one: a replayed rig runs what was
// recorded (cut or repeated to `seconds`), and refuses another profile; the others run `profile`
// (empty: `default_profile`), checked before the rig is opened. Throws what open_rig and
// profile_named throw.
struct OpenedRig {
  std::unique_ptr<Rig> rig;
  SpeedProfile profile;
};
OpenedRig open_rig_with_profile(const RigRequest& request, model::design::ToolSounds& sounds,
                                const std::string& profile, const std::string& default_profile,
                                std::optional<double> seconds);

// What a comparison simulates beside the rig: `asked` (a tool id or design point), else what the
// rig says is mounted, on `surface`, else the mounted one. Throws std::invalid_argument when the
// rig does not know what is mounted and nothing was asked.
struct SimulatedChoice {
  std::string tool, surface;
};
SimulatedChoice simulated_choice(const RigDescription& rig, const std::string& asked_tool,
                                 const std::string& asked_surface);

}  // namespace nibrig::rig
