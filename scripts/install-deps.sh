#!/usr/bin/env bash
# Installs the Debian 12 packages planar-mapper needs to build, test and run.
# MRPT is installed as its individual -dev components (the libmrpt-dev
# metapackage would drag in ROS). Uses sudo when not run as root.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake clang-format
  libmrpt-obs-dev libmrpt-maps-dev libmrpt-slam-dev libmrpt-opengl-dev libmrpt-gui-dev
  libmrpt-graphs-dev
  libmrpt-tclap-dev mrpt-common
  libeigen3-dev libopencv-dev libceres-dev liboctomap-dev nlohmann-json3-dev zlib1g-dev
  libgtest-dev libbenchmark-dev
  # report/ pictures: MRPT's offscreen renderer through EGL on Mesa (no X server)
  libegl1 libegl-mesa0 libgl1-mesa-dri
  # tests: Coin3D reads map.wrl back (VRML97); Coin loads PNG textures through simage
  libcoin-dev libsimage-dev
  # tests: viewer.html in headless Chromium; planar-mapper --gui in Xvfb
  chromium xvfb xauth
  # scripts/gui-screenshot.sh: grabs the Xvfb screen
  x11-apps netpbm
  # scripts/fuzz.sh: libFuzzer comes with clang's runtime libraries
  clang libclang-rt-14-dev
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${packages[@]}"

# npm packages, pinned by their lock files (Node.js 20 and npm come with the
# machine image; Debian 12's own nodejs is too old for playwright-core):
#   tools/web: three + esbuild bundle viewer.html at build time (configure
#              needs them), gltf-validator checks map.glb in the tests;
#   tools/viewer: playwright-core drives Chromium in the viewer tests.
if ! command -v npm > /dev/null; then
  echo "install-deps: npm not found: install Node.js >= 20 with npm" >&2
  exit 1
fi
npm ci --prefix tools/web --no-audit --no-fund
npm ci --prefix tools/viewer --no-audit --no-fund
