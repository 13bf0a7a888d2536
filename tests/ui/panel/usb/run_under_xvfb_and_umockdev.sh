#!/bin/sh
# The rig view's USB tests need both a display and an emulated USB device: a private X server
# (run_under_xvfb.sh) around umockdev's preload (run_under_umockdev.sh), in that order, so that
# the X server itself does not run with umockdev's /dev and /sys.
here=$(dirname "$0")
exec /bin/sh "$here/../run_under_xvfb.sh" /bin/sh "$here/../../../rig/usb/run_under_umockdev.sh" "$@"
