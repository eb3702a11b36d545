#!/usr/bin/env python3
"""Pareto plot of out/bench/tradeoff.csv: end-position error at t = 20 s against wall time, one
curve (its Pareto front) per model / integrator / formulation; all points drawn faintly."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--clock=")]
# --clock=cpu (default): the thread's CPU time, equal to the wall time on an idle core; on a shared,
# loaded machine the wall time is mostly waiting for a core. --clock=wall: the median wall time.
clock = next((a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--clock=")), "cpu")
src = args[0] if len(args) > 0 else "out/bench/tradeoff.csv"
dst = args[1] if len(args) > 1 else "out/bench/pareto.png"
groups = defaultdict(list)
with open(src) as f:
    for r in csv.DictReader(f):
        if r["status"] != "ok":
            continue
        key = (r["model"], r["integrator"], r["formulation"])
        groups[key].append((float(r["cpu_s" if clock == "cpu" else "wall_s"]), float(r["err_end_m"]), int(r["n"])))

fig, axes = plt.subplots(1, 2, figsize=(13, 5.5), sharey=True)
for ax, model in zip(axes, ["elastic", "inextensible"]):
    for (m, integ, form), pts in sorted(groups.items()):
        if m != model:
            continue
        pts.sort()
        front, best = [], float("inf")
        for w, e, n in pts:
            if e < best:
                front.append((w, e, n))
                best = e
        label = f"{integ} / {form}"
        line, = ax.plot([p[0] for p in front], [p[1] for p in front], "-o", ms=4, label=label)
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=10, alpha=0.3, color=line.get_color())
        for w, e, n in front:
            ax.annotate(str(n), (w, e), fontsize=6, xytext=(2, 2), textcoords="offset points")
    for y, txt in [(1e-3, "1 mm"), (1e-2, "1 cm")]:
        ax.axhline(y, color="grey", ls=":", lw=0.8)
        ax.text(0.01, y * 1.08, txt, fontsize=7, color="grey", transform=ax.get_yaxis_transform())
    for x in (0.02, 0.1):
        ax.axvline(x, color="grey", ls="--", lw=0.8)
    if model == "elastic":  # docs/validation.md: the converged elastic answer is ± (0.6, 3) mm across n
        ax.axhspan(1e-6, 3e-3, color="orange", alpha=0.07)
        ax.text(0.01, 2.2e-3, "within the reference's own spread (y ± 3 mm)", fontsize=7, color="darkorange",
                transform=ax.get_yaxis_transform())
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("CPU time (thread) for 20 s simulated [s], median of 3" if clock == "cpu"
                  else "wall time for 20 s simulated [s], median of 3")
    ax.set_title(f"Table 1 line, {model} (labels: n)")
    ax.grid(True, which="both", alpha=0.2)
    ax.legend(fontsize=7)
axes[0].set_ylabel("end position error at t = 20 s vs converged reference [m]")
fig.tight_layout()
fig.savefig(dst, dpi=120)
print(f"wrote {dst}")
