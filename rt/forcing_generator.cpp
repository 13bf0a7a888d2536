// How the noise is made. Every hop (half a frame) a new frame of independent complex Gaussian bins
// Z_k is drawn; for each table speed s the frame Z_k·M_s(k) is inverse-transformed and multiplied
// by a sine window, and each output sample is the sum of two such frames, 50 % overlapped. The work
// of a frame, its overlap-add included, is spread over the calls of the hop before it, so no call
// pays for a whole frame (when several warm voices hopped in the same call,
// moving their frames cost up to a millisecond). The sine window's squares sum to 1 at 50 %
// overlap, so the streams are stationary Gaussian processes with the table's spectra, and frames
// never repeat (xoshiro256**), so nothing in the output is periodic: a fixed-phase sum of
// sinusoids on a 1 Hz grid would repeat every second. Because all streams share the same Z, they
// are coherent: mixing two of them with weights w and 1−w gives noise whose amplitude spectrum is
// exactly w·M_s + (1−w)·M_{s+1}. The speed therefore acts through per-sample weights, with no
// filter state to update and no lag; the only cost is computing every speed's stream (one inverse
// FFT per speed per hop). The frames' band ends far below their rate, so each inverse FFT is made
// at a fraction of it and interpolated back (FrameInterpolator): a 2048-point transform fits the
// cache where an 8192-point one did not, and takes an eighth of its time.
#include "rt/forcing_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "model/numeric/vector_math.hpp"

