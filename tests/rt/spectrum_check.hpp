// How the real-time tests read a generated signal's spectrum: the catalog's own analysis (mean
// |FFT|·2/N over 1.5 s rectangular windows, 5-bin smoothing), so that what they compare with a
// catalog spectrum was measured the way that spectrum was.
#pragma once

#include <vector>

namespace nibrig::rt::testing {

// Mean amplitude of x (rate fs) at each of `frequencies`, interpolated between analysis bins.
std::vector<double> catalog_analysis(const std::vector<double>& x, double fs,
                                     const std::vector<double>& frequencies);

struct SpectrumAgreement {
  double median_abs_db, p95_abs_db, total_db;  // |20 log10(got/want)| statistics; power ratio
};
SpectrumAgreement compare_spectra(const std::vector<double>& got, const std::vector<double>& want);

}  // namespace nibrig::rt::testing
