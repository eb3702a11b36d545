# Sourced by the node benchmarks: the workspace's setup, then a private roscore on a free loopback port
# (so a benchmark never meets another ROS graph), stopped on exit. Needs root, ws; log file in $1.
set +u
source "$ws/devel/setup.bash"
set -u
port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://127.0.0.1:$port
export ROS_HOSTNAME=127.0.0.1
roscore -p "$port" >"$1" 2>&1 &
core_pid=$!
trap 'kill $core_pid 2>/dev/null; wait $core_pid 2>/dev/null' EXIT
for _ in $(seq 100); do
  /usr/bin/python3 -c 'import rosgraph, sys; sys.exit(0 if rosgraph.is_master_online() else 1)' 2>/dev/null && break
  sleep 0.1
done
