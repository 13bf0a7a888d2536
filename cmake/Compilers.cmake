# Compiler and linker flags for every target, chosen by the options of the top-level CMakeLists.txt.
# Each flag says in a line why it is there; the stories behind the workarounds are in git history.

# Batches of 24 sources: the shared third-party headers are instantiated and optimised once per batch.
# What it buys, measured on 2 cores, cold (no ccache), clang 14, the demo's `nibrig` in Release with
# the precompiled headers on in both: 169 s in batches against 368 s one file at a time, 3.3 minutes
# on that target alone, of which CI builds two trees and their tests; the precompiled headers alone
# do not make that up. Its cost: file-local names unique per batch, and a missing include hidden
# until -DNIBRIG_UNITY_BUILD=OFF.
if(NIBRIG_UNITY_BUILD)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 24)
endif()

find_program(CCACHE_PROGRAM ccache)
if(CCACHE_PROGRAM)
  # Without these two sloppiness settings ccache leaves every source with a precompiled header uncached.
  set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env CCACHE_SLOPPINESS=pch_defines,time_macros
                                  ${CCACHE_PROGRAM})
endif()

add_compile_options(-Wall -Wextra -Wpedantic)
# GCC 12 reports -Wrestrict inside libstdc++'s string concatenation at -O3 (GCC bug 105329).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  add_compile_options(-Wno-restrict)
endif()
# GCC 12's induction-variable pass can make later passes drop a store as a null dereference
# (it zeroed the logistic likelihood terms of model/space/triplet_block.hpp).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  add_compile_options(-fno-ivopts)
endif()
if(NIBRIG_WERROR)
  add_compile_options(-Werror)
endif()
if(NIBRIG_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  # In a batch every .cpp is an included file, so GCC takes a source's private helper held by its
  # own class for a header's; built one file at a time the warning stays on.
  add_compile_options(-Wno-subobject-linkage)
endif()
if(NIBRIG_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  # GCC's -Wmaybe-uninitialized fires inside instrumented libstdc++ (std::regex, std::function).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
  # Eigen's plain-malloc path, as in Release: libgmsh.so's Eigen code uses it, and memory one side
  # allocates the other may free (ASan's malloc already aligns to 16 bytes).
  add_compile_definitions(EIGEN_MALLOC_ALREADY_ALIGNED=1)
  add_link_options(-fsanitize=address,undefined)
endif()

# LeakSanitizer alone, without instrumentation, for the tree that is not sanitized.
function(nibrig_leak_check target)
  if(NIBRIG_LEAK_CHECK AND NOT NIBRIG_SANITIZE)
    target_link_options(${target} PRIVATE -fsanitize=leak)
  endif()
endfunction()
