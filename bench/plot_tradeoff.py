#!/usr/bin/env python3
"""Pareto plots of riser_sim_bench_tradeoff's CSV (out/bench/tradeoff.csv): for every case the probe
position error against the run's time, one curve (its Pareto front) per integrator / formulation /
linear solve, every run drawn faintly; the reference's own spread shaded; the speed/accuracy targets
(docs/benchmarks.md) as lines. Writes <out>/pareto_<case>.png, <out>/pareto.png (all cases) and, from
step_cost.csv when present, <out>/step_cost.png. Prints, per case and accuracy, the cheapest setting
that reaches it.

  plot_tradeoff.py [--clock=cpu|wall] [CSV [OUT_DIR]]

--clock=cpu (default): the thread's CPU time, equal to the wall time on an idle core; on a shared,
loaded machine the wall time is mostly waiting for a core. --clock=wall: the median wall time."""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--")]
clock = next((a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--clock=")), "cpu")
src = args[0] if len(args) > 0 else "out/bench/tradeoff.csv"
out = args[1] if len(args) > 1 else os.path.dirname(src) or "."
tcol = "cpu_s" if clock == "cpu" else "wall_s"

# Per case: simulated duration, title, targets (error [m], time [s]): docs/benchmarks.md, "Targets".
CASES = {
    "table1_elastic": (20.0, "Table 1 line, elastic: end at 20 s", [(1e-3, 0.1), (1e-2, 0.02)]),
    "table1_inextensible": (20.0, "Table 1 line, inextensible: end at 20 s", [(1e-3, 0.1), (1e-2, 0.02)]),
    "jlay_elastic": (27.0, "170 m J-lay, elastic: middle point at 27 s", [(1e-2, 0.27)]),
    "jlay_inextensible": (27.0, "170 m J-lay, inextensible: middle point at 27 s", [(1e-2, 0.27)]),
    "riser500": (60.0, "500 m riser: lower end at 60 s", [(1e-2, 0.6)]),
}

rows = []
with open(src) as f:
    for r in csv.DictReader(f):
        rows.append(r)


def label(r):
    solve = r.get("jacobian", "-")
    lab = f"{r['integrator']} / {r['formulation']}"
    if solve == "dense" and r["formulation"] != "absolute":
        lab += " (dense J)"
    return lab


# One colour per integrator / formulation / solve, the same in every plot.
LABELS = sorted({label(r) for r in rows if r["status"] == "ok"})
COLOR = {lab: plt.cm.tab10(i % 10) for i, lab in enumerate(LABELS)}


def front(pts):
    pts = sorted(pts)
    best, fr = float("inf"), []
    for p in pts:
        if p[1] < best:
            fr.append(p)
            best = p[1]
    return fr


def draw(ax, case):
    dur, title, targets = CASES.get(case, (1.0, case, []))
    groups = defaultdict(list)
    spread = 0.0
    for r in rows:
        if r["case"] != case:
            continue
        spread = float(r["ref_spread_m"] or 0.0)
        if r["status"] != "ok":
            continue
        err = max(float(r["err_pos_m"]), 1e-7)  # below the plot: exact to the reference
        groups[label(r)].append((float(r[tcol]), err, int(r["n"]), r["h"], r["tolerance"]))
    allpts = [p for pts in groups.values() for p in pts]
    xmin = 0.5 * min((p[0] for p in allpts), default=1e-4)
    ymin = min(1e-5, 0.3 * min((p[1] for p in allpts), default=1e-5))
    colors = {}
    for i, (lab, pts) in enumerate(sorted(groups.items())):
        fr = front(pts)
        style = "--" if "absolute" in lab else ("-." if "dense" in lab else "-")
        line, = ax.plot([p[0] for p in fr], [p[1] for p in fr], style, marker="o", ms=3.5, lw=1.2, label=lab,
                        color=COLOR[lab])
        colors[lab] = line.get_color()
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=8, alpha=0.25, color=line.get_color())
        for p in fr:
            ax.annotate(str(p[2]), (p[0], p[1]), fontsize=5.5, xytext=(2, 2), textcoords="offset points")
    if spread > 0:
        ax.axhspan(ymin, spread, color="orange", alpha=0.10)
        ax.text(0.01, spread * 0.75, f"reference spread {spread * 1e3:.2g} mm", fontsize=6.5, color="darkorange",
                transform=ax.get_yaxis_transform())
    for y, txt in [(1e-4, "0.1 mm"), (1e-3, "1 mm"), (1e-2, "1 cm")]:
        ax.axhline(y, color="grey", ls=":", lw=0.7)
        ax.text(0.995, y * 1.1, txt, fontsize=6.5, color="grey", ha="right", transform=ax.get_yaxis_transform())
    for err, t in targets:
        ax.plot([t, t], [ymin, err], color="red", lw=0.9, alpha=0.6)
        ax.plot([xmin, t], [err, err], color="red", lw=0.9, alpha=0.6)
        ax.text(t, err * 1.15, f" target: {err * 1e3:g} mm in {t:g} s", fontsize=6, color="red")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(ymin, 30)
    ax.set_xlim(left=xmin)
    ax.set_xlabel(("thread CPU time" if clock == "cpu" else "median wall time") +
                  f" for {dur:g} s simulated [s]  (RTF = {dur:g} / time)")
    ax.set_ylabel("position error vs reference [m]")
    ax.set_title(title + "  (labels: n)", fontsize=9)
    ax.grid(True, which="both", alpha=0.15)
    ax.legend(fontsize=6, loc="upper right", ncol=1)


cases = [c for c in CASES if any(r["case"] == c for r in rows)]
for c in cases:
    fig, ax = plt.subplots(figsize=(8.5, 6))
    draw(ax, c)
    fig.tight_layout()
    path = os.path.join(out, f"pareto_{c}.png")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(f"wrote {path}")
if cases:
    cols = 2
    nrow = math.ceil(len(cases) / cols)
    fig, axes = plt.subplots(nrow, cols, figsize=(16, 6 * nrow), squeeze=False)
    for ax, c in zip(axes.flat, cases):
        draw(ax, c)
    for ax in list(axes.flat)[len(cases):]:
        ax.axis("off")
    fig.tight_layout()
    path = os.path.join(out, "pareto.png")
    fig.savefig(path, dpi=85)
    plt.close(fig)
    print(f"wrote {path}")

# Cheapest setting per case and accuracy.
print(f"\nCheapest run per accuracy ({'thread CPU' if clock == 'cpu' else 'median wall'} time):\n")
print("| case | accuracy | setting | n | h or tol | CPU [s] | wall [s] | RTF (CPU) | error |")
print("|---|---|---|---|---|---|---|---|---|")
for c in cases:
    dur = CASES.get(c, (1.0,))[0]
    ok = [r for r in rows if r["case"] == c and r["status"] == "ok"]
    for acc in (1e-2, 1e-3, 1e-4):
        good = [r for r in ok if float(r["err_pos_m"]) <= acc]
        if not good:
            print(f"| {c} | {acc * 1e3:g} mm | none | | | | | | |")
            continue
        b = min(good, key=lambda r: float(r[tcol]))
        ht = b["tolerance"] if b["integrator"] == "dopri5" else b["h"]
        print(f"| {c} | {acc * 1e3:g} mm | {label(b)} | {b['n']} | {ht} | {float(b['cpu_s']):.4g} | "
              f"{float(b['wall_s']):.4g} | {dur / float(b['cpu_s']):.0f} | {float(b['err_pos_m']) * 1e3:.3g} mm |")

# Cost of one step against n.
sc = os.path.join(os.path.dirname(src) or ".", "step_cost.csv")
if os.path.exists(sc):
    data = defaultdict(list)
    with open(sc) as f:
        for r in csv.DictReader(f):
            data[(r["scene"], f"{r['integrator']} / {r['formulation']} / {r['jacobian']}")].append(
                (int(r["n"]), float(r["cpu_us_per_step"])))
    scenes = sorted({k[0] for k in data})
    scenes = [x for x in ("jlay", "riser500", "table1") if x in scenes] + [x for x in scenes if x not in
                                                                             ("jlay", "riser500", "table1")]
    fig, axes = plt.subplots(1, len(scenes), figsize=(6.5 * len(scenes), 5.5), squeeze=False)
    for ax, sc_name in zip(axes.flat, scenes):
        for (s, lab), pts in sorted(data.items()):
            if s != sc_name:
                continue
            pts.sort()
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o", ms=3, label=lab)
        xs = [10, 1000]
        for k, txt in [(1, "O(n)"), (2, "O(n²)")]:
            ax.plot(xs, [5.0 * (x / 10) ** k for x in xs], color="grey", ls=":", lw=0.8)
            ax.text(xs[1], 5.0 * (xs[1] / 10) ** k, txt, fontsize=7, color="grey")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n (segments)")
        ax.set_ylabel("thread CPU time per step [µs] (median of 3)")
        titles = {"jlay": "J-lay: drag, added mass, contents, 5 m/s flow, seabed (n <= 300)",
                  "riser500": "500 m riser: drag, added mass, 5 m/s flow", "table1": "Table 1 line (no water)"}
        ax.set_title("cost of one step, " + titles.get(sc_name, sc_name), fontsize=9)
        ax.grid(True, which="both", alpha=0.15)
        ax.legend(fontsize=6)
    fig.tight_layout()
    path = os.path.join(out, "step_cost.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"wrote {path}")
