#!/usr/bin/env bash
# Builds the catkin workspace in .ws/. The repo root is the package: .ws/src/riser_sim holds a link to each of
# its top-level entries but not to .ws itself, so tools that search the package tree (rosrun's find -L,
# rospack) never walk into the workspace (a link to the whole root made a loop and duplicate executables).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
mkdir -p "$ws/src"
pkg=$ws/src/riser_sim
[ -L "$pkg" ] && rm "$pkg"  # the earlier layout: one link to the whole root
mkdir -p "$pkg"
for entry in "$root"/*; do
  [ "$entry" -ef "$ws" ] || ln -sfn "$entry" "$pkg/$(basename "$entry")"
done
find "$pkg" -maxdepth 1 -xtype l -delete  # entries removed from the root
cd "$ws"
# ROS setup scripts read unset variables; keep -u off while sourcing them.
set +u
# RISER_SIM_SKIP_TESTS (space-separated core gtests not to build; tools/test.sh) is passed every time, so
# a later build without it builds them all again.
skip=${RISER_SIM_SKIP_TESTS:-}
catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release -DRISER_SIM_SKIP_TESTS="${skip// /;}" "$@"
