#!/usr/bin/env bash
# Render cost of truly displaced strip bark (README figures): scenes/strips_furrowed.json
# against the same trunk without its "bark" (undisplaced, same material), in the same run.
# Reports triangles diced, memory, and time to first pixel (load + bark simulation and
# dressing + tessellation + BVH), medians of REPEAT runs (default 3), at RES (default the
# scene's 960x640) and 1 spp.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
RES=${RES:-960x640}
python3 - "$out/plain.json" <<'PY'
import json, sys
s = json.load(open("scenes/strips_furrowed.json"))
del s["objects"][0]["bark"]
json.dump(s, open(sys.argv[1], "w"))
PY
measure() {  # scene -> "first_pixel_s bark_s tessellate_s bvh_s diced_triangles diced_mb embree_mb rss_mb"
  local fp=() last
  for r in $(seq "$REPEAT"); do
    ./build/phellem render "$1" --res "$RES" --spp 1 -o "$out/r.exr" --quiet --stats "$out/s.json"
    fp+=("$(python3 -c "import json;t=json.load(open('$out/s.json'))['time_s'];print(t['load']+t['build'])")")
  done
  last=$(python3 -c "import json;d=json.load(open('$out/s.json'));t=d['time_s'];print(t['bark'], t['tessellate'], t['bvh'], d['diced_triangles'], round(d['geometry_mb'],1), round(d['embree_mb'],1), round(d['peak_rss_mb']))")
  echo "$(printf '%s\n' "${fp[@]}" | median) $last"
}
read -r fp_b bark_b tess_b bvh_b tri_b mb_b em_b rss_b <<<"$(measure scenes/strips_furrowed.json)"
read -r fp_p bark_p tess_p bvh_p tri_p mb_p em_p rss_p <<<"$(measure "$out/plain.json")"
echo "strips_furrowed at $RES, 1 spp, medians of $REPEAT      displaced strip bark | same trunk, no bark"
printf "  time to first pixel (s)        %10.2f | %10.2f   (ratio %.1f)\n" "$fp_b" "$fp_p" "$(python3 -c "print($fp_b/$fp_p)")"
printf "    of which bark sim+dress (s)  %10.2f | %10.2f\n" "$bark_b" "$bark_p"
printf "    tessellation (s)             %10.2f | %10.2f\n" "$tess_b" "$tess_p"
printf "    BVH (s)                      %10.2f | %10.2f\n" "$bvh_b" "$bvh_p"
printf "  diced triangles                %10d | %10d   (ratio %.1f)\n" "$tri_b" "$tri_p" "$(python3 -c "print($tri_b/$tri_p)")"
printf "  geometry incl. bark maps (MB)  %10.1f | %10.1f\n" "$mb_b" "$mb_p"
printf "  Embree BVH (MB)                %10.1f | %10.1f\n" "$em_b" "$em_p"
printf "  peak RSS (MB)                  %10d | %10d\n" "$rss_b" "$rss_p"
