// Counts heap allocations made by the calling thread (the test binary replaces the global operator
// new), so a test can prove that code meant for the audio thread allocates nothing.
#pragma once

#include <cstddef>

namespace nibrig::testing {

// Allocations by this thread since it started.
std::size_t allocations_on_this_thread();

}  // namespace nibrig::testing
