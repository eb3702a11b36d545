#!/usr/bin/env bash
# Installs the Debian packages riser_sim needs (ROS 1 from Debian itself); skips when all are present.
set -euo pipefail
PKGS=(build-essential cmake catkin ros-core-dev libroscpp-dev librostest-dev python3-rostest rosbash
  libtf2-ros-dev libvisualization-msgs-dev libgeometry-msgs-dev libnav-msgs-dev libstd-srvs-dev
  ros-std-srvs libdiagnostic-msgs-dev ros-diagnostic-msgs ros-message-generation ros-message-runtime
  libeigen3-dev libyaml-cpp-dev libgtest-dev googletest python3-rosbag python3-matplotlib python3-numpy
  python3-yaml python3-geometry-msgs python3-visualization-msgs python3-tf2-msgs python3-diagnostic-msgs
  python3-rostopic python3-rosservice python3-rosmaster python3-roslaunch
  libnodeletlib-dev libnodelet-dev libnodeletlib-tools pluginlib-dev libclass-loader-dev
  clang-14 libclang-rt-14-dev clang-format-14 python3-distributed)
# clang-14 compiles the sanitizer build of make test (tools/test_sanitize.sh) and the scene fuzzer (make
# fuzz); its ASan/UBSan/libFuzzer runtime is libclang-rt-14-dev, only recommended by clang-14.
# clang-format-14: the code's format (.clang-format; tools/format.sh, checked by make test).
# python3-distributed: riser_sim_sweep's Dask clusters (docs/sweep.md; it brings python3-dask).
if [ "${RISER_SIM_GUI_DEPS:-0}" = 1 ]; then PKGS+=(rviz xvfb xauth ffmpeg); fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# --missing: print the missing packages and stop (the Makefile's deps target installs them).
if [ "${1:-}" = "--missing" ]; then echo "${missing[*]}"; exit 0; fi
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "installing: ${missing[*]}"
SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
