#!/usr/bin/env bash
# Cost of each force term: steps per second of the 500 m riser (n = 50, h = 1e-3 s, 20 s,
# absolute, rk4) with gravity, springs and buoyancy, then with each sea/flow term switched on alone.
# Median of 3 runs of riser_sim_cli --summary, steps per second of thread CPU time (cpu_s; the wall
# time is listed beside it: the machine may be shared); writes out/bench/terms.csv and the table
# out/bench/tables/terms.md (bench_tables.py).
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cli=${RISER_SIM_CLI:-"$root/.ws/devel/lib/riser_sim/riser_sim_cli"}  # RISER_SIM_CLI: another build to compare
scene="$root/config/scenes/paper_riser_500m.yaml"
mkdir -p "$root/out/bench"
base=(--set 'hydrodynamics={drag_normal: 0, inertia_coefficient: 1}')
declare -a names=("gravity + springs + buoyancy" "+ drag D_eta 0.7" "+ added mass C_M 2"
  "+ drag + current 0.5 m/s" "+ waves H 4 m, T 10 s" "+ internal flow u 5 m/s (paper)"
  "+ pipe flow u 5 m/s" "+ seabed" "Table 2 scene (drag + added mass)")
declare -a sets=(
  ""
  "--set hydrodynamics.drag_normal=0.7"
  "--set hydrodynamics.inertia_coefficient=2"
  "--set hydrodynamics.drag_normal=0.7 --set 'environment.current={velocity: [0.5, 0]}'"
  "--set 'environment.waves={height: 4, period: 10, depth: 1000}'"
  "--set 'internal_fluid={density: 840, velocity: 5, model: paper}'"
  "--set 'internal_fluid={density: 840, velocity: 5, model: pipe_flow}'"
  "--set 'seabed={level: -499.5, stiffness_normal: 1.0e6}'"
  "--set hydrodynamics.drag_normal=0.7 --set hydrodynamics.inertia_coefficient=2")
table=$(mktemp)
trap 'rm -f "$table"' EXIT
out() { echo "$1"; echo "$1" >>"$table"; }  # stdout and the table file
out "Cost of each term: 500 m riser, n = 50, rk4 h = 1e-3 s, 20 s simulated (median of 3)"
out ""
out "| terms | steps/s (CPU) | steps/s (wall) | cost vs the first row (CPU) |"
out "|---|---|---|---|"
echo "terms,steps_per_cpu_s,steps_per_wall_s" > "$root/out/bench/terms.csv"
ref=""
for k in "${!names[@]}"; do
  rates=()
  walls=()
  for r in 1 2 3; do
    eval "extra=(${sets[$k]})"
    out=$("$cli" --scene "$scene" --duration 20 --summary --quiet "${base[@]}" "${extra[@]}" | tail -n 1)
    rates+=("$(/usr/bin/python3 -c 'import json,sys; d=json.loads(sys.argv[1]); print(d["steps"]/d["cpu_s"])' "$out")")
    walls+=("$(/usr/bin/python3 -c 'import json,sys; d=json.loads(sys.argv[1]); print(d["steps"]/d["wall_s"])' "$out")")
  done
  med=$(printf '%s\n' "${rates[@]}" | sort -g | sed -n 2p)
  wmed=$(printf '%s\n' "${walls[@]}" | sort -g | sed -n 2p)
  [ -n "$ref" ] || ref=$med
  out "$(printf '| %s | %.0f | %.0f | %.2fx |' "${names[$k]}" "$med" "$wmed" "$(/usr/bin/python3 -c "print($ref/$med)")")"
  echo "\"${names[$k]}\",$med,$wmed" >> "$root/out/bench/terms.csv"
done
/usr/bin/python3 "$root/bench/bench_tables.py" write terms "bench/extra_terms.sh" <"$table"
