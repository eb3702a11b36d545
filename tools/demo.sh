#!/usr/bin/env bash
# make demo: installs what is needed (with rviz, xvfb, ffmpeg), builds, then runs launch/demo.launch (the 3D
# demo: demo_riser_3d.yaml, rviz orbiting the line) for RISER_SIM_DEMO_DURATION (40) s with rviz on a
# virtual display and records
#   out/demo.mp4 (the rviz window), out/demo.bag (the node's topics), out/demo_tension.png (tension, end
#   wrenches, positions), out/demo_tension_map.png (tension along the line against time)
# and prints a summary. Every process it starts is stopped at the end, also on failure or Ctrl-C.
# Environment: RISER_SIM_WS (workspace, default .ws), RISER_SIM_DEMO_OUT (default out),
# RISER_SIM_DEMO_DURATION [s], RISER_SIM_DEMO_FPS (video frame rate, default 20),
# RISER_SIM_DEMO_PLANAR (1: the planar demo, demo_riser.yaml in a side view; default 0).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
export RISER_SIM_WS=${RISER_SIM_WS:-$root/.ws}
out=$(mkdir -p "${RISER_SIM_DEMO_OUT:-$root/out}" && cd "${RISER_SIM_DEMO_OUT:-$root/out}" && pwd)
export RISER_SIM_DEMO_OUT=$out
export RISER_SIM_DEMO_DURATION=${RISER_SIM_DEMO_DURATION:-40}
export RISER_SIM_DEMO_FPS=${RISER_SIM_DEMO_FPS:-20}
export RISER_SIM_DEMO_PLANAR=${RISER_SIM_DEMO_PLANAR:-0}
planar=$([ "$RISER_SIM_DEMO_PLANAR" = 1 ] && echo true || echo false)
rviz_config=$root/rviz/$([ "$planar" = true ] && echo riser.rviz || echo riser_3d.rviz)
W=1280 H=720

log() { echo "[demo] $*"; }

