#!/usr/bin/env bash
# riser_sim_node in real time with every output published and subscribed: real-time factor, CPU share
# (the node process's utime + stime per wall second: robust to other load), step time and the p99 of one
# publish period's work. Prints a table and writes out/bench/node.csv, and the tables
# out/bench/tables/node_table1.md, node_sea3d.md (bench_tables.py) of the cases run.
#   bench/node_bench.sh [window_seconds] [table1|sea3d|all]     (default all; needs a built workspace)
# table1: the Table 1 line (config/scenes/paper_table1.yaml) at n = 40 and n = 100, the vessel surging
#   10 m / 27 s; dt per n: the largest of the paper's kind that is stable for RK4 with this stiff line
#   (EA = 1.96e8 N): the axial chain's highest frequency grows like n, so dt shrinks like 1/n.
# sea3d: the 3D sea riser at n = 100 (config/scenes/spatial_sea_riser_n100.yaml: drag, added mass, JONSWAP
#   waves, current, seabed friction) at its setting (structured midpoint, dt = 50 ms), the vessel moving
#   2, 1, 0.5 m in x, y, z with period 10 s (the scene's own top motion).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
window=${1:-10}
cases=${2:-all}
case $cases in table1|sea3d|all) ;; *) echo "node_bench: cases: table1, sea3d or all, got '$cases'" >&2; exit 2;; esac
node_bin="$ws/devel/lib/riser_sim/riser_sim_node"
[ -x "$node_bin" ] || { echo "node_bench: $node_bin not built (run make build)" >&2; exit 1; }
out="$root/out/bench"
mkdir -p "$out"
csv="$out/node.csv"
rm -f "$csv"

source "$root/bench/private_master.sh" "$out/node_bench_roscore.log"

status=0
specs=()
# scene n dt vessel-motion warm-up: the 3D sea's measurement starts after its waves' 10 s ramp.
[ "$cases" != sea3d ] && specs+=("paper_table1 40 2e-4 10,0,0,27 3" "paper_table1 100 1e-4 10,0,0,27 3")
[ "$cases" != table1 ] && specs+=("spatial_sea_riser_n100 100 0.05 2,1,0.5,10 10")
echo "node_bench: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start"
for spec in "${specs[@]}"; do
  read -r scene n dt motion warmup <<<"$spec"
  echo "node_bench: $scene, n = $n, dt = $dt s, vessel $motion, ${window} s window ..."
  /usr/bin/python3 "$root/bench/node_bench.py" --node "$node_bin" --scene "$root/config/scenes/$scene.yaml" \
    --n "$n" --dt "$dt" --motion "$motion" --warmup "$warmup" --window "$window" --csv "$csv" || status=1
done
echo "node_bench: load average $(cut -d' ' -f1-3 /proc/loadavg) at the end"

/usr/bin/python3 - "$csv" "$root/bench" "bench/node_bench.sh $*" <<'PY'
import csv, sys
sys.path.insert(0, sys.argv[2])
import bench_tables
rows = list(csv.DictReader(open(sys.argv[1])))
head = ["scene", "n", "dt [s]", "RTF", "compute RTF", "CPU [%]", "step [us]", "p99 work/period [ms]", "period [ms]",
        "publish p99 [ms]", "tension [Hz]", "status"]
keys = ["scene", "n", "dt", "real_time_factor", "compute_real_time_factor", "cpu_percent", "step_mean_us",
        "work_per_publish_period_p99_ms", "publish_period_ms", "publish_p99_ms", "tension_hz", "status"]
table = [head] + [[r.get(k, "") or "-" for k in keys] for r in rows]
widths = [max(len(row[i]) for row in table) for i in range(len(head))]
for row in table:
    print("  ".join(c.rjust(w) for c, w in zip(row, widths)))
# docs/benchmarks.md's tables, one per case.
md_head = ["n", "dt [s]", "real-time factor", "compute real-time factor", "CPU [% of a core]", "step [us]",
           "p99 work per publish period [ms]", "publish period [ms]", "publish p99 [ms]", "status"]
md_keys = ["n", "dt", "real_time_factor", "compute_real_time_factor", "cpu_percent", "step_mean_us",
           "work_per_publish_period_p99_ms", "publish_period_ms", "publish_p99_ms", "status"]
for name, scene in (("node_table1", "paper_table1"), ("node_sea3d", "spatial_sea_riser_n100")):
    mine = [r for r in rows if r.get("scene", "") == scene]
    if not mine:
        continue
    lines = ["The node on %s, every output published and subscribed:" % scene, "",
             "| " + " | ".join(md_head) + " |", "|" + "---|" * len(md_head)]
    cell = lambda v: " ".join((v or "-").replace("|", "/").split())  # a node's error text in one cell
    lines += ["| " + " | ".join(cell(r.get(k, "")) for k in md_keys) + " |" for r in mine]
    print()
    print("\n".join(lines))
    print("wrote %s" % bench_tables.write(name, lines, sys.argv[3]))
PY
echo "wrote $csv"
exit $status
