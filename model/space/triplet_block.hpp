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
  Column xa, xb, count_a, count_b;        // in
  std::array<TripletTerms, kSize> terms;  // out
  // Work between the two (here, so that it is made once an evaluation).
  std::array<detail::LinkTerms, kSize> link;
  Column c1, c2, c3, c4, c5, c6;
};

namespace detail {

using Column = TripletBlock::Column;

// Each link fills b.link[i] for i < b.size: the logs of P only where logs_wanted (no lapse: with
// one, the logs taken are of the mixture), and then only for a side some answer took (else 0, as
// link_terms leaves them: a log of an underflowed P would be −∞, and 0·∞ is not 0).

// The probit, as normal_sides: Φ of the smaller side from erfc, 1 − it for the larger, φ from exp.
// Returns whether a triplet lies beyond kNormalTail, where erfc nears underflow: the caller works
// the block out one triplet at a time then (normal_sides' continued fraction).
inline bool probit_block_link(TripletBlock& b, bool logs_wanted) {
  const std::size_t n = b.size;
  Column &z = b.c1, &erfc_arg = b.c2, &exp_arg = b.c3, &small = b.c4, &pdf = b.c5;
  bool far = false;
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
    LinkTerms& t = b.link[i];
    t.p_a = z[i] < 0 ? small[i] : large[i];
    t.p_b = z[i] < 0 ? large[i] : small[i];
    const double ra = pdf[i] / t.p_a, rb = pdf[i] / t.p_b;  // φ/Φ at z and at −z
    t.log_a_dxa = -ra, t.log_a_dxb = ra, t.log_b_dxa = rb, t.log_b_dxb = -rb;
  }
  if (!logs_wanted) return false;
  Column &log_small = b.c3, &log_large = b.c6;
  numeric::log_all(small.data(), log_small.data(), n);
  numeric::log_all(large.data(), log_large.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const double larger = log_larger_side(small[i], log_large[i]);
    LinkTerms& t = b.link[i];
    t.log_a = b.count_a[i] == 0 ? 0.0 : z[i] < 0 ? log_small[i] : larger;
    t.log_b = b.count_b[i] == 0 ? 0.0 : z[i] < 0 ? larger : log_small[i];
  }
  return false;
}

// The logistic, as link_terms<Link::logistic>: e = e^{−|cz|}, and log(1 + e) for both sides.
inline void logistic_block_link(TripletBlock& b, bool logs_wanted) {
  const std::size_t n = b.size;
  Column &cz = b.c1, &exp_arg = b.c2, &e = b.c3, &one_plus_e = b.c4, &log_one_plus_e = b.c5;
  for (std::size_t i = 0; i < n; ++i) {
    cz[i] = kLogisticSlope * (b.xb[i] - b.xa[i]);  // P(a) = σ(cz)
    exp_arg[i] = -std::abs(cz[i]);
  }
  numeric::exp_all(exp_arg.data(), e.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    one_plus_e[i] = 1.0 + e[i];
    LinkTerms& t = b.link[i];
    const double near = 1.0 / one_plus_e[i], far = e[i] * near;  // σ(|cz|), σ(−|cz|)
    t.p_a = cz[i] >= 0 ? near : far, t.p_b = cz[i] >= 0 ? far : near;
    const double ga = kLogisticSlope * t.p_b, gb = kLogisticSlope * t.p_a;
    t.log_a_dxa = -ga, t.log_a_dxb = ga, t.log_b_dxa = gb, t.log_b_dxb = -gb;
  }
  if (!logs_wanted) return;
  numeric::log_all(one_plus_e.data(), log_one_plus_e.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const double softplus_cz = std::max(cz[i], 0.0) + log_one_plus_e[i];
    LinkTerms& t = b.link[i];
    t.log_a = b.count_a[i] == 0 ? 0.0 : -(softplus_cz - cz[i]);
    t.log_b = b.count_b[i] == 0 ? 0.0 : -softplus_cz;
  }
}

