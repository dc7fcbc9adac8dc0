#!/usr/bin/env bash
# Stress-field cracking (issue 4) timings for the README: the thesis's Table 1 workloads
# (bench/scenes/stress_4378x75.json: "Bunny" 4,378 triangles x 75 iterations, CPI 8, RPI 3,
# 7 s in the thesis; bench/scenes/stress_41602x250.json: "Mouse" 41,602 x 250, CPI 15, RPI 2,
# 610 s), on procedural torus knots of those sizes after the preprocessing, then a scaling
# table over 5k/20k/80k/320k triangles at 50 iterations (CPI 10, RPI 2).
# Medians of REPEAT runs (default 3).
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
run() {  # scene -> "simulate_median preprocess_median triangles_in triangles_out cracks"
  local sim=() pre=()
  for r in $(seq "$REPEAT"); do
    ./build/phellem simulate "$1" -o "$out/o" --quiet --stats "$out/s.json"
    sim+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['simulate'])")")
    pre+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['preprocess'])")")
  done
  echo "$(printf '%s\n' "${sim[@]}" | median) $(printf '%s\n' "${pre[@]}" | median) $(python3 -c "import json;d=json.load(open('$out/s.json'));print(d['triangles_in'], d['triangles_out'], d['cracks'])")"
}
echo "thesis workloads (threads: $(nproc))"
for w in "4378x75 7" "41602x250 610"; do
  read -r name thesis <<<"$w"
  read -r sim pre tin tout cracks <<<"$(run bench/scenes/stress_$name.json)"
  python3 -c "print('  %-10s %6d -> %6d triangles, %5d cracks: simulate %.3f s (thesis %d s: %.0fx faster), preprocess %.3f s' % ('$name', $tin, $tout, $cracks, $sim, $thesis, $thesis / $sim, $pre))"
done
echo
echo "triangles  iterations  simulate_s  us_per_triangle_iteration  preprocess_s"
for n in 5000 20000 80000 320000; do
  cat > "$out/scale.json" <<JSON
{"objects": [{"type": "mesh", "name": "knot", "procedural": {"shape": "torus_knot", "triangles": $n, "radius": 0.5, "tube": 0.12},
  "bark": {"model": "stress", "preset": "bunny", "iterations": 50, "cracks_per_iteration": 10, "relaxations_per_iteration": 2}}]}
JSON
  read -r sim pre tin tout cracks <<<"$(run "$out/scale.json")"
  python3 -c "print('%9d  %10d  %10.3f  %25.3f  %12.3f' % ($tin, 50, $sim, $sim / ($tin * 50) * 1e6, $pre))"
done
