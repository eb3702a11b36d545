#!/usr/bin/env bash
# The core's and the CLI's gtests under AddressSanitizer + UndefinedBehaviorSanitizer (clang-14, any finding
# aborts), built without catkin (RISER_SIM_CORE_ONLY) in its own directory. Eigen's and libstdc++'s
# bounds assertions are on too (no NDEBUG, _GLIBCXX_ASSERTIONS). -O1 (RISER_SIM_SANITIZE_OPT): compiles ~1/3
# faster than -O2 and the tests ran no slower. RISER_SIM_SANITIZE_TEST_OPT (cmake/core.cmake's RISER_SIM_TEST_OPT)
# sets the test drivers' level alone; default: the build's -O1. -O0 compiled them in 53 s of CPU instead of 143 s
# but five of them ran in 70 s instead of 29 s (docs/hardening.md): not the default.
# Compiler: clang++-14 (tools/install_deps.sh installs it and its sanitizer runtime, libclang-rt-14-dev):
# under ASan it compiles the core in less CPU than gcc (docs/hardening.md). Without a clang that can link a
# sanitized program, g++ (with a message). RISER_SIM_SANITIZE_CXX names the compiler (e.g. g++).
#   tools/test_sanitize.sh [RESULTS_DIR]
# Writes one JUnit XML per test binary to RESULTS_DIR (sanitize-<test>.xml; a binary stopped by a
# sanitizer gets a failing one), prints "N passed, N failed" and exits non-zero on any failure.
# RISER_SIM_SANITIZE_TESTS: the test binaries built and run (default: those of tools/sanitize_tests.txt,
# every test in them; `make test` builds the others in Release only). 'all' builds and runs every one with
# the filter below.
# RISER_SIM_SANITIZE_FILTER: gtest filter. With all binaries the default leaves out the long runs that only repeat per-step
# code the other tests cover (Table 1: 20 s runs at n = 10..40 and h/2; a simulated hour; 20 s energy and
# added-mass runs): ~3/4 of the CPU time under ASan. '*' runs everything (docs/hardening.md).
# RISER_SIM_SANITIZE_JOBS: test binaries run at once (default 2). RISER_SIM_SANITIZE_BUILD_ONLY=1: build, run nothing.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
build=${RISER_SIM_SANITIZE_BUILD:-$ws/sanitize}
results=${1:-$build/test_results}
mkdir -p "$(dirname "$build")"
cxx=""
for c in ${RISER_SIM_SANITIZE_CXX:-clang++-14 clang++ g++}; do
  command -v "$c" >/dev/null 2>&1 || continue
  echo 'int main() { return 0; }' | "$c" -x c++ -fsanitize=address,undefined - -o "$build.probe" >/dev/null 2>&1 &&
    { cxx=$c; break; }
done
rm -f "$build.probe"
[ -n "$cxx" ] || { echo "sanitize: no compiler links -fsanitize=address,undefined"; echo "0 passed, 1 failed"; exit 1; }
[[ "$cxx" == clang* ]] || echo "sanitize: using $cxx (no clang with its sanitizer runtime: make deps installs clang-14 libclang-rt-14-dev)"
# A build directory configured with another compiler starts again (CMake cannot switch it in place).
[ -f "$build/CMakeCache.txt" ] && [ "$(cat "$build/.riser_sim_cxx" 2>/dev/null)" != "$cxx" ] && rm -rf "$build"
mkdir -p "$build" && echo "$cxx" >"$build/.riser_sim_cxx"
# -g1: line tables, enough for the sanitizers' stack traces (clang's -g1 is -gline-tables-only).
flags="${RISER_SIM_SANITIZE_OPT:--O1} -g1 -fno-omit-frame-pointer -D_GLIBCXX_ASSERTIONS"
flags+=" -fsanitize=address,undefined -fno-sanitize-recover=all"

default_tests=$(grep -v '^#' "$root/tools/sanitize_tests.txt" | tr '\n' ' ')
tests=${RISER_SIM_SANITIZE_TESTS:-$default_tests}
[ "$tests" = all ] && tests=""
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DRISER_SIM_CORE_ONLY=ON -DCMAKE_BUILD_TYPE=Sanitize -DRISER_SIM_TESTS="${tests// /;}" \
  -DRISER_SIM_TEST_OPT="${RISER_SIM_SANITIZE_TEST_OPT-}" \
  -DCMAKE_CXX_FLAGS_SANITIZE="$flags" -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
  >"$build.cmake.log" 2>&1 || { cat "$build.cmake.log"; echo "0 passed, 1 failed"; exit 1; }
cmake --build "$build" -j2 >"$build.build.log" 2>&1 || {
  grep -E "error|Error" "$build.build.log" | head -n 40; echo "(see $build.build.log)"; echo "0 passed, 1 failed"; exit 1; }
[ "${RISER_SIM_SANITIZE_BUILD_ONLY:-0}" = 1 ] && { echo "sanitize: built in $build"; exit 0; }

