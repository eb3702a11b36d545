#!/usr/bin/env bash
# make bench: is the step cost of the shipped scenes unchanged within 3 % of the saved baseline
# (out/bench/step_cost_baseline.csv: make bench-baseline, on the revision to compare against)?
# riser_sim_bench_step_cost --compare: ratio and verdict per scene (bench/step_cost_check.h), ~15 s.
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bin=${RISER_SIM_WS:-.ws}/devel/lib/riser_sim/riser_sim_bench_step_cost
baseline=${RISER_SIM_STEP_BASELINE:-out/bench/step_cost_baseline.csv}  # RISER_SIM_STEP_BASELINE: another baseline file
echo "== Step cost of the shipped scenes against the baseline =="
if [ ! -x "$bin" ]; then
  echo "extra_step_cost_check: $bin not built (make build)"
  exit 0
fi
if [ ! -f "$baseline" ]; then
  echo "extra_step_cost_check: no $baseline: make bench-baseline (on the revision to compare against) writes it"
  exit 0
fi
"$bin" --compare --baseline "$baseline"
