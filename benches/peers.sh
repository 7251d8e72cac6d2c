#!/usr/bin/env bash
# rtc against POV-Ray on the same work, in one session on one machine: wall time and CPU time
# (user + system) of whole processes, runs alternated, medians.
#   benches/peers.sh [REPS]        (default 7 runs each; needs povray: ../shared/peers/setup.sh)
#
#   A     peer scene A: five spheres, 400², 4×4 SS, shadows, reflection depth 2
#         rtc: scenes/five_spheres.rtc; POV-Ray: /work/shared/peers/pov/five_spheres.pov with the
#         exact flags of /work/shared/peers/README.md
#   duck  the course's devil duck, 3712 smooth triangles, 400², 3×3 SS, Phong + shadows
#         rtc: scenes/bench/duck.rtc; POV-Ray: its twin written by benches/duck_pov.py
#
# Not a test: timings on a shared machine vary; the load average is printed before and after.
set -euo pipefail
cd "$(dirname "$0")/.."
REPS="${1:-7}"
PEERS="${PEERS:-/work/shared/peers}"
command -v povray >/dev/null || { echo "povray not installed (run $PEERS/setup.sh); skipped"; exit 0; }
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
cargo build --release --quiet
rtc=$PWD/target/release/rtc
python3 benches/duck_pov.py tests/data/course/models/devilduk.obj "$OUT/duck.pov"
pov=(povray -D +WT2 +A0.0 +AM1 -J +FN File_Gamma=1.0)
declare -A CMD=(
    [A.rtc]="$rtc render scenes/five_spheres.rtc -o $OUT/a.png --threads 2"
    [A.pov]="${pov[*]} +W400 +H400 +R4 +GS +I$PEERS/pov/five_spheres.pov +O$OUT/a_pov.png"
    [duck.rtc]="$rtc render scenes/bench/duck.rtc -o $OUT/duck.png --threads 2"
    [duck.pov]="${pov[*]} +W400 +H400 +R3 +I$OUT/duck.pov +O$OUT/duck_pov.png"
)
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for run in $(seq "$REPS"); do
    for key in A.rtc A.pov duck.rtc duck.pov; do
        # bash's own `time` to the millisecond (/usr/bin/time rounds to 10 ms, a tenth of
        # rtc's times here, so its ratios jumped between neighbouring values).
        # shellcheck disable=SC2086
        { TIMEFORMAT='%3R %3U %3S'; time ${CMD[$key]} >/dev/null 2>&1; } 2> "$OUT/t"
        awk -v k="$key" '{print k, $1, $2 + $3}' "$OUT/t" >> "$OUT/times"
    done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
for scene in A duck; do
    rw=$(awk -v k="$scene.rtc" '$1==k {print $2}' "$OUT/times" | median)
    rc=$(awk -v k="$scene.rtc" '$1==k {print $3}' "$OUT/times" | median)
    pw=$(awk -v k="$scene.pov" '$1==k {print $2}' "$OUT/times" | median)
    pc=$(awk -v k="$scene.pov" '$1==k {print $3}' "$OUT/times" | median)
    printf '%-5s rtc %.3f s wall %.3f CPU-s | povray %.3f s wall %.3f CPU-s | ratio %.1fx wall %.1fx CPU\n' \
        "$scene" "$rw" "$rc" "$pw" "$pc" "$(echo "$pw / $rw" | bc -l)" "$(echo "$pc / $rc" | bc -l)"
done
