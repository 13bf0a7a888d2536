// The real-time engine: the voices loaded into presentation slots (A/B or a triplet), mixed with
// click-free crossfades at the internal rate, scaled from acceleration to output level, raised to
// the device rate and passed through the output stage. Control threads talk to it through
// lock-free queues; render() is what the audio callback and the offline render both call.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "rt/block_cpu_clock.hpp"
#include "rt/block_renderer.hpp"
#include "rt/engine_stats.hpp"
#include "rt/fir_filter.hpp"
#include "rt/output_stage.hpp"
#include "rt/spsc_queue.hpp"
#include "rt/stroke_source.hpp"
#include "rt/upsampler.hpp"
#include "rt/voice.hpp"

namespace nibrig::rt {

struct EngineSettings {
  double sample_rate_hz = 48000.0;
  // The voices run at the device rate divided by the integer nearest to rate / this: 8000 Hz at
  // 48 and 96 kHz, 7350 Hz at 44.1 kHz. The tools are rendered to 500 Hz; 16 times that keeps
  // the interpolator's images far above the band and the integrator's folded images (which the
  // voices compensate, see voice_builder.hpp) small, at 1/6 of the cost of running at 48 kHz.
  double internal_rate_hz = 8000.0;
  std::size_t max_block_frames = 4096;  // longer blocks are rendered in pieces of this size
  std::size_t slots = 3;                // presentation slots: A/B, or the three of a triplet
  double crossfade_s = 0.02;            // equal-power fade between slots and on voice swaps
  // Output level (full scale = 1) per m/s² of sensor acceleration. Without an actuator
  // calibration this is a plain scale: the default puts 18 m/s² at the limiter's 0.9.
  double output_level_per_m_s2 = 0.05;
  OutputStageSettings output;      // its sample_rate_hz is set from sample_rate_hz
  std::size_t queue_capacity = 256;  // pending commands, and objects handed over at once
};

// The internal rate an engine with these settings runs its voices at (see internal_rate_hz).
double internal_rate_for(const EngineSettings& settings);

class Engine final : public BlockRenderer {
 public:
  // Throws std::invalid_argument for a bad rate, block size, slot count, crossfade or gain.
  explicit Engine(const EngineSettings& settings);
  ~Engine() override;  // only once no thread calls render() any more
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  double sample_rate() const noexcept { return settings_.sample_rate_hz; }
  // Voices must be made at this rate (ForcingTable's sample rate).
  double internal_rate() const noexcept { return internal_rate_; }
  std::size_t slots() const noexcept { return settings_.slots; }
  // The interpolator's delay from the internal rate to the output, in output frames.
  double latency_frames() const noexcept { return upsampler_.delay(); }

  // Control side: call from one thread at a time. Each returns false, changing nothing, when the
  // engine's queue is full (it drains every block; retry after a block). A voice swapped out, a
  // source replaced, and anything refused stay the caller's or are freed by collect().

  // Puts `voice` into slot (< slots()); the voice it replaces fades out. Throws
  // std::invalid_argument for a slot out of range or a voice made at another rate. On false the
  // voice is left in `voice`.
  bool load(std::size_t slot, std::unique_ptr<Voice>&& voice);
  // Crossfades to slot; the other slots keep running silently so that switching back is instant.
  bool select(std::size_t slot);
  // Live speed (m/s) and normal force (N), e.g. from a stylus, the pad or the rig: each block
  // ramps from the last value to the newest over its samples (no lag beyond one block; a
  // LiveStroke). A live value detaches any attached stroke, starting from where it was.
  bool set_contact(double speed_m_s, double normal_force_n);
  // Speed and force from `source`, filled a block at a time on the engine's own clock from when
  // it is taken over (deterministic: an offline render and a device hear the same).
  bool attach(std::unique_ptr<StrokeSource>&& source);
  bool set_output_level(double level_per_m_s2);
  // The actuator's inverse filter (playback/actuator_file.hpp), run on the mix at the internal
  // rate: it turns requested m/s² into output level so that the actuator
  // delivers them, so with it the output level is a trim (1 = as calibrated). Its taps must be
  // designed for internal_rate(). nullptr removes it. The change is not crossfaded: load it
  // before playing.
  bool set_calibration(std::unique_ptr<FirFilter>&& filter);
  // Frees what the audio thread has let go of. Called by the control functions; call it now and
  // then when idle.
  void collect();
  EngineStats stats() const { return stats_.snapshot(); }
  // For the audio back end: one xrun seen by the device.
  void note_device_xrun() noexcept {
    stats_.device_xruns.fetch_add(1, std::memory_order_relaxed);
  }

  // Audio side.
  void render(float* out, std::size_t frames) noexcept override;

 private:
  enum class CommandKind { load, select, attach, output_level, calibration };
  struct Command {
    CommandKind kind;
    std::size_t slot;
    Voice* voice;
    StrokeSource* source;
    double value;
    std::uint64_t sequence;
    FirFilter* filter = nullptr;
  };
  struct Contact {
    double speed, force;
    std::uint64_t sequence;
  };
  struct Retired {
    Voice* voice;
    StrokeSource* source;
    FirFilter* filter = nullptr;
  };
  struct Player {
    Voice* voice = nullptr;
    std::size_t slot = 0;
    bool leaving = false;  // replaced: fades out, then retires
    double fade = 0;       // 0 silent … 1 full; the gain is sin(fade·π/2)
  };

  bool push(const Command& command);
  void render_piece(float* out, std::size_t frames) noexcept;
  void take_commands() noexcept;
  void fill_contact(std::size_t count) noexcept;
  void mix_players(std::size_t count) noexcept;
  void retire(Voice* voice, StrokeSource* source, FirFilter* filter = nullptr) noexcept;

  EngineSettings settings_;
  double internal_rate_;
  double fade_step_;  // per internal sample
  // Control side.
  std::uint64_t next_sequence_ = 1;
  std::size_t handed_over_ = 0;  // objects given to the audio thread and not yet collected
  SpscQueue<Command> commands_;
  SpscQueue<Contact> contacts_;
  SpscQueue<Retired> retired_;
  // Audio side.
  std::vector<Player> players_;
  std::size_t selected_ = 0;
  StrokeSource* source_ = nullptr;  // attached; when none, live_ fills the contact
  LiveStroke live_;
  FirFilter* calibration_ = nullptr;
  std::uint64_t source_sequence_ = 0, contact_sequence_ = 0;
  std::uint64_t source_start_ = 0;  // internal sample at which the source was taken over
  std::uint64_t internal_clock_ = 0;
  double level_, target_level_, level_step_ = 0;
  std::vector<double> speed_buffer_, force_buffer_, voice_buffer_, mix_buffer_;
  Upsampler upsampler_;
  OutputStage output_;
  BlockCpuClock cpu_clock_;
  AtomicEngineStats stats_;
};

}  // namespace nibrig::rt
