#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Prints a udev rule giving the connected serial device at <tty> the stable name
# /dev/<name>, keyed by its USB vendor, product and serial number (see doc/udev.md).
# Usage: scripts/udev_rule.sh /dev/ttyACM0 dwm1001_5722
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 <tty device, e.g. /dev/ttyUSB0> <symlink name, e.g. aoa_front>" >&2
  exit 2
fi
tty="$1"
name="$2"
# Module IDs are hex and the layout upper-cases them (robot.launch opens
# /dev/dwm1001_<ID> with the layout's ID): write the name the same way.
case "$name" in
  dwm1001_*)
    upper="dwm1001_$(printf '%s' "${name#dwm1001_}" | tr '[:lower:]' '[:upper:]')"
    if [ "$upper" != "$name" ]; then
      echo "note: module IDs are upper case in the layout and in robot.launch: using $upper" >&2
      name="$upper"
    fi
    ;;
esac
if [ ! -e "$tty" ]; then
  echo "$tty does not exist" >&2
  exit 1
fi
# `udevadm info -a` walks from the tty up its parents; the first USB device on the way
# (the one with idVendor) holds the IDs the rule must match.
info="$(udevadm info --attribute-walk --name="$tty")"
attr() {
  printf '%s\n' "$info" | sed -n "s/^ *ATTRS{$1}==\"\\(.*\\)\"\$/\\1/p" | head -n 1
}
vendor="$(attr idVendor)"
product="$(attr idProduct)"
serial="$(attr serial)"
if [ -z "$vendor" ] || [ -z "$product" ]; then
  echo "$tty is not a USB serial device (no idVendor/idProduct above it)" >&2
  exit 1
fi
if [ -z "$serial" ]; then
  echo "warning: $tty has no USB serial number; the rule will match any such device" >&2
  serial_match=""
else
  serial_match=", ATTRS{serial}==\"$serial\""
fi
case "$vendor:$product" in
  1366:0105) kind="DWM1001-DEV (SEGGER J-Link CDC)" ;;
  0403:6015) kind="FTDI FT-X (u-blox ANT-B10 / XPLR-AOA)" ;;
  *) kind="unknown device" ;;
esac
echo "# $kind at $tty"
echo "SUBSYSTEM==\"tty\", ATTRS{idVendor}==\"$vendor\", ATTRS{idProduct}==\"$product\"$serial_match, SYMLINK+=\"$name\", MODE=\"0660\", GROUP=\"dialout\", ENV{ID_MM_DEVICE_IGNORE}=\"1\""
