#include "rt/voice.hpp"

#include <stdexcept>

namespace nibrig::rt {

Voice::Voice(std::string name, const model::modal::ModalModel& modal,
             std::shared_ptr<const ForcingTable> forcing, std::uint64_t seed)
    : name_(std::move(name)),
      generator_(forcing, seed),
      integrator_(modal, forcing ? forcing->sample_rate() : 0.0) {
  // A voice joins a stroke in progress (a tool loaded, a design swapped at every slider move): its
  // modes start in equilibrium under the first force, not at rest with the force jumping from 0.
  integrator_.set_start(model::modal::LinearForcingIntegrator::Start::in_equilibrium);
}

}  // namespace nibrig::rt
