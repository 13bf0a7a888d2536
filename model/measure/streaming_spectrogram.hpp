// The spectrogram of a signal that arrives in pieces (a live rig's acceleration): samples are
// pushed in blocks of any size and every complete segment becomes a row as soon as its last sample
// is in. Rows are compute_spectrogram's rows for the concatenated signal (same analyzer, window,
// mean removal and amplitude convention; equal to a few units in the last place, as the offline
// one takes its square roots in vectors), so a live waterfall and the offline report agree.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "model/measure/spectrogram.hpp"
#include "model/measure/spectrum_analyzer.hpp"

namespace nibrig::model::measure {

// One row: the segment of samples [first_sample, first_sample + segment_length) of the stream, its
// peak amplitude spectrum (SpectrumAnalyzer::amplitude) valid only during the callback.
struct SpectrogramRow {
  std::uint64_t index = 0;
  std::uint64_t first_sample = 0;
  std::span<const double> amplitude;
};

class StreamingSpectrogram {
 public:
  // Validates as compute_spectrogram does (std::invalid_argument) and makes the FFTW plan and every
  // buffer here, so that push() never allocates.
  StreamingSpectrogram(double sample_rate_hz, const SpectrogramSettings& settings);

  const SpectrogramSettings& settings() const { return settings_; }
  double sample_rate_hz() const { return rate_; }
  std::size_t bins() const { return analyzer_.bins(); }
  const std::vector<double>& frequencies_hz() const { return frequencies_; }
  std::uint64_t rows() const { return rows_; }
  std::uint64_t samples_pushed() const { return total_; }
  // compute_spectrogram's times_s of row i: the segment's centre.
  double row_time_s(std::uint64_t index) const;

  // Appends the samples and calls on_row(const SpectrogramRow&) for each row they complete, in
  // order. No allocation, lock or exception (the sink's own aside).
  template <typename Sink>
  void push(std::span<const double> samples, Sink&& on_row) {
    push_impl(samples, &on_row, [](void* sink, const SpectrogramRow& row) {
      (*static_cast<std::remove_reference_t<Sink>*>(sink))(row);
    });
  }
  // The same for float samples (audio streams), widened to double on the way in.
  template <typename Sink>
  void push(std::span<const float> samples, Sink&& on_row) {
    push_impl(samples, &on_row, [](void* sink, const SpectrogramRow& row) {
      (*static_cast<std::remove_reference_t<Sink>*>(sink))(row);
    });
  }

  // Forgets the stream (rows restart at 0); plans and buffers are kept.
  void reset();

 private:
  using Emit = void (*)(void*, const SpectrogramRow&);
  template <typename T>
  void push_impl(std::span<const T> samples, void* sink, Emit emit);
  void emit_ready_rows(void* sink, Emit emit);

  SpectrogramSettings settings_;
  double rate_;
  SpectrumAnalyzer analyzer_;
  std::vector<double> frequencies_;
  // Samples [buffer_start_, buffer_start_ + buffered_) of the stream; twice a segment, so that
  // after dropping what no later segment needs there is always room for at least one more segment.
  std::vector<double> buffer_;
  std::size_t buffered_ = 0;
  std::uint64_t buffer_start_ = 0;
  std::uint64_t total_ = 0;  // samples pushed so far
  std::uint64_t rows_ = 0;   // rows emitted; the next starts at rows_ * hop
  std::vector<double> row_;
};

}  // namespace nibrig::model::measure
