#!/usr/bin/env bash
# make bench: every benchmark; tables to stdout and to out/bench/tables/<name>.md, CSV/PNG to out/bench/.
# At the end bench/update_docs.py puts the tables into docs/benchmarks.md (RISER_SIM_BENCH_DOCS=0: not).
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mkdir -p out/bench
export RISER_SIM_BENCH_TABLES=${RISER_SIM_BENCH_TABLES:-$root/out/bench/tables}
tables=$RISER_SIM_BENCH_TABLES
mkdir -p "$tables"
rm -f "$tables"/*.md  # only this run's tables are fresh
# One machine / date / revision line for every table of the run.
RISER_SIM_BENCH_STAMP=$(/usr/bin/python3 bench/bench_tables.py stamp)
export RISER_SIM_BENCH_STAMP
/usr/bin/python3 bench/bench_tables.py machine "make bench"
echo "== $RISER_SIM_BENCH_STAMP =="
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
if [ "${RISER_SIM_BENCH_DOCS:-1}" != 0 ]; then
  echo; echo "== docs/benchmarks.md =="
  /usr/bin/python3 bench/update_docs.py --tables "$tables"
fi
