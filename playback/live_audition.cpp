#include "playback/live_audition.hpp"

#include <stdexcept>

#include "rt/fir_filter.hpp"
#include "rt/voice_builder.hpp"

namespace nibrig::playback {

LiveAudition::LiveAudition(rt::EngineSettings settings) {
  if (settings.slots == 0) throw std::invalid_argument("a live audition needs at least one slot");
  engine_ = std::make_unique<rt::Engine>(settings);
  names_.assign(settings.slots, "");
  scratch_.assign(256, 0.0f);  // a block to drain the queue with when no device calls the engine
}

LiveAudition::~LiveAudition() { close(); }

void LiveAudition::open(const OutputSettings& output) {
  close();
  output_ = std::make_unique<AudioOutput>(*engine_, output);
}

void LiveAudition::close() {
  output_.reset();  // the callback has stopped calling the engine when this returns
  pump();
}

std::optional<StreamInfo> LiveAudition::stream_info() const {
  if (!output_) return std::nullopt;
  return output_->stream_info();
}

std::optional<OutputStats> LiveAudition::output_stats() const {
  if (!output_) return std::nullopt;
  return output_->stats();
}

std::optional<OutputStatus> LiveAudition::output_status() const {
  if (!output_) return std::nullopt;
  return output_->status();
}

std::string LiveAudition::last_problem() const { return output_ ? output_->last_problem() : ""; }

std::size_t LiveAudition::pump() {
  while (!pending_.empty()) {
    if (pending_.front().command()) {
      pending_.pop_front();
      continue;
    }
    if (output_) break;  // the callback drains the queue; the rest goes on a later pump
    engine_->render(scratch_.data(), scratch_.size());
  }
  engine_->collect();
  return pending_.size();
}

void LiveAudition::deliver(Pending pending) {
  if (pending.contact && !pending_.empty() && pending_.back().contact)
    pending_.back() = std::move(pending);  // only the newest contact matters
  else
    pending_.push_back(std::move(pending));
  pump();
}

void LiveAudition::load(std::size_t slot, const model::modal::VoiceSource& voice, std::uint64_t seed) {
  if (slot >= names_.size())
    throw std::invalid_argument("slot " + std::to_string(slot) + " out of range (" +
                                std::to_string(names_.size()) + " slots)");
  auto built = rt::build_voice(voice, engine_->internal_rate(), seed);
  const std::string name = built->name();
  auto held = std::make_shared<std::unique_ptr<rt::Voice>>(std::move(built));
  deliver({false, [this, slot, held] { return engine_->load(slot, std::move(*held)); }});
  names_[slot] = name;
}

void LiveAudition::select(std::size_t slot) {
  if (slot >= names_.size())
    throw std::invalid_argument("slot " + std::to_string(slot) + " out of range (" +
                                std::to_string(names_.size()) + " slots)");
  deliver({false, [this, slot] { return engine_->select(slot); }});
  selected_ = slot;
}

void LiveAudition::attach(std::unique_ptr<rt::StrokeSource> stroke) {
  if (!stroke) throw std::invalid_argument("no stroke to attach");
  auto source = std::make_shared<std::unique_ptr<rt::StrokeSource>>(std::move(stroke));
  deliver({false, [this, source] { return engine_->attach(std::move(*source)); }});
}

InverseFilter LiveAudition::use_actuator(const ActuatorCalibration& calibration, std::string name) {
  InverseFilter filter = redesign_for_rate(calibration, engine_->internal_rate());
  auto fir = std::make_unique<rt::FirFilter>(filter.taps);
  auto shared = std::make_shared<std::unique_ptr<rt::FirFilter>>(std::move(fir));
  deliver({false, [this, shared] { return engine_->set_calibration(std::move(*shared)); }});
  deliver({false, [this] { return engine_->set_output_level(1.0); }});
  actuator_ = std::move(name);
  return filter;
}

void LiveAudition::set_contact(double speed_m_s, double normal_force_n) {
  deliver({true, [this, speed_m_s, normal_force_n] { return engine_->set_contact(speed_m_s, normal_force_n); }});
}

}  // namespace nibrig::playback
