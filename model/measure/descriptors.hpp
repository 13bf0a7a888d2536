// The vibration descriptors of the paper's perceptual space (Sec. 4.4): a velocity-dependent
// spectrum weighted by the detection threshold and summarised as one number, or as band energies
// for spaces of more dimensions.
#pragma once

#include <map>
#include <vector>

#include "model/io/catalog_file.hpp"
#include "model/io/velocity_spectrum.hpp"
#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::measure {

// With r[s][f] = amplitude / threshold (weight_by_threshold) and each frequency bin f owning the
// cell between the midpoints to its neighbours (the end bins extended by half their neighbour
// spacing, so on a uniform grid every cell is Δf wide and the cells tile [f_0 - Δf/2, f_last +
// Δf/2]):
struct VibrationDescriptors {
  // Mean of r over all speeds and frequencies: the paper's "mean value of vibration spectrogram",
  // the descriptor its 2-D space correlates with (r = 0.95). Dimensionless.
  double weighted_mean = 0.0;
  // Mean over speeds of Σ_f r[s][f]² · width_f (Hz): the threshold-weighted vibration power, a
  // rectangle-rule ∫ r² df. It scales with the bin width, so compare tools at one resolution.
  double weighted_power = 0.0;
  // For k = 1..max_bands: k equal-width bands tiling the cells' range; entry j is the weighted
  // power (as above) of the parts of cells inside band j (a cell cut by a band edge is split in
  // proportion), so the k entries add up to weighted_power and band_energies[1] = {weighted_power}.
  std::map<int, std::vector<double>> band_energies;
};

// Needs >= 2 strictly increasing frequencies, >= 1 speed row of matching length, max_bands >= 1;
// otherwise std::invalid_argument.
VibrationDescriptors compute_vibration_descriptors(const io::VelocitySpectrum& spectrum,
                                                   const ThresholdCurve& threshold,
                                                   int max_bands = 5);

// The descriptor stage run over a catalog: every pairing with a vibration spectrum gets the
// descriptors of its spectrum weighted by `threshold` (and the threshold's source), so that a
// catalog and a space agree on the curve they were weighted by. Returns how many pairings were
// weighted. Throws what compute_vibration_descriptors throws, naming the pairing.
std::size_t weigh_catalog_vibration(io::Catalog& catalog, const ThresholdCurve& threshold,
                                    int max_bands = 5);

}  // namespace nibrig::model::measure
