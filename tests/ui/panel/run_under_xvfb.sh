#!/bin/sh
# Runs a panel test binary on a private X server (Xvfb, Mesa's llvmpipe for OpenGL): the window
# tests open a real GLFW window. -a picks a free display, so suites may run in parallel. What the
# panel keeps between runs (its cached defaults, its settings, the rig's sessions) goes into the
# tests' scratch folder, never into the user's home.
scratch="$PWD/scratch/panel_home"
export NIBRIG_CACHE="$scratch/cache"
export NIBRIG_PANEL_SETTINGS="$scratch/panel.json"
export XDG_DATA_HOME="$scratch/data"
# LeakSanitizer is off here: every test that opens a window (and the panel executable they run)
# ends with one 128-byte block reallocated inside libpulse (reached through librtaudio, seen with
# LSan preloaded on the Release build) that the sanitizer build can only report as "<unknown
# module>", which no suppression can name. The headless tests share this binary. ASan's other
# checks stay on; the libraries the panel calls keep their leak checks in their own suites.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
export ASAN_OPTIONS
exec /usr/bin/xvfb-run -a -s "-screen 0 1280x800x24" "$@"
