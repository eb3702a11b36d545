#!/usr/bin/env bash
# riser_sim_node in real time on the Table 1 line (config/scenes/paper_table1.yaml) at n = 40 and
# n = 100, with every output published and subscribed: real-time factor, CPU share, step time and
# the p99 of one publish period's work. Prints a table and writes out/bench/node.csv.
#   bench/node_bench.sh [window_seconds]       (needs a built workspace: make build)
# dt per n: the largest of the paper's kind that is stable for RK4 with this stiff line
# (EA = 1.96e8 N): the axial chain's highest frequency grows like n, so dt shrinks like 1/n.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
window=${1:-10}
node_bin="$ws/devel/lib/riser_sim/riser_sim_node"
[ -x "$node_bin" ] || { echo "node_bench: $node_bin not built (run make build)" >&2; exit 1; }
out="$root/out/bench"
mkdir -p "$out"
csv="$out/node.csv"
rm -f "$csv"

source "$root/bench/private_master.sh" "$out/node_bench_roscore.log"

status=0
for spec in "40 2e-4" "100 1e-4"; do
  read -r n dt <<<"$spec"
  echo "node_bench: n = $n, dt = $dt s, ${window} s window ..."
  /usr/bin/python3 "$root/bench/node_bench.py" --node "$node_bin" --scene "$root/config/scenes/paper_table1.yaml" \
    --n "$n" --dt "$dt" --window "$window" --csv "$csv" || status=1
done

/usr/bin/python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
head = ["n", "dt [s]", "RTF", "compute RTF", "CPU [%]", "step [us]", "p99 work/period [ms]", "period [ms]",
        "publish p99 [ms]", "tension [Hz]", "status"]
keys = ["n", "dt", "real_time_factor", "compute_real_time_factor", "cpu_percent", "step_mean_us",
        "work_per_publish_period_p99_ms", "publish_period_ms", "publish_p99_ms", "tension_hz", "status"]
table = [head] + [[r.get(k, "") or "-" for k in keys] for r in rows]
widths = [max(len(row[i]) for row in table) for i in range(len(head))]
for row in table:
    print("  ".join(c.rjust(w) for c, w in zip(row, widths)))
PY
echo "wrote $csv"
exit $status
