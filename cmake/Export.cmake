# find_package(nibrig) for a program of one's own (tests/example_project is one): the engine,
# playback, the modal model and the rig driver as static libraries, with the model parts they link
# and their headers under include/nibrig, as targets nibrig::rt, nibrig::playback,
# nibrig::model_modal, nibrig::rig and so on. Component dev.
include(CMakePackageConfigHelpers)

# What the rig driver links reaches most of model/: each exported library's own links must be too.
set(nibrig_exported nibrig_model_numeric nibrig_model_io nibrig_model_mesh_io nibrig_model_measure
    nibrig_model_space nibrig_model_modal nibrig_model_mechanics nibrig_model_catalog
    nibrig_model_forcing nibrig_model_design nibrig_rt nibrig_playback nibrig_rig nibrig_gmsh)
foreach(target IN LISTS nibrig_exported)
  string(REGEX REPLACE "^nibrig_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
endforeach()
install(TARGETS ${nibrig_exported} EXPORT nibrigTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT dev)
foreach(folder rt playback rig model)
  install(DIRECTORY "${CMAKE_SOURCE_DIR}/${folder}/" DESTINATION "include/nibrig/${folder}"
          COMPONENT dev FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
endforeach()

set(NIBRIG_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/nibrig")
install(EXPORT nibrigTargets NAMESPACE nibrig:: DESTINATION "${NIBRIG_CMAKE_DIR}" COMPONENT dev)
configure_package_config_file("${CMAKE_SOURCE_DIR}/cmake/nibrigConfig.cmake.in"
                              "${CMAKE_BINARY_DIR}/nibrigConfig.cmake"
                              INSTALL_DESTINATION "${NIBRIG_CMAKE_DIR}")
# 0.x: a minor version may change the interfaces.
write_basic_package_version_file("${CMAKE_BINARY_DIR}/nibrigConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_BINARY_DIR}/nibrigConfig.cmake" "${CMAKE_BINARY_DIR}/nibrigConfigVersion.cmake"
        DESTINATION "${NIBRIG_CMAKE_DIR}" COMPONENT dev)
