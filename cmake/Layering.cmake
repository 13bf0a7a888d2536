# Enforces the module layering of ARCHITECTURE.md at configure time: a module may include and link only
# the modules below it. Linking is checked by CMake itself (targets only link downward); includes are
# checked here because the include root is the repository root and a header-only upward include
# would otherwise slip through. An allowed entry is a folder: "model" allows all of model/,
# "model/io" only that submodule (model/'s own order is checked part by part in model/CMakeLists.txt).
#   model    -> (nothing of ours)
#   rt       -> model/numeric, model/io, model/modal (what a voice needs; never the FEM)
#   playback -> rt and what rt uses
#   rig      -> playback, rt, model but model/study (the rig plays its simulation through playback's
#               prepared engine; it knows no study)
#   rig/study -> rig and what it uses, model/study: a study's start and presenters, on the rig
#   ui       -> everything; ui/report -> nothing but itself (a leaf, checked in ui/CMakeLists.txt)

# Fails the configure when a file below `folder` includes one of our headers outside the folders
# named after it. `folder` and the allowed folders are relative to the repository root; EXCEPT names
# subfolders of `folder` that are checked as layers of their own.
function(nibrig_check_includes folder)
  cmake_parse_arguments(ARG "" "" "EXCEPT" ${ARGN})
  set(allowed ${ARG_UNPARSED_ARGUMENTS})
  file(GLOB_RECURSE files CONFIGURE_DEPENDS
       "${CMAKE_SOURCE_DIR}/${folder}/*.hpp" "${CMAKE_SOURCE_DIR}/${folder}/*.cpp")
  foreach(sub IN LISTS ARG_EXCEPT)
    list(FILTER files EXCLUDE REGEX "/${folder}/${sub}/")
  endforeach()
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"(model|rt|playback|rig|ui)/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" included "${line}")
      set(ok FALSE)
      foreach(root IN LISTS allowed)
        string(FIND "${included}" "${root}/" at)
        if(at EQUAL 0)
          set(ok TRUE)
        endif()
      endforeach()
      if(NOT ok)
        file(RELATIVE_PATH shown "${CMAKE_SOURCE_DIR}" "${file}")
        list(JOIN allowed ", " allowed_text)
        message(FATAL_ERROR "Layering violation: ${shown} includes ${included}, "
                            "but ${folder}/ may only use: ${allowed_text}")
      endif()
    endforeach()
  endforeach()
endfunction()

function(nibrig_check_layering module)
  set(allowed_model "model")
  set(allowed_rt "model/numeric;model/io;model/modal;rt")
  set(allowed_playback "model/numeric;model/io;model/modal;rt;playback")
  set(allowed_rig "model/numeric;model/io;model/mesh_io;model/measure;model/space;model/modal;model/mechanics"
                  "model/catalog;model/forcing;model/design;rt;playback;rig")
  set(except_rig "study")
  set(allowed_ui "model;rt;playback;rig;ui")
  nibrig_check_includes(${module} ${allowed_${module}} EXCEPT ${except_${module}})
endfunction()

# Headers are included by their path from the source root ("rt/engine.hpp"); installed, the same
# paths lie under include/nibrig (cmake/Export.cmake).
function(nibrig_source_includes name scope)
  target_include_directories(${name} ${scope} $<BUILD_INTERFACE:${CMAKE_SOURCE_DIR}>
                                              $<INSTALL_INTERFACE:include/nibrig>)
endfunction()

# Adds the library of a module from every .cpp below its folder. Modules without sources yet are
# interface targets so that the dependency graph already has its final shape.
function(nibrig_module_library name module)
  cmake_parse_arguments(ARG "" "" "DEPENDS;EXCEPT" ${ARGN})
  nibrig_check_layering(${module})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/${module}/*.cpp")
  list(FILTER sources EXCLUDE REGEX "/ui/cli/main\\.cpp$")
  foreach(sub IN LISTS ARG_EXCEPT)  # a layer of its own above the module's
    list(FILTER sources EXCLUDE REGEX "/${module}/${sub}/")
  endforeach()
  if(sources)
    add_library(${name} STATIC ${sources})
    nibrig_source_includes(${name} PUBLIC)
    target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
  else()
    add_library(${name} INTERFACE)
    nibrig_source_includes(${name} INTERFACE)
    target_link_libraries(${name} INTERFACE ${ARG_DEPENDS})
  endif()
endfunction()
