# Sourced by the bench/*.sh scripts after they cd to the repository root: REPEAT (runs per
# figure, default 3), a scratch directory $out removed on exit, median() of the numbers on
# standard input, and the strip benchmarks' shared pieces below.
REPEAT=${REPEAT:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# The benchmark trunk (bench/scenes/strips_trunk_1000x500.json) cut to N strips of 5 mm: trunk_scene N PATH
trunk_scene() {
  python3 - "$1" "$2" <<'PY'
import json, sys
n, path = int(sys.argv[1]), sys.argv[2]
s = json.load(open("bench/scenes/strips_trunk_1000x500.json"))
s["objects"][0]["axis"] = [[0, 0, 0], [0, n * 0.005, 0]]
json.dump(s, open(path, "w"))
PY
}

# `simulate` seconds of one run without mesh: strip_sim BINARY SCENE THREADS TAG
strip_sim() {
  "$1" simulate "$2" -o "$out/$4" --res 64x64 --no-mesh --quiet --threads "$3" --stats "$out/$4.json"
  python3 -c "import json;print(json.load(open('$out/$4.json'))['time_s']['simulate'])"
}

# Lines "A B" of paired times in FILE: their medians, the median ratio B/A and its bootstrap
# 90 % interval: pair_summary FILE PREFIX NAME_A NAME_B
pair_summary() {
  python3 - "$@" <<'PY'
import random, statistics as st, sys
path, prefix, name_a, name_b = sys.argv[1:5]
pairs = [tuple(map(float, l.split())) for l in open(path)]
r = [y / x for x, y in pairs]
random.seed(1)
boot = sorted(st.median(random.choices(r, k=len(r))) for _ in range(2000))
print(f"{prefix}{len(r)} pairs: {name_a} median {st.median(p[0] for p in pairs):.3f} s, {name_b} median "
      f"{st.median(p[1] for p in pairs):.3f} s; B/A median {st.median(r):.3f}, 90 % interval [{boot[100]:.3f}, {boot[1899]:.3f}]")
PY
}
