#!/bin/bash
# Makes the study's scene variants in the current folder (docs/accuracy-study.md).
#   variants.sh BASE NAME SAMPLING [SEED]        BASE = showcase | five_spheres
#   variants.sh --edit SRC NAME EDIT...          EDIT = light1 | light2 | point | nodof
# showcase variants are 320×180 with the mesh path made absolute; SAMPLING is the text of
# `supersampling:` (e.g. 4 or "adaptive(min: 2, max: 4, threshold: 0.02)").
R=${RTC_REPO:-$(git -C "$(dirname "$0")" rev-parse --show-toplevel)}
if [ "$1" = --edit ]; then
  src=$2 name=$3; shift 3
  cp "$src.rtc" "$name.rtc"
  for t in "$@"; do case $t in
    light1) sed -i 's/samples: \[4, 4\]/samples: [1, 1]/' "$name.rtc" ;;
    light2) sed -i 's/samples: \[4, 4\]/samples: [2, 2]/' "$name.rtc" ;;
    point) sed -i 's/^area_light  { corner: \[-2, 6, 2\], u: \[1, 0, 0\], v: \[0, 0, 1\], samples: \[4, 4\], color: rgb(0.4, 0.4, 0.5) }/point_light { position: [-1.5, 6, 2.5], color: rgb(0.4, 0.4, 0.5) }/' "$name.rtc" ;;
    nodof) sed -i 's/aperture: 0.03, /aperture: 0, /' "$name.rtc" ;;
  esac; done
  cmp -s "$src.rtc" "$name.rtc" && echo "unchanged: $name" >&2
  exit 0
fi
base=$1 name=$2 ss=$3 seed=${4:-0}
if [ "$base" = showcase ]; then
  sed -e "s#\.\./tests/data#$R/tests/data#" -e "s#resolution: \[1280, 720\]#resolution: [320, 180]#" \
      -e "s#supersampling: adaptive(min: 1, max: 16, threshold: 0.02)#supersampling: $ss\n  seed: $seed#" \
      -e '/output:/d' "$R/scenes/showcase.rtc" > "$name.rtc"
else
  sed -e "s#supersampling: 4#supersampling: $ss, seed: $seed#" "$R/scenes/five_spheres.rtc" > "$name.rtc"
fi
grep -q "supersampling: $ss" "$name.rtc" || echo "failed: $name" >&2
