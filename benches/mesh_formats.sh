#!/usr/bin/env bash
# Mesh formats (issue 38): a 1M-triangle mesh written as binary PLY loads to the first ray at
# least as fast as the same mesh in OBJ. benches/mesh_formats.py writes a latitude/longitude
# sphere of about SIZE triangles (default 1,000,000) as OBJ, binary PLY and binary STL into
# /tmp (nothing large is committed); each is rendered at 32×24
# with `--stats` and the median "first ray at" of RUNS runs (default 5) is printed per format,
# all measured in one run of this script, alternating the formats so load changes hit all.
#
#   benches/mesh_formats.sh                # 1M triangles, 5 runs each
#   SIZE=200000 RUNS=3 benches/mesh_formats.sh
#   RTC_BIN=/path/to/rtc benches/mesh_formats.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out="${TMPDIR:-/tmp}/rtc-mesh-formats"
mkdir -p "$out"
# RTC_BIN: an rtc binary already built (no cargo build).
[ -n "${RTC_BIN:-}" ] || cargo build --release -q
rtc=${RTC_BIN:-$PWD/target/release/rtc}
size="${SIZE:-1000000}"
runs="${RUNS:-5}"
python3 benches/mesh_formats.py "$size" "$out/sphere"
for f in obj ply stl; do
    cat >"$out/$f.rtc" <<RTC
rtc 1
camera { eye: [0, 0, 4], center: [0, 0, 0], fov: 45deg, resolution: [32, 24] }
point_light { position: [5, 5, 5] }
mesh(path: "sphere.$f").material(material { color: rgb(0.8, 0.3, 0.2) })
render { supersampling: 1, max_depth: 0 }
RTC
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores"
ls -l "$out"/sphere.*
for _ in $(seq "$runs"); do
    for f in obj ply stl; do
        t=$("$rtc" render --stats "$out/$f.rtc" -o "$out/$f.png" 2>&1 >/dev/null \
            | sed -n 's/.*first ray at \([0-9.]*\) s.*/\1/p')
        echo "$f $t"
    done
done | python3 -c '
import statistics as s, sys
times = {}
for line in sys.stdin:
    f, t = line.split()
    times.setdefault(f, []).append(float(t))
for f, ts in times.items():
    shown = " ".join("%.3f" % t for t in ts)
    print(f"{f}: first ray at {s.median(ts):.3f} s (median of {len(ts)}: {shown})")
obj, ply = s.median(times["obj"]), s.median(times["ply"])
print(f"PLY / OBJ = {ply / obj:.2f}", "(PLY at least as fast: met)" if ply <= obj else "(PLY slower: missed)")
'
cmp "$out/obj.png" "$out/ply.png" && cmp "$out/obj.png" "$out/stl.png" && echo "images identical"
