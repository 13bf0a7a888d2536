// Human vibrotactile detection threshold versus frequency, loaded from a data file in assets/, and
// the perceptual weighting of measured spectra by it (the paper's Sec. 4.4, after [Israr et al.
// 2006a]).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/io/velocity_spectrum.hpp"

namespace nibrig::model::measure {

class ThresholdCurve {
 public:
  // CSV: lines starting with '#' are comments (those starting "# source:" are joined into
  // source()); the first other line is the header "frequency_hz,threshold_m_s2"; then one row per
  // frequency, strictly increasing and positive, with a positive, finite threshold (PEAK
  // acceleration of a just-detectable sinusoid, m/s²). At least 2 rows. Violations throw
  // io::FormatError naming the line.
  static ThresholdCurve load(const std::filesystem::path& csv);

  // The same checks on in-memory tables, with std::invalid_argument.
  ThresholdCurve(std::vector<double> frequencies_hz, std::vector<double> thresholds_m_s2,
                 std::string source);

  // Linear interpolation of log threshold against log frequency between rows (threshold curves are
  // straight lines in dB per octave between measured points); clamped flat outside the table: the
  // first row's value below it, the last row's above it (no extrapolation of a slope that was never
  // measured). NaN or negative frequency: std::invalid_argument.
  double threshold_m_s2(double frequency_hz) const;

  const std::string& source() const { return source_; }
  const std::vector<double>& frequencies_hz() const { return frequencies_; }
  const std::vector<double>& thresholds_m_s2() const { return thresholds_; }

 private:
  std::vector<double> frequencies_;
  std::vector<double> thresholds_;
  std::string source_;
};

// Sensation ratio re threshold, result[s][f] = amplitude_m_s2[s][f] / threshold(frequencies_hz[f]):
// 1 is just detectable. Amplitudes are peak, like the thresholds, so the ratio is the same whether
// the curve was measured in displacement, velocity or acceleration. Ragged spectra:
// std::invalid_argument.
std::vector<std::vector<double>> weight_by_threshold(const io::VelocitySpectrum& spectrum,
                                                     const ThresholdCurve& curve);

}  // namespace nibrig::model::measure
