// How far a prediction's perceptual descriptors land from the measured ones: the ratio, as log10,
// of each vibration descriptor a space's axes are tied to (the perceptually weighted mean and the
// weighted band energies, measure/descriptors.hpp), predicted over measured. Collected over the
// leave-one-out predictions (leave_one_out.hpp) it is the error a predicted tool's descriptors
// carry, which its placement in the perceptual space must carry too
// (design/descriptor_uncertainty).
//
// Log10, because the space's vibration descriptors are the log10 of these values
// (space/catalog_descriptors.hpp): an error in log10 is an error in the descriptor itself.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "model/io/velocity_spectrum.hpp"
#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::forcing {

struct DescriptorError {
  std::string tool, surface;
  double log10_weighted_mean = 0.0;  // log10(predicted / measured)
  // Per band count k (2..max_bands): log10(predicted / measured) of each of the k band energies.
  std::map<int, std::vector<double>> log10_band_energies;
};

// The band counts a descriptor error holds: 2 to 5, those a 3- to 6-dimensional space uses (one
// band, the total power, is no space's descriptor).
inline constexpr int kMinDescriptorBands = 2, kMaxDescriptorBands = 5;

// A log10 ratio as a percentage off: log10(1.1) is +10 %.
double percent_off(double log10_ratio);

// Both spectra weighted by `threshold` (compute_vibration_descriptors). Throws
// std::invalid_argument naming the tool and surface when a descriptor of either is not positive
// (no logarithm), and what compute_vibration_descriptors throws for a bad grid.
DescriptorError descriptor_error(const std::string& tool, const std::string& surface,
                                 const io::VelocitySpectrum& predicted,
                                 const io::VelocitySpectrum& measured,
                                 const measure::ThresholdCurve& threshold);

// How far held-out predictions' descriptors were from the measured ones: the RMS of the log10
// ratio of the weighted mean over the errors, of every band energy at kMaxDescriptorBands, and the
// error with the largest |weighted mean| (null for no errors).
struct DescriptorErrorSummary {
  std::size_t errors = 0;
  double rms_log10_weighted_mean = 0.0, rms_log10_band_energy = 0.0;
  const DescriptorError* worst = nullptr;  // points into the summarised errors
};
DescriptorErrorSummary summarize(const std::vector<DescriptorError>& errors);

}  // namespace nibrig::model::forcing
