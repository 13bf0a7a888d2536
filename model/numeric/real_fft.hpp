// An n-point real FFT with its own buffers and FFTW plans: the one owner of FFTW memory and plans
// in nibrig (measure, mechanics, rt and playback all use it), so that every plan is made and
// destroyed under the planner lock and every buffer is freed, whatever throws.
#pragma once

#include <complex>
#include <cstddef>
#include <span>

struct fftw_plan_s;  // FFTW's plan type, kept out of this header

namespace nibrig::model::numeric {

// Buffers come from fftw_malloc (aligned for SIMD); plans are made with FFTW_ESTIMATE (see
// SpectrumAnalyzer for why), so that every process computes the same values: FFTW_MEASURE's
// transforms are about twice as fast here, but its choice, and so the rounding, varies from one
// process to the next (a simulated capture then differed between Python and the command).
// forward() transforms real() into spectrum(), the n/2 + 1 one-sided bins, unnormalised. backward()
// transforms spectrum() back into real() multiplied by n, and overwrites spectrum() on the way
// (FFTW's c2r does). Move-only; one object per thread, since the transforms work in its buffers.
class RealFft {
 public:
  enum class Plans { forward, backward, forward_and_backward };

  // n >= 1 and within FFTW's int sizes, else std::invalid_argument; std::bad_alloc when the
  // buffers cannot be had, std::runtime_error when FFTW makes no plan.
  RealFft(std::size_t n, Plans plans);
  ~RealFft();
  RealFft(RealFft&& other) noexcept;
  RealFft& operator=(RealFft&& other) noexcept;
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  std::size_t size() const { return n_; }
  // n/2 + 1; 0 once moved from.
  std::size_t bins() const { return n_ == 0 ? 0 : n_ / 2 + 1; }

  std::span<double> real() { return {real_, n_}; }
  std::span<const double> real() const { return {real_, n_}; }
  std::span<std::complex<double>> spectrum() { return {spectrum_, bins()}; }
  std::span<const std::complex<double>> spectrum() const { return {spectrum_, bins()}; }

  // Each only with a plan made for it, else std::logic_error.
  void forward();
  void backward();

 private:
  void release() noexcept;

  std::size_t n_ = 0;
  double* real_ = nullptr;
  std::complex<double>* spectrum_ = nullptr;
  fftw_plan_s* forward_ = nullptr;
  fftw_plan_s* backward_ = nullptr;
};

}  // namespace nibrig::model::numeric
