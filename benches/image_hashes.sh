#!/usr/bin/env bash
# Renders every example, course and bench scene the repository holds and prints one
# `sha256  path` line per image, sorted, so two builds can be compared byte for byte:
#
#   benches/image_hashes.sh > before.txt     # on the old commit
#   benches/image_hashes.sh > after.txt      # on the new one
#   diff before.txt after.txt                # empty when every image is the same bytes
#
# A scene that fails prints `FAILED(<exit code>)  path` instead (some course files are invalid on
# purpose; they must fail the same way on both sides). The bench scenes that need
# ../shared/models are rendered when RTC_ASSET_PATH finds them and listed as `SKIPPED` otherwise.
# Usage: benches/image_hashes.sh [RTC_BINARY]   (default target/release/rtc, built if missing)
set -uo pipefail
cd "$(dirname "$0")/.."
rtc=${1:-target/release/rtc}
[ -x "$rtc" ] || cargo build --release --locked -q || exit 2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export RTC_ASSET_PATH=${RTC_ASSET_PATH:-../shared/models}

scenes() {
  find scenes tests/data/course tests/lang tests/data/why -type f \
    \( -name '*.rtc' -o -name '*.in' -o -name '*.yaml' \) -not -path '*/lib/*' | sort
}

n=0
while IFS= read -r scene; do
  n=$((n + 1))
  png="$out/$n.png"
  if grep -q 'bunny' <<<"$scene" && [ ! -e "$RTC_ASSET_PATH/stanford-bunny.obj" ]; then
    echo "SKIPPED  $scene"
    continue
  fi
  if "$rtc" render "$scene" -o "$png" >/dev/null 2>&1; then
    echo "$(sha256sum "$png" | cut -c1-64)  $scene"
  else
    echo "FAILED($?)  $scene"
  fi
done < <(scenes)
