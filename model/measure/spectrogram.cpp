#include "model/measure/spectrogram.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace nibrig::model::measure {

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
  SpectrumAnalyzer analyzer(settings.segment_length, settings.window);
  const std::size_t segments = 1 + (signal.size() - settings.segment_length) / settings.hop;
  const std::size_t bins = analyzer.bins();

  Spectrogram result;
  result.frequencies_hz.resize(bins);
  for (std::size_t k = 0; k < bins; ++k) {
    result.frequencies_hz[k] = analyzer.bin_frequency_hz(k, sample_rate_hz);
  }
  result.times_s.resize(segments);
  result.amplitude.resize(static_cast<Eigen::Index>(segments), static_cast<Eigen::Index>(bins));
  // Segments are computed into a small row-major tile (contiguous writes, stays in cache) and each
  // tile is copied into the column-major result as 64-row column pieces: writing rows of a
  // column-major matrix directly, or transposing the whole result at the end, is several times
  // slower.
  constexpr std::size_t kTile = 64;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> tile(kTile, bins);
  const double half = static_cast<double>(settings.segment_length) / 2.0;
  for (std::size_t first = 0; first < segments; first += kTile) {
    const std::size_t count = std::min(kTile, segments - first);
    for (std::size_t r = 0; r < count; ++r) {
      const std::size_t start = (first + r) * settings.hop;
      result.times_s[first + r] = (static_cast<double>(start) + half) / sample_rate_hz;
      analyzer.amplitude(signal.subspan(start, settings.segment_length),
                         std::span<double>(tile.row(static_cast<Eigen::Index>(r)).data(), bins),
                         settings.remove_mean);
    }
    result.amplitude.middleRows(static_cast<Eigen::Index>(first),
                                static_cast<Eigen::Index>(count)) =
        tile.topRows(static_cast<Eigen::Index>(count));
  }
  return result;
}

}  // namespace nibrig::model::measure
