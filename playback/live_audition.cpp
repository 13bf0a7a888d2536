#include "playback/live_audition.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

#include "rt/fir_filter.hpp"
#include "rt/voice_builder.hpp"

namespace nibrig::playback {

LiveAudition::LiveAudition(rt::EngineSettings settings) : settings_(settings) {
  if (settings_.slots == 0) throw std::invalid_argument("a live audition needs at least one slot");
  engine_ = std::make_unique<rt::Engine>(settings_);
  names_.assign(settings_.slots, "");
  scratch_.assign(256, 0.0f);  // a block to drain the queue with when no device calls the engine
}

LiveAudition::~LiveAudition() { close(); }

void LiveAudition::open(const OutputSettings& output) {
  close();
  output_ = std::make_unique<AudioOutput>(*engine_, output);
}

void LiveAudition::close() {
  output_.reset();  // the callback has stopped calling the engine when this returns
  engine_->collect();
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

template <typename Command>
void LiveAudition::deliver(const char* what, Command&& command) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (!command()) {
    if (!output_) {
      engine_->render(scratch_.data(), scratch_.size());
      continue;
    }
    if (std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error(std::string("the engine took no ") + what +
                               " for a second: its device is " +
                               (output_->status() == OutputStatus::lost
                                    ? "lost (" + output_->last_problem() + ")"
                                    : "not calling back"));
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  engine_->collect();
}

void LiveAudition::load(std::size_t slot, const SessionVoice& voice, std::uint64_t seed) {
  if (slot >= names_.size())
    throw std::invalid_argument("slot " + std::to_string(slot) + " out of range (" +
                                std::to_string(names_.size()) + " slots)");
  auto built = rt::build_voice(voice.name, voice.modal, voice.spectrum, engine_->internal_rate(), seed);
  const std::string name = built->name();
  deliver("voice", [&] { return engine_->load(slot, std::move(built)); });
  names_[slot] = name;
}

void LiveAudition::select(std::size_t slot) {
  if (slot >= names_.size())
    throw std::invalid_argument("slot " + std::to_string(slot) + " out of range (" +
                                std::to_string(names_.size()) + " slots)");
  deliver("selection", [&] { return engine_->select(slot); });
  selected_ = slot;
}

void LiveAudition::attach(std::unique_ptr<rt::StrokeSource> stroke) {
  if (!stroke) throw std::invalid_argument("no stroke to attach");
  deliver("stroke", [&] { return engine_->attach(std::move(stroke)); });
}

InverseFilter LiveAudition::use_actuator(const ActuatorCalibration& calibration, std::string name) {
  InverseFilter filter = redesign_for_rate(calibration, engine_->internal_rate());
  auto fir = std::make_unique<rt::FirFilter>(filter.taps);
  deliver("actuator filter", [&] { return engine_->set_calibration(std::move(fir)); });
  deliver("output level", [&] { return engine_->set_output_level(1.0); });
  actuator_ = std::move(name);
  return filter;
}

void LiveAudition::set_contact(double speed_m_s, double normal_force_n) {
  deliver("contact", [&] { return engine_->set_contact(speed_m_s, normal_force_n); });
}

}  // namespace nibrig::playback
