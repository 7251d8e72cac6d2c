#!/usr/bin/env bash
# Mesh benchmarks with the peers' scene B setup (see ../shared/peers/README.md).
#
#   benches/meshes.sh            # duck, bunny, ogre, bunny-x16
#   benches/meshes.sh bunny      # one part
#   benches/meshes.sh scenes     # `rtc render` of scenes/bench/*.rtc (hyperfine when installed)
#
# bunny-x16.obj (1.1M triangles) is made once with the peers' tools/subdivide.py into
# $RTC_MODELS (default: target/models) if it is not already in /work/shared/models or the
# peers' work directory. Parts whose model is missing are skipped with a message.
set -euo pipefail
cd "$(dirname "$0")/.."
export RTC_MODELS="${RTC_MODELS:-$PWD/target/models}"
peers=/work/shared/peers
if [ ! -e "$RTC_MODELS/bunny-x16.obj" ] && [ ! -e "$peers/work/bunny-x16.obj" ] \
    && [ -e /work/shared/models/stanford-bunny.obj ] && [ -e "$peers/tools/subdivide.py" ]; then
    mkdir -p "$RTC_MODELS"
    echo "making $RTC_MODELS/bunny-x16.obj (python3 + numpy)..."
    python3 "$peers/tools/subdivide.py" /work/shared/models/stanford-bunny.obj "$RTC_MODELS/bunny-x16.obj" 2 \
        || echo "could not make bunny-x16.obj; that part will be skipped"
fi
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
if [ "${1:-}" = scenes ]; then
    # The checked-in scenes through `rtc render`, as a user runs them (hyperfine, 2 threads).
    export RTC_ASSET_PATH="/work/shared/models:$peers/work:$RTC_MODELS${RTC_ASSET_PATH:+:$RTC_ASSET_PATH}"
    cargo build --release -q
    for s in duck bunny bunny_x16; do
        if ! ./target/release/rtc check "scenes/bench/$s.rtc" >/dev/null 2>&1; then
            echo "$s: skipped (its model is missing; see scenes/bench/$s.rtc)"
            continue
        fi
        ./target/release/rtc render "scenes/bench/$s.rtc" -o "target/bench-$s.png" --stats
        if command -v hyperfine >/dev/null; then
            hyperfine -N -w 1 -r "${RUNS:-10}" \
                "./target/release/rtc render scenes/bench/$s.rtc -o target/bench-$s.png"
        fi
    done
    exit 0
fi
exec cargo bench --bench geometry -- "$@"
