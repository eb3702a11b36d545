#!/usr/bin/env bash
# Builds the catkin workspace in .ws/ (the repo root is the package, linked as .ws/src/riser_sim).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
mkdir -p "$ws/src"
[ -e "$ws/src/riser_sim" ] || ln -s "$root" "$ws/src/riser_sim"
cd "$ws"
# ROS setup scripts read unset variables; keep -u off while sourcing them.
set +u
catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release "$@"
