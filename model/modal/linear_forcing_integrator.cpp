#include "model/modal/linear_forcing_integrator.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "model/modal/linear_forcing_step.hpp"
#include "model/modal/modal_model_checks.hpp"

namespace nibrig::model::modal {
namespace {

// Modes are processed in groups of this many with one partial sum each, so that the compiler can
// keep the group in vector registers and the output sum needs no reassociation it may not do.
constexpr std::size_t kLanes = 4;
static_assert(kLanes == 4, "run() adds the four partial sums by hand");

}  // namespace

LinearForcingIntegrator::LinearForcingIntegrator(const ModalModel& model, double sample_rate)
    : modes_(model.size()), sample_rate_(sample_rate), resonant_feedthrough_(0.0), feedthrough_(0.0) {
  const std::string caller = "LinearForcingIntegrator";
  check_modal_model(model, caller);
  check_sample_rate(sample_rate, caller);
  padded_ = (modes_ + kLanes - 1) / kLanes * kLanes;
  for (auto* a : {&dd_, &dv_, &vd_, &vv_, &start_d_, &start_v_, &end_d_, &end_v_, &out_d_, &out_v_,
                  &static_d_, &q_, &v_}) {
    a->assign(padded_, 0.0);
  }
  const double h = 1.0 / sample_rate;
  for (std::size_t i = 0; i < modes_; ++i) {
    const double w = model.omega[i];
    const double b = model.input[i];
    const double c = model.output[i];
    const LinearForcingStep s = make_linear_forcing_step(w, model.zeta[i], h);
    dd_[i] = s.transition.dd;
    dv_[i] = s.transition.dv;
    vd_[i] = s.transition.vd;
    vv_[i] = s.transition.vv;
    start_d_[i] = b * s.from_start.displacement;
    start_v_[i] = b * s.from_start.velocity;
    end_d_[i] = b * s.from_end.displacement;
    end_v_[i] = b * s.from_end.velocity;
    out_d_[i] = -c * w * w;
    out_v_[i] = -2.0 * c * model.zeta[i] * w;
    const bool quasi_static = model.zeta[i] >= 1.0 || w >= std::numbers::pi * sample_rate;
    static_d_[i] = quasi_static ? b / (w * w) : 0.0;
    if (!quasi_static) resonant_feedthrough_ += c * b;
    feedthrough_ += c * b;
  }
}

void LinearForcingIntegrator::reset() noexcept {
  for (std::size_t i = 0; i < padded_; ++i) q_[i] = v_[i] = 0.0;
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
    q_[i] = displacement[i];
    v_[i] = velocity[i];
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
      for (std::size_t i = 0; i < modes_; ++i) q_[i] = static_d_[i] * f, v_[i] = 0.0;
      acceleration[0] = static_cast<Sample>(resonant_feedthrough_ * f);
    }
    previous_force_ = f;
    started_ = true;
    n = 1;
  }
  double* __restrict q = q_.data();
  double* __restrict v = v_.data();
  const double* __restrict dd = dd_.data();
  const double* __restrict dv = dv_.data();
  const double* __restrict vd = vd_.data();
  const double* __restrict vv = vv_.data();
  const double* __restrict sd = start_d_.data();
  const double* __restrict sv = start_v_.data();
  const double* __restrict ed = end_d_.data();
  const double* __restrict ev = end_v_.data();
  const double* __restrict od = out_d_.data();
  const double* __restrict ov = out_v_.data();
  for (; n < count; ++n) {
    const double f0 = previous_force_;
    const double f1 = static_cast<double>(force[n]);
    double sum[kLanes] = {};
    for (std::size_t i = 0; i < padded_; i += kLanes) {
      for (std::size_t l = 0; l < kLanes; ++l) {
        const std::size_t k = i + l;
        const double qn = dd[k] * q[k] + dv[k] * v[k] + sd[k] * f0 + ed[k] * f1;
        const double vn = vd[k] * q[k] + vv[k] * v[k] + sv[k] * f0 + ev[k] * f1;
        q[k] = qn;
        v[k] = vn;
        sum[l] += od[k] * qn + ov[k] * vn;
      }
    }
    acceleration[n] =
        static_cast<Sample>((sum[0] + sum[1]) + (sum[2] + sum[3]) + feedthrough_ * f1);
    previous_force_ = f1;
  }
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
