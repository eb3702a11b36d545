#!/usr/bin/env bash
# The installed package works on its own: `catkin_make install` into the workspace's install/, then, in an
# environment holding only install/setup.bash, (1) riser_sim_cli runs every installed scene, (2) roslaunch
# riser_sim riser_sim.launch starts the node (a private roscore), (3) a downstream catkin package finds
# riser_sim, includes the core's headers and links the core, (4) riser_sim_sweep runs a 2-case sweep. One
# JUnit test case each (install/*.xml under the results folder $1). Exit 1 when any fails.
# RISER_SIM_WS: the workspace (built first by tools/build.sh); RISER_SIM_SKIP_TESTS as for the build.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
results=${1:-$ws/build/test_results}/install
mkdir -p "$results"
log=$ws/install_space.log
: >"$log"
cases=()
failed=0
record() {  # name, status (0 ok), message
  local body=""
  if [ "$2" != 0 ]; then
    failed=1
    body="<failure message=\"$(printf '%s' "$3" | tr -d '<>&"' | head -c 400)\"/>"
    echo "install space: $1 FAILED: $3"
  else
    echo "install space: $1 ok${3:+ ($3)}"
  fi
  cases+=("<testcase name=\"$1\" classname=\"install_space\">$body</testcase>")
}
# Runs a command with only the install space sourced (no devel space, no source tree on any path).
clean() {
  env -i HOME="$HOME" PATH=/usr/bin:/bin LANG=C.UTF-8 bash -c "set +u; source '$ws/install/setup.bash'; set -u; $1"
}

start=$SECONDS
RISER_SIM_SKIP_TESTS="${RISER_SIM_SKIP_TESTS:-}" "$root/tools/build.sh" -j2 install >>"$log" 2>&1
if [ $? -ne 0 ] || [ ! -f "$ws/install/setup.bash" ]; then
  record catkin_make_install 1 "catkin_make install failed (see $log)"
else
  record catkin_make_install 0 "$((SECONDS - start)) s"
fi

