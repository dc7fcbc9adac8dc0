#!/usr/bin/env bash
# Reproduces the README's throughput figures (default scene and a ≥2M-triangle scene).
set -euo pipefail
cd "$(dirname "$0")/.."
./build/bench/phellem_bench_throughput --spp 16 --res 480x320 --repeat 3
echo
./build/bench/phellem_bench_throughput bench/scenes/two_million.json --spp 8 --res 480x320 --repeat 3
