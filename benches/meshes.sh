#!/usr/bin/env bash
# Mesh benchmarks with the peers' scene B setup (see ../shared/peers/README.md).
#
#   benches/meshes.sh            # duck, bunny, ogre, bunny-x16
#   benches/meshes.sh bunny      # one part
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
exec cargo bench --bench geometry -- "$@"