// The Student-t, as link_terms<Link::student_t>: k = r^{(α+1)/2} with r ≤ 1 the two kernels' bases'
// ratio, then log(1 + k) for the likelier side and log r for the other.
inline void student_t_block_link(TripletBlock& b, double alpha, bool logs_wanted) {
  const std::size_t n = b.size;
  Column &r = b.c1, &one_plus_k = b.c2, &log_one_plus_k = b.c3, &log_r = b.c4;
  Column& a_likelier_then = b.c5;  // 1 where w_a ≤ w_b, else 0
  const long power = std::lround(alpha + 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double xa = b.xa[i], xb = b.xb[i];
    const double wa = alpha + xa * xa, wb = alpha + xb * xb;
    const bool a_likelier = wa <= wb;
    a_likelier_then[i] = a_likelier ? 1.0 : 0.0;
    r[i] = a_likelier ? wa / wb : wb / wa;
    const double root = std::sqrt(r[i]);
    double k = 1.0;  // P(less likely)/P(likelier)
    for (long m = power; m > 0; --m) k *= root;
    one_plus_k[i] = 1.0 + k;
    const double likelier = 1.0 / one_plus_k[i], less = k * likelier;
    LinkTerms& t = b.link[i];
    t.p_a = a_likelier ? likelier : less, t.p_b = a_likelier ? less : likelier;
    const double du_dxa = (alpha + 1.0) * xa / wa, du_dxb = -(alpha + 1.0) * xb / wb;
    const double la_du = -t.p_b, lb_du = t.p_a;  // d log P(a)/du = −P(b)
    t.log_a_dxa = la_du * du_dxa, t.log_a_dxb = la_du * du_dxb;
    t.log_b_dxa = lb_du * du_dxa, t.log_b_dxb = lb_du * du_dxb;
  }
  if (!logs_wanted) return;
  numeric::log_all(one_plus_k.data(), log_one_plus_k.data(), n);
  numeric::log_all(r.data(), log_r.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    LinkTerms& t = b.link[i];
    const double log_likelier = -log_one_plus_k[i];
    const bool a_likelier = a_likelier_then[i] != 0.0;
    // log r is −∞ where r = 0 (α = 0 in 1-D, and x = 0): taken only for a side an answer took.
    const bool less_taken = a_likelier ? b.count_b[i] != 0 : b.count_a[i] != 0;
    const double log_less = less_taken ? 0.5 * (alpha + 1.0) * log_r[i] + log_likelier : 0.0;
    t.log_a = b.count_a[i] == 0 ? 0.0 : a_likelier ? log_likelier : log_less;
    t.log_b = b.count_b[i] == 0 ? 0.0 : a_likelier ? log_less : log_likelier;
  }
}

// Each answer's part from the link's: the link's logs with no lapse, else the mixture
// ε/2 + (1−ε)P and its log (ε ≥ kLapseInLogs here, so the mixture does not underflow).
inline void block_answers(const TripletKernel& k, TripletBlock& b, bool with_gradient) {
  const std::size_t n = b.size;
  const double lapse = k.lapse;
  if (lapse == 0.0) {
    for (std::size_t i = 0; i < n; ++i) {
      const LinkTerms& t = b.link[i];
      Lapsed on_a, on_b;  // a side no answer took keeps its defaults: its count multiplies it by 0
      if (b.count_a[i] != 0) on_a.value = t.log_a;
      if (b.count_b[i] != 0) on_b.value = t.log_b;
      b.terms[i] = combined(t, on_a, on_b, b.count_a[i], b.count_b[i], with_gradient);
    }
    return;
  }
  Column &mixed_a = b.c1, &mixed_b = b.c2, &log_a = b.c3, &log_b = b.c4;
  for (std::size_t i = 0; i < n; ++i) {
    mixed_a[i] = 0.5 * lapse + (1.0 - lapse) * b.link[i].p_a;
    mixed_b[i] = 0.5 * lapse + (1.0 - lapse) * b.link[i].p_b;
  }
  numeric::log_all(mixed_a.data(), log_a.data(), n);
  numeric::log_all(mixed_b.data(), log_b.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const LinkTerms& t = b.link[i];
    Lapsed on_a, on_b;
    if (b.count_a[i] != 0) on_a = lapsed_mixture(t.p_a, lapse, mixed_a[i], log_a[i]);
    if (b.count_b[i] != 0) on_b = lapsed_mixture(t.p_b, lapse, mixed_b[i], log_b[i]);
    b.terms[i] = combined(t, on_a, on_b, b.count_a[i], b.count_b[i], with_gradient);
  }
}

// One triplet at a time: a lapse below kLapseInLogs (mixed in logs), or a probit triplet in the far
// tail.
template <Link L>
void block_terms_one_by_one(const TripletKernel& k, TripletBlock& b, bool with_gradient) {
  for (std::size_t i = 0; i < b.size; ++i)
    b.terms[i] = triplet_terms<L>(k, b.xa[i], b.xb[i], b.count_a[i], b.count_b[i], with_gradient);
}

}  // namespace detail

// b.terms[i] for every i < b.size, for the link L (k.link is not read).
template <Link L>
void block_terms(const TripletKernel& k, TripletBlock& b, bool with_gradient) {
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
