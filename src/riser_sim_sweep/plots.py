"""Plots of a results folder: the largest value of a kept column against the heading (polar, the maximum over
all other overrides at each heading), the status map (each case by its first two overrides, coloured by
status) and, with keep.range_graph, every case's range-graph envelopes along the arc length. PNG files in the
results folder."""
import json
import math
import os

from .results_folder import read_table

STATUS_COLOURS = {"ok": "tab:green", "warning": "tab:orange", "diverged": "tab:red", "failed": "black",
                  "refused": "tab:gray"}


def _num(v):
    try:
        x = float(v)
        return x if math.isfinite(x) else None
    except (TypeError, ValueError):
        return None


def _matplotlib():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def heading_key(override_cols):
    keys = [k for k in override_cols if k.split(".")[-1] == "heading"]
    return keys[0] if keys else None


def polar_plot(folder, rows, override_cols, column=None, key=None):
    """max of `column` (default max_tension_max) per heading; None when there is no heading or column."""
    key = key or heading_key(override_cols)
    if not rows or key is None:
        return None
    column = column or ("max_tension_max" if "max_tension_max" in rows[0] else
                        next((c for c in rows[0] if c.startswith("max_")), None))
    if column is None:
        return None
    best = {}
    for r in rows:
        h, v = _num(r.get(key)), _num(r.get(column))
        if h is not None and v is not None and r["status"] in ("ok", "warning"):
            best[h] = max(v, best.get(h, -math.inf))
    if not best:
        return None
    plt = _matplotlib()
    hs = sorted(best)
    th = [math.radians(h) for h in hs] + [math.radians(hs[0])]
    vs = [best[h] for h in hs] + [best[hs[0]]]
    fig = plt.figure(figsize=(5.5, 5.5))
    ax = fig.add_subplot(projection="polar")
    ax.plot(th, vs, "o-")
    ax.set_theta_zero_location("E")
    ax.set_theta_direction(1)
    ax.set_title("%s: largest %s over the cases\nagainst %s [deg]" % (os.path.basename(folder), column, key),
                 fontsize=9)
    path = os.path.join(folder, "polar_%s.png" % column)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


def status_map(folder, rows, override_cols):
    if not rows:
        return None
    plt = _matplotlib()
    keys = [k for k in override_cols if len({r.get(k) for r in rows}) > 1][:2]

    def axis(k):
        vals = [r.get(k) for r in rows]
        if all(_num(v) is not None for v in vals):
            return [_num(v) for v in vals], None
        levels = sorted(set(vals), key=str)
        return [levels.index(v) for v in vals], levels

    xs, xl = axis(keys[0]) if keys else ([int(r["case"]) for r in rows], None)
    ys, yl = axis(keys[1]) if len(keys) > 1 else ([0] * len(rows), None)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for st, col in STATUS_COLOURS.items():
        pts = [(x, y) for x, y, r in zip(xs, ys, rows) if r["status"] == st]
        if pts:
            ax.scatter(*zip(*pts), c=col, label="%s (%d)" % (st, len(pts)), s=40)
    ax.set_xlabel(keys[0] if keys else "case")
    ax.set_ylabel(keys[1] if len(keys) > 1 else "")
    if xl:
        ax.set_xticks(range(len(xl)), [str(v) for v in xl], rotation=30)
    if yl:
        ax.set_yticks(range(len(yl)), [str(v) for v in yl])
    ax.legend(fontsize=8)
    ax.set_title("%s: status of %d cases" % (os.path.basename(folder), len(rows)), fontsize=9)
    path = os.path.join(folder, "status_map.png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


# Panels of the envelope plot: (arc-length column, quantity, scale, label).
RANGE_PANELS = (("s", "tension", 1e-3, "effective tension [kN]"), ("s_joint", "moment", 1e-3, "bending moment [kN m]"),
                ("s_joint", "curvature", 1.0, "curvature [1/m]"), ("s", "clearance", 1.0, "height above the seabed [m]"))


def _range_graph(path):
    """{column: array} of a range-graph CSV (the last row's empty joint columns are NaN)."""
    import numpy as np
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.genfromtxt(path, delimiter=",", skip_header=1, ndmin=2)
    return {c: data[:, i] for i, c in enumerate(header)}


def range_envelopes(folder, rows, override_cols):
    """range_envelopes.png: the min/max envelopes along the arc length of every finished case with a range graph
    (cases/<case_id>_range.csv), each case a band, and the envelope of them all; None when no case has one."""
    import numpy as np
    graphs = []
    for r in rows:
        path = os.path.join(folder, "cases", r["case_id"] + "_range.csv")
        if r["status"] in ("ok", "warning", "diverged") and os.path.isfile(path):
            label = ", ".join("%s=%s" % (k.split(".")[-1], r.get(k)) for k in override_cols) or "case %s" % r["case"]
            graphs.append((label, _range_graph(path)))
    if not graphs:
        return None
    panels = [p for p in RANGE_PANELS if all(p[1] + "_min" in g for _, g in graphs)]
    plt = _matplotlib()
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(8, 2.4 * len(panels)), squeeze=False)
    colours = plt.get_cmap("viridis")
    for ax, (s_key, key, scale, label) in zip(axes[:, 0], panels):
        bands = []
        for k, (name, g) in enumerate(graphs):
            ok = np.isfinite(g[s_key])
            s, lo, hi = g[s_key][ok], scale * g[key + "_min"][ok], scale * g[key + "_max"][ok]
            c = colours(k / max(len(graphs) - 1, 1))
            ax.fill_between(s, lo, hi, color=c, alpha=0.15, lw=0)
            ax.plot(s, hi, color=c, lw=0.6, label=name if len(graphs) <= 12 else None)
            ax.plot(s, lo, color=c, lw=0.6)
            bands.append((s, lo, hi))
        # The envelope of them all on the union of the stations (cases of another n: linear between theirs).
        grid = np.unique(np.concatenate([b[0] for b in bands]))
        inside = [(grid >= b[0][0]) & (grid <= b[0][-1]) for b in bands]
        lo_all = np.nanmin([np.where(m, np.interp(grid, b[0], b[1]), np.nan) for b, m in zip(bands, inside)], axis=0)
        hi_all = np.nanmax([np.where(m, np.interp(grid, b[0], b[2]), np.nan) for b, m in zip(bands, inside)], axis=0)
        ax.plot(grid, hi_all, color="black", lw=1.4)
        ax.plot(grid, lo_all, color="black", lw=1.4)
        ax.set_ylabel(label, fontsize=8)
        ax.grid(True, alpha=0.3)
        if key == "clearance":
            ax.set_yscale("symlog", linthresh=1.0)
    if len(graphs) <= 12:
        axes[0, 0].legend(fontsize=6, loc="best")
    axes[-1, 0].set_xlabel("arc length from the top s [m]")
    axes[0, 0].set_title("%s: range-graph envelopes of %d cases (black: of them all)"
                         % (os.path.basename(folder), len(graphs)), fontsize=9)
    fig.tight_layout()
    path = os.path.join(folder, "range_envelopes.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_folder(folder, column=None):
    with open(os.path.join(folder, "sweep.json")) as f:
        man = json.load(f)
    head = man["columns"]
    override_cols = head[2:head.index("status")]
    rows = read_table(folder)
    return [p for p in (polar_plot(folder, rows, override_cols, column), status_map(folder, rows, override_cols),
                        range_envelopes(folder, rows, override_cols)) if p]
