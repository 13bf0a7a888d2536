#!/bin/sh
# Runs a panel test binary on a private X server (Xvfb, Mesa's llvmpipe for OpenGL): the window
# tests open a real GLFW window. Each gets a display of its own, so tests may run in parallel. What the
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
# xvfb-run -a looks for a free display by its lock file, and two tests starting at once can both
# take the same one (the second then fails "Failed to open display :101"). With -displayfd the
# server claims a free number itself and writes it once it accepts clients.
number=$(mktemp)
trap 'kill "$server" 2>/dev/null; rm -f "$number"' EXIT
trap 'exit 130' INT TERM
/usr/bin/Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$number" 2>/dev/null &
server=$!
tries=0
until grep -q '^[0-9][0-9]*$' "$number" 2>/dev/null; do
  tries=$((tries + 1))
  if [ "$tries" -gt 200 ] || ! kill -0 "$server" 2>/dev/null; then
    echo "run_under_xvfb.sh: Xvfb did not start" >&2
    exit 1
  fi
  sleep 0.05
done
DISPLAY=":$(cat "$number")"
export DISPLAY
"$@"
