// Shrinks a catalog for bundling in assets/: spectra resampled onto a uniform frequency grid and
// every spectral value rounded to a few significant digits. The descriptors are recomputed from the
// compact spectra by whoever loads them, so the file stays self-consistent.
#pragma once

#include "model/io/catalog_file.hpp"

namespace nibrig::model::catalog {

// Linear interpolation onto frequency_step_hz steps spanning each spectrum's own range.
io::VelocitySpectrum resample_spectrum(const io::VelocitySpectrum& spectrum,
                                       double frequency_step_hz);

double round_significant(double value, int digits);

io::Catalog compact_catalog(io::Catalog catalog, double frequency_step_hz, int significant_digits);

}  // namespace nibrig::model::catalog
