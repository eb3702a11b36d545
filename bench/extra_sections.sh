#!/usr/bin/env bash
# Line sections (bench/sections_cost.py): a sectioned scene's cost per step against its uniform twin, and
# lazy_wave_fpso.yaml's real-time factor at its recommended setting; writes out/bench/sections_cost.csv,
# lazy_wave_fpso.csv and the tables out/bench/tables/sections_cost.md, lazy_wave_fpso.md (docs/benchmarks.md
# "Line sections"). ~2 min.
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cli=${RISER_SIM_CLI:-"$root/.ws/devel/lib/riser_sim/riser_sim_cli"}  # RISER_SIM_CLI: another build
echo "== Line sections: cost per step against a uniform line; the lazy-wave FPSO's RTF =="
/usr/bin/python3 "$root/bench/sections_cost.py" --cli "$cli" --repeat 3
