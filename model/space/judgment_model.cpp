#include "model/space/judgment_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/space/normal_tail.hpp"

namespace nibrig::model::space {
namespace {

// log(1 + e^x) without overflow, and the logistic σ(x) = its derivative.
double softplus(double x) { return x > 0 ? x + std::log1p(std::exp(-x)) : std::log1p(std::exp(x)); }
double logistic(double x) {
  if (x >= 0) return 1.0 / (1.0 + std::exp(-x));
  const double e = std::exp(x);
  return e / (1.0 + e);
}

const char* link_name(Link link) {
  switch (link) {
    case Link::probit:
      return "probit";
    case Link::logistic:
      return "logistic";
    case Link::student_t:
      return "student-t";
  }
  return "?";
}

// log P(a), log P(b) of the link alone at x_a = s·d_a/σ, x_b = s·d_b/σ, and their derivatives.
struct LinkTerms {
  double log_a = 0.0, log_b = 0.0;
  double log_a_dxa = 0.0, log_a_dxb = 0.0, log_b_dxa = 0.0, log_b_dxb = 0.0;
};

LinkTerms link_terms(Link link, double alpha, double xa, double xb) {
  LinkTerms t;
  switch (link) {
    case Link::probit: {  // z = x_b − x_a; P(a) = Φ(z)
      const NormalSides sides = normal_sides(xb - xa);
      t.log_a = sides.log_cdf;
      t.log_b = sides.log_cdf_negative;
      const double ra = sides.pdf_over_cdf, rb = sides.pdf_over_cdf_negative;
      t.log_a_dxa = -ra, t.log_a_dxb = ra, t.log_b_dxa = rb, t.log_b_dxb = -rb;
      break;
    }
    case Link::logistic: {  // P(a) = σ(c·z)
      const double cz = kLogisticSlope * (xb - xa);
      t.log_a = -softplus(-cz);
      t.log_b = -softplus(cz);
      const double ga = kLogisticSlope * logistic(-cz), gb = kLogisticSlope * logistic(cz);
      t.log_a_dxa = -ga, t.log_a_dxb = ga, t.log_b_dxa = gb, t.log_b_dxb = -gb;
      break;
    }
    case Link::student_t: {  // P(a) = K_a/(K_a + K_b) = 1/(1 + e^u), u = log K_b − log K_a
      // u = −(α+1)/2 · log((α + x_b²)/(α + x_a²)): one log; then softplus(±u) and σ(±u) from one
      // exponential and one log1p (eight transcendentals a triplet before, three now).
      const double wa = alpha + xa * xa, wb = alpha + xb * xb;
      const double u = -0.5 * (alpha + 1.0) * std::log(wb / wa);
      const double e = std::exp(-std::abs(u)), tail = std::log1p(e);
      const double softplus_u = std::max(u, 0.0) + tail;  // softplus(−u) = softplus(u) − u
      t.log_a = -softplus_u;
      t.log_b = -(softplus_u - u);
      const double sigma_abs = 1.0 / (1.0 + e), sigma_neg_abs = e / (1.0 + e);  // σ(|u|), σ(−|u|)
      const double sigma_u = u >= 0 ? sigma_abs : sigma_neg_abs,
                   sigma_minus_u = u >= 0 ? sigma_neg_abs : sigma_abs;
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

// log(ε/2 + (1−ε)·e^ℓ) and its derivatives in ℓ and ε.
struct Lapsed {
  double value = 0.0, d_log = 1.0, d_lapse = 0.0;
};
Lapsed with_lapse(double log_p, double lapse) {
  // ε = 0 only where the family fits no lapse (a fitted one is σ(θ)/2 > 0), so its derivative,
  // 1/(2P) − 1, is not asked for there: 0 saves two exponentials per triplet.
  if (lapse == 0.0) return {log_p, 1.0, 0.0};
  const double guess = std::log(0.5 * lapse), judged = std::log1p(-lapse) + log_p;
  const double high = std::max(guess, judged);
  const double value = high + std::log(std::exp(guess - high) + std::exp(judged - high));
  return {value, std::exp(judged - value), (0.5 - std::exp(log_p)) * std::exp(-value)};
}

}  // namespace

std::string family_name(const ModelFamily& family) {
  std::string name = link_name(family.link);
  if (family.lapse) name += "+lapse";
  if (family.stimulus_noise) name += "+noise";
  return name;
}

std::vector<ModelFamily> every_family() {
  std::vector<ModelFamily> all;
  for (Link link : {Link::probit, Link::logistic, Link::student_t})
    for (bool lapse : {false, true})
      for (bool noise : {false, true}) all.push_back({link, lapse, noise});
  return all;
}

ModelFamily parse_family(const std::string& name) {
  for (const ModelFamily& f : every_family())
    if (family_name(f) == name) return f;
  std::string known;
  for (const ModelFamily& f : every_family()) known += (known.empty() ? "" : ", ") + family_name(f);
  throw std::invalid_argument("unknown judgment model '" + name + "': expected one of " + known);
}

double student_degrees_of_freedom(std::size_t dims) {
  return std::max(1.0, static_cast<double>(dims) - 1.0);
}

double triplet_negative_log_likelihood(const JudgmentModel& m, std::size_t dims, double da,
                                       double db, double log_sigma, double count_a, double count_b,
                                       TripletGradient* gradient) {
  const double per = m.scale * std::exp(-log_sigma);  // ∂x/∂d
  const double xa = per * da, xb = per * db;
  const LinkTerms t = link_terms(m.family.link, student_degrees_of_freedom(dims), xa, xb);
  const Lapsed a = with_lapse(t.log_a, m.lapse), b = with_lapse(t.log_b, m.lapse);
  const double nll = -(count_a * a.value + count_b * b.value);
  if (gradient) {
    // ∂nll/∂x through each answer's log-probability, then x = per·d.
    const double dxa = -(count_a * a.d_log * t.log_a_dxa + count_b * b.d_log * t.log_b_dxa);
    const double dxb = -(count_a * a.d_log * t.log_a_dxb + count_b * b.d_log * t.log_b_dxb);
    gradient->distance_a = dxa * per;
    gradient->distance_b = dxb * per;
    gradient->log_sigma = -(dxa * xa + dxb * xb);  // ∂x/∂log σ = −x
    gradient->lapse = -(count_a * a.d_lapse + count_b * b.d_lapse);
  }
  return nll;
}

double probability_first(const JudgmentModel& m, std::size_t dims, double da, double db,
                         double log_sigma) {
  const double per = m.scale * std::exp(-log_sigma);
  const LinkTerms t =
      link_terms(m.family.link, student_degrees_of_freedom(dims), per * da, per * db);
  return std::exp(with_lapse(t.log_a, m.lapse).value);
}

double triplet_log_sigma(const JudgmentModel& m, std::size_t r, std::size_t a, std::size_t b) {
  if (m.log_noise.size() == 0) return 0.0;
  const auto size = static_cast<std::size_t>(m.log_noise.size());
  if (r >= size || a >= size || b >= size)
    throw std::invalid_argument("the judgment model has noises for " + std::to_string(size) +
                                " stimuli, a triplet names stimulus " +
                                std::to_string(std::max({r, a, b})));
  const double variance = (std::exp(2 * m.log_noise(static_cast<Eigen::Index>(r))) +
                           std::exp(2 * m.log_noise(static_cast<Eigen::Index>(a))) +
                           std::exp(2 * m.log_noise(static_cast<Eigen::Index>(b)))) /
                          3.0;
  return 0.5 * std::log(variance);
}

double typical_log_sigma(const JudgmentModel& m) {
  return m.log_noise.size() > 0 ? m.log_noise.mean() : 0.0;
}

double probability_first(const JudgmentModel& m, const Eigen::MatrixXd& q, std::size_t r,
                         std::size_t a, std::size_t b) {
  const auto col = [](std::size_t i) { return static_cast<Eigen::Index>(i); };
  const double da = (q.col(col(a)) - q.col(col(r))).norm(),
               db = (q.col(col(b)) - q.col(col(r))).norm();
  return probability_first(m, static_cast<std::size_t>(q.rows()), da, db,
                           triplet_log_sigma(m, r, a, b));
}

}  // namespace nibrig::model::space
