#include "model/numeric/real_fft.hpp"

#include <fftw3.h>

#include <limits>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/numeric/fftw_planner_lock.hpp"

namespace nibrig::model::numeric {

// FFTW documents fftw_complex (double[2]) and std::complex<double> as bit-compatible; the spectrum
// is handed to FFTW as the one and read by the callers as the other.
static_assert(sizeof(std::complex<double>) == sizeof(fftw_complex));

RealFft::RealFft(std::size_t n, Plans plans) {
  if (n < 1 || n > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::invalid_argument("RealFft: size must be 1 to " +
                                std::to_string(std::numeric_limits<int>::max()) + ", got " +
                                std::to_string(n));
  }
  n_ = n;
  real_ = static_cast<double*>(fftw_malloc(sizeof(double) * n));
  spectrum_ = static_cast<std::complex<double>*>(fftw_malloc(sizeof(fftw_complex) * bins()));
  if (real_ == nullptr || spectrum_ == nullptr) {
    release();
    throw std::bad_alloc();
  }
  auto* spectrum = reinterpret_cast<fftw_complex*>(spectrum_);
  {
    std::lock_guard lock(detail::fftw_planner_mutex());
    if (plans != Plans::backward)
      forward_ = fftw_plan_dft_r2c_1d(static_cast<int>(n), real_, spectrum, FFTW_ESTIMATE);
    if (plans != Plans::forward)
      backward_ = fftw_plan_dft_c2r_1d(static_cast<int>(n), spectrum, real_, FFTW_ESTIMATE);
  }
  if ((plans != Plans::backward && forward_ == nullptr) ||
      (plans != Plans::forward && backward_ == nullptr)) {
    release();
    throw std::runtime_error("RealFft: FFTW could not make a plan for " + std::to_string(n) +
                             " points");
  }
}

RealFft::~RealFft() { release(); }

RealFft::RealFft(RealFft&& other) noexcept
    : n_(std::exchange(other.n_, 0)),
      real_(std::exchange(other.real_, nullptr)),
      spectrum_(std::exchange(other.spectrum_, nullptr)),
      forward_(std::exchange(other.forward_, nullptr)),
      backward_(std::exchange(other.backward_, nullptr)) {}

RealFft& RealFft::operator=(RealFft&& other) noexcept {
  if (this != &other) {
    release();
    n_ = std::exchange(other.n_, 0);
    real_ = std::exchange(other.real_, nullptr);
    spectrum_ = std::exchange(other.spectrum_, nullptr);
    forward_ = std::exchange(other.forward_, nullptr);
    backward_ = std::exchange(other.backward_, nullptr);
  }
  return *this;
}

void RealFft::forward() {
  if (forward_ == nullptr) {
    throw std::logic_error("RealFft: forward() on a transform made without a forward plan");
  }
  fftw_execute(forward_);
}

void RealFft::backward() {
  if (backward_ == nullptr) {
    throw std::logic_error("RealFft: backward() on a transform made without a backward plan");
  }
  fftw_execute(backward_);
}

void RealFft::release() noexcept {
  if (forward_ != nullptr || backward_ != nullptr) {
    std::lock_guard lock(detail::fftw_planner_mutex());
    if (forward_ != nullptr) fftw_destroy_plan(forward_);
    if (backward_ != nullptr) fftw_destroy_plan(backward_);
  }
  if (spectrum_ != nullptr) fftw_free(spectrum_);
  if (real_ != nullptr) fftw_free(real_);
  n_ = 0;
  real_ = nullptr;
  spectrum_ = nullptr;
  forward_ = nullptr;
  backward_ = nullptr;
}

}  // namespace nibrig::model::numeric
