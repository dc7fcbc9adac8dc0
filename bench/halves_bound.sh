#!/usr/bin/env bash
# What a split of the strip sweep into two halves (one per core) could gain at most, measured
# without building it: the benchmark trunk on two threads (A) against two 500-strip halves of
# it simulated one thread each at the same time (B: the slower of the two). B ignores what the
# split would cost — propagation across the middle, merging each step's fracture bookkeeping —
# so B/A is a lower bound on the split's time ratio. PAIRS pairs (default 10), alternating.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
PAIRS=${PAIRS:-10}
full=bench/scenes/strips_trunk_1000x500.json
trunk_scene 500 "$out/half.json"
halves() {
  strip_sim ./build/phellem "$out/half.json" 1 h1 >"$out/t1" &
  strip_sim ./build/phellem "$out/half.json" 1 h2 >"$out/t2" &
  wait
  python3 -c "print(max(float(open('$out/t1').read()), float(open('$out/t2').read())))"
}
: >"$out/pairs"
for r in $(seq "$PAIRS"); do
  if [ $((r % 2)) = 0 ]; then
    ta=$(strip_sim ./build/phellem "$full" 2 full) tb=$(halves)
  else
    tb=$(halves) ta=$(strip_sim ./build/phellem "$full" 2 full)
  fi
  echo "$ta $tb" >>"$out/pairs"
done
pair_summary "$out/pairs" "" "trunk on 2 threads" "two halves at once"
