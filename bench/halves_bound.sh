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
python3 - "$full" "$out/half.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["objects"][0]["axis"] = [[0, 0, 0], [0, 500 * 0.005, 0]]
json.dump(s, open(sys.argv[2], "w"))
PY
sim() {  # scene, threads, tag -> simulate seconds
  ./build/phellem simulate "$1" -o "$out/$3" --res 64x64 --no-mesh --quiet --threads "$2" --stats "$out/$3.json"
  python3 -c "import json;print(json.load(open('$out/$3.json'))['time_s']['simulate'])"
}
halves() {
  sim "$out/half.json" 1 h1 >"$out/t1" &
  sim "$out/half.json" 1 h2 >"$out/t2" &
  wait
  python3 -c "print(max(float(open('$out/t1').read()), float(open('$out/t2').read())))"
}
: >"$out/pairs"
for r in $(seq "$PAIRS"); do
  if [ $((r % 2)) = 0 ]; then
    ta=$(sim "$full" 2 full) tb=$(halves)
  else
    tb=$(halves) ta=$(sim "$full" 2 full)
  fi
  echo "$ta $tb" >>"$out/pairs"
done
python3 - "$out/pairs" <<'PY'
import random, statistics as st, sys
pairs = [tuple(map(float, l.split())) for l in open(sys.argv[1])]
r = [y / x for x, y in pairs]
random.seed(1)
boot = sorted(st.median(random.choices(r, k=len(r))) for _ in range(2000))
print(f"{len(r)} pairs: trunk on 2 threads median {st.median(p[0] for p in pairs):.3f} s, two halves at once "
      f"median {st.median(p[1] for p in pairs):.3f} s; halves/trunk median {st.median(r):.3f}, "
      f"90 % interval [{boot[100]:.3f}, {boot[1899]:.3f}]")
PY
