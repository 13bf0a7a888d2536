#include "model/modal/linear_forcing_integrator.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/modal/linear_forcing_step.hpp"
#include "model/modal/modal_model_checks.hpp"
#include "model/numeric/cpu_features.hpp"

namespace nibrig::model::modal {
namespace {

using ModeGroup = LinearForcingIntegrator::ModeGroup;
constexpr std::size_t kLanes = LinearForcingIntegrator::kLanes;
static_assert(kLanes == 4, "march() adds the four partial sums by hand");

// A row of a ModeGroup as one value: an AVX2 register, or two SSE2 ones in the portable build.
// may_alias: it is read and written where the rows' doubles are.
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double)), may_alias));

[[gnu::always_inline]] inline const Lanes& row(const double (&r)[kLanes]) noexcept {
  return *reinterpret_cast<const Lanes*>(r);
}

[[gnu::always_inline]] inline Lanes& row(double (&r)[kLanes]) noexcept {
  return *reinterpret_cast<Lanes*>(r);
}

// Advances every mode through `count` samples from the force `previous`; returns the last force.
// Compiled once for any x86-64 and once with AVX2 and FMA (march_avx2_fma), where a group's row is
// one register and the multiply-adds are fused. Each lane adds its modes' outputs in the modes'
// order and the lanes are added pairwise, in either build.
template <class Sample>
[[gnu::always_inline]] inline double march(ModeGroup* groups, std::size_t group_count,
                                           double feedthrough, double previous, const Sample* force,
                                           Sample* acceleration, std::size_t count) noexcept {
  for (std::size_t n = 0; n < count; ++n) {
    const double f1 = static_cast<double>(force[n]);
    const Lanes f0s = {previous, previous, previous, previous};
    const Lanes f1s = {f1, f1, f1, f1};
    Lanes sum = {};
    for (std::size_t g = 0; g < group_count; ++g) {
      ModeGroup& m = groups[g];
      const Lanes q = row(m.q), v = row(m.v);
      const Lanes qn = row(m.dd) * q + row(m.dv) * v + row(m.sd) * f0s + row(m.ed) * f1s;
      const Lanes vn = row(m.vd) * q + row(m.vv) * v + row(m.sv) * f0s + row(m.ev) * f1s;
      row(m.q) = qn;
      row(m.v) = vn;
      sum += row(m.od) * qn + row(m.ov) * vn;
    }
    acceleration[n] = static_cast<Sample>((sum[0] + sum[1]) + (sum[2] + sum[3]) + feedthrough * f1);
    previous = f1;
  }
  return previous;
}

template <class Sample>
double march_portable(ModeGroup* groups, std::size_t group_count, double feedthrough,
                      double previous, const Sample* force, Sample* acceleration,
                      std::size_t count) noexcept {
  return march(groups, group_count, feedthrough, previous, force, acceleration, count);
}

#if defined(__x86_64__)
template <class Sample>
[[gnu::target("avx2,fma")]] double march_avx2_fma(ModeGroup* groups, std::size_t group_count,
                                                  double feedthrough, double previous,
                                                  const Sample* force, Sample* acceleration,
                                                  std::size_t count) noexcept {
  return march(groups, group_count, feedthrough, previous, force, acceleration, count);
}
#endif

}  // namespace

