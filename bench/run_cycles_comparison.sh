#!/usr/bin/env bash
# Phellem against Blender Cycles (CPU) on the same diffuse glTF scene
# (bench/scenes/cycles: sun + uniform sky, textured Lambertian materials).
#
#   bench/run_cycles_comparison.sh [OUT_DIR]        (after the README's build command)
#
# Needs Debian's `blender` and `python3-numpy` (benchmark-only dependencies:
#   sudo apt-get install blender python3-numpy). Environment knobs: THREADS (2),
#   REF_SPP (2048, the "converged" images; REUSE_REF=1 keeps those of an earlier run), SWEEP ("4 8 16 32 64 128"), REPEAT (3 timed
#   renders per sweep point, median taken; the machine is noisy).
# Reports
#   (a) agreement: relative L1 difference Σ|P − C| / Σ|C| of the two converged images;
#   (b) equal-quality speed: each renderer's RMSE against its own converged image at each
#       spp with its wall time (Phellem: load + build + render from --stats; Cycles: the
#       render call, scene sync + BVH + render, timed inside Blender), the time each needs
#       to reach a common RMSE (log-log interpolation between sweep points), and the median
#       over the sweep of the efficiency ratio (RMSE² × time of Cycles) / (same of Phellem),
#       i.e. how many times longer Cycles takes to reach any given RMSE.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-build/cycles_comparison}
THREADS=${THREADS:-2}
REF_SPP=${REF_SPP:-2048}
SWEEP=${SWEEP:-"4 8 16 32 64 128"}
REPEAT=${REPEAT:-3}
SCENE=bench/scenes/cycles/scene.json
PHELLEM=./build/phellem
COMPARE=./build/bench/phellem_bench_compare
command -v blender > /dev/null || { echo "run_cycles_comparison.sh: blender is not installed (apt-get install blender python3-numpy)" >&2; exit 2; }
[[ -x $PHELLEM && -x $COMPARE ]] || { echo "run_cycles_comparison.sh: build first (README)" >&2; exit 2; }
mkdir -p "$OUT"

phellem() {  # spp out.exr -> prints seconds
  "$PHELLEM" render "$SCENE" --spp "$1" --threads "$THREADS" -o "$2" --stats "$2.json" --quiet
  python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['time_s']['total'])" "$2.json"
}
cycles() {  # spp out.exr -> prints seconds
  blender -b --factory-startup -noaudio --python-exit-code 2 -P bench/cycles/cycles_render.py -- \
    "$SCENE" "$1" "$2" "$THREADS" 2> "$2.log" | sed -n 's/^CYCLES_RESULT //p' |
    python3 -c "import json,sys; print(json.load(sys.stdin)['time_s'])"
}

echo "warm-up (texture cache, Blender start-up)"
phellem 1 "$OUT/warm_phellem.exr" > /dev/null
cycles 1 "$OUT/warm_cycles.exr" > /dev/null

if [[ ${REUSE_REF:-0} == 1 && -f $OUT/phellem_ref.exr && -f $OUT/cycles_ref.exr ]]; then
  echo "reusing the converged images in $OUT (REUSE_REF=1)"
else
  echo "converged images at $REF_SPP spp ($THREADS threads)"
  tp=$(phellem "$REF_SPP" "$OUT/phellem_ref.exr")
  tc=$(cycles "$REF_SPP" "$OUT/cycles_ref.exr")
  echo "  phellem ${tp} s, cycles ${tc} s"
fi
agreement=$("$COMPARE" "$OUT/phellem_ref.exr" "$OUT/cycles_ref.exr")
echo "agreement (a = Phellem, b = Cycles): $agreement"

: > "$OUT/sweep.tsv"
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
for spp in $SWEEP; do
  tp=$(for r in $(seq "$REPEAT"); do phellem "$spp" "$OUT/phellem_$spp.exr"; done | median)
  tc=$(for r in $(seq "$REPEAT"); do cycles "$spp" "$OUT/cycles_$spp.exr"; done | median)
  ep=$("$COMPARE" "$OUT/phellem_$spp.exr" "$OUT/phellem_ref.exr")
  ec=$("$COMPARE" "$OUT/cycles_$spp.exr" "$OUT/cycles_ref.exr")
  printf '%s\t%s\t%s\t%s\t%s\n' "$spp" "$tp" "$ep" "$tc" "$ec" >> "$OUT/sweep.tsv"
done

python3 - "$OUT/sweep.tsv" "$agreement" <<'PY'
import json, math, sys
rows = []
for line in open(sys.argv[1]):
    spp, tp, ep, tc, ec = line.rstrip("\n").split("\t")
    rows.append((int(spp), float(tp), json.loads(ep)["rmse"], float(tc), json.loads(ec)["rmse"]))
print("\n spp | phellem s | phellem RMSE | cycles s | cycles RMSE")
for r in rows:
    print("%4d | %9.3f | %12.5f | %8.3f | %11.5f" % r)

def time_to(target, pts):
    # pts: (time, rmse) with rmse falling; log-log interpolation, None outside the sweep.
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e0 >= target >= e1 and e0 > e1:
            f = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
    return None

p = [(r[1], r[2]) for r in rows]
c = [(r[3], r[4]) for r in rows]
# Common target: the RMSE Cycles reaches at the middle of the sweep.
target = rows[len(rows) // 2][4]
tp, tc = time_to(target, p), time_to(target, c)
eff = sorted((r[4] ** 2 * r[3]) / (r[2] ** 2 * r[1]) for r in rows)
a = json.loads(sys.argv[2])
print("\nagreement: relative L1 difference %.4f (mean Phellem %.5f, mean Cycles %.5f)" % (a["rel_l1"], a["mean_a"], a["mean_b"]))
if tp and tc:
    print("equal quality (RMSE %.5f): Phellem %.3f s, Cycles %.3f s, Cycles/Phellem time ratio %.2f" % (target, tp, tc, tc / tp))
else:
    print("equal quality: target RMSE %.5f outside one renderer's sweep; widen SWEEP" % target)
print("efficiency ratio (RMSE^2 x time, Cycles / Phellem), median over the sweep: %.2f (range %.2f-%.2f)"
      % (eff[len(eff) // 2], eff[0], eff[-1]))
PY