# (1) Every scene of config/scenes is installed and runs from the install space.
if [ -f "$ws/install/setup.bash" ]; then
  want=$(ls "$root"/config/scenes/*.yaml | wc -l)
  out=$(clean '
    dir=$(rospack find riser_sim)/config/scenes
    n=0; bad=""
    for s in "$dir"/*.yaml; do
      n=$((n + 1))
      json=$(rosrun riser_sim riser_sim_cli --scene "$s" --quiet --summary --duration 0.02 2>&1)
      rc=$?
      case "$json" in *"\"status\""*) ;; *) rc=99 ;; esac
      [ $rc -eq 0 ] || bad="$bad $(basename "$s") (exit $rc: $(printf "%s" "$json" | tail -n 1 | head -c 200))"
    done
    echo "scenes=$n"; echo "bad=$bad"' 2>&1)
  n=$(printf '%s\n' "$out" | sed -n 's/^scenes=//p')
  bad=$(printf '%s\n' "$out" | sed -n 's/^bad=//p')
  if [ "$n" != "$want" ]; then
    record cli_runs_every_installed_scene 1 "installed scenes: ${n:-none} of the $want in config/scenes ($out)"
  elif [ -n "$bad" ]; then
    record cli_runs_every_installed_scene 1 "failed:$bad"
  else
    record cli_runs_every_installed_scene 0 "$n scenes"
  fi

  # (2) roslaunch riser_sim riser_sim.launch on a private master: the node advertises its ~reset service.
  out=$(clean '
    port=$(/usr/bin/python3 -c "import socket; s = socket.socket(); s.bind((\"127.0.0.1\", 0)); print(s.getsockname()[1])")
    export ROS_MASTER_URI=http://127.0.0.1:$port ROS_HOSTNAME=127.0.0.1 ROS_LOG_DIR=$(mktemp -d)
    roscore -p "$port" >/dev/null 2>&1 & core=$!
    roslaunch --wait riser_sim riser_sim.launch >"$ROS_LOG_DIR/launch.log" 2>&1 & launch=$!
    up=0
    for _ in $(seq 300); do  # up to 30 s: the node needs no pose to advertise its services
      if rosservice list 2>/dev/null | grep -qx /riser_sim/reset; then up=1; break; fi
      kill -0 $launch 2>/dev/null || break
      sleep 0.1
    done
    kill -INT $launch 2>/dev/null; wait $launch 2>/dev/null
    kill -INT $core 2>/dev/null; wait $core 2>/dev/null
    echo "up=$up"; [ $up = 1 ] || tail -n 5 "$ROS_LOG_DIR/launch.log"' 2>&1)
  if printf '%s\n' "$out" | grep -q '^up=1'; then
    record roslaunch_starts_the_node 0
  else
    record roslaunch_starts_the_node 1 "no /riser_sim/reset within 30 s: $(printf '%s' "$out" | tail -n 5 | tr '\n' ' ')"
  fi

  # (3) A downstream package links the core and loads a scene with it.
  tmp=$(mktemp -d)
  mkdir -p "$tmp/src/riser_sim_user/src"
  cat >"$tmp/src/riser_sim_user/package.xml" <<'EOF'
<?xml version="1.0"?>
<package format="2">
  <name>riser_sim_user</name>
  <version>0.0.0</version>
  <description>Links riser_sim's core from its install space.</description>
  <maintainer email="nobody@example.com">nobody</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>riser_sim</depend>
</package>
EOF
  cat >"$tmp/src/riser_sim_user/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.10)
project(riser_sim_user)
set(CMAKE_CXX_STANDARD 17)
find_package(catkin REQUIRED COMPONENTS riser_sim)
catkin_package()
include_directories(${catkin_INCLUDE_DIRS})
add_executable(scene_elements src/scene_elements.cpp)
target_link_libraries(scene_elements ${catkin_LIBRARIES})
EOF
  cat >"$tmp/src/riser_sim_user/src/scene_elements.cpp" <<'EOF'
// Prints the number of segments of a scene file, loaded by riser_sim's core.
#include <cstdio>
#include "riser_sim/scene/scene_yaml.h"
int main(int argc, char** argv) {
  if (argc < 2) return 2;
  const riser_sim::Scene s = riser_sim::loadSceneFile(argv[1]);
  std::printf("%d\n", s.elements);
  return 0;
}
EOF
  out=$(clean "cd '$tmp' && catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 >build.log 2>&1 || { tail -n 20 build.log; exit 1; }
    ./devel/lib/riser_sim_user/scene_elements \$(rospack find riser_sim)/config/scenes/paper_table1.yaml" 2>&1)
  want=$(sed -n 's/^ *elements: *\([0-9]*\).*/\1/p' "$root/config/scenes/paper_table1.yaml" | head -n 1)
  if [ "$(printf '%s\n' "$out" | tail -n 1)" = "$want" ]; then
    record downstream_package_links_the_core 0 "paper_table1 has $want elements"
  else
    record downstream_package_links_the_core 1 "expected $want, got: $(printf '%s' "$out" | tail -n 8 | tr '\n' ' ')"
  fi
  rm -rf "$tmp"

  # (4) riser_sim_sweep from the install space: its help, and a 2-case sweep on one local Dask worker running
  # the installed riser_sim_cli beside it.
  tmp=$(mktemp -d)
  out=$(clean "
    rosrun riser_sim riser_sim_sweep --help >/dev/null || exit 1
    printf '%s\n' \"scene: \$(rospack find riser_sim)/config/scenes/spatial_sea_riser.yaml\" 'duration: 0.2' \\
      'set: {line.elements: 6}' 'grid: {environment.waves.heading: [0, 90]}' >'$tmp/sweep.yaml'
    rosrun riser_sim riser_sim_sweep '$tmp/sweep.yaml' --out '$tmp/out' --workers 1 --quiet --no-plots &&
      grep -c ',ok,' '$tmp/out/results.csv'" 2>&1)
  if [ "$(printf '%s\n' "$out" | tail -n 1)" = 2 ]; then
    record sweep_runs_from_install_space 0 "2 cases ok"
  else
    record sweep_runs_from_install_space 1 "$(printf '%s' "$out" | tail -n 8 | tr '\n' ' ')"
  fi
  rm -rf "$tmp"
fi

{
  echo '<?xml version="1.0" encoding="UTF-8"?>'
  echo "<testsuites><testsuite name=\"install_space\" tests=\"${#cases[@]}\">"
  printf '%s\n' "${cases[@]}"
  echo '</testsuite></testsuites>'
} >"$results/install_space.xml"
echo "install space: $((SECONDS - start)) s"
exit $failed
