#include "model/space/judgment_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "model/space/triplet_kernel.hpp"

namespace nibrig::model::space {
namespace {

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

}  // namespace

TripletKernel kernel_of(const JudgmentModel& m, std::size_t dims) {
  return {m.family.link, student_degrees_of_freedom(dims), m.lapse};
}

std::string family_name(const ModelFamily& family) {
  std::string name = link_name(family.link);
  if (family.lapse) name += "+lapse";
  if (family.stimulus_noise) name += "+noise";
  return name;
}

std::string describe_model(const JudgmentModel& m) {
  std::string text = family_name(m.family);
  char part[96];
  if (m.family.lapse) {
    std::snprintf(part, sizeof part, ", lapse %.3f", m.lapse);
    text += part;
  }
  if (m.log_noise.size() > 0) {
    std::snprintf(part, sizeof part, ", noise per stimulus %.2f to %.2f (sigma, 1 = typical)",
                  std::exp(m.log_noise.minCoeff()), std::exp(m.log_noise.maxCoeff()));
    text += part;
  }
  return text;
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
  const TripletTerms t =
      triplet_terms(kernel_of(m, dims), xa, xb, count_a, count_b, gradient != nullptr);
  if (gradient) {
    gradient->distance_a = t.d_xa * per;
    gradient->distance_b = t.d_xb * per;
    gradient->log_sigma = -(t.d_xa * xa + t.d_xb * xb);  // ∂x/∂log σ = −x
    gradient->lapse = t.d_lapse;
  }
  return t.nll;
}

double probability_first(const JudgmentModel& m, std::size_t dims, double da, double db,
                         double log_sigma) {
  const double per = m.scale * std::exp(-log_sigma);
  const detail::LinkTerms t =
      detail::link_terms(m.family.link, student_degrees_of_freedom(dims), per * da, per * db, false, false);
  return 0.5 * m.lapse + (1.0 - m.lapse) * t.p_a;
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
