#!/usr/bin/env bash
# Soak run: riser_sim_node on the J-lay scene for an hour of simulated time, driven through
# /clock as fast as it keeps up (bench/soak.py), on a private roscore. Writes out/soak/soak.csv and
# out/soak/soak.txt (summary: RSS, step time first vs last 5 min, energy and constraint error bounds).
#   bench/soak.sh [simulated_seconds] [scene]        (make soak; needs make build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
duration=${1:-3600}
scene=${2:-$root/config/scenes/paper_jlay_170m.yaml}
node_bin="$ws/devel/lib/riser_sim/riser_sim_node"
[ -x "$node_bin" ] || { echo "soak: $node_bin not built (run make build)" >&2; exit 1; }
out="$root/out/soak"
mkdir -p "$out"

source "$root/bench/private_master.sh" "$out/roscore.log"
rosparam set /use_sim_time true
/usr/bin/python3 "$root/bench/soak.py" --node "$node_bin" --scene "$scene" --duration "$duration" --csv "$out/soak.csv"
