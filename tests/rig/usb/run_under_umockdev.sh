#!/bin/sh
# Runs a USB test binary with umockdev's preload library (umockdev-wrapper). Under ASan the preload
# comes before ASan's runtime, which ASan's link-order check refuses; the check is turned off here,
# for these tests only, keeping whatever ASAN_OPTIONS the caller set.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
export ASAN_OPTIONS
exec /usr/bin/umockdev-wrapper "$@"
