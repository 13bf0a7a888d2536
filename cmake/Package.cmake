# `cpack` (`./setup.sh package`): the install components (Install.cmake) as three Debian packages,
# split as a user installs them: nibrig (the command, its data, manual pages, udev rule), nibrig-panel
# and python3-nibrig. What each links comes from the binaries (dpkg-shlibdeps), never typed here.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME nibrig)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_CONTACT "nibrig maintainers <maintainers@users.noreply.h-seed-65287427.example>")
# Where `cpack` writes the .deb files (and its staging folder), unless given -B.
set(CPACK_PACKAGE_DIRECTORY "${CMAKE_BINARY_DIR}/packages")
# Stripped as Debian's own packages are: the symbols stay in the build tree.
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL command)
if(TARGET nibrig-panel)
  list(APPEND CPACK_COMPONENTS_ALL panel)
endif()
if(TARGET nibrig_python)
  list(APPEND CPACK_COMPONENTS_ALL python)
endif()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_COMMAND_PACKAGE_NAME nibrig)
set(CPACK_DEBIAN_PANEL_PACKAGE_NAME nibrig-panel)
set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-nibrig)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
# PLplot loads its PNG device as a plugin (dlopen), which shlibdeps cannot see in the binary: without
# it every report's figures fail (the clean root's `nibrig demo` said so).
set(CPACK_DEBIAN_COMMAND_PACKAGE_DEPENDS "plplot-driver-cairo")
# What shlibdeps cannot see in the module: it is built for one CPython, the one its file name says
# (cpython-311 on Debian 12), and it imports numpy, whose arrays it takes and returns (pybind11 finds
# numpy at run time, so no numpy ABI is linked).
if(TARGET nibrig_python)
  get_target_property(nibrig_python_suffix nibrig_python SUFFIX)
  if(NOT nibrig_python_suffix MATCHES "cpython-3([0-9]+)")
    message(FATAL_ERROR "Package.cmake: expected the module's file name to say its CPython "
                        "(like .cpython-311-x86_64-linux-gnu.so), got '${nibrig_python_suffix}'")
  endif()
  math(EXPR nibrig_python_next "${CMAKE_MATCH_1} + 1")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "python3 (>= 3.${CMAKE_MATCH_1}~), python3 (<< 3.${nibrig_python_next}), python3-numpy")
endif()

set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)  # the DEPENDS of cpack_add_component below

include(CPack)
# The panel and the module read the command's bundled assets and defaults in /usr/share/nibrig:
# each depends on the nibrig package of its own version (CPack writes "nibrig (= <version>)").
# Each description's first line is the package's synopsis.
cpack_add_component(command DISPLAY_NAME "nibrig" DESCRIPTION
  "measure, model, design and play the vibrations of drawing tools
nibrig models how a digital drawing tool (a stylus on a tablet's surface) feels
through its vibrations, designs styli that feel like a chosen tool, and plays
tools live on an actuator or a turntable rig. This package holds the nibrig
command with its bundled catalog, materials and styli, the defaults computed
when it was built, its manual pages, bash completion and the rig's udev rule.")
cpack_add_component(panel DISPLAY_NAME "nibrig-panel" DEPENDS command DESCRIPTION
  "window to browse, design and play drawing tools with nibrig
nibrig-panel shows the perceptual space of drawing tools, predicted designs,
the turntable rig's spectrograms and a pad to draw on, over the same model as
the nibrig command (ImGui, GLFW, OpenGL 3).")
cpack_add_component(python DISPLAY_NAME "python3-nibrig" DEPENDS command DESCRIPTION
  "Python 3 module of nibrig (import nibrig)
The calls of the nibrig command and panel for scripts and notebooks: measure,
space, design, render, audition, rig and study, with numpy arrays in and out.")

# What Debian's policy asks of every package: its copyright and, as a native package, a changelog
# (gzip -9n), in /usr/share/doc/<package>. The changelog says which version this is; what changed
# is the project's git history.
string(TIMESTAMP nibrig_package_date "%a, %d %b %Y %H:%M:%S +0000" UTC)  # honours SOURCE_DATE_EPOCH
set(nibrig_changelog "${CMAKE_BINARY_DIR}/package/changelog")
file(WRITE "${nibrig_changelog}"
  "nibrig (${PROJECT_VERSION}) bookworm; urgency=medium\n\n"
  "  * nibrig ${PROJECT_VERSION}, packaged with CPack from the nibrig sources; the\n"
  "    changes are the project's git history.\n\n"
  " -- ${CPACK_PACKAGE_CONTACT}  ${nibrig_package_date}\n")
execute_process(COMMAND gzip -9nf "${nibrig_changelog}" COMMAND_ERROR_IS_FATAL ANY)
foreach(component IN LISTS CPACK_COMPONENTS_ALL)
  string(TOUPPER "${component}" upper)
  set(doc "${CMAKE_INSTALL_DATADIR}/doc/${CPACK_DEBIAN_${upper}_PACKAGE_NAME}")
  install(FILES "${CMAKE_SOURCE_DIR}/ui/package/copyright" "${nibrig_changelog}.gz"
          DESTINATION "${doc}" COMPONENT ${component})
endforeach()
