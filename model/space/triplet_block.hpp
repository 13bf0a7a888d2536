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
  static constexpr std::size_t kSize = 256;  // about 56 KiB with the work below: within L2
  using Column = std::array<double, kSize>;
  std::size_t size = 0;
  Column xa, xb, count_a, count_b;  // in
  Column nll, d_xa, d_xb, d_lapse;  // out: TripletTerms, a column each
  TripletTerms terms(std::size_t i) const { return {nll[i], d_xa[i], d_xb[i], d_lapse[i]}; }
  // The link's parts (detail::LinkTerms, a column each) and work between the two, here so that
  // they are made once an evaluation. Columns, not a struct per triplet, and selects, not branches:
  // the loops then run in vector registers, where the sides' signs and the counts, which follow no
  // pattern, cost no mispredicted branches.
  Column p_a, p_b, log_a, log_b, log_a_dxa, log_a_dxb, log_b_dxa, log_b_dxb;
  Column c1, c2, c3, c4, c5;
};

namespace detail {

using Column = TripletBlock::Column;

// Each link fills the link columns for i < b.size: the logs of P only where logs_wanted (no lapse:
// with one, the logs taken are of the mixture), and then only for a side some answer took (else 0,
// as link_terms leaves them: a log of an underflowed P would be −∞, and 0·∞ is not 0).

// The probit, as normal_sides: Φ of the smaller side from erfc, 1 − it for the larger, φ from exp.
// Returns whether a triplet lies beyond kNormalTail, where erfc nears underflow: the caller works
// the block out one triplet at a time then (normal_sides' continued fraction).
[[gnu::always_inline]] inline bool probit_block_link(TripletBlock& b, bool logs_wanted) {
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
    b.p_a[i] = negative ? small[i] : large[i];
    b.p_b[i] = negative ? large[i] : small[i];
    const double ra = pdf[i] / b.p_a[i], rb = pdf[i] / b.p_b[i];  // φ/Φ at z and at −z
    b.log_a_dxa[i] = -ra, b.log_a_dxb[i] = ra, b.log_b_dxa[i] = rb, b.log_b_dxb[i] = -rb;
  }
  if (!logs_wanted) return false;
  Column &log_small = b.c3, &log_large = b.c5;
  numeric::log_all(small.data(), log_small.data(), n);
  numeric::log_all(large.data(), log_large.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const double larger = log_larger_side(small[i], log_large[i]);
    const bool negative = z[i] < 0;
    const double log_a = negative ? log_small[i] : larger, log_b = negative ? larger : log_small[i];
    b.log_a[i] = b.count_a[i] == 0 ? 0.0 : log_a;
    b.log_b[i] = b.count_b[i] == 0 ? 0.0 : log_b;
  }
  return false;
}

// The logistic, as link_terms<Link::logistic>: e = e^{−|cz|}, and log(1 + e) for both sides.
[[gnu::always_inline]] inline void logistic_block_link(TripletBlock& b, bool logs_wanted) {
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
    b.p_a[i] = up ? near : far, b.p_b[i] = up ? far : near;
    const double ga = kLogisticSlope * b.p_b[i], gb = kLogisticSlope * b.p_a[i];
    b.log_a_dxa[i] = -ga, b.log_a_dxb[i] = ga, b.log_b_dxa[i] = gb, b.log_b_dxb[i] = -gb;
  }
  if (!logs_wanted) return;
  numeric::log_all(one_plus_e.data(), log_one_plus_e.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const double softplus_cz = std::max(cz[i], 0.0) + log_one_plus_e[i];
    b.log_a[i] = b.count_a[i] == 0 ? 0.0 : -(softplus_cz - cz[i]);
    b.log_b[i] = b.count_b[i] == 0 ? 0.0 : -softplus_cz;
  }
}

// The Student-t, as link_terms<Link::student_t>: k = r^{(α+1)/2} with r ≤ 1 the two kernels' bases'
// ratio, then log(1 + k) for the likelier side and log r for the other.
[[gnu::always_inline]] inline void student_t_block_link(TripletBlock& b, double alpha,
                                                        bool logs_wanted) {
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
    b.p_a[i] = a_likelier ? likelier : less, b.p_b[i] = a_likelier ? less : likelier;
    const double du_dxa = (alpha + 1.0) * xa / wa, du_dxb = -(alpha + 1.0) * xb / wb;
    const double la_du = -b.p_b[i], lb_du = b.p_a[i];  // d log P(a)/du = −P(b)
    b.log_a_dxa[i] = la_du * du_dxa, b.log_a_dxb[i] = la_du * du_dxb;
    b.log_b_dxa[i] = lb_du * du_dxa, b.log_b_dxb[i] = lb_du * du_dxb;
  }
  if (!logs_wanted) return;
  Column& log_one_plus_k = root;
  numeric::log_all(one_plus_k.data(), log_one_plus_k.data(), n);
  numeric::log_all(r.data(), log_r.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const double log_likelier = -log_one_plus_k[i];
    const bool a_likelier = a_likelier_then[i] != 0.0;
    // log r is −∞ where r = 0 (α = 0 in 1-D, and x = 0): a side no answer took is 0 instead.
    const double log_less = 0.5 * (alpha + 1.0) * log_r[i] + log_likelier;
    const double log_a = a_likelier ? log_likelier : log_less;
    const double log_b = a_likelier ? log_less : log_likelier;
    b.log_a[i] = b.count_a[i] == 0 ? 0.0 : log_a;
    b.log_b[i] = b.count_b[i] == 0 ? 0.0 : log_b;
  }
}

// Each answer's part from the link's, and the terms, as combined() takes them: the link's logs with
// no lapse, else the mixture ε/2 + (1−ε)P and its log (ε ≥ kLapseInLogs here, so the mixture does
// not underflow and every part is finite: a side no answer took is multiplied by its count, 0).
[[gnu::always_inline]] inline void block_answers(const TripletKernel& k, TripletBlock& b,
                                                 bool with_gradient) {
  const std::size_t n = b.size;
  const double lapse = k.lapse;
  if (lapse == 0.0) {
    for (std::size_t i = 0; i < n; ++i) {
      const double ca = b.count_a[i], cb = b.count_b[i];
      b.nll[i] = -(ca * b.log_a[i] + cb * b.log_b[i]);
      b.d_xa[i] = with_gradient ? -(ca * b.log_a_dxa[i] + cb * b.log_b_dxa[i]) : 0.0;
      b.d_xb[i] = with_gradient ? -(ca * b.log_a_dxb[i] + cb * b.log_b_dxb[i]) : 0.0;
      b.d_lapse[i] = 0.0;
    }
    return;
  }
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
  const bool logs_wanted = k.lapse == 0.0;
  switch (L) {
    case Link::probit:
      if (detail::probit_block_link(b, logs_wanted))
        return detail::block_terms_one_by_one<L>(k, b, with_gradient);
      break;
    case Link::logistic:
      detail::logistic_block_link(b, logs_wanted);
      break;
    case Link::student_t:
      detail::student_t_block_link(b, k.alpha, logs_wanted);
      break;
  }
  detail::block_answers(k, b, with_gradient);
}

}  // namespace nibrig::model::space
