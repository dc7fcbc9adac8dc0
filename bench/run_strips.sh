#!/usr/bin/env bash
# Strip-model simulation and dressing time (README figures): the 1000-strip × 500-step trunk
# of bench/scenes/strips_trunk_1000x500.json (radius 0.15 m, 5 mm strips), the whole small
# tree of scenes/strips_tree.json, then the scaling table over 250/500/1000/2000 strips; the
# trunk on one thread against two (how close two threads come to halving the time).
# Medians of REPEAT runs (default 3).
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
run() {  # scene, field resolution -> "simulate dress strips fractures simulate_min simulate_max" (medians)
  local sim=() dress=() s f
  for r in $(seq "$REPEAT"); do
    ./build/phellem simulate "$1" -o "$out/fields" --res "$2" --no-mesh --quiet --stats "$out/s.json"
    sim+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['simulate'])")")
    dress+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['dress'])")")
  done
  s=$(python3 -c "import json;d=json.load(open('$out/s.json'));print(d['strips'], d['fractures'])")
  local lo hi
  lo=$(printf '%s\n' "${sim[@]}" | sort -g | head -1)
  hi=$(printf '%s\n' "${sim[@]}" | sort -g | tail -1)
  echo "$(printf '%s\n' "${sim[@]}" | median) $(printf '%s\n' "${dress[@]}" | median) $s $lo $hi"
}
echo "benchmark scene: 1000 strips x 500 steps, FractureField 4096x4096"
read -r sim dress strips fr lo hi <<<"$(run bench/scenes/strips_trunk_1000x500.json 4096x4096)"
echo "  simulate ${sim} s (runs ${lo}-${hi} s), dress ${dress} s (${strips} strips, ${fr} fractures)"
# The same trunk on one thread and on two, in alternating pairs: how close two threads come
# to halving the work.
: >"$out/threads"
for r in $(seq "$REPEAT"); do
  echo "$(strip_sim ./build/phellem bench/scenes/strips_trunk_1000x500.json 1 t1) $(strip_sim ./build/phellem bench/scenes/strips_trunk_1000x500.json 2 t2)" >>"$out/threads"
done
pair_summary "$out/threads" "  one thread against two, " "1 thread" "2 threads"
./build/phellem simulate bench/scenes/strips_trunk_1000x500.json -o "$out/mesh" --quiet --stats "$out/m.json"
python3 -c "import json;d=json.load(open('$out/m.json'));print('  bark mesh (.glb, once): %.1f s, %d triangles' % (d['time_s']['mesh'], d['mesh_triangles']))"
read -r sim dress strips fr _ <<<"$(run scenes/strips_tree.json 1024x1024)"
echo "whole small tree (scenes/strips_tree.json, trunk + 3 branches): simulate ${sim} s, dress ${dress} s at 1024x1024 per cylinder (${strips} strips, ${fr} fractures)"
echo
echo "strips  steps  fractures  simulate_s  us_per_strip_step"
for n in 250 500 1000 2000; do
  trunk_scene "$n" "$out/scene_$n.json"
  read -r sim dress strips fr _ <<<"$(run "$out/scene_$n.json" 256x256)"
  python3 -c "print(f'{$strips:6d}  500  {$fr:9d}  {$sim:10.3f}  {1e6*$sim/($strips*500):.2f}')"
done
