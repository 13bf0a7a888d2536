#include "model/space/adaptive_plan.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "model/space/normal_tail.hpp"
#include "model/space/trial_plan.hpp"

namespace nibrig::model::space {

double binary_entropy(double p) {
  double h = 0.0;
  if (p > 0 && p < 1) h = -p * std::log(p) - (1 - p) * std::log1p(-p);
  return h;
}

double bald(const std::vector<double>& member_probabilities) {
  if (member_probabilities.empty()) throw std::invalid_argument("BALD needs an ensemble");
  double mean = 0.0, mean_entropy = 0.0;
  for (double p : member_probabilities) {
    mean += p;
    mean_entropy += binary_entropy(p);
  }
  const auto s = static_cast<double>(member_probabilities.size());
  // Concavity makes this >= 0; round-off can leave −1e-17 where all members agree.
  return std::max(0.0, binary_entropy(mean / s) - mean_entropy / s);
}

std::vector<double> expected_information_gain(const std::vector<Eigen::MatrixXd>& ensemble,
                                              const std::vector<io::Triplet>& candidates,
                                              const JudgmentModel& model) {
  if (ensemble.empty()) throw std::invalid_argument("expected information gain needs an ensemble");
  for (const auto& member : ensemble)
    if (member.rows() != ensemble.front().rows() || member.cols() != ensemble.front().cols())
      throw std::invalid_argument("ensemble members differ in shape");
  const auto n = static_cast<std::size_t>(ensemble.front().cols());
  std::vector<double> gains;
  gains.reserve(candidates.size());
  std::vector<double> p(ensemble.size());
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const io::Triplet& t = candidates[c];
    if (t.reference >= n || t.a >= n || t.b >= n)
      throw std::invalid_argument("candidate " + std::to_string(c) + ": stimulus out of range (" +
                                  std::to_string(n) + " stimuli)");
    for (std::size_t s = 0; s < ensemble.size(); ++s)
      p[s] = probability_first(model, ensemble[s], t.reference, t.a, t.b);
    gains.push_back(bald(p));
  }
  return gains;
}

