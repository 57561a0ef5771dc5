#!/usr/bin/env bash
# Installs the Debian 12 packages planar-mapper needs to build, test and run.
# MRPT is installed as its individual -dev components (the libmrpt-dev
# metapackage would drag in ROS). Uses sudo when not run as root.
set -euo pipefail

packages=(
  build-essential cmake clang-format
  libmrpt-obs-dev libmrpt-maps-dev libmrpt-slam-dev libmrpt-opengl-dev libmrpt-gui-dev
  libmrpt-tclap-dev mrpt-common
  libeigen3-dev libopencv-dev libceres-dev liboctomap-dev nlohmann-json3-dev zlib1g-dev
  libgtest-dev libbenchmark-dev
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${packages[@]}"
