#!/usr/bin/env bash
# Renders the reference images for tests/renderer/test_image_regression.cpp at 4096 spp.
# Rerun only when a rendering change is intended, and look at the results before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
for s in spheres_env box_area_light displaced_trunk strip_tree stress_trunk; do
  ./build/phellem render tests/scenes/$s.json --spp 4096 -o reference_images/$s.exr --png reference_images/$s.png --quiet
done
