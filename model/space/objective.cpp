#include "model/space/objective.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "model/numeric/cpu_features.hpp"
#include "model/space/triplet_block.hpp"

namespace nibrig::model::space {
namespace {

constexpr double kCorrelationSmoothing = 1e-12;  // ε² in log √(r² + ε²)

std::string triplet_name(std::size_t t) { return "triplet " + std::to_string(t); }

// Where a triplet's two distances come from and where ∂nll/∂d_a, ∂nll/∂d_b go, with the space's
// columns as vectors of D coordinates: fixed for 1-3 dimensions (the spaces people fit), so the
// offsets live in registers and the loops unroll; Eigen::Dynamic otherwise (bench
// SpaceStartLagunas3D measures an evaluation).
//
// TripletOffsets: each triplet's two offsets from its reference, and their gradient added to the
// three columns at once. The likelihood loop measures a whole block before it pulls on any, so a
// pull measures its triplet again (a few subtractions and a square root, against the link's
// transcendentals).
template <int D>
class TripletOffsets {
 public:
  using Vector = Eigen::Matrix<double, D, 1>;
  TripletOffsets(const Eigen::MatrixXd& q, Eigen::MatrixXd* gradient)
      : q_(q), gradient_(gradient), va_(q.rows()), vb_(q.rows()) {}

  using Key = const io::Triplet*;
  static Key key(const io::Triplet& t) { return &t; }
  std::pair<double, double> distances(Key k) {
    const io::Triplet& t = *k;
    va_ = column(t.a) - column(t.reference);
    vb_ = column(t.b) - column(t.reference);
    return {va_.norm(), vb_.norm()};
  }
  // ∂nll/∂d of triplet t. ∂‖v‖/∂v = v/‖v‖, taken as 0 where two stimuli coincide (a subgradient).
  void pull(Key k, double along_a, double along_b) {
    const io::Triplet& t = *k;
    const auto [da, db] = distances(k);
    const double ka = da > 0 ? along_a / da : 0.0, kb = db > 0 ? along_b / db : 0.0;
    gradient_column(t.a) += ka * va_;
    gradient_column(t.b) += kb * vb_;
    gradient_column(t.reference) -= ka * va_ + kb * vb_;
  }
  void finish() {}

 private:
  Eigen::Map<const Vector> column(std::size_t i) const {
    return {q_.data() + static_cast<Eigen::Index>(i) * q_.rows(), q_.rows()};
  }
  Eigen::Map<Vector> gradient_column(std::size_t i) {
    return {gradient_->data() + static_cast<Eigen::Index>(i) * q_.rows(), q_.rows()};
  }
  const Eigen::MatrixXd& q_;
  Eigen::MatrixXd* gradient_;
  // Buffers made once (on the stack when D is fixed): with a heap vector per triplet, parallel
  // starts spent their time in the allocator.
  Vector va_, vb_;
};

// PairTable: every pair's distance once an evaluation, and ∂nll/∂d summed per pair before it goes
// to the two columns. Where pairs are fewer than triplet sides (Lagunas: 4,950 pairs for 45,602
// sides) a triplet then reads two numbers and adds two, with no square root, division or column
// update of its own.
template <int D>
class PairTable {
 public:
  using Vector = Eigen::Matrix<double, D, 1>;
  PairTable(const Eigen::MatrixXd& q, Eigen::MatrixXd* gradient)
      : q_(q), gradient_(gradient), n_(q.cols()), distance_(n_, n_) {
    // Squares first, then their roots a column at a time: the roots then run in vector registers.
    for (Eigen::Index j = 1; j < n_; ++j)
      for (Eigen::Index i = 0; i < j; ++i) distance_(i, j) = (column(j) - column(i)).squaredNorm();
    for (Eigen::Index j = 1; j < n_; ++j) {
      double* d = &distance_(0, j);
      for (Eigen::Index i = 0; i < j; ++i) d[i] = std::sqrt(d[i]);
    }
    // A stimulus from itself, as the offsets give it: only a triplet validate() refuses reads it.
    distance_.diagonal().setZero();
    if (gradient_) pull_.setZero(n_, n_);
  }
  // Where the triplet's two pairs are, found once for both its distances and its pulls.
  using Key = std::array<Eigen::Index, 2>;
  Key key(const io::Triplet& t) const { return {index(t.reference, t.a), index(t.reference, t.b)}; }
  std::pair<double, double> distances(Key k) const {
    return {distance_.data()[k[0]], distance_.data()[k[1]]};
  }
  void pull(Key k, double along_a, double along_b) {
    pull_.data()[k[0]] += along_a;
    pull_.data()[k[1]] += along_b;
  }
  void finish() {
    if (!gradient_) return;
    for (Eigen::Index j = 1; j < n_; ++j)
      for (Eigen::Index i = 0; i < j; ++i) {
        const double d = distance_(i, j), along = pull_(i, j);
        if (along == 0.0 || !(d > 0)) continue;  // coincident stimuli: the subgradient 0
        const Vector g = (along / d) * (column(j) - column(i));
        gradient_column(j) += g;
        gradient_column(i) -= g;
      }
  }

