#!/usr/bin/env bash
# Load figure: the largest number of risers that run at real-time factor >= 0.99, as separate
# riser_sim_node processes and as nodelets in one manager, with the vessel at 100 Hz (bench/many_risers.py).
# Scene: the paper's 500 m riser (config/scenes/paper_riser_500m.yaml: n = 50, rk4, dt = 1 ms, drag and
# added mass), its top driven by the vessel. Private roscore; out/bench/many_risers.csv and logs.
#   bench/many_risers.sh [nodes|nodelets|both] [window_s]       (~10-20 min for both; needs make build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
modes=${1:-both}
window=${2:-20}
scene=${RISER_SIM_MANY_SCENE:-$root/config/scenes/paper_riser_500m.yaml}
[ -e "$ws/devel/lib/libriser_sim_nodelets.so" ] || { echo "many_risers: not built (run make build)" >&2; exit 1; }
out="$root/out/bench"
mkdir -p "$out"
rm -f "$out/many_risers.csv"

source "$root/bench/private_master.sh" "$out/many_risers_roscore.log"
echo "many_risers: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start; scene $(basename "$scene")"
[ "$modes" = both ] && modes="nodes nodelets"
for m in $modes; do
  /usr/bin/python3 "$root/bench/many_risers.py" --mode "$m" --scene "$scene" --window "$window" --out "$out"
done
echo "many_risers: load average $(cut -d' ' -f1-3 /proc/loadavg) at the end; wrote $out/many_risers.csv"