std::vector<std::size_t> select_batch(const std::vector<double>& gains, std::size_t batch_size) {
  std::vector<std::size_t> order(gains.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const std::size_t k = std::min(batch_size, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                    [&](std::size_t x, std::size_t y) {
                      return gains[x] > gains[y] || (gains[x] == gains[y] && x < y);
                    });
  order.resize(k);
  return order;
}

std::vector<Eigen::MatrixXd> laplace_ensemble(const SpaceProblem& problem,
                                              const Eigen::MatrixXd& mode,
                                              const LaplaceOptions& options,
                                              std::mt19937_64& generator) {
  validate(problem);
  const auto dims = static_cast<Eigen::Index>(problem.dims);
  const auto n = static_cast<Eigen::Index>(problem.stimuli);
  if (mode.rows() != dims || mode.cols() != n)
    throw std::invalid_argument("laplace_ensemble: the mode is " + std::to_string(mode.rows()) +
                                " × " + std::to_string(mode.cols()) + ", expected " +
                                std::to_string(dims) + " × " + std::to_string(n));
  if (options.samples < 1) throw std::invalid_argument("laplace_ensemble: samples must be >= 1");
  if (!(options.prior_sd > 0))
    throw std::invalid_argument("laplace_ensemble: prior_sd must be > 0");
  if (options.pinned >= problem.stimuli)
    throw std::invalid_argument("laplace_ensemble: the pinned stimulus is out of range");

  const auto pinned = static_cast<Eigen::Index>(options.pinned);
  // Offset of stimulus s in the free vector; −1 for the pinned one.
  auto offset = [&](std::size_t s) {
    const auto i = static_cast<Eigen::Index>(s);
    return i == pinned ? Eigen::Index{-1} : (i < pinned ? i : i - 1) * dims;
  };
  const Eigen::Index free = dims * (n - 1);
  Eigen::MatrixXd information =
      Eigen::MatrixXd::Identity(free, free) / (options.prior_sd * options.prior_sd);
  Eigen::VectorXd g(free);
  for (const io::Triplet& t : problem.triplets) {
    const int judgments = t.count_a + t.count_b;
    if (judgments == 0) continue;
    const Eigen::VectorXd va =
        mode.col(static_cast<Eigen::Index>(t.a)) - mode.col(static_cast<Eigen::Index>(t.reference));
    const Eigen::VectorXd vb =
        mode.col(static_cast<Eigen::Index>(t.b)) - mode.col(static_cast<Eigen::Index>(t.reference));
    const double na = va.norm(), nb = vb.norm();
    // The paper's probit at the model's scale: for another link, lapse or noises this is an
    // approximation of their information, good enough to say which triplets the data pin least.
    const double scale = problem.model.scale;
    const double x = -scale * (na - nb);
    // Fisher information of one judgment about x: φ²/(Φ(x)Φ(−x)) = [φ/Φ](x)·[φ/Φ](−x).
    const double weight = judgments * scale * scale * normal_pdf_over_cdf(x) *
                          normal_pdf_over_cdf(-x);
    const Eigen::VectorXd ua = na > 0 ? Eigen::VectorXd(va / na) : Eigen::VectorXd::Zero(dims);
    const Eigen::VectorXd ub = nb > 0 ? Eigen::VectorXd(vb / nb) : Eigen::VectorXd::Zero(dims);
    g.setZero();
    if (auto o = offset(t.a); o >= 0) g.segment(o, dims) += ua;
    if (auto o = offset(t.b); o >= 0) g.segment(o, dims) -= ub;
    if (auto o = offset(t.reference); o >= 0) g.segment(o, dims) += ub - ua;
    information.selfadjointView<Eigen::Lower>().rankUpdate(g, weight);
  }
  information.triangularView<Eigen::Upper>() = information.transpose();
  const Eigen::LLT<Eigen::MatrixXd> cholesky(information);
  // The prior makes the matrix positive definite; only NaN coordinates can break that.
  if (cholesky.info() != Eigen::Success)
    throw std::runtime_error("laplace_ensemble: the information matrix is not positive definite");

  // The infinitesimal rotations about the pinned stimulus, one per pair of axes, orthonormalised.
  // F is block-diagonal between their span and its complement (F·G = 0, the prior is isotropic),
  // so dropping that component of a sample conditions it on "no rotation" exactly.
  Eigen::MatrixXd rotations = Eigen::MatrixXd::Zero(free, dims * (dims - 1) / 2);
  Eigen::Index generator_index = 0;
  for (Eigen::Index i = 0; i < dims; ++i)
    for (Eigen::Index j = i + 1; j < dims; ++j, ++generator_index)
      for (std::size_t st = 0; st < problem.stimuli; ++st)
        if (auto o = offset(st); o >= 0) {
          const Eigen::VectorXd v = mode.col(static_cast<Eigen::Index>(st)) - mode.col(pinned);
          rotations(o + i, generator_index) = -v[j];
          rotations(o + j, generator_index) = v[i];
        }
  Eigen::MatrixXd rotation_basis(free, 0);
  if (rotations.cols() > 0) {
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rotations);
    rotation_basis = Eigen::MatrixXd(qr.householderQ()).leftCols(qr.rank());
  }

  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Eigen::MatrixXd> ensemble;
  ensemble.reserve(static_cast<std::size_t>(options.samples));
  Eigen::VectorXd z(free);
  for (int s = 0; s < options.samples; ++s) {
    for (Eigen::Index i = 0; i < free; ++i) z[i] = normal(generator);
    // information = L Lᵀ: δ = L⁻ᵀ z has covariance L⁻ᵀ L⁻¹ = information⁻¹.
    Eigen::VectorXd delta = cholesky.matrixU().solve(z);
    delta -= rotation_basis * (rotation_basis.transpose() * delta);
    Eigen::MatrixXd member = mode;
    for (std::size_t st = 0; st < problem.stimuli; ++st)
      if (auto o = offset(st); o >= 0)
        member.col(static_cast<Eigen::Index>(st)) += delta.segment(o, dims);
    ensemble.push_back(std::move(member));
  }
  return ensemble;
}

