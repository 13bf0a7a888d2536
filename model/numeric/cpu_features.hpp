// What this CPU's vector units can run, for the loops compiled twice (for any x86-64 and for AVX2):
// asked once where each loop is chosen, never on the audio thread.
#pragma once

namespace nibrig::model::numeric {

// True on an x86-64 CPU with AVX2 and FMA; false elsewhere.
bool cpu_has_avx2_fma() noexcept;

}  // namespace nibrig::model::numeric
