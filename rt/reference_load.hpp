// The normal force under which the paper measured every tool (the pilot study's mean, Sec. 4.3),
// and how far the real-time forcing extrapolates from it.
#pragma once

namespace nibrig::rt {

inline constexpr double kReferenceNormalForce = 2.2;  // N
// The forcing grows linearly with normal force up to this multiple of the reference, then stays.
inline constexpr double kMaxNormalForceRatio = 4.0;

}  // namespace nibrig::rt
