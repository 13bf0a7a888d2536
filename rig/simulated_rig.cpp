#include "rig/simulated_rig.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "rig/acceleration_engine.hpp"
#include "rt/gaussian_noise.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::rig {
namespace {

// The motor's speed, frame by frame, computed as far ahead as anyone asks: the engine (which
// interpolates it at its internal rate) and the encoder read the same track. The ring holds the
// last kRing frames; both readers stay within a block of the newest.
class MotorTrack {
 public:
  MotorTrack(const SpeedProfile& profile, double frame_rate_hz, double time_constant_s)
      : profile_(profile),
        frame_rate_(frame_rate_hz),
        alpha_(1.0 - std::exp(-1.0 / (frame_rate_hz * time_constant_s))) {}

  // Speed at frame k (time k / frame rate). The turntable starts at rest.
  double speed(std::uint64_t k) noexcept {
    while (computed_ <= k) {
      if (computed_ > 0) {
        const double target = profile_.speed_at(static_cast<double>(computed_) / frame_rate_);
        speed_ += alpha_ * (target - speed_);
      }
      ring_[computed_ % kRing] = speed_;
      ++computed_;
    }
    return ring_[k % kRing];
  }

  // Linear between frames, at time t.
  double speed_at(double t) noexcept {
    const double x = std::max(0.0, t * frame_rate_);
    const auto k = static_cast<std::uint64_t>(x);
    const double f = x - static_cast<double>(k);
    return (1.0 - f) * speed(k) + f * speed(k + 1);
  }

 private:
  static constexpr std::size_t kRing = 4096;
  const SpeedProfile& profile_;
  double frame_rate_, alpha_;
  std::array<double, kRing> ring_{};
  std::uint64_t computed_ = 0;
  double speed_ = 0.0;
};

// What the simulated tool feels: the motor's actual speed and the arm's load.
class MotorStroke final : public rt::StrokeSource {
 public:
  MotorStroke(MotorTrack& track, double load_N) : track_(track), load_(load_N) {}
  void fill(std::uint64_t first, double rate, double* speed, double* force,
            std::size_t count) noexcept override {
    for (std::size_t i = 0; i < count; ++i) {
      speed[i] = track_.speed_at(static_cast<double>(first + i) / rate);
      force[i] = load_;
    }
  }

 private:
  MotorTrack& track_;
  double load_;
};

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("simulated rig: " + what);
}

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace

struct SimulatedRig::Simulation {
  Simulation(const SimulatedRigSettings& s, const model::design::ToolSound& sound,
             const SpeedProfile& profile)
      : track(profile, s.frame_rate_hz, s.motor_time_constant_s),
        session(acceleration_engine(sound, s.acceleration_rate_hz,
                                    std::make_unique<MotorStroke>(track, s.normal_load_N),
                                    SimulatedRig::tool_seed(s.seed))),
        sensor_noise(s.seed ^ 0x5eed5eedULL) {}

  double noise() noexcept {
    if (spare_ready) {
      spare_ready = false;
      return spare;
    }
    double first = 0.0;
    sensor_noise.normal_pair(first, spare);
    spare_ready = true;
    return first;
  }

  MotorTrack track;
  std::unique_ptr<playback::PreparedEngine> session;
  rt::GaussianNoise sensor_noise;
  double spare = 0.0;
  bool spare_ready = false;
  double motor_phase = 0.0;
  std::vector<float> rendered;
};

SimulatedRig::SimulatedRig(const SimulatedRigSettings& settings,
                           const model::design::ToolSound& sound, const std::string& tool,
                           const std::string& surface)
    : settings_(settings), sound_(sound), pacer_(settings.speedup, settings.frame_rate_hz) {
  const auto& s = settings_;
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  const auto non_negative = [](double x) { return std::isfinite(x) && x >= 0.0; };
  require(positive(s.frame_rate_hz) && std::floor(s.frame_rate_hz) == s.frame_rate_hz,
          "the frame rate must be a whole positive number of hertz");
  require(positive(s.acceleration_rate_hz) &&
              std::floor(s.acceleration_rate_hz) == s.acceleration_rate_hz &&
              s.acceleration_rate_hz >= s.frame_rate_hz,
          "the acceleration rate must be whole hertz, at least the frame rate");
  require(non_negative(s.normal_load_N), "the load must be >= 0 N");
  require(non_negative(s.mu), "mu must be >= 0");
  require(positive(s.max_speed_m_s), "the motor's top speed must be positive");
  require(positive(s.motor_time_constant_s), "the motor's time constant must be positive");
  require(non_negative(s.motor_line_hz_per_m_s) && non_negative(s.motor_line_m_s2) &&
              non_negative(s.encoder_noise_m_s) && non_negative(s.force_noise_N) &&
              non_negative(s.accelerometer_noise_m_s2),
          "noise and motor-line levels must be >= 0");
  require(positive(s.normal_full_scale_N) && positive(s.tangential_full_scale_N),
          "force full scales must be positive");
  require(positive(s.accelerometer_m_s2_per_unit), "the accelerometer scale must be positive");

  description_.kind = "simulated";
  description_.tool = tool;
  description_.surface = surface;
  description_.name = "simulated rig: " + sound.name + " (modes of " + sound.modes + "), seed " +
                      std::to_string(s.seed);
  description_.frame_rate_hz = s.frame_rate_hz;
  description_.acceleration_rate_hz = s.acceleration_rate_hz;
  description_.max_speed_m_s = s.max_speed_m_s;
  description_.normal_load_N = s.normal_load_N;
  description_.accelerometer_m_s2_per_unit = s.accelerometer_m_s2_per_unit;
  description_.acceleration_units = "audio full scale (×" + fixed(s.accelerometer_m_s2_per_unit, 2) +
                                    " = m/s²)";
}

