#!/usr/bin/env bash
# Load figure: the largest number of risers that run at real-time factor >= 0.99, as separate
# riser_sim_node processes and as nodelets in one manager, with the vessel at 100 Hz (bench/many_risers.py).
# 2d (default): the paper's 500 m riser (config/scenes/paper_riser_500m.yaml: n = 50, rk4, dt = 1 ms, drag and
#   added mass), hang-offs 10 m apart; out/bench/many_risers.csv.
# 3d: the 3D sea riser (config/scenes/spatial_sea_riser.yaml: n = 50, structured midpoint at 50 ms, drag, added
#   mass, JONSWAP waves, current, seabed friction), hang-offs 0.25 m apart (every anchor is at x = 90 m: a hang-off
#   beyond x ~ 31 m, with the vessel's 10 m surge, puts the 160 m line so far onto the seabed that its start diverged
#   or its statics failed), the vessel started once every riser waits for its first pose and fading in over 60 s (a
#   3D sea node started against a moving vessel can diverge, docs/benchmarks.md); out/bench/many_risers_3d.csv.
# Either way the top is driven by the vessel; private roscore; logs in out/bench. The table per k (nodes beside
# nodelets) is printed and written to out/bench/tables/many_risers.md / many_risers_3d.md (bench_tables.py).
#   bench/many_risers.sh [nodes|nodelets|both] [window_s] [2d|3d]       (~10-20 min per mode; needs make build)
# RISER_SIM_MANY_SCENE replaces the scene; RISER_SIM_MANY_LOOP_RATE sets the risers' ~loop_rate [Hz];
# RISER_SIM_MANY_START (first k of the doubling, default 1) and RISER_SIM_MANY_MAX (the largest k tried, default
# 64) rerun a bisection between two known counts.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
modes=${1:-both}
window=${2:-20}
space=${3:-2d}
case $space in
  2d) scene=$root/config/scenes/paper_riser_500m.yaml; spacing=10; tag=""; extra=() ;;
  3d) scene=$root/config/scenes/spatial_sea_riser.yaml; spacing=0.25; tag="_3d"; extra=(--vessel-last --vessel-param fade_in=60) ;;
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
    ${RISER_SIM_MANY_LOOP_RATE:+--loop-rate "$RISER_SIM_MANY_LOOP_RATE"} "${extra[@]}"
done
echo "many_risers: load average $(cut -d' ' -f1-3 /proc/loadavg) at the end; wrote $out/many_risers$tag.csv"
/usr/bin/python3 - "$out/many_risers$tag.csv" "$root/bench" "many_risers$tag" "bench/many_risers.sh $*" <<'PY'
import csv, sys
sys.path.insert(0, sys.argv[2])
import bench_tables
rows = list(csv.DictReader(open(sys.argv[1])))
by_k = {}
for r in rows:
    by_k.setdefault(int(r["count"]), {})[r["mode"]] = r
def cells(r):
    if r is None:
        return ["", "", ""]
    rtf = r["min_rtf"] if r["pass"] == "True" else "%s (%s)" % (r["min_rtf"], r["note"].replace("|", "/") or "fail")
    return [rtf, r["cpu_cores"], r["step_mean_us"]]
lines = ["Risers at real time (every riser's RTF over the window >= 0.99, no time dropped), %s:" % rows[0]["scene"], "",
         "| k risers | nodes: min RTF | nodes: CPU [cores] | nodes: step [us] | nodelets: min RTF | "
         "nodelets: CPU [cores] | nodelets: step [us] |", "|---|---|---|---|---|---|---|"]
for k in sorted(by_k):
    lines.append("| %d | %s |" % (k, " | ".join(cells(by_k[k].get("nodes")) + cells(by_k[k].get("nodelets")))))
print("\n".join(lines))
print("wrote %s" % bench_tables.write(sys.argv[3], lines, sys.argv[4]))
PY
