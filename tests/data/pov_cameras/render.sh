#!/usr/bin/env bash
# Renders every POV-Ray camera twin in this directory, NAME.pov -> NAME.png, the references
# that tests/pov_cameras.rs compares rtc's renders of NAME.rtc with (see README.md).
#
# Made with POV-Ray 3.7.0.10 (Debian's `povray` package), as
#
#   povray -D +WT1 +W<w> +H<h> -A +FN File_Gamma=sRGB +INAME.pov +ONAME.png
#
# where NAME.pov's second line, `// size <w> <h>`, gives the image size (the .rtc twin's
# `resolution`). -A: one ray per pixel through its centre; File_Gamma=sRGB as in
# ../pov_twins/render.sh. Each .pov sets `assumed_gamma 1.0 ambient_light 1` and
# `finish { ambient 1 diffuse 0 }`: a pixel is the pigment's linear colour.
#
# Usage: tests/data/pov_cameras/render.sh [NAME...]   (default: every NAME.pov here)
set -euo pipefail
cd "$(dirname "$0")"
command -v povray >/dev/null || { echo "render.sh: povray is not installed" >&2; exit 1; }
if [ $# -eq 0 ]; then
  set -- $(ls *.pov | sed 's/\.pov$//')
fi
for name in "$@"; do
  read -r _ _ w h < <(sed -n 2p "$name.pov")
  log=$(mktemp)
  if ! povray -D +WT1 "+W$w" "+H$h" -A +FN File_Gamma=sRGB "+I$name.pov" "+O$name.png" >"$log" 2>&1; then
    cat "$log" >&2
    rm -f "$log"
    echo "render.sh: povray failed on $name.pov" >&2
    exit 1
  fi
  rm -f "$log"
  echo "$name.png"
done
