#!/usr/bin/env bash
# Load figure: the largest number of risers that run at real-time factor >= 0.99, as separate
# riser_sim_node processes and as nodelets in one manager, with the vessel at 100 Hz (bench/many_risers.py).
# 2d (default): the paper's 500 m riser (config/scenes/paper_riser_500m.yaml: n = 50, rk4, dt = 1 ms, drag and
#   added mass), hang-offs 10 m apart; out/bench/many_risers.csv.
# 3d: the 3D sea riser (config/scenes/spatial_sea_riser.yaml: n = 50, drag, added mass, JONSWAP waves, current,
#   seabed friction) at the structured midpoint with dt = 20 ms (its 50 ms diverges in the node within the first
#   second when the vessel only surges, docs/benchmarks.md "Many risers"), hang-offs 1 m apart (the anchors are
#   90 m from the vessel's origin: 10 m apart would stretch the 64th riser past its 160 m); many_risers_3d.csv.
# Either way the top is driven by the vessel; private roscore; logs in out/bench.
#   bench/many_risers.sh [nodes|nodelets|both] [window_s] [2d|3d]       (~10-20 min per mode; needs make build)
# RISER_SIM_MANY_SCENE replaces the scene; RISER_SIM_MANY_LOOP_RATE sets the risers' ~loop_rate [Hz]; RISER_SIM_MANY_START (first k of the doubling, default 1) and
# RISER_SIM_MANY_MAX (the largest k tried, default 64) rerun a bisection between two known counts.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
modes=${1:-both}
window=${2:-20}
space=${3:-2d}
case $space in
  2d) scene=$root/config/scenes/paper_riser_500m.yaml; spacing=10; tag=""; set=() ;;
  3d) scene=$root/config/scenes/spatial_sea_riser.yaml; spacing=1; tag="_3d"; set=(--vessel-last --vessel-param fade_in=60) ;;
  *) echo "many_risers: 2d or 3d, got '$space'" >&2; exit 2 ;;
esac
scene=${RISER_SIM_MANY_SCENE:-$scene}
[ -e "$ws/devel/lib/libriser_sim_nodelets.so" ] || { echo "many_risers: not built (run make build)" >&2; exit 1; }
out="$root/out/bench"
mkdir -p "$out"
rm -f "$out/many_risers$tag.csv"

source "$root/bench/private_master.sh" "$out/many_risers${tag}_roscore.log"
echo "many_risers: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start; scene $(basename "$scene")"
[ "$modes" = both ] && modes="nodes nodelets"
for m in $modes; do
  /usr/bin/python3 "$root/bench/many_risers.py" --mode "$m" --scene "$scene" --window "$window" --out "$out" \
    --spacing "$spacing" --tag "$tag" --start "${RISER_SIM_MANY_START:-1}" --max-count "${RISER_SIM_MANY_MAX:-64}" \
    ${RISER_SIM_MANY_LOOP_RATE:+--loop-rate "$RISER_SIM_MANY_LOOP_RATE"} "${set[@]}"
done
echo "many_risers: load average $(cut -d' ' -f1-3 /proc/loadavg) at the end; wrote $out/many_risers$tag.csv"
