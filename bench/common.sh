# Sourced by the bench/run_*.sh scripts after they cd to the repository root: REPEAT (runs per
# figure, default 3), a scratch directory $out removed on exit, and median() of the numbers on
# standard input.
REPEAT=${REPEAT:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
