#!/usr/bin/python3
"""The paper's Table 1 (m_s = 1000 kg on a 100 m line, RK4, h = 1e-4 s, 20 s) run with riser_sim_cli:
our x_s(20), y_s(20) and wall time (median of --repeat runs) beside the paper's.
--sim: one run each for n = 10, 20, 40 (make sim: a quick check). Without --sim the table is also written to
out/bench/tables/paper_table1.md (bench_tables.py) for docs/benchmarks.md."""
import argparse
import json
import os
import statistics
import subprocess
import sys

import bench_tables

PAPER = {  # n: (x_s, y_s, seconds) absolute coordinates, Table 1 of Adamiec-Wojcik et al. 2013
    10: (-49.547, -86.750, 37), 20: (-49.551, -86.763, 83), 30: (-49.552, -86.765, 140),
    40: (-49.552, -86.765, 210), 50: (-49.552, -86.765, 292), 100: (-49.552, -86.765, 863)}
CONVERGED = (-49.9183, -86.604)  # our converged answer (docs/validation.md, test_table1)


def run(cli, scene, n, extra):
    cmd = [cli, "--scene", scene, "--set", f"line.elements={n}", "--summary", "--quiet"] + extra
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sim", action="store_true")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--ns", default="10,20,30,40,50,100")
    ap.add_argument("--csv", default="out/bench/paper_table1.csv")
    ap.add_argument("--formulation", default="absolute")
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    cli = os.environ.get("RISER_SIM_CLI", os.path.join(root, ".ws", "devel", "lib", "riser_sim", "riser_sim_cli"))
    scene = os.path.join(root, "config", "scenes", "paper_table1.yaml")
    ns = [10, 20, 40] if a.sim else [int(v) for v in a.ns.split(",")]
    reps = 1 if a.sim else a.repeat
    extra = ["--set", f"solver.formulation={a.formulation}"]
    rows = []
    table = []

    def out(line):
        print(line, flush=True)
        table.append(line)

    out(f"Table 1 (paper) vs riser_sim, formulation {a.formulation}, RK4 h = 1e-4 s, 20 s"
        f"{'' if a.sim else f', wall = median of {reps} runs'}")
    out("")
    out("| n | x_s(20) ours | y_s(20) ours | x_s paper | y_s paper | wall [s] ours | paper [s] | speed-up |")
    out("|---|---|---|---|---|---|---|---|")
    for n in ns:
        res = [run(cli, scene, n, extra) for _ in range(reps)]
        wall = statistics.median(r["wall_s"] for r in res)
        r = res[0]
        px, py, pt = PAPER.get(n, (float("nan"),) * 3)
        rows.append((n, r["x_end"], r["z_end"], wall, px, py, pt))
        out(f"| {n} | {r['x_end']:.4f} | {r['z_end']:.4f} | {px:.3f} | {py:.3f} | {wall:.2f} | {pt:.0f} |"
            f" {pt / wall:.0f}x |")
    print(f"converged answer of the stated problem (n -> inf, h -> 0): x_s = {CONVERGED[0]}, y_s = {CONVERGED[1]}"
          " (docs/validation.md explains the 0.37 m / 0.16 m gap to the paper)")
    if not a.sim:
        os.makedirs(os.path.dirname(a.csv), exist_ok=True)
        with open(a.csv, "w") as f:
            f.write("n,x_s,y_s,wall_s_median,paper_x_s,paper_y_s,paper_s\n")
            for row in rows:
                f.write(",".join(f"{v:.6g}" for v in row) + "\n")
        print(f"wrote {a.csv}")
        command = " ".join(["bench/paper_table1.py"] + sys.argv[1:])
        print(f"wrote {bench_tables.write('paper_table1', table, command)}")


if __name__ == "__main__":
    sys.exit(main())
