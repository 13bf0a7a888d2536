#include "model/measure/streaming_spectrogram.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nibrig::model::measure {

namespace {

// compute_spectrogram's checks, made here once so that push() has nothing left to refuse.
const SpectrogramSettings& checked(const SpectrogramSettings& s, double rate) {
  if (s.segment_length < 2)
    throw std::invalid_argument("streaming spectrogram: segment length must be at least 2 samples");
  if (s.hop == 0)
    throw std::invalid_argument("streaming spectrogram: hop must be at least 1 sample");
  if (!(rate > 0.0) || !std::isfinite(rate))
    throw std::invalid_argument("streaming spectrogram: sample rate must be positive and finite");
  return s;
}

}  // namespace

StreamingSpectrogram::StreamingSpectrogram(double sample_rate_hz,
                                           const SpectrogramSettings& settings)
    : settings_(checked(settings, sample_rate_hz)),
      rate_(sample_rate_hz),
      analyzer_(settings.segment_length, settings.window),
      frequencies_(analyzer_.bins()),
      buffer_(2 * settings.segment_length),
      row_(analyzer_.bins()) {
  for (std::size_t k = 0; k < frequencies_.size(); ++k)
    frequencies_[k] = analyzer_.bin_frequency_hz(k, rate_);
}

double StreamingSpectrogram::row_time_s(std::uint64_t index) const {
  // The same expression as compute_spectrogram's, so that times compare exactly too.
  const double half = static_cast<double>(settings_.segment_length) / 2.0;
  return (static_cast<double>(index * settings_.hop) + half) / rate_;
}

void StreamingSpectrogram::reset() {
  buffered_ = 0;
  buffer_start_ = 0;
  total_ = 0;
  rows_ = 0;
}

template <typename T>
void StreamingSpectrogram::push_impl(std::span<const T> samples, void* sink, Emit emit) {
  while (!samples.empty()) {
    const std::uint64_t next_start = rows_ * settings_.hop;
    if (buffered_ == buffer_.size()) {
      // Full: drop what precedes the next segment. Fewer than a segment's samples from next_start
      // on are ever left unanalysed, so at least a segment's room comes free.
      const auto drop =
          static_cast<std::size_t>(std::min<std::uint64_t>(buffered_, next_start - buffer_start_));
      std::copy(buffer_.begin() + static_cast<std::ptrdiff_t>(drop),
                buffer_.begin() + static_cast<std::ptrdiff_t>(buffered_), buffer_.begin());
      buffered_ -= drop;
      buffer_start_ += drop;
    }
    if (buffered_ == 0 && total_ < next_start) {
      // A hop longer than a segment leaves samples no segment covers: skip them unstored.
      const auto skip =
          static_cast<std::size_t>(std::min<std::uint64_t>(samples.size(), next_start - total_));
      samples = samples.subspan(skip);
      total_ += skip;
      buffer_start_ = total_;
      continue;
    }
    if (buffered_ == 0) buffer_start_ = total_;
    const std::size_t n = std::min(samples.size(), buffer_.size() - buffered_);
    std::copy(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(n),
              buffer_.begin() + static_cast<std::ptrdiff_t>(buffered_));
    buffered_ += n;
    total_ += n;
    samples = samples.subspan(n);
    emit_ready_rows(sink, emit);
  }
}

void StreamingSpectrogram::emit_ready_rows(void* sink, Emit emit) {
  const std::size_t length = settings_.segment_length;
  for (;;) {
    const std::uint64_t start = rows_ * settings_.hop;
    if (start < buffer_start_ || start + length > buffer_start_ + buffered_) return;
    const auto offset = static_cast<std::size_t>(start - buffer_start_);
    analyzer_.amplitude(std::span<const double>(buffer_).subspan(offset, length), row_,
                        settings_.remove_mean);
    emit(sink, SpectrogramRow{rows_, start, row_});
    ++rows_;
  }
}

template void StreamingSpectrogram::push_impl(std::span<const double>, void*, Emit);
template void StreamingSpectrogram::push_impl(std::span<const float>, void*, Emit);

}  // namespace nibrig::model::measure
