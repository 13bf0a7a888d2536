#include "rig/rig_request.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/design/predicted_tool.hpp"
#include "model/design/tool_sound.hpp"
#include "playback/audio_devices.hpp"
#include "rig/pacer.hpp"
#include "rig/replay_rig.hpp"
#include "rig/simulated_rig.hpp"
#include "rig/usb_rig.hpp"

namespace nibrig::rig {
namespace {

// The sliding friction the simulated arm feels: the catalog's μ for the pairing; for a design
// point, the μ a prediction gives it (interpolated between the printed tools measured on the
// surface); else (a pairing measured without friction, a design the catalog cannot interpolate) the
// mean μ of the catalog's tools on that surface, or 0.3 when the surface has none.
double friction_for(const model::io::Catalog& catalog, const std::string& tool,
                    const std::string& surface) {
  if (model::design::names_design_point(tool)) try {
      return model::design::interpolated_friction(catalog, model::design::parse_design_point(tool),
                                                  surface)
          .mu;
    } catch (const std::invalid_argument&) {
    }
  double sum = 0.0;
  int count = 0;
  for (const auto& p : catalog.pairings) {
    if (p.surface != surface || !p.friction) continue;
    if (p.tool == tool) return p.friction->mu;
    sum += p.friction->mu;
    ++count;
  }
  return count > 0 ? sum / count : 0.3;
}

void check_rig_range(double value, double low, double high, const std::string& who, const char* unit,
                     const char* what) {
  if (std::isfinite(value) && value >= low && value <= high) return;
  std::ostringstream message;
  if (!who.empty()) message << who << ": ";
  message << value << " " << unit << ": expected " << what << ", " << low << " to " << high;
  throw std::invalid_argument(message.str());
}

using RigField = RigRequestRefused::Field;

// A range check of rig_request's own, as the refusal of `field`.
template <typename Check>
void refuse_unless(RigField field, Check&& check) {
  try {
    check();
  } catch (const RigRequestRefused&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw RigRequestRefused(field, e.what());
  }
}

}  // namespace

RigRequestRefused::RigRequestRefused(Field field, const std::string& what)
    : std::invalid_argument(what), field_(field) {}

const char* field_name(RigRequestRefused::Field field) {
  switch (field) {
    case RigField::rig:
      return "rig";
    case RigField::tool:
      return "tool";
    case RigField::surface:
      return "surface";
    case RigField::load:
      return "load";
    case RigField::speedup:
      return "speedup";
    case RigField::accelerometer:
      return "accelerometer";
    case RigField::input_channel:
      return "input_channel";
    case RigField::replay:
      return "replay";
    case RigField::profile:
      return "profile";
    case RigField::seconds:
      return "seconds";
    case RigField::simulate:
      return "simulate";
  }
  return "?";
}

void check_rig_request(const RigRequest& r) {
  // A replayed session says its own load and scale; the request's are what the others run with.
  if (r.kind != RigKind::replay) refuse_unless(RigField::load, [&] { check_load(r.load_N, {}); });
  if (r.kind != RigKind::usb)
    refuse_unless(RigField::speedup, [&] { Pacer::check_speedup(r.speedup, nullptr); });
  switch (r.kind) {
    case RigKind::simulated:
      if (r.tool.empty())
        throw RigRequestRefused(RigField::tool, "the simulated rig needs a tool to simulate");
      if (r.surface.empty())
        throw RigRequestRefused(RigField::surface, "the simulated rig needs a surface to simulate");
      break;
    case RigKind::replay:
      if (r.replay.empty())
        throw RigRequestRefused(RigField::replay,
                                "expected a session folder or a paper recording to replay");
      break;
    case RigKind::usb:
      refuse_unless(RigField::accelerometer,
                    [&] { check_accelerometer_scale(r.accelerometer_m_s2_per_full_scale, {}); });
      if (r.input_channel < 1 || r.input_channel > playback::kMostOutputChannels)
        throw RigRequestRefused(RigField::input_channel,
                                std::to_string(r.input_channel) + ": expected a channel, 1 to " +
                                    std::to_string(playback::kMostOutputChannels) + " (1-based)");
      break;
  }
}

void check_capture_seconds(double seconds, const std::string& who) {
  check_rig_range(seconds, kShortestCaptureSeconds, kMaxProfileSeconds, who, "s", "a capture's length in seconds");
}

void check_load(double load_N, const std::string& who) {
  check_rig_range(load_N, kLightestLoadN, kHeaviestLoadN, who, "N", "the arm's normal load in N");
}

void check_accelerometer_scale(double m_s2_per_full_scale, const std::string& who) {
  check_rig_range(m_s2_per_full_scale, kLeastAccelerometerM_s2, kMostAccelerometerM_s2, who, "m/s²",
                  "an accelerometer's m/s² at full scale");
}

std::unique_ptr<Rig> open_rig(const RigRequest& request, model::design::ToolSounds& sounds) {
  check_rig_request(request);
  switch (request.kind) {
    case RigKind::simulated: {
      refuse_unless(RigField::tool, [&] { sounds.check(request.tool, request.surface); });
      SimulatedRigSettings settings;
      settings.normal_load_N = request.load_N;
      settings.seed = request.seed;
      settings.speedup = request.speedup;
      settings.mu = friction_for(sounds.catalog(), request.tool, request.surface);
      return std::make_unique<SimulatedRig>(settings, sounds.sound(request.tool, request.surface),
                                            request.tool, request.surface);
    }
    case RigKind::replay:
      return std::make_unique<ReplayRig>(request.replay, request.speedup, request.replay_friction);
    case RigKind::usb: {
      UsbRigSettings settings;
      settings.controller.serial = request.usb_serial;
      settings.accelerometer.stream.api = request.input_api;
      settings.accelerometer.stream.device = request.input_device;
      settings.accelerometer.stream.input_channel = request.input_channel;
      settings.accelerometer.m_s2_per_full_scale = request.accelerometer_m_s2_per_full_scale;
      settings.normal_load_N = request.load_N;
      auto rig = std::make_unique<UsbRig>(settings);
      return rig;
    }
  }
  throw std::logic_error("unknown rig kind");
}

SpeedProfile profile_named(const std::string& name_or_file, std::optional<double> seconds) {
  if (seconds) refuse_unless(RigField::seconds, [&] { check_capture_seconds(*seconds, {}); });
  if (name_or_file == "steps") return paper_steps(seconds.value_or(42.0));
  if (name_or_file == "sweep") return study_sweep_profile(seconds.value_or(6.0));
  const std::filesystem::path file(name_or_file);
  if (!std::filesystem::exists(file))
    throw RigRequestRefused(
        RigField::profile,
        name_or_file + ": expected steps, sweep or a CSV file (time_s,speed_mm_s); no such file");
  const SpeedProfile profile = read_speed_profile(file);
  return seconds ? fit_to_duration(profile, *seconds) : profile;
}

std::optional<SpeedProfile> profile_to_run(const RigRequest& request, const std::string& profile,
                                           const std::string& default_profile,
                                           std::optional<double> seconds) {
  if (request.kind != RigKind::replay)
    return profile_named(profile.empty() ? default_profile : profile, seconds);
  if (!profile.empty())
    throw RigRequestRefused(
        RigField::profile,
        profile + ": a replayed rig runs the profile that was recorded (give seconds to cut it)");
  if (seconds) refuse_unless(RigField::seconds, [&] { check_capture_seconds(*seconds, {}); });
  return std::nullopt;
}

OpenedRig open_rig_with_profile(const RigRequest& request, model::design::ToolSounds& sounds,
                                const std::string& profile, const std::string& default_profile,
                                std::optional<double> seconds) {
  return open_rig_running(request, sounds,
                          profile_to_run(request, profile, default_profile, seconds), seconds);
}

OpenedRig open_rig_running(const RigRequest& request, model::design::ToolSounds& sounds,
                           std::optional<SpeedProfile> asked, std::optional<double> seconds) {
  std::unique_ptr<Rig> rig = open_rig(request, sounds);
  if (asked) return {std::move(rig), std::move(*asked)};
  const SpeedProfile* own = rig->own_profile();
  if (own == nullptr)
    throw RigRequestRefused(RigField::profile,
                            request.replay.string() + ": the session has no speed profile to run");
  SpeedProfile run = seconds ? fit_to_duration(*own, *seconds) : *own;
  return {std::move(rig), std::move(run)};
}

SimulatedChoice simulated_choice(const RigDescription& rig, const std::string& asked_tool,
                                 const std::string& asked_surface) {
  SimulatedChoice c{asked_tool.empty() ? rig.tool : asked_tool, asked_surface.empty() ? rig.surface : asked_surface};
  if (c.tool.empty() || c.surface.empty())
    throw RigRequestRefused(
        RigField::simulate,
        "say which tool to simulate and on which surface: this rig does not know what is mounted");
  return c;
}

}  // namespace nibrig::rig
