#!/usr/bin/env bash
# Builds and runs every test (gtest + rostest); exits non-zero on any failure and ends with
# "N passed, N failed".
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
"$root/scripts/build.sh" -j2 all tests || { echo "0 passed, 1 failed"; exit 1; }
cd "$ws"
rm -rf build/test_results
set +u
source devel/setup.bash
catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 run_tests -j1 >"$ws/run_tests.log" 2>&1
rc_run=$?
grep -E "^\[ +(RUN|OK|FAILED|PASSED) +\]|FAILURE|Error|error:" "$ws/run_tests.log" | grep -v "^\[ RUN" | tail -n 200
/usr/bin/python3 "$root/scripts/count_results.py" build/test_results
rc_count=$?
catkin_test_results build/test_results >/dev/null 2>&1
rc_res=$?
if [ $rc_run -ne 0 ] || [ $rc_res -ne 0 ] || [ $rc_count -ne 0 ]; then
  echo "(see $ws/run_tests.log)"
  /usr/bin/python3 "$root/scripts/count_results.py" build/test_results --line-only
  exit 1
fi
/usr/bin/python3 "$root/scripts/count_results.py" build/test_results --line-only
