#!/usr/bin/python3
"""Draws the lowest natural mode shapes of a scene about its static state (riser_sim_cli --modes).

usage: plot_modes.py --cli BINARY --scene FILE [--modes 4] [-o PNG] [--set KEY=VALUE ...]

One panel per mode: the static shape (grey) and the shape displaced by +/- the mode (unitless
shapes scaled to 6 % of the line's extent), with period and character in the title.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_modes(path):
    modes = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            m = modes.setdefault(int(row["mode"]), {"period": float(row["period_s"]),
                                                    "character": row["character"], "pts": []})
            m["pts"].append(tuple(float(row[k]) for k in ("x", "y", "dx", "dy")))
    return modes


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", required=True, help="riser_sim_cli binary")
    ap.add_argument("--scene", required=True)
    ap.add_argument("--modes", type=int, default=4)
    ap.add_argument("--set", action="append", default=[], help="scene override KEY=VALUE")
    ap.add_argument("-o", "--output", help="PNG (default out/figures/modes_<scene>.png)")
    a = ap.parse_args()
    name = os.path.splitext(os.path.basename(a.scene))[0]
    out = a.output or os.path.join("out", "figures", "modes_%s.png" % name)
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        shapes = os.path.join(tmp, "modes.csv")
        cmd = [a.cli, "--scene", a.scene, "--modes", str(a.modes), "--modes-csv", shapes, "--quiet"]
        for s in a.set:
            cmd += ["--set", s]
        run = subprocess.run(cmd, stdout=subprocess.PIPE, universal_newlines=True)
        if run.returncode != 0:
            sys.exit("plot_modes.py: %s failed (exit %d)" % (" ".join(cmd), run.returncode))
        print(run.stdout, end="")
        modes = read_modes(shapes)
    first = next(iter(modes.values()))["pts"]
    xs = [p[0] for p in first]
    ys = [p[1] for p in first]
    scale = 0.06 * max(max(xs) - min(xs), max(ys) - min(ys))
    cols = min(len(modes), 4)
    rows = (len(modes) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(3.6 * cols, 3.8 * rows), squeeze=False)
    for ax in axes.flat:
        ax.set_visible(False)
    for ax, (k, m) in zip(axes.flat, sorted(modes.items())):
        ax.set_visible(True)
        ax.plot(xs, ys, color="0.6", lw=1.5, label="static")
        for sign, style in ((1, "-"), (-1, "--")):
            ax.plot([p[0] + sign * scale * p[2] for p in m["pts"]], [p[1] + sign * scale * p[3] for p in m["pts"]],
                    style, color="C%d" % (k - 1), lw=1.2)
        period = "%.4g s" % m["period"] if m["period"] > 0 else "no oscillation"
        ax.set_title("mode %d: T = %s\n%s" % (k, period, m["character"]), fontsize=10)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("x [m]")
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("y [m]")
    fig.suptitle("%s: natural modes about the static state (shapes x %.3g m)" % (name, scale), fontsize=11)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
