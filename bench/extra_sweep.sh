#!/usr/bin/env bash
# riser_sim_sweep: speedup of a sweep with 2 local Dask workers against 1 (8 cases of ~1 s) and the overhead
# per case beyond the CLI process (bench/sweep_bench.py); writes out/bench/sweep.csv and the table
# out/bench/tables/sweep.md (bench_tables.py; docs/benchmarks.md "Sweeps").
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cli=${RISER_SIM_CLI:-"$root/.ws/devel/lib/riser_sim/riser_sim_cli"}  # RISER_SIM_CLI: another build
mkdir -p "$root/out/bench"
echo "== riser_sim_sweep: 2 workers against 1, overhead per case =="
/usr/bin/python3 "$root/bench/sweep_bench.py" --cli "$cli" --tool "$root/src/riser_sim_sweep/riser_sim_sweep" \
  --out "$root/out/bench" | tee "$root/out/bench/sweep.md" |
  /usr/bin/python3 "$root/bench/bench_tables.py" write sweep "bench/extra_sweep.sh"
cat "$root/out/bench/sweep.md"
