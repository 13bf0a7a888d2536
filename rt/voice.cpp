#include "rt/voice.hpp"

#include <stdexcept>

namespace nibrig::rt {

Voice::Voice(std::string name, const model::modal::ModalModel& modal,
             std::shared_ptr<const ForcingTable> forcing, std::uint64_t seed)
    : name_(std::move(name)),
      generator_(forcing, seed),
      integrator_(modal, forcing ? forcing->sample_rate() : 0.0) {}

}  // namespace nibrig::rt