LinearForcingIntegrator::LinearForcingIntegrator(const ModalModel& model, double sample_rate)
    : modes_(model.size()),
      sample_rate_(sample_rate),
      resonant_feedthrough_(0.0),
      feedthrough_(0.0),
      kernel_(numeric::cpu_has_avx2_fma() ? Kernel::avx2_fma : Kernel::portable) {
  const std::string caller = "LinearForcingIntegrator";
  check_modal_model(model, caller);
  check_sample_rate(sample_rate, caller);
  groups_.assign((modes_ + kLanes - 1) / kLanes, ModeGroup{});
  static_d_.assign(modes_, 0.0);
  const double h = 1.0 / sample_rate;
  for (std::size_t i = 0; i < modes_; ++i) {
    const double w = model.omega[i];
    const double b = model.input[i];
    const double c = model.output[i];
    const LinearForcingStep s = make_linear_forcing_step(w, model.zeta[i], h);
    ModeGroup& g = groups_[i / kLanes];
    const std::size_t l = i % kLanes;
    g.dd[l] = s.transition.dd;
    g.dv[l] = s.transition.dv;
    g.vd[l] = s.transition.vd;
    g.vv[l] = s.transition.vv;
    g.sd[l] = b * s.from_start.displacement;
    g.sv[l] = b * s.from_start.velocity;
    g.ed[l] = b * s.from_end.displacement;
    g.ev[l] = b * s.from_end.velocity;
    g.od[l] = -c * w * w;
    g.ov[l] = -2.0 * c * model.zeta[i] * w;
    const bool quasi_static = model.zeta[i] >= 1.0 || w >= std::numbers::pi * sample_rate;
    static_d_[i] = quasi_static ? b / (w * w) : 0.0;
    if (!quasi_static) resonant_feedthrough_ += c * b;
    feedthrough_ += c * b;
  }
}

void LinearForcingIntegrator::set_kernel(Kernel kernel) {
  if (kernel == Kernel::avx2_fma && !numeric::cpu_has_avx2_fma())
    throw std::invalid_argument("LinearForcingIntegrator: this CPU has no AVX2 and FMA");
  kernel_ = kernel;
}

void LinearForcingIntegrator::reset() noexcept {
  for (auto& g : groups_)
    for (std::size_t l = 0; l < kLanes; ++l) g.q[l] = g.v[l] = 0.0;
  previous_force_ = 0.0;
  started_ = false;
}

void LinearForcingIntegrator::set_state(std::span<const double> displacement,
                                        std::span<const double> velocity, double force) {
  const std::string caller = "LinearForcingIntegrator::set_state";
  check_same_size(displacement.size(), modes_, "displacement (one per mode)", caller);
  check_same_size(velocity.size(), modes_, "velocity (one per mode)", caller);
  check_finite(force, "force (N)", caller);
  for (std::size_t i = 0; i < modes_; ++i) {
    check_finite(displacement[i], "displacement[" + std::to_string(i) + "]", caller);
    check_finite(velocity[i], "velocity[" + std::to_string(i) + "]", caller);
  }
  for (std::size_t i = 0; i < modes_; ++i) {
    groups_[i / kLanes].q[i % kLanes] = displacement[i];
    groups_[i / kLanes].v[i % kLanes] = velocity[i];
  }
  previous_force_ = force;
  started_ = true;
}

template <class Sample>
void LinearForcingIntegrator::run(const Sample* force, Sample* acceleration,
                                  std::size_t count) noexcept {
  std::size_t n = 0;
  if (!started_ && count > 0) {
    const double f = static_cast<double>(force[0]);
    if (start_ == Start::at_rest) {
      // At rest at the time origin: only the instantaneous part b·f of q̈ reaches the sensor.
      acceleration[0] = static_cast<Sample>(feedthrough_ * f);
    } else {
      // The quasi-static modes held still under f (b·f − ω²q = 0: no acceleration), the others at
      // rest (their instantaneous b·f only).
      for (std::size_t i = 0; i < modes_; ++i) {
        groups_[i / kLanes].q[i % kLanes] = static_d_[i] * f;
        groups_[i / kLanes].v[i % kLanes] = 0.0;
      }
      acceleration[0] = static_cast<Sample>(resonant_feedthrough_ * f);
    }
    previous_force_ = f;
    started_ = true;
    n = 1;
  }
#if defined(__x86_64__)
  if (kernel_ == Kernel::avx2_fma) {
    previous_force_ = march_avx2_fma(groups_.data(), groups_.size(), feedthrough_, previous_force_,
                                     force + n, acceleration + n, count - n);
    return;
  }
#endif
  previous_force_ = march_portable(groups_.data(), groups_.size(), feedthrough_, previous_force_,
                                   force + n, acceleration + n, count - n);
}

void LinearForcingIntegrator::process(const float* force, float* acceleration,
                                      std::size_t count) noexcept {
  run(force, acceleration, count);
}

void LinearForcingIntegrator::process(const double* force, double* acceleration,
                                      std::size_t count) noexcept {
  run(force, acceleration, count);
}

}  // namespace nibrig::model::modal
