#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine: install what Glint needs (only what is
# missing, so a second run is quick), build Release, then either render the built-in scene
# or run the whole test suite.
#
#   scripts/setup.sh render   # -> spheres.png
#   scripts/setup.sh test     # ctest, as CI runs it
set -euo pipefail

mode=${1:-render}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${GLINT_BUILD_DIR:-"$root/build"}
cd "$root"

packages=(
  cmake ninja-build g++ pkg-config
  libtbb-dev libopenimageio-dev openimageio-tools libopenexr-dev zlib1g-dev libpng-dev libjpeg-dev libassimp-dev libtomlplusplus-dev
  libcli11-dev libfmt-dev libpcg-cpp-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libembree-dev
  clang libclang-rt-14-dev  # libFuzzer and sanitizers for the fuzz targets (fuzz/)
  libsdl2-dev libimgui-dev xvfb xauth  # glint view, and its tests in a virtual display
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module (python/) and its tests
  libopenmpi-dev openmpi-bin  # one frame across processes: mpirun -np N glint render (docs/scale-out.md)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build_dir" -j "$(nproc)"

case "$mode" in
  render)
    "$build_dir/glint" render -o spheres.png
    ;;
  test)
    ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)"
    ;;
  *)
    echo "usage: scripts/setup.sh [render|test]" >&2
    exit 2
    ;;
esac
