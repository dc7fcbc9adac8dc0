#!/usr/bin/env bash
# Cambial growth (issue 24) timings for the README: the paper's Table 1 "tree close-up"
# (10k -> 39k interface vertices over 200 steps, 162 ms per step on one 2.0 GHz core) as
# bench/scenes/growth_tree_closeup.json, then the same growth from 4k, 10k and 39k starting
# vertices (20 steps) to show how a step's time grows with the interface. `simulate --stats`
# reports growth.steps, growth.vertices_start/_end, time_s.growth (the steps) and
# time_s.growth_setup (TetGen) separately. Medians of REPEAT runs (default 3).
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
run() {  # scene -> "growth_median setup_median steps v_start v_end"
  local g=() s=()
  for r in $(seq "$REPEAT"); do
    ./build/phellem simulate "$1" -o "$out/o" --quiet --stats "$out/s.json"
    g+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['growth'])")")
    s+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['growth_setup'])")")
  done
  echo "$(printf '%s\n' "${g[@]}" | median) $(printf '%s\n' "${s[@]}" | median) $(python3 -c "import json;d=json.load(open('$out/s.json'))['growth'];print(d['steps'], d['vertices_start'], d['vertices_end'])")"
}
echo "tree close-up (threads: $(nproc))"
read -r g s steps v0 v1 <<<"$(run bench/scenes/growth_tree_closeup.json)"
python3 -c "print('  %d -> %d interface vertices, %d steps: %.1f ms per step (paper 162 ms: %.1fx faster), TetGen set-up %.2f s' % ($v0, $v1, $steps, $g / $steps * 1e3, 162 / ($g / $steps * 1e3), $s))"
echo "the same with the volume's upkeep every step (tetrahedra.upkeep_reach 0; bench/scenes/growth_tree_closeup_every_step.json)"
read -r g s steps v0 v1 <<<"$(run bench/scenes/growth_tree_closeup_every_step.json)"
python3 -c "print('  %d -> %d interface vertices, %d steps: %.1f ms per step, TetGen set-up %.2f s' % ($v0, $v1, $steps, $g / $steps * 1e3, $s))"
echo "the same with crack coupling on (3 stress iterations a step; bench/scenes/growth_tree_closeup_cracks.json, one run)"
./build/phellem simulate bench/scenes/growth_tree_closeup_cracks.json -o "$out/o" --quiet --stats "$out/s.json"
python3 -c "
import json
d = json.load(open('$out/s.json')); t = d['time_s']; g = d['growth']
print('  %d -> %d interface vertices, %d steps: %.1f ms per step growing + %.1f ms per step crack coupling, TetGen set-up %.2f s' %
      (g['vertices_start'], g['vertices_end'], g['steps'], t['growth'] / g['steps'] * 1e3, t['growth_crack'] / g['steps'] * 1e3, t['growth_setup']))"
echo "the same growth on a sphere of the log's area (no rims; bench/scenes/growth_sphere_closeup.json)"
read -r g s steps v0 v1 <<<"$(run bench/scenes/growth_sphere_closeup.json)"
python3 -c "print('  %d -> %d interface vertices, %d steps: %.1f ms per step, TetGen set-up %.2f s' % ($v0, $v1, $steps, $g / $steps * 1e3, $s))"
# The scaling loops: the close-up with 8000, 20000 and 78000 triangles, 20 steps, the band
# scaled with the triangles' size. "fixed growth" keeps the close-up's first 6 years, so a finer
# mesh moves more edge lengths a step; "growth scaled" shortens the years with the band, so
# every mesh moves the same share of its edges a step and only the vertex count changes.
for mode in fixed scaled; do
  echo
  echo "growth $mode: vertices_start  vertices_end  steps  ms_per_step  us_per_vertex_step  setup_s"
  for n in 8000 20000 78000; do
    python3 - "$n" "$out/scale.json" "$mode" <<'PY'
import json, sys
n, path, mode = int(sys.argv[1]), sys.argv[2], sys.argv[3]
s = json.load(open("bench/scenes/growth_tree_closeup.json"))
o = s["objects"][0]
o["procedural"]["triangles"] = n
e = 0.013 * (20000 / n) ** 0.5
years = 6 if mode == "fixed" else 6 * e / 0.013
o["growth"].update({"steps": 20, "years": years, "edge_length": [0.385 * e, e]})
json.dump(s, open(path, "w"))
PY
    read -r g s steps v0 v1 <<<"$(run "$out/scale.json")"
    python3 -c "print('%14d  %12d  %5d  %11.1f  %18.2f  %7.2f' % ($v0, $v1, $steps, $g / $steps * 1e3, $g / $steps / (($v0 + $v1) / 2) * 1e6, $s))"
  done
done
