# `cmake --install`: the programs, the bundled assets and the defaults the build computed, the
# manual pages and bash completion the command writes from its own parser, the Python package, the
# panel's desktop entry and icon, and the rig's udev rule, in the GNU install directories. An installed program finds its assets and
# defaults in <prefix>/share/nibrig beside its bin/ (model/io/bundled_assets.hpp), from any folder.
include(GNUInstallDirs)

set(NIBRIG_INSTALL_SHARE "${CMAKE_INSTALL_DATADIR}/nibrig")
if(TARGET nibrig)
  install(TARGETS nibrig RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT command)
  # The README's pictures are not the program's.
  install(DIRECTORY "${CMAKE_SOURCE_DIR}/assets/" DESTINATION "${NIBRIG_INSTALL_SHARE}/assets"
          COMPONENT command PATTERN "readme" EXCLUDE)
endif()
if(TARGET nibrig_docs_pages)
  install(DIRECTORY "${NIBRIG_MAN_DIR}/" DESTINATION "${CMAKE_INSTALL_MANDIR}/man1" COMPONENT command
          FILES_MATCHING PATTERN "*.1")
  install(FILES "${NIBRIG_COMPLETION}" DESTINATION "${CMAKE_INSTALL_DATADIR}/bash-completion/completions"
          RENAME nibrig COMPONENT command)
endif()
# Where Debian's python3 finds packages of the prefix (/usr/lib/python3/dist-packages).
if(TARGET nibrig_python)
  install(DIRECTORY "${CMAKE_BINARY_DIR}/python/nibrig" DESTINATION "lib/python3/dist-packages" COMPONENT python
          PATTERN "__pycache__" EXCLUDE)
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
