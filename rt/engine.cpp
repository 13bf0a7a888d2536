#include "rt/engine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rt/denormals.hpp"

namespace nibrig::rt {
namespace {

std::size_t upsampling_factor(const EngineSettings& s) {
  if (!(s.sample_rate_hz > 0) || !std::isfinite(s.sample_rate_hz))
    throw std::invalid_argument("the engine needs a positive sample rate");
  if (!(s.internal_rate_hz > 0) || !std::isfinite(s.internal_rate_hz))
    throw std::invalid_argument("the engine needs a positive internal rate");
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(s.sample_rate_hz / s.internal_rate_hz)));
}

OutputStageSettings output_settings(const EngineSettings& s) {
  OutputStageSettings o = s.output;
  o.sample_rate_hz = s.sample_rate_hz;
  return o;
}

void check(const EngineSettings& s) {
  if (s.max_block_frames == 0) throw std::invalid_argument("the engine needs a block size");
  if (s.slots == 0) throw std::invalid_argument("the engine needs at least one slot");
  if (!(s.crossfade_s > 0) || !std::isfinite(s.crossfade_s))
    throw std::invalid_argument("the crossfade must last a positive time");
  if (!(s.output_level_per_m_s2 >= 0) || !std::isfinite(s.output_level_per_m_s2))
    throw std::invalid_argument("the output level per m/s² must be finite and >= 0");
  if (s.queue_capacity < 4) throw std::invalid_argument("the engine's queues need room for 4 items");
}

}  // namespace

double internal_rate_for(const EngineSettings& settings) {
  return settings.sample_rate_hz / static_cast<double>(upsampling_factor(settings));
}

Engine::Engine(const EngineSettings& settings)
    : settings_(settings),
      internal_rate_(internal_rate_for(settings)),
      fade_step_(0),
      commands_(settings.queue_capacity),
      contacts_(settings.queue_capacity),
      // Everything handed over comes back through here at most once, and handed_over_ never
      // exceeds queue_capacity (push refuses), so the audio thread never finds it full.
      retired_(settings.queue_capacity + 2 * settings.slots + 2),
      level_(settings.output_level_per_m_s2),
      target_level_(settings.output_level_per_m_s2),
      upsampler_(upsampling_factor(settings)),
      output_(output_settings(settings)) {
  check(settings);
  fade_step_ = 1.0 / (settings.crossfade_s * internal_rate_);
  // Room for every slot's voice plus as many fading out again: a swap never waits for a fade.
  players_.resize(2 * settings.slots + 2);
  const std::size_t internal_block = settings.max_block_frames / upsampler_.factor() + 2;
  speed_buffer_.resize(internal_block);
  force_buffer_.resize(internal_block);
  voice_buffer_.resize(internal_block);
  mix_buffer_.resize(internal_block);
}

Engine::~Engine() {
  collect();
  while (auto c = commands_.try_pop()) {
    delete c->voice;
    delete c->source;
    delete c->filter;
  }
  for (auto& p : players_) delete p.voice;
  delete source_;
  delete calibration_;
}

