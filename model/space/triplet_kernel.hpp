// One triplet's likelihood term at x = s·d/σ_t for each link, with a lapse, and its derivatives:
// the innermost loop of every fit (23,000 triplets an evaluation on Lagunas's data, a hundred
// evaluations a start), so it is inline here, where the likelihood loop (objective.cpp) can fold
// it into its own body. judgment_model.hpp's triplet_negative_log_likelihood and
// probability_first are the readable entries to the same terms.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "model/space/judgment_model.hpp"
#include "model/space/normal_tail.hpp"

namespace nibrig::model::space {

// What every triplet of an evaluation shares, worked out once.
struct TripletKernel {
  Link link = Link::probit;
  double alpha = 1.0;  // student_degrees_of_freedom
  double lapse = 0.0;
};
TripletKernel kernel_of(const JudgmentModel& model, std::size_t dims);

// −(n_a log P'(a) + n_b log P'(b)) and, when asked, ∂/∂x_a, ∂/∂x_b and ∂/∂ε.
struct TripletTerms {
  double nll = 0.0, d_xa = 0.0, d_xb = 0.0, d_lapse = 0.0;
};

namespace detail {

// The link alone at x_a = s·d_a/σ, x_b = s·d_b/σ: P(a), P(b) (0 where they underflow, far in a
// tail), log P(a) and log P(b) where asked (else 0), and the logs' derivatives (finite everywhere).
struct LinkTerms {
  double p_a = 0.0, p_b = 0.0;
  double log_a = 0.0, log_b = 0.0;
  double log_a_dxa = 0.0, log_a_dxb = 0.0, log_b_dxa = 0.0, log_b_dxb = 0.0;
};

// A template on the link, so that the likelihood loop is made once for each with no choice left
// inside it.
template <Link L>
inline LinkTerms link_terms(double alpha, double xa, double xb, bool log_a_wanted,
                            bool log_b_wanted) {
  LinkTerms t;
  switch (L) {
    case Link::probit: {  // z = x_b − x_a; P(a) = Φ(z)
      const NormalSides sides = normal_sides(xb - xa, log_a_wanted, log_b_wanted);
      t.p_a = sides.cdf, t.p_b = sides.cdf_negative;
      t.log_a = sides.log_cdf;
      t.log_b = sides.log_cdf_negative;
      const double ra = sides.pdf_over_cdf, rb = sides.pdf_over_cdf_negative;
      t.log_a_dxa = -ra, t.log_a_dxb = ra, t.log_b_dxa = rb, t.log_b_dxb = -rb;
      break;
    }
    case Link::logistic: {  // P(a) = σ(c·z)
      // One exponential and one log give both sides: softplus(−cz) = softplus(cz) − cz. log(1 + e),
      // not log1p: a sum of likelihoods needs its terms to 1e-16 absolute, and log is twice as
      // fast.
      const double cz = kLogisticSlope * (xb - xa);
      const double e = std::exp(-std::abs(cz)), softplus_cz = std::max(cz, 0.0) + std::log(1.0 + e);
      t.log_a = -(softplus_cz - cz);
      t.log_b = -softplus_cz;
      const double near = 1.0 / (1.0 + e), far = e / (1.0 + e);  // σ(|cz|), σ(−|cz|)
      t.p_a = cz >= 0 ? near : far, t.p_b = cz >= 0 ? far : near;
      const double ga = kLogisticSlope * t.p_b,
                   gb = kLogisticSlope * t.p_a;  // d log σ(y)/dy = σ(−y)
      t.log_a_dxa = -ga, t.log_a_dxb = ga, t.log_b_dxa = gb, t.log_b_dxb = -gb;
      break;
    }
    case Link::student_t: {  // P(a) = K_a/(K_a + K_b) = 1/(1 + e^u), u = log K_b − log K_a
      // e^{±u} = r^{(α+1)/2}, r = the smaller of w_a/w_b and w_b/w_a (w = α + x²), is ≤ 1 and,
      // with α a whole number (dims − 1), a power of √r: no exponential, and no overflow however
      // far apart the two are. Then log(1 + k) for the likelier side, and log r as well for the
      // other only where an answer took it: one or two transcendentals a triplet, not three.
      const double wa = alpha + xa * xa, wb = alpha + xb * xb;
      const bool a_likelier = wa <= wb;
      const double r = a_likelier ? wa / wb : wb / wa, root = std::sqrt(r);
      double k = 1.0;  // r^{(α+1)/2} = P(less likely)/P(likelier)
      for (long n = std::lround(alpha + 1.0); n > 0; --n) k *= root;
      const double likelier = 1.0 / (1.0 + k), less = k * likelier;
      const bool less_log = a_likelier ? log_b_wanted : log_a_wanted;
      const bool likelier_log = a_likelier ? log_a_wanted : log_b_wanted;
      const double log_likelier = likelier_log || less_log ? -std::log(1.0 + k) : 0.0;
      const double log_less = less_log ? 0.5 * (alpha + 1.0) * std::log(r) + log_likelier : 0.0;
      t.p_a = a_likelier ? likelier : less, t.p_b = a_likelier ? less : likelier;
      t.log_a = !log_a_wanted ? 0.0 : a_likelier ? log_likelier : log_less;
      t.log_b = !log_b_wanted ? 0.0 : a_likelier ? log_less : log_likelier;
      const double sigma_u = t.p_b, sigma_minus_u = t.p_a;  // d log P(a)/du = −σ(u) = −P(b)
      // d log K/dx = −(α+1)·x/(α + x²)
      const double du_dxa = (alpha + 1.0) * xa / wa, du_dxb = -(alpha + 1.0) * xb / wb;
      const double la_du = -sigma_u, lb_du = sigma_minus_u;
      t.log_a_dxa = la_du * du_dxa, t.log_a_dxb = la_du * du_dxb;
      t.log_b_dxa = lb_du * du_dxa, t.log_b_dxb = lb_du * du_dxb;
      break;
    }
  }
  return t;
}

inline LinkTerms link_terms(Link link, double alpha, double xa, double xb, bool log_a_wanted,
                            bool log_b_wanted) {
  switch (link) {
    case Link::logistic:
      return link_terms<Link::logistic>(alpha, xa, xb, log_a_wanted, log_b_wanted);
    case Link::student_t:
      return link_terms<Link::student_t>(alpha, xa, xb, log_a_wanted, log_b_wanted);
    case Link::probit:
      break;
  }
  return link_terms<Link::probit>(alpha, xa, xb, log_a_wanted, log_b_wanted);
}

// log(ε/2 + (1−ε)·P) and its derivatives in log P and ε.
struct Lapsed {
  double value = 0.0, d_log = 1.0, d_lapse = 0.0;
};

// Below this ε the mixture is taken in logs: ε/2 + (1−ε)P could underflow where P does.
inline constexpr double kLapseInLogs = 1e-200;

// From log P, for ε = 0 (no lapse fitted) or one below kLapseInLogs.
inline Lapsed with_lapse_in_logs(double log_p, double lapse) {
  // ε = 0 only where the family fits no lapse (a fitted one is σ(θ)/2 > 0), so its derivative,
  // 1/(2P) − 1, is not asked for there.
  if (lapse == 0.0) return {log_p, 1.0, 0.0};
  const double guess = std::log(0.5 * lapse), judged = std::log1p(-lapse) + log_p;
  const double high = std::max(guess, judged);
  const double value = high + std::log(std::exp(guess - high) + std::exp(judged - high));
  return {value, std::exp(judged - value), (0.5 - std::exp(log_p)) * std::exp(-value)};
}

// From P itself: ε/2 ≥ kLapseInLogs/2 keeps the mixture from underflow, so one log and one
// division (five exponentials and logs in logs).
// From P, the mixture ε/2 + (1−ε)P and its log, however taken (a block takes the logs at once).
inline Lapsed lapsed_mixture(double p, double lapse, double mixed, double log_mixed) {
  const double inverse = 1.0 / mixed;
  return {log_mixed, (1.0 - lapse) * p * inverse, (0.5 - p) * inverse};
}
inline Lapsed with_lapse(double p, double lapse) {
  const double mixed = 0.5 * lapse + (1.0 - lapse) * p;
  return lapsed_mixture(p, lapse, mixed, std::log(mixed));
}

// The triplet's terms from its link's (t) and each answer's (a, b) parts.
inline TripletTerms combined(const LinkTerms& t, const Lapsed& a, const Lapsed& b, double count_a,
                             double count_b, bool with_gradient) {
  TripletTerms out;
  out.nll = -(count_a * a.value + count_b * b.value);
  if (!with_gradient) return out;
  // ∂nll/∂x through each answer's log-probability.
  out.d_xa = -(count_a * a.d_log * t.log_a_dxa + count_b * b.d_log * t.log_b_dxa);
  out.d_xb = -(count_a * a.d_log * t.log_a_dxb + count_b * b.d_log * t.log_b_dxb);
  out.d_lapse = -(count_a * a.d_lapse + count_b * b.d_lapse);
  return out;
}

}  // namespace detail

// For the link L (kernel.link is not read: the caller chose L from it).
template <Link L>
[[gnu::always_inline]] inline TripletTerms triplet_terms(const TripletKernel& k, double xa,
                                                         double xb, double count_a, double count_b,
                                                         bool with_gradient) {
  const bool in_logs = k.lapse < detail::kLapseInLogs;
  const detail::LinkTerms t =
      detail::link_terms<L>(k.alpha, xa, xb, in_logs && count_a != 0, in_logs && count_b != 0);
  // A side no answer took is not worked out: its count multiplies it by 0.
  detail::Lapsed a, b;
  if (count_a != 0)
    a = in_logs ? detail::with_lapse_in_logs(t.log_a, k.lapse) : detail::with_lapse(t.p_a, k.lapse);
  if (count_b != 0)
    b = in_logs ? detail::with_lapse_in_logs(t.log_b, k.lapse) : detail::with_lapse(t.p_b, k.lapse);
  return detail::combined(t, a, b, count_a, count_b, with_gradient);
}

inline TripletTerms triplet_terms(const TripletKernel& k, double xa, double xb, double count_a,
                                  double count_b, bool with_gradient) {
  switch (k.link) {
    case Link::logistic:
      return triplet_terms<Link::logistic>(k, xa, xb, count_a, count_b, with_gradient);
    case Link::student_t:
      return triplet_terms<Link::student_t>(k, xa, xb, count_a, count_b, with_gradient);
    case Link::probit:
      break;
  }
  return triplet_terms<Link::probit>(k, xa, xb, count_a, count_b, with_gradient);
}

}  // namespace nibrig::model::space
