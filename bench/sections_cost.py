#!/usr/bin/python3
"""Sectioned lines against uniform ones, and the lazy-wave FPSO at its recommended setting (docs/benchmarks.md,
"Line sections"). Two tables through bench_tables.py:

  sections_cost: the stepping CPU time per step of a shipped scene with sections (lazy_wave_riser.yaml, planar,
    n = 140; lazy_wave_fpso.yaml, 3D, n = 76, with a bend stiffener) against the same scene as one uniform
    section of the same n (line.sections and line.bend_stiffener removed, line.length and line.elements set):
    rk4 at one fixed step (the same work per step whatever the shape) and an implicit integrator with the
    structured solve (per step and per Newton iteration: its iterations follow the shape). The runs alternate
    sectioned / uniform, REPEAT pairs, and the ratio is of the medians (the machine's load drifts alike for both).
  lazy_wave_fpso: the shipped scene as it is (its run.duration) REPEAT times: the real-time factor of the whole
    process (simulated time / the process's wall and CPU time, statics included) and of the stepping (the
    summary's rtf, wall, and its cpu_s); medians, with the load average at the start.

  bench/sections_cost.py [--cli PATH] [--repeat 3]
CSV: out/bench/sections_cost.csv, out/bench/lazy_wave_fpso.csv."""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import time

import bench_tables

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.path.join(ROOT, "config", "scenes")

# (scene, n, length [m], rk4 step [s] below both variants' stable steps, duration of the rk4 runs [s], the
# implicit row's label, overrides and duration [s]: planar on the recursive formulation, whose structured solve
# relinearises every step (the scene's absolute one refreshes a dense Jacobian every 0.1 s: its cost per step
# is that refresh's and Newton's count, not the step's work)).
CASES = [("lazy_wave_riser.yaml", 140, 1400.0, 0.005, 4.0, "generalized_alpha, recursive, 0.05 s",
          ["solver.formulation=recursive"], 12.0),
         ("lazy_wave_fpso.yaml", 76, 1400.0, 0.001, 1.0, "the scene's: midpoint, 0.05 s", [], 12.0)]


def run(cli, scene, sets, duration=None):
    """(process wall [s], process CPU [s]: user + system, the summary)."""
    cmd = [cli, "--scene", os.path.join(SCENES, scene), "--summary", "--quiet"]
    if duration is not None:
        cmd += ["--duration", repr(duration)]
    for s in sets:
        cmd += ["--set", s]
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    if p.returncode != 0:
        sys.exit("sections_cost: %s failed (exit %d): %s" % (" ".join(cmd), p.returncode, p.stderr[-800:]))
    summary = json.loads(p.stdout.strip().splitlines()[-1])
    if summary.get("status") != "ok":
        sys.exit("sections_cost: %s: status %s %s" % (" ".join(cmd), summary.get("status"), summary.get("warning")))
    return wall, cpu, summary


def section_table(cli, repeat, table, rows):
    table.append("| scene | integrator, dt | per step: sections / uniform [us] | ratio | per Newton iteration: "
                 "sections / uniform [us] | ratio |")
    table.append("|---|---|---|---|---|---|")
    for scene, n, length, dt_rk4, dur_rk4, implicit, implicit_sets, dur_implicit in CASES:
        with open(os.path.join(SCENES, scene)) as f:
            text = f.read()
        # The uniform twin: one section of the same n and length (--set KEY=null needs the key in the scene).
        uniform = ["line.sections=null", "line.length=%r" % length, "line.elements=%d" % n]
        if "\n  bend_stiffener:" in text:
            uniform.append("line.bend_stiffener=null")
        for label, sets, dur in (("rk4, %g s" % dt_rk4, ["solver.integrator=rk4", "solver.dt=%r" % dt_rk4], dur_rk4),
                                 (implicit, implicit_sets, dur_implicit)):
            per = {"sections": [], "uniform": []}
            per_newton = {"sections": [], "uniform": []}
            for _ in range(repeat):
                for kind, extra in (("sections", []), ("uniform", uniform)):
                    _, _, s = run(cli, scene, sets + extra, dur)
                    if s["steps"] <= 0 or s["cpu_s"] <= 0:
                        sys.exit("sections_cost: %s %s: no steps timed (cpu_s %s)" % (scene, kind, s["cpu_s"]))
                    per[kind].append(s["cpu_s"] / s["steps"])
                    if s.get("newton_iterations"):
                        per_newton[kind].append(s["cpu_s"] / s["newton_iterations"])
            a, b = statistics.median(per["sections"]), statistics.median(per["uniform"])
            cells = ["%.1f / %.1f" % (1e6 * a, 1e6 * b), "%.3f" % (a / b)]
            if per_newton["sections"]:
                an, bn = statistics.median(per_newton["sections"]), statistics.median(per_newton["uniform"])
                cells += ["%.1f / %.1f" % (1e6 * an, 1e6 * bn), "%.3f" % (an / bn)]
            else:
                cells += ["–", "–"]
            table.append("| %s (n = %d) | %s | %s |" % (scene, n, label, " | ".join(cells)))
            rows.append("%s,%d,%s,%.6g,%.6g,%s" % (scene, n, label.replace(",", ""), a, b, cells[1]))
            print(table[-1], flush=True)


