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
sim() {  # binary, threads, tag -> simulate seconds
  "$1" simulate "$scene" -o "$out/$3" --res 64x64 --no-mesh --quiet --threads "$2" --stats "$out/$3.json"
  python3 -c "import json;print(json.load(open('$out/$3.json'))['time_s']['simulate'])"
}
: >"$out/pairs"
for r in $(seq "$PAIRS"); do
  if [ "$MODE" = concurrent ]; then
    sim "$A" 1 a >"$out/ta" &
    sim "$B" 1 b >"$out/tb" &
    wait
    ta=$(cat "$out/ta") tb=$(cat "$out/tb")
  elif [ $((r % 2)) = 0 ]; then
    ta=$(sim "$A" 2 a) tb=$(sim "$B" 2 b)
  else
    tb=$(sim "$B" 2 b) ta=$(sim "$A" 2 a)
  fi
  echo "$ta $tb" >>"$out/pairs"
done
python3 - "$out/pairs" "$MODE" <<'PY'
import random, statistics as st, sys
pairs = [tuple(map(float, l.split())) for l in open(sys.argv[1])]
a, b = [p[0] for p in pairs], [p[1] for p in pairs]
r = [y / x for x, y in pairs]
random.seed(1)
boot = sorted(st.median(random.choices(r, k=len(r))) for _ in range(2000))
print(f"{sys.argv[2]}, {len(r)} pairs: A median {st.median(a):.3f} s, B median {st.median(b):.3f} s; "
      f"B/A median {st.median(r):.3f}, 90 % interval [{boot[100]:.3f}, {boot[1899]:.3f}]")
PY
