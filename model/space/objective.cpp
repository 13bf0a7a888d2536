#include "model/space/objective.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace nibrig::model::space {
namespace {

constexpr double kCorrelationSmoothing = 1e-12;  // ε² in log √(r² + ε²)

std::string triplet_name(std::size_t t) { return "triplet " + std::to_string(t); }

// The likelihood over the triplets with the space's columns as vectors of D coordinates: fixed for
// 1-3 dimensions (the spaces people fit), so the offsets live in registers and the loops unroll;
// Eigen::Dynamic otherwise. Fixed sizes took the Lagunas 3-D evaluation from 122 to 98 ns a
// triplet.
template <int D>
double likelihood_over_triplets(const SpaceProblem& p, const JudgmentModel& m,
                                const Eigen::MatrixXd& q, Eigen::MatrixXd* gradient,
                                ModelGradient* model_gradient) {
  using Vector = Eigen::Matrix<double, D, 1>;
  const auto dims = static_cast<Eigen::Index>(p.dims);
  const auto column = [&](const Eigen::MatrixXd& x, std::size_t i) {
    return Eigen::Map<const Vector>(x.data() + static_cast<Eigen::Index>(i) * dims, dims);
  };
  const auto gradient_column = [&](std::size_t i) {
    return Eigen::Map<Vector>(gradient->data() + static_cast<Eigen::Index>(i) * dims, dims);
  };
  const bool noise = m.log_noise.size() > 0;
  double nll = 0.0;
  TripletGradient g;
  // The two offsets from the reference, in buffers made once (on the stack when D is fixed): with a
  // heap vector per triplet, parallel starts spent their time in the allocator.
  Vector va(dims), vb(dims);
  for (const auto& t : p.triplets) {
    va = column(q, t.a) - column(q, t.reference);
    vb = column(q, t.b) - column(q, t.reference);
    const double da = va.norm(), db = vb.norm();
    const double log_sigma = triplet_log_sigma(m, t.reference, t.a, t.b);
    nll += triplet_negative_log_likelihood(m, p.dims, da, db, log_sigma, t.count_a, t.count_b,
                                           gradient || model_gradient ? &g : nullptr);
    if (gradient) {
      // ∂‖v‖/∂v = v/‖v‖, taken as 0 where two stimuli coincide (a subgradient).
      const double ka = da > 0 ? g.distance_a / da : 0.0, kb = db > 0 ? g.distance_b / db : 0.0;
      gradient_column(t.a) += ka * va;
      gradient_column(t.b) += kb * vb;
      gradient_column(t.reference) -= ka * va + kb * vb;
    }
    if (!model_gradient) continue;
    model_gradient->lapse += g.lapse;
    if (noise) {
      // ∂log σ_t/∂η_i = σ_i²/(3σ_t²) for each of the triplet's three stimuli.
      const double inverse = std::exp(-2.0 * log_sigma) / 3.0;
      for (std::size_t i : {t.reference, t.a, t.b}) {
        const auto k = static_cast<Eigen::Index>(i);
        model_gradient->log_noise(k) += g.log_sigma * std::exp(2.0 * m.log_noise(k)) * inverse;
      }
    }
  }
  return nll;
}

double likelihood_part(const SpaceProblem& p, const JudgmentModel& m, const Eigen::MatrixXd& q,
                       Eigen::MatrixXd* gradient, ModelGradient* model_gradient) {
  switch (p.dims) {
    case 1:
      return likelihood_over_triplets<1>(p, m, q, gradient, model_gradient);
    case 2:
      return likelihood_over_triplets<2>(p, m, q, gradient, model_gradient);
    case 3:
      return likelihood_over_triplets<3>(p, m, q, gradient, model_gradient);
    default:
      return likelihood_over_triplets<Eigen::Dynamic>(p, m, q, gradient, model_gradient);
  }
}

double correlation_part(const SpaceProblem& p, const Eigen::MatrixXd& q, Eigen::MatrixXd* gradient,
                        double weight) {
  double penalty = 0.0;
  for (std::size_t d = 0; d < p.dims; ++d) {
    const Eigen::VectorXd x = p.descriptors.col(static_cast<Eigen::Index>(d)).array() -
                              p.descriptors.col(static_cast<Eigen::Index>(d)).mean();
    const Eigen::VectorXd c = q.row(static_cast<Eigen::Index>(d)).transpose().array() -
                              q.row(static_cast<Eigen::Index>(d)).mean();
    const double nx = x.norm(), nc = c.norm();
    if (nc == 0) {  // every stimulus at the same coordinate: r undefined, taken as 0
      penalty -= 0.5 * std::log(kCorrelationSmoothing);
      continue;
    }
    const double r = c.dot(x) / (nc * nx);
    penalty -= 0.5 * std::log(r * r + kCorrelationSmoothing);
    if (!gradient) continue;
    // ∂r/∂q = x̃/(‖q̃‖‖x̃‖) − r q̃/‖q̃‖² (already zero-mean, so centring adds nothing)
    const Eigen::VectorXd dr = x / (nc * nx) - r * c / (nc * nc);
    gradient->row(static_cast<Eigen::Index>(d)) -=
        weight * (r / (r * r + kCorrelationSmoothing)) * dr.transpose();
  }
  return penalty;
}

}  // namespace

