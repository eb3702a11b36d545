#!/usr/bin/env bash
# `make figures`: the paper's section 4 runs (riser_sim_cli --csv) and their plots in out/figures/.
#   500 m riser (Figs. 10, 11): D_eta in {0.7, 1.0, 1.3} at C_M = 2; C_M in {1, 1.5, 2} at D_eta = 0.7.
#   170 m J-lay (Figs. 13, 14): rho_f = 0 vs 840 at u = 0; u in {0, 5, 10} m/s at rho_f = 840 with
#   both flow models (paper, pipe_flow); h/2 runs for the convergence in h; the end force released
#   instead of held; a variant with 1 % axial structural damping (docs/figures.md).
# Runs two at a time. Set FIG_DURATION_500=S / FIG_DURATION_JLAY=S to shorten the runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ws=${RISER_SIM_WS:-$root/.ws}
cli=$ws/devel/lib/riser_sim/riser_sim_cli
out=$root/out/figures
mkdir -p "$out"
[ -x "$cli" ] || { echo "figures: $cli not built (run make build)" >&2; exit 1; }
d500=${FIG_DURATION_500:-200}
djlay=${FIG_DURATION_JLAY:-81}
riser=$root/config/scenes/paper_riser_500m.yaml
jlay=$root/config/scenes/paper_jlay_170m.yaml
# Axial structural damping c_EA = 2 zeta EA / omega_1 with zeta = 1 % at the first axial mode of the
# J-lay's static state (9.81 Hz, omega_1 = 61.64 rad/s, riser_sim_cli --modes), EA = 3.642e9 N.
damped="line.axial_damping=1.18e6"
# name|scene|duration|overrides...
jobs=(
  "riser_D0.7_CM2|$riser|$d500|hydrodynamics.drag_normal=0.7 hydrodynamics.inertia_coefficient=2.0"
  "riser_D1.0_CM2|$riser|$d500|hydrodynamics.drag_normal=1.0 hydrodynamics.inertia_coefficient=2.0"
  "riser_D1.3_CM2|$riser|$d500|hydrodynamics.drag_normal=1.3 hydrodynamics.inertia_coefficient=2.0"
  "riser_D0.7_CM1|$riser|$d500|hydrodynamics.drag_normal=0.7 hydrodynamics.inertia_coefficient=1.0"
  "riser_D0.7_CM1.5|$riser|$d500|hydrodynamics.drag_normal=0.7 hydrodynamics.inertia_coefficient=1.5"
  "jlay_rf0_u0|$jlay|$djlay|internal_fluid.density=0"
  "jlay_u0|$jlay|$djlay|"
  "jlay_paper_u5|$jlay|$djlay|internal_fluid.velocity=5 internal_fluid.model=paper"
  "jlay_paper_u10|$jlay|$djlay|internal_fluid.velocity=10 internal_fluid.model=paper"
  "jlay_pipe_u5|$jlay|$djlay|internal_fluid.velocity=5 internal_fluid.model=pipe_flow"
  "jlay_pipe_u10|$jlay|$djlay|internal_fluid.velocity=10 internal_fluid.model=pipe_flow"
  "jlay_u0_h2|$jlay|$djlay|solver.dt=2.5e-4"
  "jlay_paper_u10_h2|$jlay|$djlay|solver.dt=2.5e-4 internal_fluid.velocity=10 internal_fluid.model=paper"
  "jlay_release_u0|$jlay|$djlay|initial.end_force=release"
  "jlay_damped_u0|$jlay|$djlay|$damped"
  "jlay_damped_paper_u10|$jlay|$djlay|$damped internal_fluid.velocity=10 internal_fluid.model=paper"
  "jlay_damped_pipe_u10|$jlay|$djlay|$damped internal_fluid.velocity=10 internal_fluid.model=pipe_flow"
  "jlay_damped_u0_h2|$jlay|$djlay|$damped solver.dt=2.5e-4"
  "jlay_damped_paper_u10_h2|$jlay|$djlay|$damped solver.dt=2.5e-4 internal_fluid.velocity=10 internal_fluid.model=paper"
)
run_one() {
  IFS='|' read -r name scene dur sets <<<"$1"
  args=()
  for s in $sets; do args+=(--set "$s"); done
  # rfe 0 and rfe 20 (the middle of the J-lay at n = 40: Figs. 13b, 14b).
  "$cli" --scene "$scene" --duration "$dur" "${args[@]}" --csv "$out/$name.csv" --output-dt 0.01 --summary --quiet \
    --probe-rfe 0 --probe-rfe 20 >"$out/$name.json"
  echo "figures: $name $(cat "$out/$name.json" | /usr/bin/python3 -c 'import json,sys; d=json.load(sys.stdin); print("status", d["status"], "rtf", round(d["rtf"], 2))')"
}
export -f run_one
export cli out
printf '%s\n' "${jobs[@]}" | xargs -P 2 -I{} bash -c 'run_one "$@"' _ {}
/usr/bin/python3 "$root/scripts/plot_figures.py" "$out"
