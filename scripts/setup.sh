#!/usr/bin/env bash
# Installs the Debian 12 packages penumbra needs, only those missing (idempotent).
# `setup.sh fuzz` adds what `make fuzz` needs: clang, libFuzzer, llvm-cov.
set -euo pipefail
packages=(
  cmake g++ make pkg-config
  libglfw3-dev libglm-dev libimgui-dev libtinygltf-dev nlohmann-json3-dev
  libopenimageio-dev openimageio-tools libepoxy-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri
  xvfb xauth libcli11-dev googletest libgtest-dev assimp-testmodels
  xdotool  # real X input events in the window tests (tests/window/real_input_combo.sh)
  libembree-dev
  libcairo2-dev  # the bench report's charts as PNG, SVG and PDF (app/bench/plot.cpp)
  graphviz  # docs/stage_graph.svg from `penumbra graph` (README, layout)
  libgsl-dev  # chi-square and normal distributions of the hash statistics (app/stats/hash_stats.cpp)
  dieharder  # the real DIEHARD battery: penumbra hash-stats --dieharder (docs/hash_stats.md)
  ffmpeg  # the MP4s and GIFs of penumbra export --time-range and the window's Record; ffprobe in the tests
  glslang-tools  # glslangValidator: every shader variant checked by a second compiler (tests/gl)
)
if [ "${1:-}" = fuzz ]; then packages+=(clang libfuzzer-14-dev llvm-14); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
