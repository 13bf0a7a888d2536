# `cmake --install`: the programs, the bundled assets and the defaults the build computed, the
# manual pages and bash completion the command writes from its own parser, the Python package, the
# panel's desktop entry and icon, and the rig's udev rule, in the GNU install directories. An
# installed program finds its assets and defaults in <prefix>/share/nibrig beside its bin/
# (model/io/bundled_assets.hpp), from any folder.
include(GNUInstallDirs)

set(NIBRIG_INSTALL_SHARE "${CMAKE_INSTALL_DATADIR}/nibrig")
if(TARGET nibrig)
  # The tests' tree links LeakSanitizer into `nibrig` (NIBRIG_LEAK_CHECK), which a user's must not
  # have: there the command is linked again without it, from the same objects, and that one is
  # installed, so that `cmake --install` and the packages of any tree hold the command a user builds.
  set(nibrig_installed nibrig)
  if(NIBRIG_LEAK_CHECK AND NOT NIBRIG_SANITIZE)
    add_executable(nibrig_installed "${CMAKE_SOURCE_DIR}/ui/cli/main.cpp")
    target_link_libraries(nibrig_installed PRIVATE nibrig_cli)
    set_target_properties(nibrig_installed PROPERTIES OUTPUT_NAME nibrig
      RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/installed-command")
    set(nibrig_installed nibrig_installed)
  endif()
  install(TARGETS ${nibrig_installed} RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT command)
  # The README's pictures are not the program's.
  install(DIRECTORY "${CMAKE_SOURCE_DIR}/assets/" DESTINATION "${NIBRIG_INSTALL_SHARE}/assets"
          COMPONENT command PATTERN "readme" EXCLUDE)
endif()
if(TARGET nibrig_docs_pages)
  # The manual pages installed as Debian's policy has them and man reads them: gzip -9, no name or
  # time stamp in the header, so the same pages make the same files.
  set(man_gz "${CMAKE_BINARY_DIR}/docs/man-gz")
  add_custom_command(OUTPUT "${man_gz}/nibrig.1.gz"
    COMMAND "${CMAKE_COMMAND}" -E rm -rf "${man_gz}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${man_gz}"
    COMMAND sh -c [[for page in "$0"/*.1; do gzip -9n -c "$page" >"$1/${page##*/}.gz" || exit 1; done]]
            "${NIBRIG_MAN_DIR}" "${man_gz}"
    DEPENDS "${NIBRIG_MAN_DIR}/nibrig.1" nibrig_docs_pages
    COMMENT "Compressing the manual pages"
    VERBATIM)
  add_custom_target(nibrig_man_gz ALL DEPENDS "${man_gz}/nibrig.1.gz")
  install(DIRECTORY "${man_gz}/" DESTINATION "${CMAKE_INSTALL_MANDIR}/man1" COMPONENT command
          FILES_MATCHING PATTERN "*.1.gz")
  install(FILES "${NIBRIG_COMPLETION}" DESTINATION "${CMAKE_INSTALL_DATADIR}/bash-completion/completions"
          RENAME nibrig COMPONENT command)
endif()
# Where Debian's python3 finds packages of the prefix (/usr/lib/python3/dist-packages).
if(TARGET nibrig_python)
  # The compiled module as a target, so that an install that strips (the packages') strips it too.
  install(DIRECTORY "${CMAKE_BINARY_DIR}/python/nibrig" DESTINATION "lib/python3/dist-packages" COMPONENT python
          PATTERN "__pycache__" EXCLUDE PATTERN "_core*.so" EXCLUDE)
  install(TARGETS nibrig_python LIBRARY DESTINATION "lib/python3/dist-packages/nibrig" COMPONENT python)
endif()
if(TARGET nibrig-panel)
  install(TARGETS nibrig-panel RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT panel)
  # The desktop's menu entry and its icon, found by name (Icon=nibrig-panel) in the hicolor theme.
  install(FILES "${CMAKE_SOURCE_DIR}/ui/panel/nibrig-panel.desktop"
          DESTINATION "${CMAKE_INSTALL_DATADIR}/applications" COMPONENT panel)
  install(FILES "${CMAKE_SOURCE_DIR}/ui/panel/nibrig-panel.svg"
          DESTINATION "${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps" COMPONENT panel)
endif()
if(NIBRIG_SHIPPED_DEFAULTS)
  install(DIRECTORY "${NIBRIG_DEFAULTS_DIR}/" DESTINATION "${NIBRIG_INSTALL_SHARE}/defaults"
          COMPONENT command FILES_MATCHING PATTERN "*.json")
endif()
# The rig controller's firmware, for `nibrig rig flash` (rig/usb/firmware_flash.hpp).
if(NIBRIG_BUILD_FIRMWARE)
  install(FILES "${CMAKE_BINARY_DIR}/rig/firmware/nibrig-rig.hex" DESTINATION "${NIBRIG_INSTALL_SHARE}/firmware"
          COMPONENT command)
endif()
# udev reads packaged rules from /usr/lib/udev/rules.d (the prefix's lib/, never lib/<multiarch>).
install(FILES "${CMAKE_SOURCE_DIR}/rig/70-nibrig-rig.rules" DESTINATION "lib/udev/rules.d"
        COMPONENT command)
