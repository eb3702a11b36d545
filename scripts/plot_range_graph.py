#!/usr/bin/env python3
"""Plots a range graph (riser_sim_cli --range-graph FILE.csv): the min/max envelopes of the effective
tension, the bending moment, the curvature and (with a seabed) the clearance along the arc length.

usage: /usr/bin/python3 scripts/plot_range_graph.py RANGE.csv OUT.png [TITLE]
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(csv_path, png_path, title):
    # The last row's joint columns are empty (no joint past the end): read as NaN, dropped below.
    d = np.genfromtxt(csv_path, delimiter=",", names=True)
    if d.ndim == 0:
        d = d.reshape(1)
    names = d.dtype.names
    panels = [("s", "tension", 1e-3, "effective tension [kN]"),
              ("s_joint", "moment", 1e-3, "bending moment [kN m]"),
              ("s_joint", "curvature", 1.0, "curvature [1/m]")]
    if "clearance_min" in names:
        panels.append(("s", "clearance", 1.0, "height above the seabed [m]"))
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(8, 2.4 * len(panels)))
    for ax, (s_key, key, scale, label) in zip(axes, panels):
        ok = np.isfinite(d[s_key])
        s, lo, hi = d[s_key][ok], scale * d[key + "_min"][ok], scale * d[key + "_max"][ok]
        ax.fill_between(s, lo, hi, color="tab:blue", alpha=0.3, lw=0)
        ax.plot(s, hi, color="tab:red", lw=1.0, label="max")
        ax.plot(s, lo, color="tab:blue", lw=1.0, label="min")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(loc="best", fontsize="small")
    if "clearance_min" in names:
        axes[-1].set_yscale("symlog", linthresh=1.0)
    axes[-1].set_xlabel("arc length from the top s [m]")
    axes[0].set_title(title)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) == 4 else "range graph")
