#!/usr/bin/env bash
# Phellem's one set-up script: installs the Debian 12 packages the build needs (only the
# missing ones), builds in Release with ccache, then either renders the embedded default
# scene or runs the whole test suite.
#
#   scripts/setup.sh render   # install + build + render out/default.exr and out/default.png
#   scripts/setup.sh test     # install + build + ctest
set -euo pipefail
cd "$(dirname "$0")/.."

# Every package the project builds, links, tests and benchmarks against. Nothing else is
# needed on a fresh Debian 12 machine.
PACKAGES=(
  build-essential cmake ccache pkg-config git
  libembree-dev libopenimageio-dev openimageio-tools libopenexr-dev libopencolorio-dev
  libeigen3-dev libtinygltf-dev libtinyobjloader-dev libtbb-dev nlohmann-json3-dev libcgal-dev
  libgtest-dev libgmock-dev libbenchmark-dev libnlopt-cxx-dev chromium
  libglfw3-dev libepoxy-dev libegl-dev libgl1-mesa-dri glslang-tools xvfb xauth libtet1.5-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "phellem setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

LAUNCHER=()
command -v ccache >/dev/null && LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Paths relative to the checkout in ccache's keys: a fresh clone elsewhere (CI) reuses the cache.
export CCACHE_BASEDIR="$PWD"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${LAUNCHER[@]}"
cmake --build build -j2

case "${1:-render}" in
  render)
    mkdir -p out
    ./build/phellem render -o out/default.exr --png out/default.png --stats out/default_stats.json
    echo "phellem setup: wrote out/default.exr and out/default.png"
    ;;
  test)
    ctest --test-dir build --output-on-failure -j2
    ;;
  *)
    echo "usage: scripts/setup.sh render|test" >&2
    exit 2
    ;;
esac
