#!/usr/bin/env bash
# Builds and runs every test (gtest + rostest, the core's gtests under sanitizers; RISER_SIM_FUZZ_SECONDS=N
# adds an N s scene fuzz run with clang-14);
# exits non-zero on any failure and ends with "N passed, N failed".
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
phase() { echo "time: $1 done at ${SECONDS} s"; }  # where CI's minutes go
# The core gtests of tools/sanitize_tests.txt run under the sanitizers below, not in Release (each test file
# is compiled once); RISER_SIM_SANITIZE=0 builds and runs them all here.
skip=""
[ "${RISER_SIM_SANITIZE:-1}" != 0 ] && skip=$(grep -v '^#' "$root/tools/sanitize_tests.txt" | tr '\n' ' ')
RISER_SIM_SKIP_TESTS="$skip" "$root/tools/build.sh" -j2 all tests || { echo "0 passed, 1 failed"; exit 1; }
phase "catkin build"
cd "$ws"
# The sanitizer (and fuzzer) builds (~14 min of CPU) compile at the lowest priority while the tests below
# run: the rostests mostly wait on real time. Their steps further down then find them built.
prebuild_pid=""
if [ "${RISER_SIM_SANITIZE:-1}" != 0 ] || [ "${RISER_SIM_FUZZ_SECONDS:-0}" != 0 ]; then
  (
    [ "${RISER_SIM_SANITIZE:-1}" != 0 ] && RISER_SIM_SANITIZE_BUILD_ONLY=1 nice -n 19 "$root/tools/test_sanitize.sh"
    [ "${RISER_SIM_FUZZ_SECONDS:-0}" != 0 ] && nice -n 19 make -C "$root" --no-print-directory -j2 -f test/fuzz/Makefile build
  ) >"$ws/prebuild.log" 2>&1 &
  prebuild_pid=$!
fi
rm -rf build/test_results
set +u
source devel/setup.bash
catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 run_tests -j1 >"$ws/run_tests.log" 2>&1
rc_run=$?
phase "gtests and rostests"
grep -E "^\[ +(RUN|OK|FAILED|PASSED) +\]|FAILURE|Error|error:" "$ws/run_tests.log" | grep -v "^\[ RUN" | tail -n 200
# The install space on its own (test/install/install_space.sh): the CLI on every scene, the launch file, a
# downstream package linking the core. After run_tests: it builds the install target in the same workspace.
RISER_SIM_SKIP_TESTS="$skip" RISER_SIM_WS="$ws" "$root/test/install/install_space.sh" "$ws/build/test_results" \
  >"$ws/install_space_run.log" 2>&1
grep -E "^install space: " "$ws/install_space_run.log"
phase "install space"
[ -n "$prebuild_pid" ] && wait "$prebuild_pid"  # a failed build is reported by its step below
phase "sanitizer and fuzzer builds"
# The core's and the CLI's gtests again under ASan + UBSan (docs/hardening.md); their JUnit files go
# next to catkin's, so the line below counts them. RISER_SIM_SANITIZE=0 skips this step.
rc_san=0
if [ "${RISER_SIM_SANITIZE:-1}" != 0 ]; then
  "$root/tools/test_sanitize.sh" "$ws/build/test_results/sanitize" >"$ws/test_sanitize.log" 2>&1
  rc_san=$?
  grep -E "^sanitize: |ERROR: |runtime error:" "$ws/test_sanitize.log" | head -n 40
  echo "sanitizers: $(tail -n 1 "$ws/test_sanitize.log") (see $ws/test_sanitize.log)"
  phase "sanitizer tests"
fi
# Optional libFuzzer run on the scene loader (docs/hardening.md): builds out/fuzz/fuzz_scene (clang-14)
# and fuzzes from the seeds and regressions for RISER_SIM_FUZZ_SECONDS (default 0: skipped; the
# seeds and regressions replay as gtests anyway) with a fixed seed, so a failure reproduces. One test case.
rc_fuzz=0
fuzz_s=${RISER_SIM_FUZZ_SECONDS:-0}
if [ "$fuzz_s" != 0 ]; then
  make -C "$root" --no-print-directory -j2 -f test/fuzz/Makefile run FUZZ_SECONDS="$fuzz_s" FUZZ_FLAGS=-seed=1 \
    >"$ws/fuzz.log" 2>&1
  rc_fuzz=$?
  mkdir -p build/test_results/fuzz
  failure=""
  if [ $rc_fuzz -ne 0 ]; then
    failure="<failure message=\"exit $rc_fuzz: see $ws/fuzz.log\"/>"
    grep -E "scene fuzz defect|ERROR: |runtime error:|Test unit written|fuzz: " "$ws/fuzz.log" | head -n 20
  fi
  printf '%s\n' '<?xml version="1.0" encoding="UTF-8"?>' "<testsuites><testsuite name=\"fuzz\" tests=\"1\">" \
    "<testcase name=\"scene_${fuzz_s}s\" classname=\"fuzz\">$failure</testcase></testsuite></testsuites>" \
    >build/test_results/fuzz/fuzz_scene.xml
  echo "fuzz: $(grep -E "^Done [0-9]+ runs" "$ws/fuzz.log" | tail -n 1) (see $ws/fuzz.log)"
  phase "fuzz"
fi
# The code's format (.clang-format): one JUnit case, failed naming the files that differ (make format fixes them).
"$root/tools/format.sh" --check build/test_results/format | tail -n 21
rc_fmt=${PIPESTATUS[0]}
/usr/bin/python3 "$root/tools/count_results.py" build/test_results
rc_count=$?
catkin_test_results build/test_results >/dev/null 2>&1
rc_res=$?
if [ $rc_run -ne 0 ] || [ $rc_fmt -ne 0 ] || [ $rc_res -ne 0 ] || [ $rc_count -ne 0 ] || [ $rc_san -ne 0 ] || [ $rc_fuzz -ne 0 ]; then
  echo "(see $ws/run_tests.log)"
  /usr/bin/python3 "$root/tools/count_results.py" build/test_results --line-only
  exit 1
fi
/usr/bin/python3 "$root/tools/count_results.py" build/test_results --line-only
