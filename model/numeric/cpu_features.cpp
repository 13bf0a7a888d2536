#include "model/numeric/cpu_features.hpp"

namespace nibrig::model::numeric {

bool cpu_has_avx2_fma() noexcept {
#if defined(__x86_64__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

}  // namespace nibrig::model::numeric
