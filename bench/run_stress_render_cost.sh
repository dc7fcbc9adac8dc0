#!/usr/bin/env bash
# Render cost of the stress-bark cracks (README figures): scenes/stress_pine.json diced
# crack-aware (only edges the cracks can reach are subdivided) against uniform dicing at the
# same crack resolution (render.tessellation.crack_aware false: every edge diced to the same
# pixels per micro-edge), in the same run. Reports diced triangles, their memory, Embree's
# memory and the tessellation and BVH times, medians of REPEAT runs (default 3), at RES
# (default 1280x960) and 1 spp. The cracked mesh is simulated once per run of the scene.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
RES=${RES:-1280x960}
python3 - "$out/uniform.json" <<'PY'
import json, sys
s = json.load(open("scenes/stress_pine.json"))
s["render"].setdefault("tessellation", {})["crack_aware"] = False
json.dump(s, open(sys.argv[1], "w"))
PY
measure() {  # scene -> "tessellate_s bvh_s diced_triangles diced_mb embree_mb"
  local tess=() bvh=() last
  for r in $(seq "$REPEAT"); do
    ./build/phellem render "$1" --res "$RES" --spp 1 -o "$out/r.exr" --quiet --stats "$out/s.json"
    tess+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['tessellate'])")")
    bvh+=("$(python3 -c "import json;print(json.load(open('$out/s.json'))['time_s']['bvh'])")")
  done
  last=$(python3 -c "import json;d=json.load(open('$out/s.json'));print(d['diced_triangles'], round(d['diced_mb'],1), round(d['embree_mb'],1))")
  echo "$(printf '%s\n' "${tess[@]}" | median) $(printf '%s\n' "${bvh[@]}" | median) $last"
}
read -r tess_a bvh_a tri_a mb_a em_a <<<"$(measure scenes/stress_pine.json)"
read -r tess_u bvh_u tri_u mb_u em_u <<<"$(measure "$out/uniform.json")"
echo "scenes/stress_pine.json at $RES, medians of $REPEAT"
printf '%-12s %12s %10s %10s %12s %8s\n' dicing triangles diced_MB embree_MB tessellate_s bvh_s
printf '%-12s %12s %10s %10s %12s %8s\n' crack-aware "$tri_a" "$mb_a" "$em_a" "$tess_a" "$bvh_a"
printf '%-12s %12s %10s %10s %12s %8s\n' uniform "$tri_u" "$mb_u" "$em_u" "$tess_u" "$bvh_u"
python3 -c "print('ratio uniform / crack-aware: triangles %.1fx, diced memory %.1fx' % ($tri_u / $tri_a, $mb_u / $mb_a))"
