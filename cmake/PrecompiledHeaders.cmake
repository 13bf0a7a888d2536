# Precompiled headers beside the unity build, for clang's Release build (the tree a user plays):
# the third-party headers most sources of a target include (Eigen, nlohmann::json, spdlog, CLI11)
# parsed, and their common templates instantiated, once per target instead of once per unit. The
# model parts share one, as they compile with the same flags (all but space's -fno-math-errno; a
# part given flags or definitions of its own needs a header of its own).
# Not under the sanitizers, where instrumented code generation dominates and they do not pay; not
# with GCC 12, which through a precompiled header reports libstdc++'s std::string internals as
# array-bounds errors in our code.
# A file must still include what it uses; -DNIBRIG_UNITY_BUILD=OFF with GCC checks that.
set(nibrig_pch_common <string> <vector> <map> <optional> <functional> <filesystem> <algorithm>
                      <stdexcept> <cmath> <Eigen/Dense> <nlohmann/json.hpp> <spdlog/spdlog.h>)

# KIND: model (a model/ part) or face (ui/cli, ui/panel: adds CLI11 and fmt).
function(nibrig_precompile target kind)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NIBRIG_SANITIZE)
    return()
  endif()
  set(headers ${nibrig_pch_common})
  if(kind STREQUAL "face")
    list(APPEND headers <CLI/CLI.hpp> <fmt/format.h>)
  elseif(NOT kind STREQUAL "model")
    message(FATAL_ERROR "nibrig_precompile(${target}): KIND must be model or face")
  endif()
  if(kind STREQUAL "model" AND NOT target STREQUAL "nibrig_model_numeric"
     AND NOT target STREQUAL "nibrig_model_space")
    target_precompile_headers(${target} REUSE_FROM nibrig_model_numeric)
  else()
    target_precompile_headers(${target} PRIVATE ${headers})
  endif()
endfunction()