 private:
  // (i, j) with i < j: the upper triangle, column-major.
  Eigen::Index index(std::size_t x, std::size_t y) const {
    const auto i = static_cast<Eigen::Index>(std::min(x, y)), j = static_cast<Eigen::Index>(std::max(x, y));
    return i + j * n_;
  }
  Eigen::Map<const Vector> column(Eigen::Index i) const {
    return {q_.data() + i * q_.rows(), q_.rows()};
  }
  Eigen::Map<Vector> gradient_column(Eigen::Index i) {
    return {gradient_->data() + i * q_.rows(), q_.rows()};
  }
  const Eigen::MatrixXd& q_;
  Eigen::MatrixXd* gradient_;
  Eigen::Index n_;
  Eigen::MatrixXd distance_, pull_;
};

// The likelihood over the triplets, their distances from `Distances`, for the link L.
template <Link L, class Distances>
[[gnu::always_inline]] inline double likelihood_over_triplets(const SpaceProblem& p,
                                                              const JudgmentModel& m,
                                                              Distances& distances,
                                                              bool coordinate_gradient,
                                                              ModelGradient* model_gradient) {
  const bool noise = m.log_noise.size() > 0;
  const TripletKernel kernel = kernel_of(m, p.dims);
  const bool with_gradient = coordinate_gradient || model_gradient;
  // σ_i² = e^{2η_i} once an evaluation, not three times a triplet: σ_t² is their mean over the
  // triplet's three stimuli, x = s·d/σ_t, and ∂log σ_t/∂η_i = σ_i²/(3σ_t²).
  const Eigen::VectorXd variance = noise ? Eigen::VectorXd((2.0 * m.log_noise).array().exp())
                                         : Eigen::VectorXd();
  if (noise && static_cast<std::size_t>(variance.size()) != p.stimuli)
    throw std::invalid_argument("the judgment model has noises for " +
                                std::to_string(variance.size()) + " stimuli, the problem " +
                                std::to_string(p.stimuli));
  // A block's x_a, x_b and counts are gathered, its terms worked out together (block_terms), and
  // then spread back to the distances and the model.
  TripletBlock block;
  std::array<double, TripletBlock::kSize> per, sum;  // ∂x/∂d = s/σ_t, and Σσ_i² of the three
  std::array<typename Distances::Key, TripletBlock::kSize> keys;
  double nll = 0.0, lapse_gradient = 0.0;
  const double scale = m.scale;
  for (std::size_t first = 0; first < p.triplets.size(); first += TripletBlock::kSize) {
    block.size = std::min(TripletBlock::kSize, p.triplets.size() - first);
    for (std::size_t i = 0; i < block.size; ++i) {
      const io::Triplet& t = p.triplets[first + i];
      keys[i] = distances.key(t);
      std::tie(block.xa[i], block.xb[i]) = distances.distances(keys[i]);  // d_a, d_b until scaled
      block.count_a[i] = t.count_a, block.count_b[i] = t.count_b;
      if (noise)
        sum[i] = variance(static_cast<Eigen::Index>(t.reference)) +
                 variance(static_cast<Eigen::Index>(t.a)) + variance(static_cast<Eigen::Index>(t.b));
    }
    // The gathers above apart from the arithmetic here, which then runs in vector registers.
    if (noise)
      for (std::size_t i = 0; i < block.size; ++i) per[i] = scale * std::sqrt(3.0 / sum[i]);
    else
      per.fill(scale);
    for (std::size_t i = 0; i < block.size; ++i) block.xa[i] *= per[i], block.xb[i] *= per[i];
    block_terms<L>(kernel, block, with_gradient);
    // The sum in the pulls' loop, in the same order: its additions' latency hides behind their
    // loads.
    if (coordinate_gradient) {
      for (std::size_t i = 0; i < block.size; ++i) {
        nll += block.nll[i];
        distances.pull(keys[i], block.d_xa[i] * per[i], block.d_xb[i] * per[i]);
      }
    } else {
      for (std::size_t i = 0; i < block.size; ++i) nll += block.nll[i];
    }
    if (!model_gradient) continue;
    // In a local, not through the pointer: a store and a load a triplet otherwise, as the
    // compiler cannot tell the model's gradient from the distances' pulls.
    if (kernel.lapse != 0.0)  // else every ∂/∂ε is 0
      for (std::size_t i = 0; i < block.size; ++i) lapse_gradient += block.d_lapse[i];
    if (!noise) continue;
    for (std::size_t i = 0; i < block.size; ++i) {
      const io::Triplet& t = p.triplets[first + i];
      // ∂x/∂log σ = −x, and ∂log σ_t/∂η_k = σ_k²/Σσ²: one division a triplet, not three.
      const double d_log_sigma = -(block.d_xa[i] * block.xa[i] + block.d_xb[i] * block.xb[i]);
      const double per_variance = d_log_sigma / sum[i];
      for (std::size_t s : {t.reference, t.a, t.b}) {
        const auto k = static_cast<Eigen::Index>(s);
        model_gradient->log_noise(k) += per_variance * variance(k);
      }
    }
  }
  if (model_gradient) model_gradient->lapse += lapse_gradient;
  if (coordinate_gradient) distances.finish();
  return nll;
}

template <class Distances>
[[gnu::always_inline]] inline double likelihood_by_link(const SpaceProblem& p,
                                                        const JudgmentModel& m,
                                                        Distances& distances,
                                                        bool coordinate_gradient,
                                                        ModelGradient* model_gradient) {
  switch (m.family.link) {
    case Link::logistic:
      return likelihood_over_triplets<Link::logistic>(p, m, distances, coordinate_gradient,
                                                      model_gradient);
    case Link::student_t:
      return likelihood_over_triplets<Link::student_t>(p, m, distances, coordinate_gradient,
                                                       model_gradient);
    case Link::probit:
      break;
  }
  return likelihood_over_triplets<Link::probit>(p, m, distances, coordinate_gradient,
                                                model_gradient);
}

template <int D>
[[gnu::always_inline]] inline double likelihood_in(const SpaceProblem& p, const JudgmentModel& m,
                                                   const Eigen::MatrixXd& q,
                                                   Eigen::MatrixXd* gradient,
                                                   ModelGradient* model_gradient) {
  const auto n = static_cast<std::size_t>(q.cols());
  if (n * (n - 1) / 2 <= 2 * p.triplets.size()) {
    PairTable<D> pairs(q, gradient);
    return likelihood_by_link(p, m, pairs, gradient != nullptr, model_gradient);
  }
  TripletOffsets<D> offsets(q, gradient);
  return likelihood_by_link(p, m, offsets, gradient != nullptr, model_gradient);
}

// The likelihood's loops compiled twice: for any x86-64 (SSE2's two lanes, likelihood_in itself)
// and for AVX2 (four), everything from likelihood_in down inlined into each. No FMA in either (its
// single rounding would differ), so both give the same bits
// (SpaceObjective.TheAvx2LoopsGiveThePortableLoopsBits).
template <int D>
[[gnu::target("avx2")]] double likelihood_in_avx2(const SpaceProblem& p, const JudgmentModel& m,
                                                  const Eigen::MatrixXd& q,
                                                  Eigen::MatrixXd* gradient,
                                                  ModelGradient* model_gradient) {
  return likelihood_in<D>(p, m, q, gradient, model_gradient);
}

template <int D>
double likelihood_built(LoopBuild build, const SpaceProblem& p, const JudgmentModel& m,
                        const Eigen::MatrixXd& q, Eigen::MatrixXd* gradient,
                        ModelGradient* model_gradient) {
  static const bool avx2 = numeric::cpu_has_avx2_fma();
  if (build == LoopBuild::avx2 && !avx2)
    throw std::invalid_argument("the likelihood's AVX2 loops were asked for; this CPU has no AVX2");
  if (build == LoopBuild::avx2 || (build == LoopBuild::automatic && avx2))
    return likelihood_in_avx2<D>(p, m, q, gradient, model_gradient);
  return likelihood_in<D>(p, m, q, gradient, model_gradient);
}

double likelihood_part(const SpaceProblem& p, const JudgmentModel& m, const Eigen::MatrixXd& q,
                       Eigen::MatrixXd* gradient, ModelGradient* model_gradient,
                       LoopBuild build = LoopBuild::automatic) {
  switch (p.dims) {
    case 1:
      return likelihood_built<1>(build, p, m, q, gradient, model_gradient);
    case 2:
      return likelihood_built<2>(build, p, m, q, gradient, model_gradient);
    case 3:
      return likelihood_built<3>(build, p, m, q, gradient, model_gradient);
    default:
      return likelihood_built<Eigen::Dynamic>(build, p, m, q, gradient, model_gradient);
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
  if (!(p.lambda >= 0) || !(p.lambda <= kMaxLambda))
    throw std::invalid_argument("lambda " + std::to_string(p.lambda) + ": expected 0 to " +
                                std::to_string(static_cast<long>(kMaxLambda)) +
                                " (beyond, the descriptor term outweighs every judgment)");
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
  return objective(p, q, m, gradient, model_gradient, LoopBuild::automatic);
}

double objective(const SpaceProblem& p, const Eigen::MatrixXd& q, const JudgmentModel& m,
                 Eigen::MatrixXd* gradient, ModelGradient* model_gradient, LoopBuild build) {
  if (gradient) gradient->setZero(q.rows(), q.cols());
  if (model_gradient) {
    model_gradient->lapse = 0.0;
    model_gradient->log_noise.setZero(m.log_noise.size());
  }
  double value = likelihood_part(p, m, q, gradient, model_gradient, build);
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
