#!/bin/bash
# Does adaptive sampling pay? (issue 9, item 4; docs/convergence.md has the results.)
# For each scene: a 16×16 reference, uniform 4×4, and adaptive / progressive settings; per setting
# the mean user CPU seconds of single-threaded renders (mean of RUNS runs; the machine
# is shared, so CPU time, not wall time), the rays of --stats, and the error against the reference
# from examples/image_error.rs (mean ꟻLIP, worst-1% ꟻLIP, RMSE, relMSE).
#
#   benches/adaptive.sh [five_spheres|showcase|all] [RUNS]      (default: all 3)
#
# showcase is rendered at 320×180 (mesh path made absolute, output line dropped). Settings:
#   uN          supersampling: N (the scene's light sampling)
#   uN-spread   the same with spread_light_samples: true
#   aMIN-MAX-T  supersampling: adaptive(min: MIN, max: MAX, threshold: T), spread lights
#   pE          rtc render --target-error E (progressive), spread lights
# Work files go to ${WORK:-/tmp/rtc-adaptive} (the reference is kept there between runs).
set -euo pipefail
R=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
WHICH=${1:-all}
RUNS=${2:-3}
WORK=${WORK:-/tmp/rtc-adaptive}
mkdir -p "$WORK"
[ -n "${NO_BUILD:-}" ] || cargo build --release --quiet --manifest-path "$R/Cargo.toml" --bin rtc --example image_error
RTC=$R/target/release/rtc
ERR=$R/target/release/examples/image_error

# variant BASE NAME SAMPLING SPREAD: writes $WORK/NAME.rtc
variant() {
  local base=$1 name=$2 ss=$3 spread=$4 out=$WORK/$2.rtc
  if [ "$base" = showcase ]; then
    sed -e "s#\.\./tests/data#$R/tests/data#" -e "s#resolution: \[1280, 720\]#resolution: [320, 180]#" \
        -e "s#supersampling: adaptive(min: 1, max: 16, threshold: 0.02)#supersampling: $ss\n  spread_light_samples: $spread#" \
        -e '/output:/d' "$R/scenes/showcase.rtc" > "$out"
  else
    sed -e "s#supersampling: 4#supersampling: $ss, spread_light_samples: $spread#" \
        "$R/scenes/five_spheres.rtc" > "$out"
  fi
  grep -q "supersampling: $ss" "$out" || { echo "failed to make $name" >&2; exit 1; }
}

# cpu NAME ARGS...: renders RUNS times single-threaded; prints the mean user seconds and the rays.
cpu() {
  local name=$1; shift
  local total=0
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -f "%U" -o "$WORK/$name.time" "$RTC" render "$WORK/$name.rtc" \
      -o "$WORK/$name.png" --threads 1 --stats "$@" 2> "$WORK/$name.stats" >/dev/null
    total=$(echo "$total + $(cat "$WORK/$name.time")" | bc -l)
  done
  local rays
  rays=$(grep -o 'stats: [0-9]* rays' "$WORK/$name.stats" | grep -o '[0-9]*')
  printf "%s\t%.3f\t%s\n" "$name" "$(echo "$total / $RUNS" | bc -l)" "$rays"
}

scene() {
  local base=$1; shift
  echo "== $base (RUNS=$RUNS)"
  if [ ! -f "$WORK/${base}_u16.png" ]; then
    variant "$base" "${base}_u16" 16 true
    "$RTC" render "$WORK/${base}_u16.rtc" -o "$WORK/${base}_u16.png" 2>/dev/null
  fi
  local names=()
  variant "$base" "${base}_u4" 4 false; names+=("${base}_u4")
  variant "$base" "${base}_u4-spread" 4 true; names+=("${base}_u4-spread")
  for a in "$@"; do
    case $a in
      a*) IFS=- read -r min max t <<< "${a#a}"
          variant "$base" "${base}_$a" "adaptive(min: $min, max: $max, threshold: $t)" true ;;
      p*) variant "$base" "${base}_$a" 1 true ;;
    esac
    names+=("${base}_$a")
  done
  echo -e "setting\tcpu_s\trays"
  for n in "${names[@]}"; do
    case $n in
      *_p*) cpu "$n" --target-error "${n##*_p}" --samples-to "$WORK/$n.samples" ;;
      *) cpu "$n" ;;
    esac
  done
  "$ERR" "$WORK/${base}_u16.png" $(printf "$WORK/%s.png " "${names[@]}")
}

case $WHICH in
  five_spheres|all) scene five_spheres a1-4-0.02 a1-4-0.01 a1-5-0.05 a1-5-0.1 ;;&
  showcase|all) scene showcase a2-4-0.02 a2-5-0.02 a2-6-0.02 a1-4-0.02 p0.006 p0.008 ;;
esac