rm -rf "$results"
mkdir -p "$results"
long="Table1.*:Extremes.OneHourMidpointEnergyBounded"
long+=":FormulationsAgree.Table1EndPositionAfter20s:FormulationsAgree.EnergyConservedInConservativeCase"
long+=":Energy.ConservativeRunKeepsEnergy:HydroDynamics.AddedMassAndBuoyancyScaleThePeriod"
# Sweeps of the same steps over integrator x formulation x h (Release: 40 / 30 / 10 / 4 / 3 s, under ASan
# 10x): NoAlloc, PinnedImplicit.AtRestStaysAtRest and the short tests run every combination once.
long+=":Extremes.Table:Extremes.OneHourAbsoluteConstraintBounded:PinnedImplicit.MovingTopAgreesWithReference"
long+=":ImplicitTerms.SecondOrderWithEveryTerm:GeneralizedAlpha.JlayTensionAtLargeStep"
# The 3D runs of thousands of small steps (under ASan 22-148 s each): the spatial no-allocation, force,
# solve and short agreement tests run the same per-step code.
long+=":SpatialIndependent.*:SpatialIndependentCharts.WhirlThroughVerticalKeepsEnergyBalance"
long+=":SpatialPendulum.*:SpatialShifted.StructuredSchemesAreSecondOrder:SpatialFlexJoint.*"
long+=":SpatialTorsion.Pendulum*:SpatialTorsion.LightLine*:SpatialTorsion.EnergyBalanceExplicit"
long+=":SpatialTorsion.ImplicitSchemesStaySecondOrder:SpatialTorsion.Axial*:SpatialTorsion.Charts*"
# The 3D ends' runs to rest through the CLI (40 s at 0.5 ms; 23 s each under ASan).
long+=":CliSpatialEnds.FlexJointTopMomentBalancesTheWeight:CliSpatialEnds.PinnedBottomForceAndMoment"
# Whole-scene runs through the CLI and long energy balances (11-15 s each under ASan); the per-step code they
# run is covered by the short tests. Every shipped scene's statics in process and the planar ones' 0.5 s in 3D
# against 2D (test_cli_shipped_scenes: 99 s and 53 s under ASan): Cli.EveryShippedSceneRuns and
# CliSpatial.PlanarScenesRunThroughTheSpatialPath run each scene's statics and first steps.
long+=":SceneYaml.EveryShippedSceneParsesAndBuilds"
long+=":CliSpatial.PlanarScenesThroughTheSpatialPath:CliSpatial.YawedSceneGivesTheRotatedResult"
long+=":TermData.SimulatorsSharingAModelRunIndependently:HydroInternalFlow.EnergyBalanceHoldsWithConstantAndAcceleratingFlow"
# The listed binaries are short: every test in them runs (their tests run nowhere else in make test).
default_filter="-$long"
[ -n "$tests" ] && default_filter="*"
export GTEST_FILTER=${RISER_SIM_SANITIZE_FILTER:-$default_filter}
# allow_addr2line: clang's runtime symbolizes with llvm-symbolizer (package llvm-14, not installed by
# install_deps.sh), else with binutils' addr2line only when allowed.
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:strict_string_checks=1:allow_addr2line=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:allow_addr2line=1"
export root build results

# One test binary. A sanitizer stops it before (or after) gtest writes its XML: a failed run without a
# <failure> in its XML gets a failing one of its own.
run_one() {
  local bin=$1 name xml log status reason
  name=$(basename "$bin")
  xml="$results/sanitize-$name.xml"
  log="$build/$name.log"
  (cd "$root" && "$bin" --gtest_output="xml:$xml") >"$log" 2>&1
  status=$?
  [ $status -eq 0 ] && return 0
  grep -E "^\[  FAILED  \]|ERROR: (Address|Leak)Sanitizer|runtime error:|SUMMARY:" "$log" | head -n 20
  if ! grep -q "<failure" "$xml" 2>/dev/null; then
    reason=$(grep -m1 -E "ERROR: (Address|Leak)Sanitizer|runtime error:|SUMMARY:" "$log" | sed 's/[<>&"]/_/g')
    printf '%s\n' '<?xml version="1.0" encoding="UTF-8"?>' \
      '<testsuites tests="1" failures="1"><testsuite name="sanitize" tests="1" failures="1">' \
      "<testcase name=\"$name\" classname=\"sanitize\"><failure message=\"exit status $status: ${reason:-see $log}\"/></testcase>" \
      '</testsuite></testsuites>' >"$results/sanitize-$name-exit.xml"
  fi
  echo "sanitize: $name failed (exit $status, see $log)"
  return 1
}
export -f run_one
# The longest first, two at a time (test_cli: every shipped scene, ~100 s under ASan).
first=" test_cli test_extremes test_formulations_agree test_energy test_hydro_dynamics test_cli_spatial test_modal "
{
  for n in $first; do
    [ -x "$build/tests/$n" ] && { [ -z "$tests" ] || [[ " $tests " == *" $n "* ]]; } && echo "$build/tests/$n"
  done
  for b in "$build"/tests/test_*; do
    n=$(basename "$b")
    [[ "$first" == *" $n "* ]] && continue
    [ -z "$tests" ] || [[ " $tests " == *" $n "* ]] && echo "$b"  # not a binary left from another selection
  done
} | xargs -P "${RISER_SIM_SANITIZE_JOBS:-2}" -I{} bash -c 'run_one "$1"' _ {}
rc=$?
/usr/bin/python3 "$root/tools/count_results.py" "$results" --line-only
[ $rc -eq 0 ] || exit 1