# ---- inside xvfb-run: roscore, rviz, ffmpeg, the launch ----
if [ "${1:-}" = --in-xvfb ]; then
  set +u; source "$RISER_SIM_WS/devel/setup.bash"; set -u
  export ROS_LOG_DIR=$out/ros_logs ROS_HOME=$out/ros_home
  mkdir -p "$ROS_LOG_DIR" "$ROS_HOME"
  # A private master on a free port: never talks to (or kills) another roscore on this machine.
  port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  export ROS_MASTER_URI=http://127.0.0.1:$port
  pids=()
  # start LOG CMD...: CMD in the background in its own process group (job control on just for it), so
  # it is stopped as a whole and keeps default signal handling. Foreground commands stay in our group:
  # a Ctrl-C (SIGINT to the group) kills them too, and bash then runs the INT trap at once.
  start() { local log=$1; shift; set -m; "$@" >"$log" 2>&1 & set +m; }
  stop() {  # stop PID...: SIGINT to each process group; SIGTERM after 10 s, SIGKILL after 15 s
    local p i
    for p in "$@"; do kill -INT -- "-$p" 2>/dev/null || true; done
    for p in "$@"; do
      for i in $(seq 150); do
        kill -0 "$p" 2>/dev/null || break
        [ "$i" != 100 ] || kill -TERM -- "-$p" 2>/dev/null || true  # SIGINT may be ignored (inherited)
        sleep 0.1
      done
      kill -KILL -- "-$p" 2>/dev/null || true
      wait "$p" 2>/dev/null || true
    done
  }
  cleanup() {
    local rc=$?
    trap - EXIT INT TERM
    [ ${#pids[@]} -eq 0 ] || stop "${pids[@]}"
    exit $rc
  }
  trap cleanup EXIT
  trap 'exit 130' INT
  trap 'exit 143' TERM
  wait_for() {  # wait_for SECONDS WHAT COMMAND...: polls COMMAND every 0.2 s
    local secs=$1 what=$2; shift 2
    local deadline=$((SECONDS + secs))
    until "$@" >/dev/null 2>&1; do
      if [ $SECONDS -ge $deadline ]; then log "timed out after ${secs} s waiting for $what"; return 1; fi
      sleep 0.2
    done
  }
  subscribed() { timeout -k 2 5 rostopic info "$1" 2>/dev/null | sed -n '/^Subscribers:/,$p' | grep -q "$2"; }

  log "display $DISPLAY, master $ROS_MASTER_URI"
  start "$out/roscore.log" roscore -p "$port"
  pids+=($!)
  wait_for 30 "roscore" rosparam get /run_id

  start "$out/rviz.log" rviz -d "$rviz_config"
  rviz_pid=$!; pids=("$rviz_pid" "${pids[@]}")
  # rviz subscribes to its displays' topics once its window and config are up.
  wait_for 60 "rviz to subscribe to /riser_sim/markers" subscribed /riser_sim/markers /rviz

  rm -f "$out/demo.mp4" "$out/demo.bag" "$out/demo.bag.active" "$out/demo_tension_map.png"
  start "$out/ffmpeg.log" ffmpeg -nostdin -y -loglevel error -f x11grab -draw_mouse 0 -video_size ${W}x${H} \
    -framerate "$RISER_SIM_DEMO_FPS" -i "$DISPLAY" -t $((RISER_SIM_DEMO_DURATION + 30)) \
    -c:v libx264 -preset ultrafast -crf 26 -pix_fmt yuv420p "$out/demo.mp4"
  ffmpeg_pid=$!; pids=("$ffmpeg_pid" "${pids[@]}")

  log "running the $([ "$planar" = true ] && echo planar || echo 3D) demo for $RISER_SIM_DEMO_DURATION s"
  start "$out/roslaunch.log" roslaunch riser_sim demo.launch rviz:=false record:=true bag:="$out/demo.bag" \
    duration:="$RISER_SIM_DEMO_DURATION" planar:="$planar"
  launch_pid=$!; pids=("$launch_pid" "${pids[@]}")
  # One rostopic waiting up to 60 s (it has been seen to hang on SIGTERM: -k kills it 5 s later).
  if ! timeout -k 5 60 rostopic echo -n 1 /riser_sim/tension >/dev/null 2>&1; then
    log "no message on /riser_sim/tension within 60 s"; tail -n 30 "$out/roslaunch.log"; exit 1
  fi
  log "node is publishing; rviz and ffmpeg are recording"
  # The launch ends by itself when vessel_motion (required) finishes its duration.
  rc=0
  wait_for $((RISER_SIM_DEMO_DURATION + 60)) "the launch to end" bash -c "! kill -0 $launch_pid" || rc=1
  wait "$launch_pid" 2>/dev/null || true
  stop "$ffmpeg_pid" "$rviz_pid"
  if grep -q "\[riser_sim-[0-9]*\] process has died" "$out/roslaunch.log"; then
    grep -E "ERROR|FATAL|process has died" "$out/roslaunch.log" | head -n 5
    log "riser_sim_node died (see $out/roslaunch.log)"; rc=1
  fi
  exit $rc
fi

# ---- outside: deps, build, then the run under a virtual X server ----
log "installing dependencies"
RISER_SIM_GUI_DEPS=1 "$root/tools/install_deps.sh"
log "building in $RISER_SIM_WS"
"$root/tools/build.sh" -j2 >"$out/build.log" 2>&1 || { tail -n 40 "$out/build.log"; log "build failed (see $out/build.log)"; exit 1; }
xvfb-run -a -s "-screen 0 ${W}x${H}x24" bash "$root/tools/demo.sh" --in-xvfb

[ -s "$out/demo.bag" ] || { log "no bag was written"; exit 1; }
[ -s "$out/demo.mp4" ] || { log "no video was written (see $out/ffmpeg.log)"; exit 1; }
log "plotting"
/usr/bin/python3 "$root/scripts/plot_demo.py" "$out/demo.bag" -o "$out/demo_tension.png" | sed 's/^/  /'
video_s=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$out/demo.mp4" 2>/dev/null || echo "?")
echo
log "outputs:"
echo "  video: $out/demo.mp4 (${video_s} s, ${W}x${H})"
echo "  bag:   $out/demo.bag ($(du -h "$out/demo.bag" | cut -f1))"
echo "  plots: $out/demo_tension.png, $out/demo_tension_map.png"
echo "  logs:  $out/ros_logs, $out/roslaunch.log, $out/rviz.log"
