#include "model/numeric/vector_math.hpp"

#include <cmath>

#include "model/numeric/cpu_features.hpp"

#if defined(__x86_64__) && defined(__GLIBC__)
#if __GLIBC_PREREQ(2, 35)  // libmvec's erfc came with 2.35
#define NIBRIG_LIBMVEC 1
#include <immintrin.h>
#endif
#endif

namespace nibrig::model::numeric {
namespace {

using ArrayFunction = void (*)(const double*, double*, std::size_t);

// The tail after the last whole vector, and every element where there is no libmvec.
template <double (*F)(double)>
void scalar_from(const double* x, double* y, std::size_t from, std::size_t n) {
  for (std::size_t i = from; i < n; ++i) y[i] = F(x[i]);
}
double erfc_of(double x) { return std::erfc(x); }
double exp_of(double x) { return std::exp(x); }
double log_of(double x) { return std::log(x); }
double sin_of(double x) { return std::sin(x); }
double cos_of(double x) { return std::cos(x); }

template <double (*F)(double)>
void scalar_all(const double* x, double* y, std::size_t n) {
  scalar_from<F>(x, y, 0, n);
}

#ifdef NIBRIG_LIBMVEC
// libmvec's entry points by the x86-64 vector function ABI: 'b' two lanes in SSE registers (the
// x86-64 baseline; glibc picks its SSE4.1 code where the CPU has it), 'd' four lanes in AVX2
// registers, to be called only where the CPU has AVX2.
extern "C" {
__m128d _ZGVbN2v_erfc(__m128d);
__m128d _ZGVbN2v_exp(__m128d);
__m128d _ZGVbN2v_log(__m128d);
__m128d _ZGVbN2v_sin(__m128d);
__m128d _ZGVbN2v_cos(__m128d);
}

template <__m128d (*V)(__m128d), double (*F)(double)>
void sse2_all(const double* x, double* y, std::size_t n) {
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) _mm_storeu_pd(y + i, V(_mm_loadu_pd(x + i)));
  scalar_from<F>(x, y, i, n);
}

extern "C" {
__m256d _ZGVdN4v_erfc(__m256d);
__m256d _ZGVdN4v_exp(__m256d);
__m256d _ZGVdN4v_log(__m256d);
__m256d _ZGVdN4v_sin(__m256d);
__m256d _ZGVdN4v_cos(__m256d);
}

template <__m256d (*V)(__m256d), double (*F)(double)>
__attribute__((target("avx2"))) void avx2_all(const double* x, double* y, std::size_t n) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(y + i, V(_mm256_loadu_pd(x + i)));
  scalar_from<F>(x, y, i, n);
}
#endif

struct Implementation {
  const char* kind;
  ArrayFunction erfc, exp, log, sin, cos;
};

Implementation choose() {
#ifdef NIBRIG_LIBMVEC
  if (cpu_has_avx2_fma())
    return {"avx2",
            avx2_all<_ZGVdN4v_erfc, erfc_of>,
            avx2_all<_ZGVdN4v_exp, exp_of>,
            avx2_all<_ZGVdN4v_log, log_of>,
            avx2_all<_ZGVdN4v_sin, sin_of>,
            avx2_all<_ZGVdN4v_cos, cos_of>};
  return {"sse2",
          sse2_all<_ZGVbN2v_erfc, erfc_of>,
          sse2_all<_ZGVbN2v_exp, exp_of>,
          sse2_all<_ZGVbN2v_log, log_of>,
          sse2_all<_ZGVbN2v_sin, sin_of>,
          sse2_all<_ZGVbN2v_cos, cos_of>};
#else
  return {"scalar",           scalar_all<erfc_of>, scalar_all<exp_of>,
          scalar_all<log_of>, scalar_all<sin_of>,  scalar_all<cos_of>};
#endif
}

// Chosen once, on first use (a function-local static: thread-safe, and no allocation).
const Implementation& implementation() {
  static const Implementation chosen = choose();
  return chosen;
}

}  // namespace

void erfc_all(const double* x, double* y, std::size_t n) { implementation().erfc(x, y, n); }
void exp_all(const double* x, double* y, std::size_t n) { implementation().exp(x, y, n); }
void log_all(const double* x, double* y, std::size_t n) { implementation().log(x, y, n); }
void sin_all(const double* x, double* y, std::size_t n) { implementation().sin(x, y, n); }
void cos_all(const double* x, double* y, std::size_t n) { implementation().cos(x, y, n); }
const char* vector_math_kind() { return implementation().kind; }

}  // namespace nibrig::model::numeric
