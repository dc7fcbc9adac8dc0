#!/usr/bin/env bash
# `phellem fit` against its time budget (issue 22's benchmark): the strip fit of each shared
# scan at 10 px/cm, seed 1, for each budget in BUDGETS (default "75 150 300 600" s), one fit at
# a time on the whole machine. Prints a CSV (scan, budget_s, wall_s, evaluations, score,
# orientation_emd_deg, objective) and, with PLOT=FILE.svg, draws score against budget
# (scripts/plot_fit_budget.py); with KEEP=DIR, each fit's outputs stay in DIR/SCAN_BUDGET. The
# scans: $PHOTOS (default data/photos).
#   bench/run_fit_budget.sh > fit_budget.csv
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh
PHOTOS=${PHOTOS:-data/photos}
BUDGETS=${BUDGETS:-"75 150 300 600"}
csv="$out/fit_budget.csv"
echo "scan,budget_s,wall_s,evaluations,score,orientation_emd_deg,objective" | tee "$csv"
for scan in bark_brown_01_polyhaven_disp.jpg pine_bark_polyhaven_disp.png; do
  for b in $BUDGETS; do
    ./build/phellem fit "$PHOTOS/$scan" --scale 10 --model strips -o "$out/fit" --time-budget "$b" --seed 1 --quiet
    python3 - "$out/fit/report.json" "$scan" "$b" <<'PY' | tee -a "$csv"
import json, sys
r = json.load(open(sys.argv[1]))
f = r["fit"]
print(f'{sys.argv[2]},{sys.argv[3]},{f["wall_s"]:.1f},{f["evaluations"]},{r["score"]:.4f},{r["orientation_emd_deg"]:.2f},{f["objective"]["mean"]:.4f}')
PY
    if [ -n "${KEEP:-}" ]; then mkdir -p "$KEEP" && rm -rf "$KEEP/${scan%%.*}_$b" && mv "$out/fit" "$KEEP/${scan%%.*}_$b"; fi
    rm -rf "$out/fit"
  done
done
if [ -n "${PLOT:-}" ]; then python3 scripts/plot_fit_budget.py "$csv" >"$PLOT"; fi
