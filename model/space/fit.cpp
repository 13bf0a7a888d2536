#include "model/space/fit.hpp"

#include <LBFGS.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <random>
#include <stdexcept>
#include <thread>

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
  double objective = 0.0;
  int iterations = 0;
};

StartResult run_start(const SpaceProblem& problem, const FitOptions& options, int start) {
  std::mt19937_64 generator(options.seed + static_cast<unsigned>(start));
  std::normal_distribution<double> normal(0.0, options.start_spread);
  Eigen::MatrixXd q0(static_cast<Eigen::Index>(problem.dims),
                     static_cast<Eigen::Index>(problem.stimuli));
  for (Eigen::Index i = 0; i < q0.size(); ++i) q0.data()[i] = normal(generator);
  q0.col(static_cast<Eigen::Index>(options.pinned)).setZero();
  Eigen::VectorXd x = free_part(q0, options.pinned);

  auto function = [&](const Eigen::VectorXd& v, Eigen::VectorXd& grad) {
    const Eigen::MatrixXd q = to_coordinates(v, problem.dims, problem.stimuli, options.pinned);
    Eigen::MatrixXd g;
    const double f = objective(problem, q, &g);
    grad = free_part(g, options.pinned);
    return f;
  };
  LBFGSpp::LBFGSParam<double> param;
  param.epsilon = 1e-6;  // relative gradient norm: far below what a count of judgments resolves
  param.max_iterations = options.max_iterations;
  LBFGSpp::LBFGSSolver<double> solver(param);
  StartResult result;
  double fx = 0.0;
  try {
    result.iterations = solver.minimize(function, x, fx);
  } catch (const std::exception&) {
    // LBFGSpp throws when its line search cannot improve further (at a kink where stimuli coincide,
    // or at round-off level near the optimum): x then holds its last accepted point, which is kept.
    Eigen::VectorXd grad(x.size());
    fx = function(x, grad);
  }
  result.coordinates = to_coordinates(x, problem.dims, problem.stimuli, options.pinned);
  result.objective = fx;
  return result;
}

}  // namespace

FitResult fit_space(const SpaceProblem& problem, const FitOptions& options) {
  validate(problem);
  if (options.starts < 1) throw std::invalid_argument("fit needs at least one start");
  if (options.pinned >= problem.stimuli)
    throw std::invalid_argument("the pinned stimulus is out of range");

  std::vector<StartResult> results(static_cast<std::size_t>(options.starts));
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> failures(results.size());
  auto worker = [&] {
    for (int s = next++; s < options.starts; s = next++) {
      try {
        results[static_cast<std::size_t>(s)] = run_start(problem, options, s);
      } catch (...) {  // rethrown on the calling thread once every worker has joined
        failures[static_cast<std::size_t>(s)] = std::current_exception();
      }
    }
  };
  const unsigned threads = std::min<unsigned>(
      options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency()),
      static_cast<unsigned>(options.starts));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);

  FitResult fit;
  for (std::size_t s = 0; s < results.size(); ++s) {
    fit.start_objectives.push_back(results[s].objective);
    if (results[s].objective < results[static_cast<std::size_t>(fit.best_start)].objective)
      fit.best_start = static_cast<int>(s);
  }
  std::sort(fit.start_objectives.begin(), fit.start_objectives.end());
  const StartResult& best = results[static_cast<std::size_t>(fit.best_start)];
  fit.coordinates = best.coordinates;
  fit.objective = best.objective;
  fit.iterations = best.iterations;
  fit.negative_log_likelihood = negative_log_likelihood(problem, best.coordinates);
  fit.correlation_penalty = correlation_penalty(problem, best.coordinates);
  return fit;
}

}  // namespace nibrig::model::space
