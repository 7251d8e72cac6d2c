#!/usr/bin/env bash
# Slurm array job: one task per shard of one image. Submit with
#   sbatch --array=0-15 docs/examples/slurm/render-array.sh SCENE.rtc OUT_DIR
# then merge on any machine that sees OUT_DIR:
#   rtc merge OUT_DIR/part-*.rtcpart -o image.png
# Each task renders `--shard auto`: rtc reads SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN and
# SLURM_ARRAY_TASK_COUNT, so the array's size is the number of shards. A task that is re-run
# (requeued, failed node) overwrites its own part and nothing else.
#SBATCH --job-name=rtc-shards
#SBATCH --cpus-per-task=1
#SBATCH --output=rtc-shard-%A_%a.log
set -euo pipefail
scene=$1
out=$2
rtc=${RTC:-rtc}
mkdir -p "$out"
exec "$rtc" render "$scene" --shard auto --threads "${SLURM_CPUS_PER_TASK:-0}" \
  -o "$out/part-${SLURM_ARRAY_TASK_ID}.rtcpart"
