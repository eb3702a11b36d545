#!/usr/bin/env bash
# make bench: every benchmark, tables to stdout, CSV/PNG to out/bench/.
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mkdir -p out/bench
echo "== Paper Table 1 =="
bench/paper_table1.py --repeat 3
if [ -x .ws/devel/lib/riser_sim/riser_sim_bench_formulations ]; then
  echo; echo "== Formulations: wall time vs n =="
  .ws/devel/lib/riser_sim/riser_sim_bench_formulations
fi
for extra in bench/extra_*.sh; do [ -x "$extra" ] && { echo; "$extra"; }; done
if [ -x bench/node_bench.sh ] && [ "${RISER_SIM_BENCH_NODE:-1}" = 1 ]; then
  echo; echo "== Node real-time factor =="
  bench/node_bench.sh
fi
