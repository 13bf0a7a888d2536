// The naive reference the benchmarks set the integrator against: each mode advanced one step by
// the matrix exponential of its augmented 4×4 generator, computed afresh at every step. Same
// arithmetic result as the precomputed recursion, none of its reuse.
#pragma once

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "model/modal/modal_model.hpp"

namespace nibrig::bench {

// Advances every mode's (q, q̇) in x over h with the force going linearly from f0 to f1, and
// returns the sensor acceleration at the end: exp of h·[[0, 1, 0, 0], [−ω², −2ζω, b, 0],
// [0, 0, 0, 1], [0, 0, 0, 0]] on [q, q̇, f, f'].
inline double naive_modal_step(const model::modal::ModalModel& m, std::vector<Eigen::Vector2d>& x,
                               double f0, double f1, double h) {
  double a = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double w = m.omega[i], z = m.zeta[i];
    Eigen::Matrix4d g = Eigen::Matrix4d::Zero();
    g(0, 1) = 1.0;
    g(1, 0) = -w * w;
    g(1, 1) = -2.0 * z * w;
    g(1, 2) = m.input[i];
    g(2, 3) = 1.0;
    const Eigen::Matrix4d e = (g * h).exp();
    const Eigen::Vector4d s(x[i][0], x[i][1], f0, (f1 - f0) / h);
    x[i] = (e * s).head<2>();
    a += m.output[i] * (-w * w * x[i][0] - 2.0 * z * w * x[i][1] + m.input[i] * f1);
  }
  return a;
}

}  // namespace nibrig::bench
