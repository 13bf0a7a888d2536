// What a catalog amplitude means for a random signal. The paper's spectra are the mean of |FFT|·2/N
// over rectangular windows; for a stationary Gaussian signal that mean is fixed by the power
// spectral density and the window length, which lets a generator synthesise noise that the same
// analysis reads back as the same amplitude.
#pragma once

namespace nibrig::model::numeric {

// The windows of the paper's analysis and of our catalog: 1500 samples at 1 kHz.
inline constexpr double kCatalogWindowSeconds = 1.5;

// For Gaussian noise of one-sided PSD S (units²/Hz), each bin's amplitude a = 2|X|/N over a
// rectangular window of T seconds is Rayleigh distributed with E[a²] = 2·S/T, so its mean is
// E[a] = (√π/2)·√(2S/T). These invert and apply that relation. T > 0, amplitude and PSD ≥ 0.
double noise_psd_from_mean_amplitude(double mean_amplitude, double window_seconds);
double mean_amplitude_from_noise_psd(double psd, double window_seconds);

}  // namespace nibrig::model::numeric
