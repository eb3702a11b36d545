#!/usr/bin/env bash
# Speed against accuracy, part of `make bench`:
#  1. riser_sim_bench_step_cost: cost of one step vs n per integrator / formulation / linear solve
#     -> out/bench/step_cost.csv;
#  2. riser_sim_bench_tradeoff: integrator x formulation x n x h (or tolerance) on the seven cases
#     (the five paper cases, the damped Table 1 line and J-lay), positions and force histories
#     -> out/bench/tradeoff.csv, references.csv; and the 3D swing (n = 5, 10, 20, end position; 5.5 min
#     of wall time under load, ~1.2 min of it stepping) -> out/bench/tradeoff_spatial.csv;
#  3. bench/plot_tradeoff.py -> out/bench/pareto_<case>.png, pareto.png, step_cost.png and the cheapest
#     setting per accuracy.
# By default a shorter sweep than the one in docs/benchmarks.md: n in {10, 20, 40, 100} (3D: 5, 10, 20), runs over 2 s of
# CPU skipped, step cost to n = 400 (11 min on the 2-core machine, 10.5 min of CPU, measured before the
# force histories; their references add ~4 min of CPU: the damped variants' and Table 1's n = 200 runs). RISER_SIM_TRADEOFF_FULL=1
# runs the documented sweep (every n to 1000, 20 s budget per run: 20 min of wall time on a quiet machine,
# 19 min of CPU, plus the full step cost table).
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bin=${RISER_SIM_WS:-.ws}/devel/lib/riser_sim
[ -x "$bin/riser_sim_bench_tradeoff" ] || bin=.ws/devel/lib/riser_sim
if [ ! -x "$bin/riser_sim_bench_tradeoff" ] || [ ! -x "$bin/riser_sim_bench_step_cost" ]; then
  echo "extra_tradeoff: benchmarks not built (make build)"
  exit 0
fi
mkdir -p out/bench
if [ "${RISER_SIM_TRADEOFF_FULL:-0}" = 1 ]; then
  cost_args=()
  sweep_args=()
else
  cost_args=(--max-n 400 --target 0.2)
  sweep_args=(--ns 5,10,20,40,100 --max-run 2)  # n = 5: the 3D swing's only
fi
echo "== Speed against accuracy: cost of one step vs n =="
"$bin/riser_sim_bench_step_cost" --out out/bench "${cost_args[@]}"
echo
echo "== Speed against accuracy: the trade per case =="
"$bin/riser_sim_bench_tradeoff" --out out/bench "${sweep_args[@]}"
/usr/bin/python3 bench/plot_tradeoff.py out/bench/tradeoff.csv out/bench
