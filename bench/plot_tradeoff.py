"""Pareto plots of riser_sim_bench_tradeoff's CSV (out/bench/tradeoff.csv): for every case the probe
position error, the top tension's and the largest axial force's RMS history error against the run's
time, one curve (its Pareto front) per integrator / formulation / linear solve, every run drawn faintly;
the reference's own convergence shaded; the speed/accuracy targets (docs/benchmarks.md) as lines. Writes
<out>/pareto_<case>.png (position | top tension | largest axial force), <out>/pareto.png (positions, all
cases), <out>/pareto_forces.png (forces, all cases) and, from step_cost.csv when present,
<out>/step_cost.png. Prints, per case and accuracy, the cheapest setting that reaches it, and whether
the force targets are met; both tables also go to out/bench/tables/tradeoff_cheapest.md and
tradeoff_force_targets.md (bench_tables.py) for docs/benchmarks.md.

  plot_tradeoff.py [--clock=cpu|wall] [CSV [OUT_DIR]]

--clock=cpu (default): the thread's CPU time, equal to the wall time on an idle core; on a shared,
loaded machine the wall time is mostly waiting for a core. --clock=wall: the median wall time."""
import csv
import math
import os
import sys
from collections import defaultdict

import bench_tables  # noqa: E402  (beside this script)
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--")]
clock = next((a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--clock=")), "cpu")
src = args[0] if len(args) > 0 else "out/bench/tradeoff.csv"
out = args[1] if len(args) > 1 else os.path.dirname(src) or "."
tcol = "cpu_s" if clock == "cpu" else "wall_s"

# Per case: simulated duration, title, position targets (error [m], time [s]): docs/benchmarks.md, "Targets".
CASES = {
    "table1_elastic": (20.0, "Table 1 line, elastic: end at 20 s", [(1e-3, 0.1), (1e-2, 0.02)]),
    "table1_elastic_damped": (20.0, "Table 1 line, elastic, 2 % axial damping: end at 20 s",
                              [(1e-3, 0.1), (1e-2, 0.02)]),
    "table1_inextensible": (20.0, "Table 1 line, inextensible: end at 20 s", [(1e-3, 0.1), (1e-2, 0.02)]),
    "jlay_elastic": (27.0, "170 m J-lay, elastic: middle point at 27 s", [(1e-2, 0.27)]),
    "jlay_elastic_damped": (27.0, "170 m J-lay, elastic, 2 % axial damping, seabed springs per metre",
                            [(1e-2, 0.27)]),
    "jlay_inextensible": (27.0, "170 m J-lay, inextensible: middle point at 27 s", [(1e-2, 0.27)]),
    "riser500": (60.0, "500 m riser: lower end at 60 s", [(1e-2, 0.6)]),
}
JLAY = ("jlay_elastic", "jlay_elastic_damped")
# Force targets (docs/benchmarks.md, "Tension against cost"): cases, text, n (None: any), the limits
# on tradeoff.csv's error columns, the smallest RTF (simulated time / run time).
FORCE_TARGETS = [
    (JLAY, "top tension <= 2 % RMS and <= 5 % max at RTF >= 100", 100,
     [("err_top_rms", 0.02), ("err_top_max", 0.05)], 100),
    (JLAY, "top tension <= 1 % RMS at RTF >= 30", 100, [("err_top_rms", 0.01)], 30),
    (("riser500", "table1_elastic", "table1_elastic_damped", "table1_inextensible"), "largest axial force <= 2 % RMS at RTF >= 100",
     None, [("err_axial_rms", 0.02)], 100),
]
# What a panel shows: error column, reference-convergence column, axis label, guide lines, unit scale.
MEASURES = {
    "pos": ("err_pos_m", "ref_spread_m", "position error vs reference [m]",
            [(1e-4, "0.1 mm"), (1e-3, "1 mm"), (1e-2, "1 cm")]),
    "top": ("err_top_rms", "ref_top_rms", "top tension: RMS history error / RMS reference",
            [(1e-2, "1 %"), (2e-2, "2 %"), (5e-2, "5 %")]),
    "axial": ("err_axial_rms", "ref_axial_rms", "largest axial force: RMS history error / RMS reference",
              [(1e-2, "1 %"), (2e-2, "2 %"), (5e-2, "5 %")]),
}

rows = []
with open(src) as f:
    for r in csv.DictReader(f):
        rows.append(r)


def num(r, col):
    try:
        return float(r.get(col) or "nan")
    except ValueError:
        return float("nan")


def case_info(case):
    """(duration, title, position targets); a case not in CASES: its duration from rtf_cpu x cpu_s."""
    if case in CASES:
        return CASES[case]
    dur = next((num(r, "rtf_cpu") * num(r, "cpu_s") for r in rows if r["case"] == case and r["status"] == "ok"), 1.0)
    return (round(dur, 6), case, [])


def label(r):
    solve = r.get("jacobian", "-")
    integ = r["integrator"] + (f" rho_inf={r['rho_inf']}" if r.get("rho_inf") else "")
    lab = f"{integ} / {r['formulation']}"
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


def targets_of(case, measure):
    """(error, time) lines of the panel: position targets, or the RMS force targets of this case."""
    dur, _, pos = case_info(case)
    if measure == "pos":
        return [(e, t, f"{e * 1e3:g} mm in {t:g} s") for e, t in pos]
    col = MEASURES[measure][0]
    out = []
    for cases, _, n, limits, rtf in FORCE_TARGETS:
        for c, lim in limits:
            if case in cases and c == col:
                out.append((lim, dur / rtf, f"{lim * 100:g} % at RTF {rtf:g}" + (f", n = {n}" if n else "")))
    return out


def draw(ax, case, measure="pos"):
    dur, title, _ = case_info(case)
    col, spread_col, ylabel, guides = MEASURES[measure]
    groups = defaultdict(list)
    spread = 0.0
    for r in rows:
        if r["case"] != case:
            continue
        spread = num(r, spread_col) if math.isfinite(num(r, spread_col)) else 0.0
        if r["status"] != "ok" or not math.isfinite(num(r, col)):
            continue
        err = max(num(r, col), 1e-7)  # below the plot: exact to the reference
        groups[label(r)].append((float(r[tcol]), err, int(r["n"]), r["h"], r["tolerance"]))
    allpts = [p for pts in groups.values() for p in pts]
    xmin = 0.5 * min((p[0] for p in allpts), default=1e-4)
    ymin = min(1e-5, 0.3 * min((p[1] for p in allpts), default=1e-5))
    for lab, pts in sorted(groups.items()):
        fr = front(pts)
        style = "--" if "absolute" in lab else ("-." if "dense" in lab else "-")
        line, = ax.plot([p[0] for p in fr], [p[1] for p in fr], style, marker="o", ms=3.5, lw=1.2, label=lab,
                        color=COLOR[lab])
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=8, alpha=0.25, color=line.get_color())
        for p in fr:
            ax.annotate(str(p[2]), (p[0], p[1]), fontsize=5.5, xytext=(2, 2), textcoords="offset points")
    if spread > 0:
        ax.axhspan(ymin, spread, color="orange", alpha=0.10)
        txt = f"{spread * 1e3:.2g} mm" if measure == "pos" else f"{spread * 100:.2g} %"
        ax.text(0.01, spread * 0.75, f"reference's own convergence {txt}", fontsize=6.5, color="darkorange",
                transform=ax.get_yaxis_transform())
    for y, txt in guides:
        ax.axhline(y, color="grey", ls=":", lw=0.7)
        ax.text(0.995, y * 1.1, txt, fontsize=6.5, color="grey", ha="right", transform=ax.get_yaxis_transform())
    for err, t, txt in targets_of(case, measure):
        ax.plot([t, t], [ymin, err], color="red", lw=0.9, alpha=0.6)
        ax.plot([xmin, t], [err, err], color="red", lw=0.9, alpha=0.6)
        ax.text(t, err * 1.15, f" target: {txt}", fontsize=6, color="red")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(ymin, 30)
    ax.set_xlim(left=xmin)
    ax.set_xlabel(("thread CPU time" if clock == "cpu" else "median wall time") +
                  f" for {dur:g} s simulated [s]  (RTF = {dur:g} / time)")
    ax.set_ylabel(ylabel, fontsize=8)
    ax.set_title(title + "  (labels: n)", fontsize=9)
    ax.grid(True, which="both", alpha=0.15)
    ax.legend(fontsize=6, loc="upper right", ncol=1)


def has_forces(case):
    return any(r["case"] == case and math.isfinite(num(r, "err_top_rms")) for r in rows)


cases = [c for c in CASES if any(r["case"] == c for r in rows)]
cases += sorted({r["case"] for r in rows} - set(cases))
for c in cases:
    panels = ["pos"] + (["top", "axial"] if has_forces(c) else [])
    fig, axes = plt.subplots(1, len(panels), figsize=(8.5 * len(panels), 6), squeeze=False)
    for ax, m in zip(axes.flat, panels):
        draw(ax, c, m)
    fig.tight_layout()
    path = os.path.join(out, f"pareto_{c}.png")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print(f"wrote {path}")


def grid_plot(name, panels_of):
    """One figure, one row of panels per case (or two cases per row for single panels)."""
    items = [(c, m) for c in cases for m in panels_of(c)]
    if not items:
        return
    cols = 2
    nrow = math.ceil(len(items) / cols)
    fig, axes = plt.subplots(nrow, cols, figsize=(16, 6 * nrow), squeeze=False)
    for ax, (c, m) in zip(axes.flat, items):
        draw(ax, c, m)
    for ax in list(axes.flat)[len(items):]:
        ax.axis("off")
    fig.tight_layout()
    path = os.path.join(out, name)
    fig.savefig(path, dpi=85)
    plt.close(fig)
    print(f"wrote {path}")


grid_plot("pareto.png", lambda c: ["pos"])
grid_plot("pareto_forces.png", lambda c: ["top", "axial"] if has_forces(c) else [])


def setting(b):
    return b["tolerance"] if b["integrator"] == "dopri5" else b["h"]


def pct(x):
    return f"{x * 100:.3g} %"


# Cheapest setting per case and accuracy: position, then the two force histories.
cheapest, force_targets = [], []


def out(table, line):
    print(line)
    table.append(line)


print()
out(cheapest, f"Cheapest run per accuracy ({'thread CPU' if clock == 'cpu' else 'median wall'} time):")
out(cheapest, "")
out(cheapest, "| case | measure | accuracy | setting | n | h or tol | CPU [s] | wall [s] | RTF (CPU) | error |")
out(cheapest, "|---|---|---|---|---|---|---|---|---|---|")
KINDS = [("position", "err_pos_m", (1e-2, 1e-3, 1e-4), lambda a: f"{a * 1e3:g} mm", lambda e: f"{e * 1e3:.3g} mm"),
         ("top T RMS", "err_top_rms", (5e-2, 2e-2, 1e-2), pct, pct),
         ("max axial RMS", "err_axial_rms", (5e-2, 2e-2, 1e-2), pct, pct)]
for c in cases:
    dur = case_info(c)[0]
    ok = [r for r in rows if r["case"] == c and r["status"] == "ok"]
    for kind, col, accs, fa, fe in KINDS:
        if not any(math.isfinite(num(r, col)) for r in ok):
            continue
        for acc in accs:
            good = [r for r in ok if num(r, col) <= acc]
            if not good:
                out(cheapest, f"| {c} | {kind} | {fa(acc)} | none | | | | | | |")
                continue
            b = min(good, key=lambda r: float(r[tcol]))
            out(cheapest, f"| {c} | {kind} | {fa(acc)} | {label(b)} | {b['n']} | {setting(b)} | {float(b['cpu_s']):.4g} | "
                          f"{float(b['wall_s']):.4g} | {dur / float(b['cpu_s']):.0f} | {fe(num(b, col))} |")

# The force targets: met or not, and the cheapest run that meets them.
print()
out(force_targets, f"Force targets (RTF by {'thread CPU' if clock == 'cpu' else 'median wall'} time):")
out(force_targets, "")
out(force_targets, "| case | target | met? | cheapest run that meets it | n | h or tol | RTF | top T RMS / max | "
      "max axial RMS / max |")
out(force_targets, "|---|---|---|---|---|---|---|---|---|")
for tcases, text, n, limits, rtf in FORCE_TARGETS:
    for c in tcases:
        if c not in cases:
            continue
        dur = case_info(c)[0]
        ok = [r for r in rows if r["case"] == c and r["status"] == "ok" and (n is None or int(r["n"]) == n)]
        good = [r for r in ok if dur / float(r[tcol]) >= rtf and all(num(r, col) <= lim for col, lim in limits)]
        where = text + (f" (n = {n})" if n else "")
        if not ok:
            out(force_targets, f"| {c} | {where} | not run | | | | | | |")
            continue
        if not good:
            out(force_targets, f"| {c} | {where} | **not met** | | | | | | |")
            continue
        b = min(good, key=lambda r: float(r[tcol]))
        out(force_targets, f"| {c} | {where} | **met** | {label(b)} | {b['n']} | {setting(b)} | "
                           f"{dur / float(b[tcol]):.0f} | {pct(num(b, 'err_top_rms'))} / {pct(num(b, 'err_top_max'))} | "
                           f"{pct(num(b, 'err_axial_rms'))} / {pct(num(b, 'err_axial_max'))} |")

command = " ".join(["bench/plot_tradeoff.py"] + sys.argv[1:])
print(f"wrote {bench_tables.write('tradeoff_cheapest', cheapest, command)}")
if len(force_targets) > 4:  # a row beyond the caption and the header
    print(f"wrote {bench_tables.write('tradeoff_force_targets', force_targets, command)}")

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
