#!/usr/bin/env bash
# Scaling curves (issue 12): render time and memory against object count and against resolution.
#
#  - objects: N spheres (10³ … 10⁶) on a jittered grid filling the same cube, radius ∝ N^(-1/3)
#    (the same fraction of the cube is solid at every N, so the image looks alike), one light,
#    shadows, 320×240, 1 sample per pixel. Measured per N: time to first ray (read, evaluate,
#    prepare, BVH) and the tracing time (render minus world build) and rays from `--stats`, peak
#    RSS from /usr/bin/time.
#  - resolution: the 10⁵-sphere scene at 160×120 … 1280×960 (render time should grow like pixels).
#  - meshes: a unit sphere tessellated into 10⁴ … 10⁷ triangles (benches/mesh_sphere.py writes the
#    OBJ files into target/bench-scaling; nothing large is committed), 320×240, one light with
#    shadows; the same measurements (MESH_MAX, default 10⁷, is the largest count; MESH_RUNS=2).
#
# Writes docs/images/scaling-objects.svg, scaling-resolution.svg and scaling-meshes.svg and prints
# the tables.
# Tracing time per ray should grow like log N for a BVH; the plot draws a log N reference line
# through the first point and the table gives the ratio measured/predicted.
#
#   benches/scaling.sh            # MAX=1000000 (largest N), RUNS=3
#   PARTS=meshes benches/scaling.sh   # one or more of: objects resolution meshes
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/bench-scaling
mkdir -p "$out"
cargo build --release -q
rtc=$PWD/target/release/rtc
runs="${RUNS:-3}"
max="${MAX:-1000000}"
scene() { # N WIDTH HEIGHT -> path
    local n=$1 w=$2 h=$3 f="$out/spheres_$1_$2.rtc"
    cat >"$f" <<RTC
rtc 1
// $n spheres filling the cube [-10, 10]^3 (benches/scaling.sh)
camera { eye: [0, 8, 34], center: [0, 0, 0], fov: 45deg, resolution: [$w, $h] }
point_light { position: [20, 40, 30] }
let m = material { color: rgb(0.8, 0.3, 0.2), ka: 0.2, kd: 0.7, ks: 0.3, n: 16 }
let side = ceil(pow($n, 1 / 3) - 1e-9)
let pitch = 20 / side
let r = pitch * 0.3
for i in 0..$n {
  let x = i % side
  let y = floor(i / side) % side
  let z = floor(i / (side * side))
  sphere(center: [x * pitch - 10 + r, y * pitch - 10 + r, z * pitch - 10 + r], radius: r).material(m)
}
render { shadows: true, max_depth: 0, supersampling: 1 }
RTC
    echo "$f"
}
measure() { # label file
    for _ in $(seq "$runs"); do
        /usr/bin/time -f "rss %M" "$rtc" render --stats "$2" -o "$out/x.png" 2>&1 >/dev/null \
            | grep -E "first ray at|^stats: render|^rss|rays =" | tr '\n' ' '
        echo
    done | python3 -c '
import re, statistics as s, sys
rows = []
for l in sys.stdin:
    f = re.search(r"first ray at ([0-9.]+) s", l); r = re.search(r"render ([0-9.]+) s", l)
    b = re.search(r"world built in ([0-9.]+) s", l)
    m = re.search(r"rss ([0-9]+)", l); n = re.search(r"([0-9]+) rays =", l)
    if f and r and m and n and b:
        # --stats counts the world build inside the render time: tracing is the rest.
        rows.append((float(f.group(1)), float(r.group(1)) - float(b.group(1)), int(m.group(1)), int(n.group(1))))
first = s.median(x[0] for x in rows); render = s.median(x[1] for x in rows)
print(sys.argv[1], f"{first:.4f}", f"{render:.4f}", max(x[2] for x in rows), rows[0][3])' "$1"
}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $(nproc) cores" | tee "$out/machine"
parts="${PARTS:-objects resolution meshes}"
want() { [[ " $parts " == *" $1 "* ]]; }
want objects && : >"$out/objects"
want objects && for n in 1000 3162 10000 31623 100000 316228 1000000; do
    [ "$n" -le "$max" ] || continue
    measure "$n" "$(scene "$n" 320 240)" | tee -a "$out/objects"
done
want resolution && : >"$out/resolution"
want resolution && for wh in "160 120" "320 240" "640 480" "1280 960"; do
    set -- $wh
    measure "$(($1 * $2))" "$(scene 100000 "$1" "$2")" | tee -a "$out/resolution"
done
want meshes && : >"$out/meshes"
want meshes && for n in 10000 31623 100000 316228 1000000 3162278 10000000; do
    [ "$n" -le "${MESH_MAX:-10000000}" ] || continue
    [ -e "$out/sphere_$n.obj" ] || python3 benches/mesh_sphere.py "$n" "$out/sphere_$n.obj" >/dev/null
    cat >"$out/mesh_$n.rtc" <<RTC
rtc 1
// A unit sphere of about $n triangles (benches/scaling.sh)
camera { eye: [0, 0.8, 3.4], center: [0, 0, 0], fov: 45deg, resolution: [320, 240] }
point_light { position: [2, 4, 3] }
mesh("sphere_$n.obj").material(material { color: rgb(0.8, 0.3, 0.2), ka: 0.2, kd: 0.7, ks: 0.3, n: 16 })
render { shadows: true, max_depth: 0, supersampling: 1 }
RTC
    runs="${MESH_RUNS:-2}" measure "$n" "$out/mesh_$n.rtc" | tee -a "$out/meshes"
done
python3 benches/scaling_plot.py "$out" docs/images
