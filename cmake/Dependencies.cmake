# Third-party libraries, all from Debian's packages (setup.sh installs them).
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(spdlog REQUIRED)
find_package(ZLIB REQUIRED)
find_package(Threads REQUIRED)
find_package(Boost 1.74 REQUIRED)  # header-only: Boost.Math distributions (p-values)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
pkg_check_modules(SNDFILE REQUIRED IMPORTED_TARGET sndfile)
# RtAudio 5.2 with its JACK, ALSA and PulseAudio back ends; libjack itself only for the tests'
# loopback clients (playback/ talks to devices through RtAudio alone).
pkg_check_modules(RTAUDIO REQUIRED IMPORTED_TARGET rtaudio)
pkg_check_modules(JACK REQUIRED IMPORTED_TARGET jack)
pkg_check_modules(ALSA REQUIRED IMPORTED_TARGET alsa)  # only to quiet alsa-lib's stderr
# The rig's USB controller (rig/usb) talks libusb 1.0.26 (Debian 12: no libusb_init_context); its tests
# emulate the device in-process with umockdev, which nothing but those tests links.
pkg_check_modules(LIBUSB REQUIRED IMPORTED_TARGET libusb-1.0)
# Pen tablets: libinput reads them (through udev), libwacom names them and gives their size.
pkg_check_modules(LIBINPUT REQUIRED IMPORTED_TARGET libinput libudev libwacom)
# A design's stylus as a 3MF file (model/mesh_io/stylus_3mf): lib3mf 1.8's C interface.
pkg_check_modules(LIB3MF REQUIRED IMPORTED_TARGET lib3MF)
if(NIBRIG_BUILD_TESTS)
  pkg_check_modules(UMOCKDEV REQUIRED IMPORTED_TARGET umockdev-1.0)
endif()
# The firmware's tests run its ELF on simavr's ATmega32U4 (libsimavr 1.6, which needs libelf).
if(NIBRIG_BUILD_TESTS AND NIBRIG_BUILD_FIRMWARE)
  pkg_check_modules(SIMAVR REQUIRED IMPORTED_TARGET simavr)
endif()
pkg_check_modules(PLPLOT REQUIRED IMPORTED_TARGET plplot plplot-c++)
find_package(Spectra 1.0 REQUIRED PATHS /usr/share/spectra/cmake)
# Gmsh ships only a header and a shared library in Debian (no CMake or pkg-config file).
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
add_library(nibrig_gmsh INTERFACE)
target_include_directories(nibrig_gmsh SYSTEM INTERFACE ${GMSH_INCLUDE_DIR})
target_link_libraries(nibrig_gmsh INTERFACE ${GMSH_LIBRARY})
# The panel (ui/panel): Dear ImGui 1.86, whose static library already holds the GLFW and OpenGL 3
# back ends, a GLFW 3.3 window, and stb_image_write (compiled into libstb) for its screenshots.
if(NIBRIG_BUILD_PANEL)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
  find_package(glfw3 3.3 REQUIRED)
  find_package(OpenGL REQUIRED)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
endif()