def fpso_table(cli, repeat, table, rows):
    scene = "lazy_wave_fpso.yaml"
    load = os.getloadavg()[0]
    runs = []
    for _ in range(repeat):
        wall, cpu, s = run(cli, scene, [])
        runs.append({"process": s["sim_s"] / wall, "process_cpu": s["sim_s"] / cpu, "stepping": s["rtf"],
                     "stepping_cpu": s["sim_s"] / s["cpu_s"], "wall": wall, "summary": s})
        rows.append("%.6g,%.6g,%.6g,%.6g,%.6g,%.6g" % (s["sim_s"], wall, cpu, s["wall_s"], s["cpu_s"], load))
    s = runs[0]["summary"]
    med = {k: statistics.median(r[k] for r in runs) for k in ("process", "process_cpu", "stepping", "stepping_cpu",
                                                               "wall")}
    table.append("| setting | simulated [s] | process wall [s] | RTF: process, wall | process, CPU | stepping, wall | "
                 "stepping, CPU | Newton/step |")
    table.append("|---|---|---|---|---|---|---|---|")
    table.append("| n = %s, %s, dt %g s | %g | %.2f | %.1f | %.1f | %.1f | %.1f | %.2f |"
                 % (s["n"], s["integrator"], s["dt"], s["sim_s"], med["wall"], med["process"], med["process_cpu"],
                    med["stepping"], med["stepping_cpu"], s["newton_iterations"] / s["steps"]))
    table.append("")
    table.append("Medians of %d runs, load average %.1f at the start: on a loaded machine the wall-time RTFs fall "
                 "below the CPU-time ones by the share of a core the process gets. The process counts the start, the "
                 "statics and the stability estimate." % (repeat, load))
    print("\n".join(table[-5:]), flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default=os.environ.get("RISER_SIM_CLI",
                                                    os.path.join(ROOT, ".ws/devel/lib/riser_sim/riser_sim_cli")))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", choices=["sections", "fpso"])
    a = ap.parse_args()
    out = os.path.join(ROOT, "out", "bench")
    os.makedirs(out, exist_ok=True)
    cmd = " ".join(["bench/sections_cost.py"] + sys.argv[1:])
    if a.only != "fpso":
        table, rows = ["Stepping CPU time per step, sectioned scene against its uniform twin (same n), medians of "
                       "%d interleaved pairs" % a.repeat, ""], []
        section_table(a.cli, a.repeat, table, rows)
        with open(os.path.join(out, "sections_cost.csv"), "w") as f:
            f.write("scene,n,setting,per_step_sections_s,per_step_uniform_s,ratio\n" + "\n".join(rows) + "\n")
        print("wrote %s" % bench_tables.write("sections_cost", table, cmd))
    if a.only != "sections":
        table, rows = ["lazy_wave_fpso.yaml at its recommended setting (the scene's solver block)", ""], []
        fpso_table(a.cli, a.repeat, table, rows)
        with open(os.path.join(out, "lazy_wave_fpso.csv"), "w") as f:
            f.write("sim_s,process_wall_s,process_cpu_s,stepping_wall_s,stepping_cpu_s,load_average\n" + "\n".join(rows)
                    + "\n")
        print("wrote %s" % bench_tables.write("lazy_wave_fpso", table, cmd))
    return 0


if __name__ == "__main__":
    sys.exit(main())
