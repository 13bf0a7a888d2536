#include "model/space/fit.hpp"

#include <LBFGS.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "model/numeric/parallel_for.hpp"
#include "model/space/spectral_start.hpp"

namespace nibrig::model::space {
namespace {

// The free coordinates (all but the pinned stimulus) as one vector, and back.
Eigen::MatrixXd to_coordinates(const Eigen::VectorXd& x, std::size_t dims, std::size_t stimuli,
                               std::size_t pinned) {
  Eigen::MatrixXd q =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(dims), static_cast<Eigen::Index>(stimuli));
  Eigen::Index k = 0;
  for (std::size_t s = 0; s < stimuli; ++s) {
    if (s == pinned) continue;
    q.col(static_cast<Eigen::Index>(s)) = x.segment(k, static_cast<Eigen::Index>(dims));
    k += static_cast<Eigen::Index>(dims);
  }
  return q;
}

Eigen::VectorXd free_part(const Eigen::MatrixXd& q, std::size_t pinned) {
  Eigen::VectorXd x(q.rows() * (q.cols() - 1));
  Eigen::Index k = 0;
  for (Eigen::Index s = 0; s < q.cols(); ++s) {
    if (static_cast<std::size_t>(s) == pinned) continue;
    x.segment(k, q.rows()) = q.col(s);
    k += q.rows();
  }
  return x;
}

struct StartResult {
  Eigen::MatrixXd coordinates;
  JudgmentModel model;
  double objective = 0.0;
  int iterations = 0, evaluations = 0;
};

// The fitted parts of the model after the coordinates in the optimiser's vector: θ with
// ε = σ(θ)/2 (a lapse stays in [0, 0.5), where half the answers at random is the most it can mean),
// then η per stimulus.
constexpr double kStartLapse = 0.02;
// The spectral start's RMS radius: in units where one unit of distance is a 75 % judgment, the
// size of a fitted Lagunas space (from radius 2 it reached the best optimum random starts find,
// from 1 one 8 nats worse; Salmon's 1-D fit reached the same optimum from 0.5 to 8).
constexpr double kSpectralStartRadius = 2.0;

double sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x)); }

Eigen::Index model_parameters(const ModelFamily& f, std::size_t stimuli) {
  return (f.lapse ? 1 : 0) + (f.stimulus_noise ? static_cast<Eigen::Index>(stimuli) : 0);
}

// Writes the model's fitted parts from x[from...] into `model`.
void read_model(const Eigen::VectorXd& x, Eigen::Index from, JudgmentModel& model) {
  if (model.family.lapse) model.lapse = 0.5 * sigmoid(x(from++));
  if (model.family.stimulus_noise) model.log_noise = x.segment(from, model.log_noise.size());
}