std::vector<Trial> next_adaptive_batch(const SpaceProblem& problem, const Eigen::MatrixXd& mode,
                                       const std::vector<io::Triplet>& candidates,
                                       const LaplaceOptions& ensemble_options,
                                       std::size_t batch_size, int stage,
                                       std::mt19937_64& generator) {
  const std::vector<Eigen::MatrixXd> ensemble =
      laplace_ensemble(problem, mode, ensemble_options, generator);
  const std::vector<std::size_t> batch =
      select_batch(expected_information_gain(ensemble, candidates, problem.model), batch_size);
  std::vector<Trial> asked;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const io::Triplet& t = candidates[batch[i]];
    asked.push_back(i % 2 ? Trial{t.reference, t.b, t.a, stage} : Trial{t.reference, t.a, t.b, stage});
  }
  return asked;
}

std::vector<AdaptiveCheckpoint> run_adaptive_study(const SimulatedObserver& observer,
                                                   std::size_t dims, const AdaptiveOptions& options,
                                                   std::uint64_t seed) {
  const auto n = static_cast<std::size_t>(observer.truth().cols());
  const std::vector<io::Triplet> candidates = all_triplets(n);
  std::vector<std::size_t> checkpoints = options.checkpoints;
  std::sort(checkpoints.begin(), checkpoints.end());
  checkpoints.erase(std::unique(checkpoints.begin(), checkpoints.end()), checkpoints.end());
  if (options.batch_size == 0) throw std::invalid_argument("adaptive study: batch size 0");
  if (checkpoints.empty()) throw std::invalid_argument("adaptive study: no checkpoints");
  if (options.initial_trials < 1 || options.initial_trials > candidates.size() ||
      options.initial_trials > checkpoints.front())
    throw std::invalid_argument(
        "adaptive study: initial trials must be between 1 and both the first checkpoint (" +
        std::to_string(checkpoints.front()) + ") and the number of triplets (" +
        std::to_string(candidates.size()) + "), found " + std::to_string(options.initial_trials));

  std::mt19937_64 generator(seed);
  std::vector<Trial> trials = plan_all_triplets(
      n, 1, generator(),
      static_cast<double>(options.initial_trials) / static_cast<double>(candidates.size()));
  std::vector<Choice> choices = observer.answer(trials, generator);

  SpaceProblem problem;
  problem.stimuli = n;
  problem.dims = dims;
  // The fit maximises the posterior whose Laplace approximation the ensemble samples: without the
  // prior, a handful of single answers is often explained perfectly by some configuration and the
  // likelihood alone would stretch it without bound.
  problem.prior_sd = options.ensemble.prior_sd;
  FitOptions fit_options = options.fit;
  std::vector<AdaptiveCheckpoint> reported;
  for (int round = 1;; ++round) {
    problem.triplets = merge_trials(trials, choices);
    fit_options.seed = options.fit.seed + 7919u * static_cast<unsigned>(round);
    const FitResult fit = fit_space(problem, fit_options);
    fit_options.initial = fit.coordinates;  // the next round's first start: one batch away
    const std::size_t next = checkpoints[reported.size()];
    if (trials.size() >= next) {
      reported.push_back({trials.size(), fit.coordinates, problem.triplets});
      if (reported.size() == checkpoints.size()) break;
    }
    const std::size_t target = checkpoints[reported.size()];
    const std::vector<Trial> asked =
        next_adaptive_batch(problem, fit.coordinates, candidates, options.ensemble,
                            std::min(options.batch_size, target - trials.size()), round + 1,
                            generator);
    const std::vector<Choice> answers = observer.answer(asked, generator);
    trials.insert(trials.end(), asked.begin(), asked.end());
    choices.insert(choices.end(), answers.begin(), answers.end());
  }
  return reported;
}

}  // namespace nibrig::model::space
