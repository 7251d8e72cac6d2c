#!/usr/bin/env bash
# The 1M-sphere case of issue 12: 100 × 100 × 100 spheres made by a loop (the loop file of
# benches/literal_spheres.py at 1M), `rtc check` (parse, evaluate, lint, prepare: BVH included)
# and a 640×480 render with one light and shadows, each the median of RUNS runs of
# /usr/bin/time (wall, user + system CPU, peak RSS), then the front end alone (parse + evaluate,
# no preparation) through `cargo bench --bench eval -- FILE`.
#
# The spheres are written with `center:` by default; `translate` writes each as
# `sphere(radius: r).translate(p)` and `scale` as `sphere().scale(r).translate(p)` (issue 42
# item 4: the same spheres must take the same memory however they are written).
#
#   benches/million.sh            # RUNS=5 by default
#   benches/million.sh translate  # or: scale
#   RTC=/path/to/rtc benches/million.sh translate   # another build (no cargo build, no
#                                                   # front-end bench)
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/bench-1m
mkdir -p "$out"
spelling="${1:-center}"
case "$spelling" in
center) file=spheres_loop.rtc ;;
translate) file=spheres_translate.rtc ;;
scale) file=spheres_scale.rtc ;;
*) echo "usage: benches/million.sh [center|translate|scale]" >&2; exit 2 ;;
esac
python3 benches/literal_spheres.py "$out/all" 100 100 100 >/dev/null
mv "$out/all/$file" "$out/spheres_loop.rtc"
rm -r "$out/all" # the literal twins of 1M spheres (85 MB) are not needed here
if [ -z "${RTC:-}" ]; then
    cargo build --release -q
fi
rtc=${RTC:-$PWD/target/release/rtc}
runs="${RUNS:-5}"
echo "spelling: $spelling; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
median() {
    for _ in $(seq "$runs"); do
        /usr/bin/time -f "%e %U %S %M" "$@" 2>&1 >/dev/null | tail -1
    done | python3 -c '
import statistics as s, sys
r = [l.split() for l in sys.stdin if l.strip()]
wall = s.median(float(x[0]) for x in r)
cpu = s.median(float(x[1]) + float(x[2]) for x in r)
rss = s.median(int(x[3]) for x in r) / 1024
print(f"wall {wall:.2f} s, CPU {cpu:.2f} s, peak RSS {rss:.0f} MiB (medians of {len(r)})")'
}
echo -n "rtc check 1M: "
median "$rtc" check "$out/spheres_loop.rtc"
echo -n "rtc render 1M 640x480: "
median "$rtc" render "$out/spheres_loop.rtc" -o "$out/loop.png"
"$rtc" render --stats "$out/spheres_loop.rtc" -o "$out/loop.png" 2>&1 | tail -12
if [ -z "${RTC:-}" ]; then
    cargo bench -q --bench eval -- "$out/spheres_loop.rtc"
fi
