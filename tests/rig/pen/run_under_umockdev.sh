#!/bin/sh
# Runs a pen test binary under umockdev's preload (as tests/rig/usb/run_under_umockdev.sh does), with the shim
# that gives umockdev udev's database and fstat on emulated nodes (umockdev_input_shim.c), preloaded
# from the build tree: $1 is the shim, the rest the command.
shim="$1"
shift
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
export ASAN_OPTIONS
# The shim first: umockdev's wrappers call libc directly, past anything preloaded after them.
LD_PRELOAD="$shim:libumockdev-preload.so.0${LD_PRELOAD:+:$LD_PRELOAD}"
export LD_PRELOAD
exec "$@"