void validate(const SpaceProblem& p) {
  if (p.dims < 1) throw std::invalid_argument("a perceptual space needs at least one dimension");
  if (p.stimuli < p.dims + 1)
    throw std::invalid_argument("a " + std::to_string(p.dims) + "-D space needs at least " +
                                std::to_string(p.dims + 1) + " stimuli, found " +
                                std::to_string(p.stimuli));
  if (!(p.lambda >= 0) || !std::isfinite(p.lambda))
    throw std::invalid_argument("lambda must be zero or positive");
  if (!(p.model.scale > 0) || !std::isfinite(p.model.scale))
    throw std::invalid_argument("the judgment model's scale must be positive");
  if (!(p.model.lapse >= 0 && p.model.lapse < 0.5))
    throw std::invalid_argument("the judgment model's lapse rate must be in [0, 0.5)");
  if (p.model.log_noise.size() > 0 &&
      (static_cast<std::size_t>(p.model.log_noise.size()) != p.stimuli ||
       !p.model.log_noise.allFinite()))
    throw std::invalid_argument(
        "the judgment model has " + std::to_string(p.model.log_noise.size()) +
        " noises, expected one per stimulus (" + std::to_string(p.stimuli) + "), finite");
  if (!(p.prior_sd >= 0) || !std::isfinite(p.prior_sd))
    throw std::invalid_argument("the coordinate prior's sd must be zero (none) or positive");
  for (std::size_t i = 0; i < p.triplets.size(); ++i) {
    const auto& t = p.triplets[i];
    if (t.reference >= p.stimuli || t.a >= p.stimuli || t.b >= p.stimuli)
      throw std::invalid_argument(triplet_name(i) + ": stimulus index out of range (" +
                                  std::to_string(p.stimuli) + " stimuli)");
    if (t.reference == t.a || t.reference == t.b || t.a == t.b)
      throw std::invalid_argument(triplet_name(i) +
                                  ": the reference and both candidates must be different stimuli");
    if (t.count_a < 0 || t.count_b < 0)
      throw std::invalid_argument(triplet_name(i) + ": negative count");
  }
  if (p.lambda > 0 || p.descriptors.size() > 0) {
    if (static_cast<std::size_t>(p.descriptors.rows()) != p.stimuli ||
        static_cast<std::size_t>(p.descriptors.cols()) < p.dims)
      throw std::invalid_argument("descriptor table is " + std::to_string(p.descriptors.rows()) +
                                  " × " + std::to_string(p.descriptors.cols()) +
                                  ", expected one row per stimulus (" + std::to_string(p.stimuli) +
                                  ") and a column per dimension (" + std::to_string(p.dims) + ")");
    for (std::size_t d = 0; d < p.dims; ++d) {
      const auto column = p.descriptors.col(static_cast<Eigen::Index>(d));
      if (!column.allFinite())
        throw std::invalid_argument("descriptor " + std::to_string(d) + " is not finite");
      if (column.maxCoeff() == column.minCoeff())
        throw std::invalid_argument("descriptor " + std::to_string(d) +
                                    " is constant: nothing can correlate with it");
    }
  }
}

double objective(const SpaceProblem& p, const Eigen::MatrixXd& q, Eigen::MatrixXd* gradient) {
  return objective(p, q, p.model, gradient, nullptr);
}

double objective(const SpaceProblem& p, const Eigen::MatrixXd& q, const JudgmentModel& m,
                 Eigen::MatrixXd* gradient, ModelGradient* model_gradient) {
  if (gradient) gradient->setZero(q.rows(), q.cols());
  if (model_gradient) {
    model_gradient->lapse = 0.0;
    model_gradient->log_noise.setZero(m.log_noise.size());
  }
  double value = likelihood_part(p, m, q, gradient, model_gradient);
  if (p.lambda > 0) value += p.lambda * correlation_part(p, q, gradient, p.lambda);
  if (p.prior_sd > 0) {
    const double precision = 1.0 / (p.prior_sd * p.prior_sd);
    value += 0.5 * precision * q.squaredNorm();
    if (gradient) *gradient += precision * q;
  }
  if (m.log_noise.size() > 0) {
    const double precision = 1.0 / (kNoisePriorSd * kNoisePriorSd);
    value += 0.5 * precision * m.log_noise.squaredNorm();
    if (model_gradient) model_gradient->log_noise += precision * m.log_noise;
  }
  return value;
}

SpaceProblem with_link_prior(SpaceProblem p) {
  if (p.model.family.link == Link::student_t && p.prior_sd == 0)
    p.prior_sd = kStudentCoordinatePriorSd;
  return p;
}

double negative_log_likelihood(const SpaceProblem& p, const Eigen::MatrixXd& q) {
  return likelihood_part(p, p.model, q, nullptr, nullptr);
}

double correlation_penalty(const SpaceProblem& p, const Eigen::MatrixXd& q) {
  return p.descriptors.size() > 0 ? correlation_part(p, q, nullptr, 0.0) : 0.0;
}

}  // namespace nibrig::model::space
