#!/bin/sh
# Runs a panel test binary on a private X server (Xvfb, Mesa's llvmpipe for OpenGL): the window
# tests open a real GLFW window. -a picks a free display, so suites may run in parallel.
exec /usr/bin/xvfb-run -a -s "-screen 0 1280x800x24" "$@"
