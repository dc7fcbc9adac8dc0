#!/usr/bin/env bash
# The preview's frame times on this machine's OpenGL (llvmpipe without a GPU), issue 23:
# the stress trunk and the strip tree at 1280x720 and 1920x1200 (median of 15 frames after
# 3 warm-up frames, against a plain mesh of as many triangles drawn in the same run; stress
# bark's tints off as the window starts, then on), then the
# time from `phellem preview` to the first frame of the default scene in a window (xvfb).
#   bench/run_preview.sh [EDGE_PX]
set -euo pipefail
cd "$(dirname "$0")/.."
EDGE=${1:-6}
for scene in scenes/stress_pine.json scenes/strips_tree.json; do
  for res in 1280x720 1920x1200; do
    build/bench/phellem_bench_preview "$scene" "$res" 15 "$EDGE"
  done
done
# Stress bark's per-plate and per-crack tints on (T in the window):
build/bench/phellem_bench_preview scenes/stress_pine.json 1280x720 15 "$EDGE" tints
for i in 1 2 3; do
  xvfb-run -a -s "-screen 0 1920x1200x24" build/phellem preview --frames 2 2>&1 | tail -1
done
