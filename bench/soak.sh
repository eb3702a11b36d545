#!/usr/bin/env bash
# Soak run (issue 6): riser_sim_node on the J-lay scene for an hour of simulated time, driven through
# /clock as fast as it keeps up (bench/soak.py), on a private roscore. Writes out/soak/soak.csv and
# out/soak/soak.txt (summary: RSS, step time first vs last 5 min, energy and constraint error bounds).
#   bench/soak.sh [simulated_seconds] [scene]        (make soak; needs make build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
duration=${1:-3600}
scene=${2:-$root/config/scenes/paper_jlay_170m.yaml}
set +u
source "$ws/devel/setup.bash"
set -u
node_bin="$ws/devel/lib/riser_sim/riser_sim_node"
[ -x "$node_bin" ] || { echo "soak: $node_bin not built (run make build)" >&2; exit 1; }
out="$root/out/soak"
mkdir -p "$out"

port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://127.0.0.1:$port
export ROS_HOSTNAME=127.0.0.1
roscore -p "$port" >"$out/roscore.log" 2>&1 &
core_pid=$!
trap 'kill $core_pid 2>/dev/null; wait $core_pid 2>/dev/null' EXIT
for _ in $(seq 100); do
  /usr/bin/python3 -c 'import rosgraph, sys; sys.exit(0 if rosgraph.is_master_online() else 1)' 2>/dev/null && break
  sleep 0.1
done
rosparam set /use_sim_time true
/usr/bin/python3 "$root/bench/soak.py" --node "$node_bin" --scene "$scene" --duration "$duration" --csv "$out/soak.csv"
