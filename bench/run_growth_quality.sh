#!/usr/bin/env bash
# Cambial growth (issue 24): the large-growth quality benchmark (a jittered log grown to twice
# its radius in 40 steps, build/bench/phellem_bench_growth_quality 60 40 2) on several jitter
# seeds, since one seed's log is one draw of a chaotic process. Prints each seed's summary line
# and the worst lag, radius s.d. and normal turn over the seeds. SEEDS (default "1 2 3 4 5 7").
set -euo pipefail
cd "$(dirname "$0")/.."
SEEDS=${SEEDS:-"1 2 3 4 5 7"}
lines=()
for seed in $SEEDS; do
  line=$(./build/bench/phellem_bench_growth_quality 60 40 2 - "$seed" | tail -1)
  echo "seed $seed: $line"
  lines+=("$line")
done
printf '%s\n' "${lines[@]}" | python3 -c '
import re, sys
rows = [l for l in sys.stdin if l.strip()]
def grab(pattern):
    return [float(re.search(pattern, l).group(1)) for l in rows]
lag = grab(r"worst lag ([0-9.]+)")
sd = grab(r"sd ([0-9.]+)")
turn = grab(r"normal turn ([0-9.]+)")
print("over %d seeds: worst lag %.2f mm, worst radius s.d. %.2f mm, worst normal turn %.1f deg" % (len(rows), 1e3 * max(lag), 1e3 * max(sd), max(turn)))
'