bool Engine::push(const Command& command) {
  const bool hands_over = command.voice != nullptr || command.source != nullptr ||
                          command.kind == CommandKind::calibration;
  if (hands_over && handed_over_ >= settings_.queue_capacity) collect();
  if ((hands_over && handed_over_ >= settings_.queue_capacity) || !commands_.try_push(command)) {
    stats_.refused_commands.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  handed_over_ += hands_over;
  return true;
}

bool Engine::load(std::size_t slot, std::unique_ptr<Voice>&& voice) {
  if (slot >= settings_.slots)
    throw std::invalid_argument("slot " + std::to_string(slot) + " does not exist (the engine has " +
                                std::to_string(settings_.slots) + ")");
  if (!voice) throw std::invalid_argument("no voice to load");
  if (std::abs(voice->sample_rate() - internal_rate_) > 1e-9 * internal_rate_)
    throw std::invalid_argument("voice '" + voice->name() + "' runs at " +
                                std::to_string(voice->sample_rate()) +
                                " Hz; this engine needs " + std::to_string(internal_rate_) + " Hz");
  collect();
  if (!push({CommandKind::load, slot, voice.get(), nullptr, 0, 0})) return false;
  voice.release();
  return true;
}

bool Engine::select(std::size_t slot) {
  if (slot >= settings_.slots)
    throw std::invalid_argument("slot " + std::to_string(slot) + " does not exist");
  return push({CommandKind::select, slot, nullptr, nullptr, 0, 0});
}

bool Engine::attach(std::unique_ptr<StrokeSource>&& source) {
  if (!source) throw std::invalid_argument("no stroke to attach");
  collect();
  if (!push({CommandKind::attach, 0, nullptr, source.get(), 0, next_sequence_})) return false;
  ++next_sequence_;
  source.release();
  return true;
}

bool Engine::set_contact(double speed_m_s, double normal_force_n) {
  if (!contacts_.try_push({speed_m_s, normal_force_n, next_sequence_})) {
    stats_.refused_commands.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  ++next_sequence_;
  return true;
}

bool Engine::set_output_level(double level_per_m_s2) {
  if (!(level_per_m_s2 >= 0) || !std::isfinite(level_per_m_s2))
    throw std::invalid_argument("the output level per m/s² must be finite and >= 0");
  return push({CommandKind::output_level, 0, nullptr, nullptr, level_per_m_s2, 0});
}

bool Engine::set_calibration(std::unique_ptr<FirFilter>&& filter) {
  collect();
  // Counted as handed over even when it is nullptr: the audio thread retires the old filter in
  // exchange, one item back for the one given.
  if (!push({CommandKind::calibration, 0, nullptr, nullptr, 0, 0, filter.get()})) return false;
  filter.release();
  return true;
}

void Engine::collect() {
  while (auto r = retired_.try_pop()) {
    delete r->voice;
    delete r->source;
    delete r->filter;
    --handed_over_;
  }
}

// ---- audio thread ----

void Engine::retire(Voice* voice, StrokeSource* source, FirFilter* filter) noexcept {
  // Cannot fail: see the capacity of retired_ in the constructor.
  retired_.try_push({voice, source, filter});
}

void Engine::take_commands() noexcept {
  while (auto c = commands_.try_pop()) {
    switch (c->kind) {
      case CommandKind::load: {
        for (auto& p : players_)
          if (p.voice && p.slot == c->slot && !p.leaving) p.leaving = true;
        auto free = std::find_if(players_.begin(), players_.end(),
                                 [](const Player& p) { return p.voice == nullptr; });
        if (free == players_.end()) {
          // Every place is busy with fades (swaps faster than the crossfade): the quietest
          // leaving voice stops now.
          free = std::min_element(players_.begin(), players_.end(),
                                  [](const Player& a, const Player& b) {
                                    return (a.leaving ? a.fade : 2.0) < (b.leaving ? b.fade : 2.0);
                                  });
          retire(free->voice, nullptr);
        }
        *free = Player{c->voice, c->slot, false, 0.0};
        break;
      }
      case CommandKind::select:
        selected_ = c->slot;
        break;
      case CommandKind::attach:
        if (source_) retire(nullptr, source_);
        source_ = c->source;
        source_sequence_ = c->sequence;
        source_start_ = internal_clock_;
        break;
      case CommandKind::calibration:
        retire(nullptr, nullptr, calibration_);  // an empty retirement when there was none
        calibration_ = c->filter;
        break;
      case CommandKind::output_level:
        target_level_ = c->value;
        level_step_ = std::abs(target_level_ - level_) * fade_step_;
        break;
    }
  }
  if (auto contact = contacts_.pop_latest()) {
    live_.aim(contact->speed, contact->force);
    contact_sequence_ = contact->sequence;
  }
  if (source_ && contact_sequence_ > source_sequence_) {  // a newer live value: the stylus took over
    // Start the live ramp from where the stroke is now, so the switch does not jump.
    double speed = 0, force = 0;
    source_->fill(internal_clock_ - source_start_, internal_rate_, &speed, &force, 1);
    live_.start_from(speed, force);
    retire(nullptr, source_);
    source_ = nullptr;
  }
}

void Engine::fill_contact(std::size_t count) noexcept {
  if (source_)
    source_->fill(internal_clock_ - source_start_, internal_rate_, speed_buffer_.data(),
                  force_buffer_.data(), count);
  else
    live_.fill(0, internal_rate_, speed_buffer_.data(), force_buffer_.data(), count);
}

void Engine::mix_players(std::size_t count) noexcept {
  std::fill_n(mix_buffer_.begin(), count, 0.0);
  std::uint64_t above = 0;
  std::size_t running = 0;
  for (auto& p : players_) {
    if (!p.voice) continue;
    ++running;
    const std::uint64_t before = p.voice->forcing().samples_above_speed_range();
    p.voice->process(speed_buffer_.data(), force_buffer_.data(), voice_buffer_.data(), count);
    above += p.voice->forcing().samples_above_speed_range() - before;
    const double target = (!p.leaving && p.slot == selected_) ? 1.0 : 0.0;
    if (p.fade == target) {  // steady: full or silent, no gain curve to follow
      if (target > 0)
        for (std::size_t i = 0; i < count; ++i) mix_buffer_[i] += voice_buffer_[i];
    } else {
      for (std::size_t i = 0; i < count; ++i) {
        if (p.fade < target) p.fade = std::min(target, p.fade + fade_step_);
        else if (p.fade > target) p.fade = std::max(target, p.fade - fade_step_);
        if (p.fade > 0) mix_buffer_[i] += std::sin(0.5 * std::numbers::pi * p.fade) * voice_buffer_[i];
      }
    }
    if (p.leaving && p.fade == 0.0) {
      retire(p.voice, nullptr);
      p = Player{};
    }
  }
  stats_.voices.store(running, std::memory_order_relaxed);
  if (above) stats_.samples_above_speed_range.fetch_add(above, std::memory_order_relaxed);
  // The output level glides over a crossfade's time, so a gain change never steps.
  for (std::size_t i = 0; i < count; ++i) {
    if (level_ != target_level_)
      level_ = level_ < target_level_ ? std::min(target_level_, level_ + level_step_)
                                      : std::max(target_level_, level_ - level_step_);
    mix_buffer_[i] *= level_;
  }
}

void Engine::render_piece(float* out, std::size_t frames) noexcept {
  take_commands();
  const std::size_t count = upsampler_.inputs_needed(frames);
  fill_contact(count);
  mix_players(count);
  if (calibration_) calibration_->process(mix_buffer_.data(), count);
  internal_clock_ += count;
  upsampler_.process(mix_buffer_.data(), out, frames);
  output_.process(out, frames);
}

void Engine::render(float* out, std::size_t frames) noexcept {
  const auto start = std::chrono::steady_clock::now();
  const double period = static_cast<double>(frames) / settings_.sample_rate_hz;
  cpu_clock_.block_starts(std::chrono::duration<double>(start.time_since_epoch()).count(), period);
  {
    DenormalGuard flush_to_zero;
    for (std::size_t done = 0; done < frames;) {
      const std::size_t piece = std::min(settings_.max_block_frames, frames - done);
      render_piece(out + done, piece);
      done += piece;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpu_clock_.block_ends(seconds, period);
  constexpr auto relaxed = std::memory_order_relaxed;
  stats_.callbacks.fetch_add(1, relaxed);
  stats_.frames.fetch_add(frames, relaxed);
  if (cpu > period) stats_.overruns.fetch_add(1, relaxed);
  if (seconds > stats_.max_callback_s.load(relaxed)) stats_.max_callback_s.store(seconds, relaxed);
  if (cpu > stats_.max_callback_cpu_s.load(relaxed)) stats_.max_callback_cpu_s.store(cpu, relaxed);
  stats_.callback_time_histogram[callback_time_bin(seconds)].fetch_add(1, relaxed);
  const auto& counts = output_.counts();
  stats_.peak_output.store(counts.peak, relaxed);
  stats_.limited_samples.store(counts.limited_samples, relaxed);
  stats_.non_finite_samples.store(counts.non_finite_samples, relaxed);
}

}  // namespace nibrig::rt