// L-BFGS from q0 (and the model's lapse and noises as problem.model holds them, where its family
// fits them) to the best point it reaches.
StartResult minimize_from(const SpaceProblem& problem, const Eigen::MatrixXd& q0,
                          const FitOptions& options, int start) {
  const Eigen::VectorXd coordinates = free_part(q0, options.pinned);
  const Eigen::Index free_coordinates = coordinates.size();
  JudgmentModel model = problem.model;
  if (model.family.stimulus_noise && model.log_noise.size() == 0)
    model.log_noise = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(problem.stimuli));
  if (!model.family.stimulus_noise) model.log_noise.resize(0);
  if (!model.family.lapse) model.lapse = 0.0;
  Eigen::VectorXd x(free_coordinates + model_parameters(model.family, problem.stimuli));
  x.head(free_coordinates) = coordinates;
  {
    Eigen::Index k = free_coordinates;
    if (model.family.lapse) {
      const double start_lapse = model.lapse > 0 ? model.lapse : kStartLapse;
      x(k++) = std::log(2.0 * start_lapse / (1.0 - 2.0 * start_lapse));  // σ⁻¹(2ε)
    }
    if (model.family.stimulus_noise) x.segment(k, model.log_noise.size()) = model.log_noise;
  }

  // The best finite point any evaluation saw: LBFGSpp's line search evaluates trial points in
  // place and, when it gives up (at a kink where stimuli coincide, at round-off level near the
  // optimum, or after a trial step overflowed to a non-finite point), leaves x at its last trial.
  Eigen::VectorXd best_x = x, best_grad;
  double best_f = std::numeric_limits<double>::infinity();
  JudgmentModel trial = model;
  StartResult result;
  auto function = [&](const Eigen::VectorXd& v, Eigen::VectorXd& grad) {
    // A restart (below) begins where an evaluation has been: its value and gradient are kept. A
    // Student-t start restarts several times in its first steps, where the curvature is negative.
    if (best_grad.size() > 0 && v == best_x) {
      grad = best_grad;
      return best_f;
    }
    ++result.evaluations;
    const Eigen::MatrixXd q =
        to_coordinates(v.head(free_coordinates), problem.dims, problem.stimuli, options.pinned);
    read_model(v, free_coordinates, trial);
    Eigen::MatrixXd g;
    ModelGradient mg;
    const double f = objective(problem, q, trial, &g, &mg);
    grad.resize(v.size());
    grad.head(free_coordinates) = free_part(g, options.pinned);
    Eigen::Index k = free_coordinates;
    if (trial.family.lapse) {
      const double u = sigmoid(v(k));
      grad(k++) = mg.lapse * 0.5 * u * (1.0 - u);
    }
    if (trial.family.stimulus_noise) grad.segment(k, mg.log_noise.size()) = mg.log_noise;
    if (std::isfinite(f) && f < best_f && grad.allFinite()) {
      best_f = f;
      best_x = v;
      best_grad = grad;
    }
    return std::isfinite(f) ? f : std::numeric_limits<double>::infinity();
  };
  LBFGSpp::LBFGSParam<double> param;
  param.epsilon = 1e-6;  // relative gradient norm: far below what a count of judgments resolves
  // Or when an iteration gains less than 2.2e-9 of the objective, scipy's L-BFGS-B's default ftol:
  // Lagunas's 43,000 nats then move by 1e-4, far below what a judgment resolves, where the gradient
  // test alone spends many more evaluations polishing the same optimum to its last digits.
  param.past = 1;
  param.delta = 2.220446049250313e-09;
  param.m = 10;  // corrections kept, as scipy's L-BFGS-B (maxcor); LBFGSpp's default is 6
  param.max_iterations = options.max_iterations;
  LBFGSpp::LBFGSSolver<double> solver(param);
  // A line search that gives up at a kink (two stimuli crossing, common in 1-D) has stopped short
  // of the optimum, not reached it: restart the quasi-Newton memory from the best point while that
  // still improves the objective.
  constexpr int kMaxRestarts = 50;
  for (int restart = 0; restart <= kMaxRestarts; ++restart) {
    const double before = best_f;
    double fx = 0.0;
    try {
      result.iterations += solver.minimize(function, x, fx);
      break;  // converged
    } catch (const std::exception&) {
      x = best_x;  // the best point evaluated so far (above)
    }
    if (std::isfinite(before) && !(best_f < before - 1e-10 * std::abs(before))) break;
  }
  if (!std::isfinite(best_f))
    throw std::runtime_error("the objective is not finite anywhere the fit looked (start " +
                             std::to_string(start) + ", lambda " + std::to_string(problem.lambda) +
                             ", " + std::to_string(problem.dims) + " dimensions)");
  x = best_x;
  const double fx = best_f;
  result.coordinates =
      to_coordinates(x.head(free_coordinates), problem.dims, problem.stimuli, options.pinned);
  read_model(x, free_coordinates, model);
  result.model = model;
  result.objective = fx;
  return result;
}

