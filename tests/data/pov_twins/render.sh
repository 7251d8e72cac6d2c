#!/usr/bin/env bash
# Renders every POV-Ray twin in this directory, NAME.pov -> NAME.png, the references that
# tests/pov_twins.rs compares rtc's renders of NAME.rtc with (see README.md).
#
# Made with POV-Ray 3.7.0.10 (Debian's `povray` package, "3.7.0.10.unofficial"), as
#
#   povray -D +WT1 +W160 +H120 -A +FN File_Gamma=sRGB +INAME.pov +ONAME.png
#
#   -D               no display window
#   +WT1             one render thread (the image does not depend on it without anti-aliasing)
#   +W160 +H120      every twin is 160 x 120 pixels (the .rtc twins say `resolution: [160, 120]`)
#   -A               no anti-aliasing: one ray per pixel, through the pixel's centre
#   +FN              PNG, 8 bits per channel (the default bit depth)
#   File_Gamma=sRGB  the sRGB curve on output, rounded to the nearest level: with
#                    `assumed_gamma 1.0` a linear 0.5 is written as 188, as rtc writes it
#                    (3.7's default for PNG already; spelled out so a changed povray.ini
#                    cannot move it). `gamma_ramp` checks this pixel by pixel.
#
# Each .pov sets `#version 3.7; global_settings { assumed_gamma 1.0 ambient_light 1 }` and
# `finish { ambient 1 diffuse 0 }`: the pixel is the pigment's linear colour, no light needed.
#
# Usage: tests/data/pov_twins/render.sh [NAME...]   (default: every NAME.pov here)
# POV-Ray is not needed to run the tests: the PNGs are committed. Re-render after changing a
# .pov file, or set RTC_POV_TWINS_RERENDER=1 when running tests/pov_twins.rs.
set -euo pipefail
cd "$(dirname "$0")"
command -v povray >/dev/null || { echo "render.sh: povray is not installed" >&2; exit 1; }
version=$(povray --version 2>&1 | grep -o 'POV-Ray 3\.[0-9.]*' | head -1)
case "$version" in
  "POV-Ray 3.7"*) ;;
  *) echo "render.sh: warning: made with POV-Ray 3.7.0.10, this is '$version'" >&2 ;;
esac
if [ $# -eq 0 ]; then
  set -- $(ls *.pov | sed 's/\.pov$//')
fi
for name in "$@"; do
  log=$(mktemp)
  if ! povray -D +WT1 +W160 +H120 -A +FN File_Gamma=sRGB "+I$name.pov" "+O$name.png" >"$log" 2>&1; then
    cat "$log" >&2
    rm -f "$log"
    echo "render.sh: povray failed on $name.pov" >&2
    exit 1
  fi
  rm -f "$log"
  echo "$name.png"
done
