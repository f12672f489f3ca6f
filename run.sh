#!/usr/bin/env bash
# One command for a fresh Debian 12 machine: installs what is missing, builds, and then
#   ./run.sh demo   runs pcl_multi_instance_discovery on the sample scene shipped in data/
#   ./run.sh test   runs the whole test suite
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(cmake g++ make pkg-config libpcl-dev libopencv-dev libvtk9-dev libeigen3-dev
          libflann-dev libboost-dev libboost-graph-dev libgtest-dev libbenchmark-dev
          xvfb xauth)
BUILD_DIR=${MID_BUILD_DIR:-build}
JOBS=${MID_JOBS:-2}

install_missing_packages() {
  local missing=()
  for package in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "Installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "$@"
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

case "${1:-}" in
  demo)
    install_missing_packages
    build
    "$BUILD_DIR/apps/pcl_multi_instance_discovery" data/sample_scene/scene.pcd
    ;;
  test)
    install_missing_packages
    build -DMID_WARNINGS_AS_ERRORS=ON
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
    ;;
  *)
    echo "usage: $0 demo|test" >&2
    exit 2
    ;;
esac
