#!/usr/bin/env bash
# Speed against accuracy (issue 5): integrator x formulation x n x h sweep on the Table 1 line,
# out/bench/tradeoff.csv + out/bench/pareto.png. About 5 min on 2 cores.
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
exe=${RISER_SIM_WS:-.ws}/devel/lib/riser_sim/riser_sim_bench_tradeoff
[ -x "$exe" ] || exe=.ws/devel/lib/riser_sim/riser_sim_bench_tradeoff
if [ ! -x "$exe" ]; then echo "extra_tradeoff: $exe not built (make build)"; exit 0; fi
echo "== Speed against accuracy: integrators (issue 5) =="
mkdir -p out/bench
"$exe" --out out/bench/tradeoff.csv
/usr/bin/python3 bench/plot_tradeoff.py out/bench/tradeoff.csv out/bench/pareto.png
