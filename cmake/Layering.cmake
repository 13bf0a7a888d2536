# Enforces the module layering of DESIGN.md at configure time: a module may include and link only
# the modules below it. Linking is checked by CMake itself (targets only link downward); includes are
# checked here because the include root is the repository root and a header-only upward include
# would otherwise slip through.
#   model    -> (nothing of ours)
#   rt       -> model
#   playback -> rt, model
#   rig      -> rt, model
#   ui       -> everything
function(nibrig_check_layering module)
  set(allowed_model "model")
  set(allowed_rt "model;rt")
  set(allowed_playback "model;rt;playback")
  set(allowed_rig "model;rt;rig")
  set(allowed_ui "model;rt;playback;rig;ui")
  set(allowed ${allowed_${module}})
  file(GLOB_RECURSE files CONFIGURE_DEPENDS
       "${CMAKE_SOURCE_DIR}/${module}/*.hpp" "${CMAKE_SOURCE_DIR}/${module}/*.cpp")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"(model|rt|playback|rig|ui)/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([a-z]+)/.*" "\\1" target_module "${line}")
      if(NOT target_module IN_LIST allowed)
        message(FATAL_ERROR "Layering violation: ${file} includes ${target_module}/, "
                            "but ${module}/ may only use: ${allowed}")
      endif()
    endforeach()
  endforeach()
endfunction()

# Adds the library of a module from every .cpp below its folder. Modules without sources yet are
# interface targets so that the dependency graph already has its final shape.
function(nibrig_module_library name module)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  nibrig_check_layering(${module})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/${module}/*.cpp")
  list(FILTER sources EXCLUDE REGEX "/ui/cli/main\\.cpp$")
  if(sources)
    add_library(${name} STATIC ${sources})
    target_include_directories(${name} PUBLIC ${CMAKE_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${CMAKE_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARG_DEPENDS})
  endif()
endfunction()
