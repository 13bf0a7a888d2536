// erfc, exp, log, sin and cos over whole arrays: y[i] = f(x[i]) for i < n. On x86-64 with glibc
// these are libmvec's vector functions (four lanes with AVX2, two otherwise; within 4 ulp, as glibc
// documents them), elsewhere the scalar std:: functions. Loops that need one of these per element
// (the perceptual space's likelihood: an erfc, an exp and a log or two for each of 23,000 triplets
// an evaluation) gather the arguments into a block and call these once, as the scalar calls are
// much of an evaluation's time; the audio thread's Gaussian draws (rt/gaussian_noise.hpp) do the
// same. The choice is made on first use: call vector_math_kind() once off the audio thread.
#pragma once

#include <cstddef>

namespace nibrig::model::numeric {

void erfc_all(const double* x, double* y, std::size_t n);
void exp_all(const double* x, double* y, std::size_t n);
void log_all(const double* x, double* y, std::size_t n);
void sin_all(const double* x, double* y, std::size_t n);
void cos_all(const double* x, double* y, std::size_t n);

// Which of the implementations above runs on this machine ("avx2", "sse2" or "scalar"), for a
// benchmark's label and a test's message.
const char* vector_math_kind();

}  // namespace nibrig::model::numeric
