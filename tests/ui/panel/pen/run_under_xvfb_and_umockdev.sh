#!/bin/sh
# The pad's pen tests need a display and an emulated tablet: a private X server (run_under_xvfb.sh)
# around umockdev's preload with the input shim (rig/pen/run_under_umockdev.sh; $1 is the shim), in
# that order, so that the X server itself does not run with umockdev's /dev and /sys.
here=$(dirname "$0")
exec /bin/sh "$here/../run_under_xvfb.sh" /bin/sh "$here/../../../rig/pen/run_under_umockdev.sh" "$@"
