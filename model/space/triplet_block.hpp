// The likelihood terms of a block of triplets at once: the same terms as triplet_terms<L> gives one
// triplet at a time (triplet_kernel.hpp), with the links' erfc, exp and logs (and the lapse's logs)
// taken over the whole block by numeric/vector_math (libmvec where there is one). One at a time,
// those calls were about 40 % of an evaluation. The likelihood loop (objective.cpp) gathers a
// block's x_a, x_b and counts, calls block_terms, and spreads the terms back.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "model/numeric/vector_math.hpp"
#include "model/space/triplet_kernel.hpp"

namespace nibrig::model::space {

struct TripletBlock {
  static constexpr std::size_t kSize = 256;  // about 50 KiB with the work below: within L2
  using Column = std::array<double, kSize>;
  std::size_t size = 0;
  Column xa, xb, count_a, count_b;  // in
  Column nll, d_xa, d_xb, d_lapse;  // out: TripletTerms, a column each
  TripletTerms terms(std::size_t i) const { return {nll[i], d_xa[i], d_xb[i], d_lapse[i]}; }
  // The link's parts where a lapse is fitted (detail::LinkTerms without the logs, a column each)
  // and work between the two, here so that they are made once an evaluation. Columns, not a struct
  // per triplet, and selects, not branches: the loops then run in vector registers, where the
  // sides' signs and the counts, which follow no pattern, cost no mispredicted branches.
  Column p_a, p_b, log_a_dxa, log_a_dxb, log_b_dxa, log_b_dxb;
  Column c1, c2, c3, c4, c5;
};

namespace detail {

using Column = TripletBlock::Column;

// Each link works out its terms for i < b.size and hands them, a triplet at a time, to one of two
// places. With no lapse (kNoLapse) the link's own logs are the answers' and go straight into the
// triplet's sums (add_link_terms, add_link_logs), in the link's own loops. With a lapse the logs
// taken are of the mixture: the link's parts go to the link columns for block_answers. Writing
// those columns and reading them back took 6-12 % of an evaluation with no lapse.

// The triplet's gradient from its link's derivatives; with a lapse, those derivatives and P.
template <bool kNoLapse>
[[gnu::always_inline]] inline void add_link_terms(TripletBlock& b, std::size_t i, double p_a,
                                                  double p_b, double log_a_dxa, double log_a_dxb,
                                                  double log_b_dxa, double log_b_dxb,
                                                  bool with_gradient) {
  if constexpr (kNoLapse) {
    const double ca = b.count_a[i], cb = b.count_b[i];
    b.d_xa[i] = with_gradient ? -(ca * log_a_dxa + cb * log_b_dxa) : 0.0;
    b.d_xb[i] = with_gradient ? -(ca * log_a_dxb + cb * log_b_dxb) : 0.0;
    b.d_lapse[i] = 0.0;
  } else {
    b.p_a[i] = p_a, b.p_b[i] = p_b;
    b.log_a_dxa[i] = log_a_dxa, b.log_a_dxb[i] = log_a_dxb;
    b.log_b_dxa[i] = log_b_dxa, b.log_b_dxb[i] = log_b_dxb;
  }
}

// With no lapse, the triplet's −log-likelihood from its link's logs: a side no answer took is 0,
// as link_terms leaves it (the log of an underflowed P would be −∞, and 0·∞ is not 0).
[[gnu::always_inline]] inline void add_link_logs(TripletBlock& b, std::size_t i, double log_a,
                                                 double log_b) {
  const double ca = b.count_a[i], cb = b.count_b[i];
  b.nll[i] = -(ca * (ca == 0 ? 0.0 : log_a) + cb * (cb == 0 ? 0.0 : log_b));
}

// The probit, as normal_sides: Φ of the smaller side from erfc, 1 − it for the larger, φ from exp.
// Returns whether a triplet lies beyond kNormalTail, where erfc nears underflow: the caller works
// the block out one triplet at a time then (normal_sides' continued fraction).
template <bool kNoLapse>
[[gnu::always_inline]] inline bool probit_block_link(TripletBlock& b, bool with_gradient) {
  const std::size_t n = b.size;
  Column &z = b.c1, &erfc_arg = b.c2, &exp_arg = b.c3, &small = b.c4, &pdf = b.c5;
  int far = 0;
  for (std::size_t i = 0; i < n; ++i) {
    z[i] = b.xb[i] - b.xa[i];  // P(a) = Φ(z)
    const double t = std::abs(z[i]);
    far |= -t < kNormalTail;
    erfc_arg[i] = t / kSqrt2;
    exp_arg[i] = -0.5 * t * t - kLogSqrt2Pi;
  }
  if (far) return true;
  numeric::erfc_all(erfc_arg.data(), small.data(), n);
  numeric::exp_all(exp_arg.data(), pdf.data(), n);
  Column& large = b.c2;
  for (std::size_t i = 0; i < n; ++i) {
    small[i] *= 0.5;  // Φ(−|z|)
    large[i] = 1.0 - small[i];
    const bool negative = z[i] < 0;
    const double p_a = negative ? small[i] : large[i], p_b = negative ? large[i] : small[i];
    const double ra = pdf[i] / p_a, rb = pdf[i] / p_b;  // φ/Φ at z and at −z
    add_link_terms<kNoLapse>(b, i, p_a, p_b, -ra, ra, rb, -rb, with_gradient);
  }
  if constexpr (kNoLapse) {
    Column &log_small = b.c3, &log_large = b.c5;
    numeric::log_all(small.data(), log_small.data(), n);
    numeric::log_all(large.data(), log_large.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const double larger = log_larger_side(small[i], log_large[i]);
      const bool negative = z[i] < 0;
      add_link_logs(b, i, negative ? log_small[i] : larger, negative ? larger : log_small[i]);
    }
  }
  return false;
}

// The logistic, as link_terms<Link::logistic>: e = e^{−|cz|}, and log(1 + e) for both sides.
template <bool kNoLapse>
[[gnu::always_inline]] inline void logistic_block_link(TripletBlock& b, bool with_gradient) {
  const std::size_t n = b.size;
  Column &cz = b.c1, &exp_arg = b.c2, &e = b.c3, &one_plus_e = b.c4, &log_one_plus_e = b.c5;
  for (std::size_t i = 0; i < n; ++i) {
    cz[i] = kLogisticSlope * (b.xb[i] - b.xa[i]);  // P(a) = σ(cz)
    exp_arg[i] = -std::abs(cz[i]);
  }
  numeric::exp_all(exp_arg.data(), e.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    one_plus_e[i] = 1.0 + e[i];
    const double near = 1.0 / one_plus_e[i], far = e[i] * near;  // σ(|cz|), σ(−|cz|)
    const bool up = cz[i] >= 0;
    const double p_a = up ? near : far, p_b = up ? far : near;
    const double ga = kLogisticSlope * p_b, gb = kLogisticSlope * p_a;
    add_link_terms<kNoLapse>(b, i, p_a, p_b, -ga, ga, gb, -gb, with_gradient);
  }
  if constexpr (kNoLapse) {
    numeric::log_all(one_plus_e.data(), log_one_plus_e.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const double softplus_cz = std::max(cz[i], 0.0) + log_one_plus_e[i];
      add_link_logs(b, i, -(softplus_cz - cz[i]), -softplus_cz);
    }
  }
}

// The Student-t, as link_terms<Link::student_t>: k = r^{(α+1)/2} with r ≤ 1 the two kernels' bases'
// ratio, then log(1 + k) for the likelier side and log r for the other.
template <bool kNoLapse>
[[gnu::always_inline]] inline void student_t_block_link(TripletBlock& b, double alpha,
                                                        bool with_gradient) {
  const std::size_t n = b.size;
  Column &r = b.c1, &k = b.c2, &root = b.c3, &log_r = b.c4;
  Column& a_likelier_then = b.c5;  // 1 where w_a ≤ w_b, else 0
  for (std::size_t i = 0; i < n; ++i) {
    const double wa = alpha + b.xa[i] * b.xa[i], wb = alpha + b.xb[i] * b.xb[i];
    a_likelier_then[i] = wa <= wb ? 1.0 : 0.0;
    r[i] = std::min(wa, wb) / std::max(wa, wb);
    root[i] = std::sqrt(r[i]);
    k[i] = 1.0;
  }
  // √r multiplied in α+1 times, a loop of its own so that the loop above has no inner one.
  for (long m = std::lround(alpha + 1.0); m > 0; --m)
    for (std::size_t i = 0; i < n; ++i) k[i] *= root[i];
  Column& one_plus_k = k;  // k itself is needed no further than the first line below
  for (std::size_t i = 0; i < n; ++i) {
    const double xa = b.xa[i], xb = b.xb[i];
    const double wa = alpha + xa * xa, wb = alpha + xb * xb;
    const double likelier = 1.0 / (1.0 + k[i]), less = k[i] * likelier;  // P(less)/P(likelier) = k
    one_plus_k[i] = 1.0 + k[i];
    const bool a_likelier = a_likelier_then[i] != 0.0;
    const double p_a = a_likelier ? likelier : less, p_b = a_likelier ? less : likelier;
    const double du_dxa = (alpha + 1.0) * xa / wa, du_dxb = -(alpha + 1.0) * xb / wb;
    const double la_du = -p_b, lb_du = p_a;  // d log P(a)/du = −P(b)
    add_link_terms<kNoLapse>(b, i, p_a, p_b, la_du * du_dxa, la_du * du_dxb, lb_du * du_dxa,
                             lb_du * du_dxb, with_gradient);
  }
  if constexpr (kNoLapse) {
    Column& log_one_plus_k = root;
    numeric::log_all(one_plus_k.data(), log_one_plus_k.data(), n);
    numeric::log_all(r.data(), log_r.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const double log_likelier = -log_one_plus_k[i];
      const bool a_likelier = a_likelier_then[i] != 0.0;
      // log r is −∞ where r = 0 (α = 0 in 1-D, and x = 0): add_link_logs gives 0 for a side no
      // answer took.
      const double log_less = 0.5 * (alpha + 1.0) * log_r[i] + log_likelier;
      add_link_logs(b, i, a_likelier ? log_likelier : log_less,
                    a_likelier ? log_less : log_likelier);
    }
  }
}

// With a lapse, each answer's part from the link's columns, and the terms, as combined() takes
// them: the mixture ε/2 + (1−ε)P and its log (ε ≥ kLapseInLogs here, so the mixture does not
// underflow and every part is finite: a side no answer took is multiplied by its count, 0).
[[gnu::always_inline]] inline void block_answers(const TripletKernel& k, TripletBlock& b,
                                                 bool with_gradient) {
  const std::size_t n = b.size;
  const double lapse = k.lapse;
  Column &mixed_a = b.c1, &mixed_b = b.c2, &log_a = b.c3, &log_b = b.c4;
  for (std::size_t i = 0; i < n; ++i) {
    mixed_a[i] = 0.5 * lapse + (1.0 - lapse) * b.p_a[i];
    mixed_b[i] = 0.5 * lapse + (1.0 - lapse) * b.p_b[i];
  }
  numeric::log_all(mixed_a.data(), log_a.data(), n);
  numeric::log_all(mixed_b.data(), log_b.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const double ca = b.count_a[i], cb = b.count_b[i];
    const Lapsed on_a = lapsed_mixture(b.p_a[i], lapse, mixed_a[i], log_a[i]);
    const Lapsed on_b = lapsed_mixture(b.p_b[i], lapse, mixed_b[i], log_b[i]);
    b.nll[i] = -(ca * on_a.value + cb * on_b.value);
    const double da = ca * on_a.d_log, db = cb * on_b.d_log;
    b.d_xa[i] = with_gradient ? -(da * b.log_a_dxa[i] + db * b.log_b_dxa[i]) : 0.0;
    b.d_xb[i] = with_gradient ? -(da * b.log_a_dxb[i] + db * b.log_b_dxb[i]) : 0.0;
    b.d_lapse[i] = with_gradient ? -(ca * on_a.d_lapse + cb * on_b.d_lapse) : 0.0;
  }
}

// The link L's block; whether a triplet lies beyond the probit's kNormalTail.
template <Link L, bool kNoLapse>
[[gnu::always_inline]] inline bool block_link(const TripletKernel& k, TripletBlock& b,
                                              bool with_gradient) {
  switch (L) {
    case Link::probit:
      return probit_block_link<kNoLapse>(b, with_gradient);
    case Link::logistic:
      logistic_block_link<kNoLapse>(b, with_gradient);
      break;
    case Link::student_t:
      student_t_block_link<kNoLapse>(b, k.alpha, with_gradient);
      break;
  }
  return false;
}

// One triplet at a time: a lapse below kLapseInLogs (mixed in logs), or a probit triplet in the far
// tail.
template <Link L>
[[gnu::always_inline]] inline void block_terms_one_by_one(const TripletKernel& k, TripletBlock& b,
                                                          bool with_gradient) {
  for (std::size_t i = 0; i < b.size; ++i) {
    const TripletTerms t =
        triplet_terms<L>(k, b.xa[i], b.xb[i], b.count_a[i], b.count_b[i], with_gradient);
    b.nll[i] = t.nll, b.d_xa[i] = t.d_xa, b.d_xb[i] = t.d_xb, b.d_lapse[i] = t.d_lapse;
  }
}

}  // namespace detail

// The terms (b.nll, b.d_xa, b.d_xb, b.d_lapse) for every i < b.size, for the link L (k.link is not
// read). Inlined whole into its callers, so that the likelihood's AVX2 build (objective.cpp)
// compiles all of it for AVX2.
template <Link L>
[[gnu::always_inline]] inline void block_terms(const TripletKernel& k, TripletBlock& b,
                                               bool with_gradient) {
  if (k.lapse != 0.0 && k.lapse < detail::kLapseInLogs)
    return detail::block_terms_one_by_one<L>(k, b, with_gradient);
  const bool far = k.lapse == 0.0 ? detail::block_link<L, true>(k, b, with_gradient)
                                  : detail::block_link<L, false>(k, b, with_gradient);
  if (far) return detail::block_terms_one_by_one<L>(k, b, with_gradient);
  if (k.lapse != 0.0) detail::block_answers(k, b, with_gradient);
}

}  // namespace nibrig::model::space
