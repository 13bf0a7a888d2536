#!/bin/sh
# Runs a panel test binary on a private X server (Xvfb, Mesa's llvmpipe for OpenGL): the window
# tests open a real GLFW window. -a picks a free display, so suites may run in parallel. What the
# panel keeps between runs (its cached defaults, its settings, the rig's sessions) goes into the
# tests' scratch folder, never into the user's home.
scratch="$PWD/scratch/panel_home"
export NIBRIG_CACHE="$scratch/cache"
export NIBRIG_PANEL_SETTINGS="$scratch/panel.json"
export XDG_DATA_HOME="$scratch/data"
exec /usr/bin/xvfb-run -a -s "-screen 0 1280x800x24" "$@"
