#!/usr/bin/env bash
# The edit-test loop: the ROS-free core, the CLI and their gtests (Release, no catkin) in .ws/check,
# then ctest. Long validation runs are skipped unless RISER_SIM_LONG=1 (they run in make test).
# Arguments go to ctest (e.g. -R statics).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${RISER_SIM_CHECK_DIR:-$root/.ws/check}
mkdir -p "$(dirname "$build")"  # a fresh clone has no .ws yet (the cmake log goes beside the build dir)
cmake -S "$root" -B "$build" -DRISER_SIM_CORE_ONLY=ON -DCMAKE_BUILD_TYPE=Release >"$build.cmake.log" 2>&1 ||
  { cat "$build.cmake.log"; echo "0 passed, 1 failed"; exit 1; }
cmake --build "$build" -j"$(nproc)" 2>&1 | grep -E "error|warning:" | head -n 40
[ "${PIPESTATUS[0]}" = 0 ] || { echo "check: build failed"; echo "0 passed, 1 failed"; exit 1; }
# RISER_SIM_CHECK=1: the long tests skip themselves unless RISER_SIM_LONG=1.
cd "$build" && RISER_SIM_CHECK=1 ctest --output-on-failure -j"$(nproc)" "$@"
