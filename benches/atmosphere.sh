#!/usr/bin/env bash
# "Skies and fog cost what they must and nothing when absent" (issue 37): one stage (a floor, a
# mirror ball and a glass ball, 640×400, 2×2 supersampling, 5 bounces) rendered as it is (the
# background colour) and with constant fog, ground fog, a procedural sky and an HDR environment
# map (docs/images/sky.hdr). Rounds alternate the variants so a change in machine load hits them
# alike; each figure is the median over RUNS rounds of /usr/bin/time (user + system CPU, and
# wall), with the rays traced from `--stats`.
#
#   benches/atmosphere.sh            # RUNS=5 by default; prints a Markdown table
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/bench-atmosphere
mkdir -p "$out"
# RTC=path/to/rtc uses that binary as it is (no build first).
if [ -z "${RTC:-}" ]; then
    cargo build --release -q --locked
fi
rtc=${RTC:-$PWD/target/release/rtc}
hdr=$PWD/docs/images/sky.hdr
variant() { # name render-fields
    cat >"$out/$1.rtc" <<RTC
rtc 1.1
import std.materials as mat
plane(point: [0, 0, 0], normal: Y).material(mat.matte with {
    texture: checker(size: 1, a: rgb(0.8, 0.8, 0.75), b: rgb(0.3, 0.3, 0.3))
})
sphere(center: [-1.1, 1, 0], radius: 1).material(mat.mirror)
sphere(center: [1.3, 0.8, 0.6], radius: 0.8).material(mat.glass)
camera { eye: [0, 1.6, 7], center: [0, 1.4, 0], fov: 45deg, resolution: [640, 400] }
point_light { position: [4, 8, 6] }
render { supersampling: 2, background: rgb(0.3, 0.5, 0.9)$2 }
RTC
}
variant plain ''
variant fog ', fog: fog { color: rgb(0.75, 0.78, 0.82), distance: 12 }'
variant ground_fog ', fog: fog { color: rgb(0.9, 0.9, 0.88), distance: 3, offset: 0.4, altitude: 0.5 }'
variant sky ', sky: gradient(axis: Y).colors([rgb(0.95, 0.85, 0.65), rgb(0.05, 0.15, 0.45)])'
variant environment ", sky: image(path: \"$hdr\", filter: \"bilinear\")"
names="plain fog ground_fog sky environment"
runs="${RUNS:-5}"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $(nproc) cores"
: >"$out/times"
for _ in $(seq "$runs"); do
    for n in $names; do
        t=$(/usr/bin/time -f "%e %U %S" "$rtc" render "$out/$n.rtc" -o "$out/$n.png" 2>&1 >/dev/null | tail -1)
        echo "$n $t" >>"$out/times"
    done
done
for n in $names; do
    rays=$("$rtc" render --stats "$out/$n.rtc" -o "$out/$n.png" 2>&1 | grep -m1 -o '[0-9,]* rays' | tr -d ', rays' || true)
    echo "$n rays ${rays:-?}" >>"$out/times"
done
python3 - "$out/times" <<'PY'
import statistics as s, sys
cpu, wall, rays = {}, {}, {}
for line in open(sys.argv[1]):
    p = line.split()
    if p[1] == "rays":
        rays[p[0]] = p[2]
        continue
    cpu.setdefault(p[0], []).append(float(p[2]) + float(p[3]))
    wall.setdefault(p[0], []).append(float(p[1]))
base = s.median(cpu["plain"])
print("| variant | rays | CPU s (median) | wall s | CPU vs plain |")
print("|---|---|---|---|---|")
for n in cpu:
    c = s.median(cpu[n])
    print(f"| {n} | {rays.get(n, '?')} | {c:.3f} | {s.median(wall[n]):.3f} | {c / base:.2f}× |")
PY