StartResult run_start(const SpaceProblem& problem, const FitOptions& options, int start) {
  std::mt19937_64 generator(options.seed + static_cast<unsigned>(start));
  std::normal_distribution<double> normal(0.0, options.start_spread);
  Eigen::MatrixXd q0(static_cast<Eigen::Index>(problem.dims),
                     static_cast<Eigen::Index>(problem.stimuli));
  const bool given = start == 0 && options.initial.size() > 0;
  const Eigen::MatrixXd spectral = start == 0 && !given && options.spectral_start
                                       ? spectral_start(problem, kSpectralStartRadius)
                                       : Eigen::MatrixXd();
  if (given) {
    q0 = options.initial.colwise() - options.initial.col(static_cast<Eigen::Index>(options.pinned));
  } else if (spectral.size() > 0) {
    q0 = spectral.colwise() - spectral.col(static_cast<Eigen::Index>(options.pinned));
  } else {
    for (Eigen::Index i = 0; i < q0.size(); ++i) q0.data()[i] = normal(generator);
    q0.col(static_cast<Eigen::Index>(options.pinned)).setZero();
  }
  const ModelFamily& family = problem.model.family;
  if (given || (!family.lapse && !family.stimulus_noise))
    return minimize_from(problem, q0, options, start);
  // From a random start, the coordinates are found first by the link alone, and the lapse and
  // noises fitted with them from there: fitted together from the start, while every prediction is
  // still a guess, the lapse ran to ½ (all answers random) and stayed, its sigmoid flat there
  // (Lagunas, Student-t + lapse).
  SpaceProblem link_alone = problem;
  link_alone.model.family.lapse = link_alone.model.family.stimulus_noise = false;
  const StartResult first = minimize_from(link_alone, q0, options, start);
  StartResult result = minimize_from(problem, first.coordinates, options, start);
  result.iterations += first.iterations;
  result.evaluations += first.evaluations;
  return result;
}

}  // namespace

FitResult fit_space(const SpaceProblem& problem, const FitOptions& options,
                    const numeric::Progress& progress) {
  validate(problem);
  if (options.starts < 1 || options.starts > kMostFitStarts)
    throw std::invalid_argument("starts: " + std::to_string(options.starts) + ": expected a number of starts, 1 to " +
                                std::to_string(kMostFitStarts));
  if (options.pinned >= problem.stimuli)
    throw std::invalid_argument("the pinned stimulus is out of range");
  if (options.initial.size() > 0 &&
      (options.initial.rows() != static_cast<Eigen::Index>(problem.dims) ||
       options.initial.cols() != static_cast<Eigen::Index>(problem.stimuli) ||
       !options.initial.allFinite()))
    throw std::invalid_argument("the initial space must be finite, " +
                                std::to_string(problem.dims) + " × " +
                                std::to_string(problem.stimuli));

  const SpaceProblem as_fitted = with_link_prior(problem);
  std::vector<StartResult> results(static_cast<std::size_t>(options.starts));
  numeric::ProgressCounter counter(progress, results.size());
  numeric::parallel_for(results.size(), options.threads, [&](std::size_t s) {
    if (options.stop.stop_requested()) return;
    results[s] = run_start(as_fitted, options, static_cast<int>(s));
    counter.finished();
  });
  // Checked after the join, so that no worker still writes into `results` when the caller unwinds.
  numeric::throw_if_cancelled(options.stop, "space fit");

  FitResult fit;
  for (std::size_t s = 0; s < results.size(); ++s) {
    fit.start_objectives.push_back(results[s].objective);
    if (results[s].objective < results[static_cast<std::size_t>(fit.best_start)].objective)
      fit.best_start = static_cast<int>(s);
  }
  std::sort(fit.start_objectives.begin(), fit.start_objectives.end());
  const StartResult& best = results[static_cast<std::size_t>(fit.best_start)];
  fit.coordinates = best.coordinates;
  fit.model = best.model;
  fit.objective = best.objective;
  fit.iterations = best.iterations;
  fit.evaluations = best.evaluations;
  SpaceProblem fitted = problem;
  fitted.model = best.model;
  fit.negative_log_likelihood = negative_log_likelihood(fitted, best.coordinates);
  fit.correlation_penalty = correlation_penalty(problem, best.coordinates);
  return fit;
}

}  // namespace nibrig::model::space
