#!/usr/bin/env bash
# "Effects stay free" (issue 12): scene A (scenes/five_spheres.rtc: shadows, 2 bounces, 4×4
# supersampling) rendered as it is and with one effect switched off at a time. Each switched-off
# effect must make the render faster, never slower. Rounds alternate the variants so a change in
# machine load hits them alike; each figure is the median over RUNS rounds of /usr/bin/time
# (user + system CPU, and wall), with the rays traced from `--stats`.
#
#   benches/effects.sh            # RUNS=7 by default; prints a Markdown table
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/bench-effects
mkdir -p "$out"
cargo build --release -q
rtc=$PWD/target/release/rtc
base=scenes/five_spheres.rtc
grep -q 'render { shadows: true, max_depth: 2, supersampling: 4' "$base" \
    || { echo "effects.sh: $base no longer has the render line this bench edits" >&2; exit 2; }
variant() { # name sed-expression
    sed "$2" "$base" >"$out/$1.rtc"
}
variant all 's/x/x/'
variant no_shadows 's/shadows: true/shadows: false/'
variant no_reflection 's/max_depth: 2/max_depth: 0/'
variant no_supersampling 's/supersampling: 4/supersampling: 1/'
variant nothing 's/shadows: true, max_depth: 2, supersampling: 4/shadows: false, max_depth: 0, supersampling: 1/'
names="all no_shadows no_reflection no_supersampling nothing"
runs="${RUNS:-7}"
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
base = s.median(cpu["all"])
print("| variant | rays | CPU s (median) | wall s | CPU vs all on | faster? |")
print("|---|---|---|---|---|---|")
ok = True
for n in cpu:
    c = s.median(cpu[n])
    faster = "—" if n == "all" else ("yes" if c < base else "**no**")
    ok &= faster != "**no**"
    print(f"| {n} | {rays.get(n, '?')} | {c:.3f} | {s.median(wall[n]):.3f} | {c / base:.2f}× | {faster} |")
print()
print("every switched-off effect is faster" if ok else "SOME SWITCHED-OFF EFFECT IS NOT FASTER")
PY
