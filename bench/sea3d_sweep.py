#!/usr/bin/python3
"""3D sea speed/accuracy: config/scenes/spatial_sea_riser.yaml (n = 50, JONSWAP, current, drag, added mass,
seabed friction), 30 s, the structured midpoint at several steps against midpoint at 1.25 ms (converged:
2.5 ms is within 3 um of it). Errors: largest distance of the top, rfes 10/25/40 and the end, and of the top
tension, over every 0.1 s sample; real-time factor from thread CPU (cpu_s). Writes out/bench/sea3d.csv and the
table out/bench/tables/sea3d.md (bench_tables.py)."""
import csv, json, math, os, subprocess, sys

import bench_tables

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
cli = os.environ.get("RISER_SIM_CLI", os.path.join(root, ".ws/devel/lib/riser_sim/riser_sim_cli"))
scene = os.path.join(root, "config/scenes/spatial_sea_riser.yaml")
out = os.path.join(root, "out/bench")
os.makedirs(out, exist_ok=True)
points = ["top", "end", "rfe10", "rfe25", "rfe40"]


def run(dt):
    path = os.path.join(out, "sea3d_%g.csv" % dt)
    cmd = [cli, "--scene", scene, "--duration", "30", "--set", "solver.dt=%g" % dt, "--output-dt", "0.1",
           "--probe-rfe", "10", "--probe-rfe", "25", "--probe-rfe", "40", "--csv", path, "--summary", "--quiet"]
    summary = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout.splitlines()[0])
    rows = {round(float(r["t"]), 6): r for r in csv.DictReader(open(path))}
    return summary, rows


ref_summary, ref = run(0.00125)
table = []


def out(line):
    print(line, flush=True)
    table.append(line)


out("3D sea: spatial_sea_riser (n = 50), 30 s, structured midpoint vs midpoint at 1.25 ms")
out("")
out("| dt [s] | position error [mm] | top tension error [N] | of the mean tension | Newton/step | RTF (CPU) |")
out("|---|---|---|---|---|---|")
mean_t = sum(float(r["tension_top"]) for r in ref.values()) / len(ref)
with open(os.path.join(out, "sea3d.csv"), "w") as f:
    f.write("dt,position_error_m,tension_error_n,newton_per_step,rtf_cpu\n")
    for dt in [0.0025, 0.01, 0.02, 0.05, 0.1]:
        s, rows = run(dt)
        pos = ten = 0.0
        for t, a in rows.items():
            b = ref.get(t)
            if b is None:
                continue
            for p in points:
                pos = max(pos, math.sqrt(sum((float(a[c + "_" + p]) - float(b[c + "_" + p])) ** 2 for c in "xyz")))
            ten = max(ten, abs(float(a["tension_top"]) - float(b["tension_top"])))
        rtf = s["sim_s"] / s["cpu_s"]
        nps = s["newton_iterations"] / s["steps"]
        out("| %g | %.3g | %.0f | %.2g %% | %.2f | %.1f |" % (dt, 1e3 * pos, ten, 100 * ten / mean_t, nps, rtf))
        f.write("%g,%.6g,%.6g,%.4g,%.4g\n" % (dt, pos, ten, nps, rtf))
print("wrote %s" % bench_tables.write("sea3d", table, " ".join(["bench/sea3d_sweep.py"] + sys.argv[1:])))
sys.exit(0)
