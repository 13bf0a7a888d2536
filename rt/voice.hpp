// One simulated tool on one surface, ready to sound: the stylus's modal model, stepped exactly for
// forcing that is linear between samples (App. A), driven by the forcing generator at the current
// speed and normal force. Runs at the engine's internal rate; made on a control thread.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "model/modal/linear_forcing_integrator.hpp"
#include "model/modal/modal_model.hpp"
#include "rt/forcing_generator.hpp"
#include "rt/forcing_table.hpp"

namespace nibrig::rt {

class Voice {
 public:
  // The integrator runs at forcing->sample_rate(). Throws std::invalid_argument for a bad model
  // or a missing table.
  Voice(std::string name, const model::modal::ModalModel& modal,
        std::shared_ptr<const ForcingTable> forcing, std::uint64_t seed);

  const std::string& name() const noexcept { return name_; }
  double sample_rate() const noexcept { return integrator_.sample_rate(); }
  std::size_t modes() const noexcept { return integrator_.modes(); }
  const ForcingGenerator& forcing() const noexcept { return generator_; }

  // acceleration[i] (m/s² at the sensor) for speed[i] (m/s) and normal_force[i] (N). Real-time
  // safe.
  void process(const double* speed_m_s, const double* normal_force_n, double* acceleration,
               std::size_t count) noexcept {
    generator_.generate(speed_m_s, normal_force_n, acceleration, count);
    integrator_.process(acceleration, acceleration, count);
  }

 private:
  std::string name_;
  ForcingGenerator generator_;
  model::modal::LinearForcingIntegrator integrator_;
};

}  // namespace nibrig::rt