SimulatedRig::~SimulatedRig() = default;

void SimulatedRig::start(const SpeedProfile& profile) {
  if (profile_) throw std::logic_error("simulated rig: already started");
  check_within_motor(profile, settings_.max_speed_m_s);
  if (!(profile.duration_s() > 0.0))
    throw std::invalid_argument("the profile lasts no time: give it a length");
  profile_.emplace(profile);
  simulation_ = std::make_unique<Simulation>(settings_, sound_, *profile_);
  frames_total_ = static_cast<std::uint64_t>(std::llround(profile_->duration_s() * settings_.frame_rate_hz));
  pacer_.start();
}

// One block of 10 frames (10 ms at 1 kHz) and the acceleration samples of the same span.
void SimulatedRig::produce_block(RigData& into) {
  auto& sim = *simulation_;
  const auto& s = settings_;
  const std::uint64_t k0 = frames_made_;
  const std::uint64_t k1 = std::min(frames_total_, k0 + 10);
  for (std::uint64_t k = k0; k < k1; ++k) {
    const double t = static_cast<double>(k) / s.frame_rate_hz;
    const double v = sim.track.speed(k);
    SensorFrame frame;
    frame.device_time_us = static_cast<std::uint64_t>(std::llround(t * 1e6));
    frame.sequence = static_cast<std::uint32_t>(k);
    frame.speed_m_s = static_cast<float>(v + s.encoder_noise_m_s * sim.noise());
    double normal = s.normal_load_N + s.force_noise_N * sim.noise();
    // Sliding friction needs sliding: below 1 mm/s the tip is taken to stick, carrying no load.
    double tangential = (v > 0.001 ? s.mu * s.normal_load_N : 0.0) + s.force_noise_N * sim.noise();
    if (std::abs(normal) >= s.normal_full_scale_N) {
      normal = std::copysign(s.normal_full_scale_N, normal);
      frame.flags |= kNormalForceSaturated;
    }
    if (std::abs(tangential) >= s.tangential_full_scale_N) {
      tangential = std::copysign(s.tangential_full_scale_N, tangential);
      frame.flags |= kTangentialForceSaturated;
    }
    frame.normal_force_N = static_cast<float>(normal);
    frame.tangential_force_N = static_cast<float>(tangential);
    if (k + 1 < frames_total_) frame.flags |= kProfileRunning;
    if (frame.flags & (kNormalForceSaturated | kTangentialForceSaturated)) ++health_.saturated_frames;
    into.frames.push_back(frame);
  }
  // Acceleration sample n is at n / rate; the block ends where frame k1 begins.
  const auto samples_end = static_cast<std::uint64_t>(
      std::floor(static_cast<double>(k1) * s.acceleration_rate_hz / s.frame_rate_hz));
  const std::size_t count = samples_end - samples_made_;
  sim.rendered.resize(count);
  sim.session->engine().render(sim.rendered.data(), count);
  const double dt = 1.0 / s.acceleration_rate_hz;
  for (std::size_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(samples_made_ + i) * dt;
    const double v = sim.track.speed_at(t);
    sim.motor_phase += 2.0 * std::numbers::pi * s.motor_line_hz_per_m_s * v * dt;
    if (sim.motor_phase > 2.0 * std::numbers::pi) sim.motor_phase -= 2.0 * std::numbers::pi;
    const double a = static_cast<double>(sim.rendered[i]) * kEngineHeadroom_m_s2 +
                     s.motor_line_m_s2 * std::sin(sim.motor_phase) +
                     s.accelerometer_noise_m_s2 * sim.noise();
    into.acceleration.push_back(static_cast<float>(a / s.accelerometer_m_s2_per_unit));
  }
  health_.frames += k1 - k0;
  health_.acceleration_samples += count;
  samples_made_ = samples_end;
  frames_made_ = k1;
}

bool SimulatedRig::read(RigData& into, std::chrono::milliseconds wait) {
  if (!profile_) throw std::logic_error("simulated rig: read() before start()");
  if (stopped_ || frames_made_ >= frames_total_) {
    if (health_.ended_because.empty()) health_.ended_because = "profile finished";
    return false;
  }
  const std::uint64_t due = pacer_.due(frames_made_, frames_total_, 10,
                                       static_cast<std::uint64_t>(settings_.frame_rate_hz / 10), wait);
  const std::size_t before = into.frames.size();
  while (frames_made_ + 10 <= due || (due == frames_total_ && frames_made_ < due)) produce_block(into);
  tell_listener(into.frames, before);
  if (frames_made_ >= frames_total_) {
    health_.ended_because = "profile finished";
    return false;
  }
  return true;
}

void SimulatedRig::stop() {
  if (!stopped_ && health_.ended_because.empty() && frames_made_ < frames_total_)
    health_.ended_because = "stopped";
  stopped_ = true;
}

}  // namespace nibrig::rig
