#!/usr/bin/env bash
# Scaling of sharded renders on one machine (docs/scale-out.md): for N = 1, 2, 4, 8, 16 shards,
# every shard runs as its own process with one thread (as one task of a farm would), one after
# another, and the script prints the time to first ray (load + prepare, from --stats), the mean
# and slowest shard's time and the sum over shards, then fits total = setup·N + work. Shard
# times are CPU seconds (user + system of the one-thread process): on an idle machine that is
# its wall time, and on a busy one it is still the work the shard costs.
#
# Usage: benches/shards.sh [RTC_BINARY]   (default target/release/rtc; run from the repo root)
# The bunny needs /work/shared/models (or RTC_ASSET_PATH) and is skipped with a message without it.
set -euo pipefail
cd "$(dirname "$0")/.."
rtc=$(realpath "${1:-target/release/rtc}")
tmp=$(mktemp -d /tmp/rtc-shards-bench.XXXXXX)
# The heavy scene's copy sits beside the original so its relative mesh path still resolves.
heavy=scenes/.showcase_320.bench.rtc
trap 'rm -rf "$tmp" "$heavy"' EXIT
export RTC_ASSET_PATH=${RTC_ASSET_PATH:-/work/shared/models}

# The heavy distributed-effects scene: the showcase (area light 4×4, depth of field, adaptive
# up to 16×16) at 320×180 so the bench takes minutes, not hours.
sed 's/resolution: \[1280, 720\]/resolution: [320, 180]/' scenes/showcase.rtc >"$heavy"

scenes=("scenes/five_spheres.rtc" "$heavy")
if [ -f "$RTC_ASSET_PATH/stanford-bunny.obj" ]; then
  scenes+=("scenes/bench/bunny.rtc")
else
  echo "shards.sh: skipping the bunny: stanford-bunny.obj not found in RTC_ASSET_PATH=$RTC_ASSET_PATH" >&2
fi

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .rtc | tr -d .)
  first=$("$rtc" render "$scene" --threads 1 --stats -o "$tmp/$name.png" 2>&1 >/dev/null \
    | sed -n 's/.*first ray at \([0-9.]*\) s.*/\1/p')
  echo "== $name: time to first ray ${first:-?} s (load + prepare, one process)"
  printf '%6s %10s %10s %10s\n' N mean_s max_s total_s
  fit=""
  for n in 1 2 4 8 16; do
    sum=0; max=0
    for k in $(seq 0 $((n - 1))); do
      /usr/bin/time -f '%U %S' -o "$tmp/time" \
        "$rtc" render "$scene" --threads 1 --shard "$k/$n" -o "$tmp/$name.$k.rtcpart" 2>/dev/null
      t=$(awk '{print $1 + $2}' "$tmp/time")
      sum=$(echo "$sum + $t" | bc); max=$(echo "if ($t > $max) $t else $max" | bc)
    done
    "$rtc" merge "$tmp"/"$name".*.rtcpart -o "$tmp/$name.merged.png" 2>/dev/null
    cmp -s "$tmp/$name.png" "$tmp/$name.merged.png" || { echo "MERGED DIFFERS for $name, N=$n" >&2; exit 1; }
    rm -f "$tmp"/"$name".*.rtcpart
    printf '%6d %10.3f %10.3f %10.3f\n' "$n" "$(echo "$sum / $n" | bc -l)" "$max" "$sum"
    fit="$fit $n $sum"
  done
  # Least squares of total = setup·N + work over the five points.
  echo "$fit" | awk '{ for (i = 1; i <= NF; i += 2) { n = $i; t = $(i+1); sn += n; st += t; snn += n*n; snt += n*t; m++ }
    setup = (m*snt - sn*st) / (m*snn - sn*sn); work = (st - setup*sn) / m;
    printf "fit: setup %.4f s per shard, work %.3f s; splitting stops paying (efficiency 50%%) at N = %.0f\n", setup, work, (setup > 0 ? work/setup : 1e9) }'
done
