#!/usr/bin/env bash
# End-to-end wall time of rtc versus POV-Ray on peer scene A (five spheres, 400x400, 4x4
# supersampling, shadows, reflection depth 2), in one session on one machine.
#   benches/peers.sh [REPS]        (default 10 runs each; needs povray, optional hyperfine)
# rtc renders scenes/five_spheres.rtc (same bytes as scenes/five_spheres.yaml) with the release binary; POV-Ray renders
# /work/shared/peers/pov/five_spheres.pov with the exact flags of /work/shared/peers/README.md.
# Prints the median wall time of each and the ratio POV-Ray / rtc. Not a test: timings on a
# shared machine vary; check `uptime` before trusting a number.
set -euo pipefail
cd "$(dirname "$0")/.."
REPS="${1:-10}"
PEERS="${PEERS:-/work/shared/peers}"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
cargo build --release --quiet
RTC=(target/release/rtc render scenes/five_spheres.rtc -o "$OUT/rtc.png" --threads 2)
POV=(povray -D +WT2 +W400 +H400 +A0.0 +AM1 +R4 -J +FN File_Gamma=1.0 +GS
     "+I$PEERS/pov/five_spheres.pov" "+O$OUT/pov.png")
echo "load before: $(uptime)"
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
time_runs() {
    for _ in $(seq "$REPS"); do
        local t0 t1
        t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N)
        echo "$t1 - $t0" | bc -l
    done | median
}
if command -v hyperfine >/dev/null; then
    hyperfine -N -w 2 -r "$REPS" --export-json "$OUT/h.json" "${RTC[*]}" "${POV[*]}"
fi
rtc_s=$(time_runs "${RTC[@]}")
pov_s=$(time_runs "${POV[@]}")
echo "load after: $(uptime)"
printf 'rtc     median wall %.3f s\npovray  median wall %.3f s\nratio   %.1fx (target >= 10x)\n' \
    "$rtc_s" "$pov_s" "$(echo "$pov_s / $rtc_s" | bc -l)"
