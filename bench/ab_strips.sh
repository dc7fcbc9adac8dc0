#!/usr/bin/env bash
# Same-run A/B of two phellem binaries on the strip benchmark trunk, for changes too small to
# see through this machine's drift (±30 % within minutes): PAIRS pairs (default 12), each
# pair's ratio B/A of `simulate` time, their median and a bootstrap 90 % interval.
#   bench/ab_strips.sh BIN_A BIN_B           two threads, A and B alternating (order swapped
#                                            every pair)
#   MODE=concurrent bench/ab_strips.sh A B   one thread each, A and B at the same time on the two
#                                            cores (both see the same noise: the tightest
#                                            measure of total work, blind to cross-core effects)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
A=$(realpath "$1") B=$(realpath "$2")
PAIRS=${PAIRS:-12} MODE=${MODE:-alternating}
scene=bench/scenes/strips_trunk_1000x500.json
: >"$out/pairs"
for r in $(seq "$PAIRS"); do
  if [ "$MODE" = concurrent ]; then
    strip_sim "$A" "$scene" 1 a >"$out/ta" &
    strip_sim "$B" "$scene" 1 b >"$out/tb" &
    wait
    ta=$(cat "$out/ta") tb=$(cat "$out/tb")
  elif [ $((r % 2)) = 0 ]; then
    ta=$(strip_sim "$A" "$scene" 2 a) tb=$(strip_sim "$B" "$scene" 2 b)
  else
    tb=$(strip_sim "$B" "$scene" 2 b) ta=$(strip_sim "$A" "$scene" 2 a)
  fi
  echo "$ta $tb" >>"$out/pairs"
done
pair_summary "$out/pairs" "$MODE, " A B
