#include "model/measure/spectrogram.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/numeric/parallel_for.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>

#include <cstdint>
#endif

namespace nibrig::model::measure {

namespace {

// A minute of 48 kHz audio makes a 46 MB result, a fresh mapping on every call, and touching it for
// the first time 4 KiB page by page cost about a third of the spectrogram's time. Transparent huge
// pages (Linux, when the system allows them on request) fault it in 2 MiB at a time. Only advice:
// nothing changes where the kernel declines.
void prefer_huge_pages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// values = sqrt(values · factor) over rows × bins values (factor per bin). Square roots are most of
// a spectrogram's arithmetic: std::sqrt one value at a time (all SpectrumAnalyzer::amplitude can
// do, since it must keep errno) is a large share of the time, which AVX's four lanes cut down.
// (AVX-512's eight would do more, but GCC 12's header for them trips its own maybe-uninitialized
// warning.) IEEE square roots and products are correctly rounded in every form, so the path taken
// changes no value.
void scaled_square_roots_portable(double* values, const double* factor, std::size_t rows,
                                  std::size_t bins) {
  for (std::size_t r = 0; r < rows; ++r, values += bins)
    for (std::size_t k = 0; k < bins; ++k) values[k] = std::sqrt(values[k] * factor[k]);
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx"))) void scaled_square_roots_avx(double* values, const double* factor,
                                                            std::size_t rows, std::size_t bins) {
  for (std::size_t r = 0; r < rows; ++r, values += bins) {
    std::size_t k = 0;
    for (; k + 4 <= bins; k += 4)
      _mm256_storeu_pd(values + k, _mm256_sqrt_pd(_mm256_mul_pd(_mm256_loadu_pd(values + k),
                                                                _mm256_loadu_pd(factor + k))));
    for (; k < bins; ++k) values[k] = std::sqrt(values[k] * factor[k]);
  }
}
#endif

using SquareRoots = void (*)(double*, const double*, std::size_t, std::size_t);

SquareRoots scaled_square_roots() {
#if defined(__x86_64__) && defined(__GNUC__)
  if (__builtin_cpu_supports("avx")) return scaled_square_roots_avx;
#endif
  return scaled_square_roots_portable;
}

}  // namespace

Spectrogram compute_spectrogram(std::span<const double> signal, double sample_rate_hz,
                                const SpectrogramSettings& settings) {
  if (settings.segment_length < 2) {
    throw std::invalid_argument("spectrogram: segment length must be at least 2 samples");
  }
  if (settings.hop == 0) throw std::invalid_argument("spectrogram: hop must be at least 1 sample");
  if (!(sample_rate_hz > 0.0) || !std::isfinite(sample_rate_hz)) {
    throw std::invalid_argument("spectrogram: sample rate must be positive and finite");
  }
  if (signal.size() < settings.segment_length) {
    throw std::invalid_argument("spectrogram: signal has " + std::to_string(signal.size()) +
                                " samples, fewer than one segment of " +
                                std::to_string(settings.segment_length));
  }
  const std::size_t segments = 1 + (signal.size() - settings.segment_length) / settings.hop;
  const std::size_t bins = settings.segment_length / 2 + 1;

  Spectrogram result;
  result.frequencies_hz.resize(bins);
  for (std::size_t k = 0; k < bins; ++k) {
    // SpectrumAnalyzer::bin_frequency_hz's expression, without making an analyzer for it.
    result.frequencies_hz[k] =
        static_cast<double>(k) * sample_rate_hz / static_cast<double>(settings.segment_length);
  }
  result.times_s.resize(segments);
  const double half = static_cast<double>(settings.segment_length) / 2.0;
  for (std::size_t i = 0; i < segments; ++i) {
    result.times_s[i] = (static_cast<double>(i * settings.hop) + half) / sample_rate_hz;
  }
  result.amplitude.resize(static_cast<Eigen::Index>(segments), static_cast<Eigen::Index>(bins));
  prefer_huge_pages(result.amplitude.data(), sizeof(double) * segments * bins);

  // Each row is the analyzer's power spectral density, turned into the amplitude 64 rows at a
  // time (scaled_square_roots). With psd_k = c_k |X_k|² / (fs Σw²) and amplitude_k = c_k |X_k| / Σw
  // (c_k = 2, 1 at DC and the even-length Nyquist bin), amplitude_k = sqrt(psd_k · c_k fs Σw² /
  // (Σw)²): SpectrumAnalyzer::amplitude's numbers to a few units in the last place.
  const std::vector<double> w = window_coefficients(settings.window, settings.segment_length);
  const double sum_w = std::accumulate(w.begin(), w.end(), 0.0);
  const double sum_w2 = std::inner_product(w.begin(), w.end(), w.begin(), 0.0);
  std::vector<double> factor(bins, 2.0 * sample_rate_hz * sum_w2 / (sum_w * sum_w));
  factor.front() *= 0.5;
  if (settings.segment_length % 2 == 0) factor.back() *= 0.5;
  const SquareRoots square_roots = scaled_square_roots();

  // Segments are independent: a few contiguous runs of them go to parallel_for's threads, each
  // with its own analyzer (an analyzer's buffers are its own). Two threads halve a minute of 48 kHz
  // audio (the machines this runs on have two cores to spare, and more threads than cores only
  // add planning and scheduling); short signals stay on the calling thread, where starting a thread
  // would cost more than it saves. Every segment is computed the same way wherever it falls, so the
  // result does not depend on the split.
  constexpr std::size_t kSegmentsPerThread = 512;
  constexpr unsigned kMaxThreads = 2;
  const auto runs =
      static_cast<unsigned>(std::clamp<std::size_t>(segments / kSegmentsPerThread, 1, kMaxThreads));
  numeric::parallel_for(runs, runs, [&](std::size_t run) {
    const std::size_t begin = segments * run / runs, end = segments * (run + 1) / runs;
    SpectrumAnalyzer analyzer(settings.segment_length, settings.window);
    // Segments are computed into a small row-major tile (contiguous writes, stays in cache) and
    // each tile is copied into the column-major result as 64-row column pieces: writing rows of a
    // column-major matrix directly, or transposing the whole result at the end, is several times
    // slower.
    constexpr std::size_t kTile = 64;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> tile(kTile, bins);
    for (std::size_t first = begin; first < end; first += kTile) {
      const std::size_t count = std::min(kTile, end - first);
      for (std::size_t r = 0; r < count; ++r) {
        analyzer.power_spectral_density(
            signal.subspan((first + r) * settings.hop, settings.segment_length), sample_rate_hz,
            std::span<double>(tile.row(static_cast<Eigen::Index>(r)).data(), bins),
            settings.remove_mean);
      }
      square_roots(tile.data(), factor.data(), count, bins);
      result.amplitude.middleRows(static_cast<Eigen::Index>(first),
                                  static_cast<Eigen::Index>(count)) =
          tile.topRows(static_cast<Eigen::Index>(count));
    }
  });
  return result;
}

}  // namespace nibrig::model::measure