namespace nibrig::rt {

namespace {

// Z is drawn in this many parts (about 64 bins each at 8 kHz), so that no call pays for all of a
// frame's Gaussian draws; the draws come in the same order, so the noise does not depend on it.
constexpr std::size_t kNoiseChunks = 8;

// Where in each step's share of the hop a generator does it: the seed's multiple of the golden
// ratio, so that voices seeded 1, 2, 3 ... (as a pool seeds them) are spread evenly over it. Only
// when the work is done depends on it, never the output.
double step_phase(std::uint64_t seed) {
  constexpr double kGoldenRatioFraction = 0.6180339887498949;
  const double phase = static_cast<double>(seed % (1u << 20)) * kGoldenRatioFraction;
  return phase - std::floor(phase);
}

}  // namespace

ForcingGenerator::ForcingGenerator(std::shared_ptr<const ForcingTable> table, std::uint64_t seed,
                                   FrameRate frame_rate)
    : table_(std::move(table)),
      noise_(seed),
      interpolator_(table_ ? table_->frame_length() : 2, table_ ? table_->active_bins() : 1,
                    frame_rate),
      fft_(interpolator_.reduced_length(), model::numeric::RealFft::Plans::backward),
      frame_(table_ ? table_->frame_length() : 2),
      hop_(frame_ / 2),
      step_phase_(step_phase(seed)) {
  if (!table_) throw std::invalid_argument("a forcing generator needs a table");
  window_.resize(frame_);
  for (std::size_t n = 0; n < frame_; ++n)
    window_[n] = std::sin(std::numbers::pi * (static_cast<double>(n) + 0.5) /
                          static_cast<double>(frame_));
  frames_.assign(2 * table_->speeds().size() * frame_, 0.0);
  // Only the bins some speed reaches are drawn: the others are zero in every frame.
  z_.resize(table_->active_bins());
  for (auto* draws : {&draw_re_, &draw_im_, &draw_scratch_})
    draws->resize(table_->active_bins() / kNoiseChunks + 1);
  model::numeric::vector_math_kind();  // its choice made here, not on the audio thread
  finish_next_frame();
  start_next_hop();     // frame −1: its second half overlaps the first output hop
  finish_next_frame();  // frame 0, which the first call's hop makes current
  position_ = hop_;
}

std::size_t ForcingGenerator::frame_steps() const noexcept {
  return kNoiseChunks + table_->speeds().size();
}

void ForcingGenerator::prepare_next_frame_step() noexcept {
  const std::size_t active = table_->active_bins();
  if (steps_done_ < kNoiseChunks) {
    // One draw of Z for all speeds (the coherence above), E|Z|² = 1.
    const std::size_t from = active * steps_done_ / kNoiseChunks;
    const std::size_t to = active * (steps_done_ + 1) / kNoiseChunks;
    noise_.normal_pairs(draw_re_.data(), draw_im_.data(), draw_scratch_.data(), to - from);
    for (std::size_t k = from; k < to; ++k)
      z_[k] = {draw_re_[k - from] * std::numbers::sqrt2 / 2,
               draw_im_[k - from] * std::numbers::sqrt2 / 2};
  } else {
    const std::size_t s = steps_done_ - kNoiseChunks;
    // FFTW's backward is unnormalised. The reduced frame holds every factor-th sample of the
    // full-rate one (same bins, same spacing), so the scale is the full frame's.
    const double scale = 1.0 / static_cast<double>(frame_);
    auto spectrum = fft_.spectrum();
    const auto magnitude = table_->magnitudes(s);
    for (std::size_t k = 0; k < active; ++k) spectrum[k] = z_[k] * magnitude[k];
    std::fill(spectrum.begin() + static_cast<std::ptrdiff_t>(active), spectrum.end(), 0.0);
    fft_.backward();
    double* next = frame_slot(next_, s);
    const double* current = frame_slot(current_, s);
    interpolator_.interpolate(fft_.real().data(), next);
    for (std::size_t n = 0; n < frame_; ++n) next[n] = window_[n] * next[n] * scale;
    for (std::size_t n = 0; n < hop_; ++n) next[n] += current[hop_ + n];
  }
  ++steps_done_;
}

void ForcingGenerator::finish_next_frame() noexcept {
  while (steps_done_ < frame_steps()) prepare_next_frame_step();
}

void ForcingGenerator::start_next_hop() noexcept {
  finish_next_frame();  // normally done already, spread over the calls of the hop
  std::swap(current_, next_);
  steps_done_ = 0;
  position_ = 0;
}

void ForcingGenerator::generate(const double* speed_m_s, const double* normal_force_n,
                                double* out, std::size_t count) noexcept {
  const auto& speeds = table_->speeds();
  const std::size_t last = speeds.size() - 1;
  // The next frame's steps are spread evenly over the hop, step j due at (j + phase) / steps of it,
  // so that a call does at most one at the usual few dozen samples (a hop is thousands), and voices
  // whose hops start together do theirs in different calls.
  const double due_at = static_cast<double>(std::min(position_ + count, hop_)) *
                            static_cast<double>(frame_steps()) / static_cast<double>(hop_) -
                        step_phase_;
  const std::size_t due =
      std::min(frame_steps(), static_cast<std::size_t>(std::max(0.0, std::ceil(due_at))));
  while (steps_done_ < due) prepare_next_frame_step();
  for (std::size_t i = 0; i < count; ++i) {
    if (position_ == hop_) start_next_hop();
    const double v = std::isfinite(speed_m_s[i]) ? std::max(0.0, speed_m_s[i]) : 0.0;
    const double force = std::isfinite(normal_force_n[i]) ? normal_force_n[i] : 0.0;
    const double gain = std::clamp(force / kReferenceNormalForce, 0.0, kMaxNormalForceRatio);
    auto stream = [&](std::size_t s) { return frame_slot(current_, s)[position_]; };
    double value;
    if (v <= speeds.front()) {
      value = (v / speeds.front()) * stream(0);
    } else if (v >= speeds[last]) {
      value = stream(last);
      above_range_ += v > speeds[last];
    } else {
      std::size_t s = 1;
      while (speeds[s] < v) ++s;  // at most the table's few speeds
      const double u = (v - speeds[s - 1]) / (speeds[s] - speeds[s - 1]);
      value = (1 - u) * stream(s - 1) + u * stream(s);
    }
    out[i] = gain * value;
    ++position_;
  }
}

}  // namespace nibrig::rt
