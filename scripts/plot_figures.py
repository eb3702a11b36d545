#!/usr/bin/env python3
"""Plots of the paper's section 4 runs (out/figures/*.csv from scripts/figures.sh) and the numbers
quoted in docs/figures.md (written to out/figures/numbers.txt)."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load(out, name):
    return np.genfromtxt(os.path.join(out, name + ".csv"), delimiter=",", names=True)


def smooth(y, n):
    """Centred moving average over n samples (removes the axial vibration of the tension)."""
    k = np.ones(n) / n
    return np.convolve(y, k, mode="same")


def main(out):
    lines = []
    # Figs. 10 / 11: trajectory of the lower end A.
    for fig, runs, title in (
        ("fig10_drag", [("riser_D0.7_CM2", "D_eta = 0.7"), ("riser_D1.0_CM2", "D_eta = 1.0"),
                        ("riser_D1.3_CM2", "D_eta = 1.3")], "C_M = 2: influence of D_eta"),
        ("fig11_inertia", [("riser_D0.7_CM1", "C_M = 1"), ("riser_D0.7_CM1.5", "C_M = 1.5"),
                           ("riser_D0.7_CM2", "C_M = 2")], "D_eta = 0.7: influence of C_M")):
        f, ax = plt.subplots(1, 2, figsize=(11, 4.2))
        for name, label in runs:
            d = load(out, name)
            ax[0].plot(d["x_end"], d["y_end"], label=label)
            ax[1].plot(d["t"], d["x_end"], label=label)
        ax[1].plot(d["t"], d["x_top"], "k--", lw=0.8, label="vessel x_0")
        ax[0].set_xlabel("x_A [m]"); ax[0].set_ylabel("y_A [m]"); ax[0].set_title("lower end A, " + title)
        ax[1].set_xlabel("t [s]"); ax[1].set_ylabel("x [m]"); ax[1].set_title("x of A and of the vessel")
        for a in ax:
            a.grid(True, alpha=0.3); a.legend(fontsize=8)
        f.tight_layout(); f.savefig(os.path.join(out, fig + ".png"), dpi=110); plt.close(f)

    def maxdiff(a, b, col):
        A, B = load(out, a), load(out, b)
        m = min(len(A), len(B))
        return np.max(np.abs(A[col][:m] - B[col][:m]))
    lines.append("500 m riser, max |x_A difference| over the run [m]:")
    lines.append("  D_eta 0.7 vs 1.3 (C_M = 2): %.2f" % maxdiff("riser_D0.7_CM2", "riser_D1.3_CM2", "x_end"))
    lines.append("  D_eta 0.7 vs 1.0 (C_M = 2): %.2f" % maxdiff("riser_D0.7_CM2", "riser_D1.0_CM2", "x_end"))
    lines.append("  C_M 1 vs 2 (D_eta = 0.7):   %.2f" % maxdiff("riser_D0.7_CM1", "riser_D0.7_CM2", "x_end"))
    lines.append("  C_M 1.5 vs 2 (D_eta = 0.7): %.2f" % maxdiff("riser_D0.7_CM1.5", "riser_D0.7_CM2", "x_end"))
    lines.append("  max |y_A difference| D_eta 0.7 vs 1.3: %.2f, C_M 1 vs 2: %.2f" % (
        maxdiff("riser_D0.7_CM2", "riser_D1.3_CM2", "y_end"), maxdiff("riser_D0.7_CM1", "riser_D0.7_CM2", "y_end")))

    # Fig. 13: rho_f = 0 vs 840 at u = 0; Fig. 14: u = 0, 5, 10.
    for fig, runs, title in (
        ("fig13_fluid_mass", [("jlay_rf0_u0", "rho_f = 0"), ("jlay_rf840_u0", "rho_f = 840, u = 0")],
         "J-lay: internal fluid mass"),
        ("fig14_flow_velocity", [("jlay_rf840_u0", "u = 0"), ("jlay_rf840_u5", "u = 5 m/s"),
                                 ("jlay_rf840_u10", "u = 10 m/s")], "J-lay: internal flow velocity")):
        f, ax = plt.subplots(1, 3, figsize=(15, 4.2))
        for name, label in runs:
            d = load(out, name)
            ax[0].plot(d["t"], d["tension_top"] / 1e3, lw=0.5, label=label)
            ax[1].plot(d["t"][20:-20], smooth(d["tension_top"], 20)[20:-20] / 1e3, label=label)
            ax[2].plot(d["x_end"], d["y_end"], label=label)
        ax[0].set_title(title + ": tension at the top (rfe 0)")
        ax[1].set_title("same, 1 s moving average")
        ax[2].set_title("trajectory of the end A")
        for a in ax[:2]:
            a.set_xlabel("t [s]"); a.set_ylabel("tension [kN]")
        ax[2].set_xlabel("x_A [m]"); ax[2].set_ylabel("y_A [m]")
        for a in ax:
            a.grid(True, alpha=0.3); a.legend(fontsize=8)
        f.tight_layout(); f.savefig(os.path.join(out, fig + ".png"), dpi=110); plt.close(f)

    def reltension(a, b, n):
        A, B = load(out, a), load(out, b)
        m = min(len(A), len(B))
        ta, tb = A["tension_top"][:m], B["tension_top"][:m]
        if n > 1:
            ta, tb = smooth(ta, n)[n:-n], smooth(tb, n)[n:-n]
        return np.max(np.abs(ta - tb)) / np.max(np.abs(tb)), np.mean(np.abs(ta - tb)) / np.mean(np.abs(tb))
    for a, b in (("jlay_rf840_u10", "jlay_rf840_u0"), ("jlay_rf840_u5", "jlay_rf840_u0"),
                 ("jlay_rf0_u0", "jlay_rf840_u0")):
        r, rm = reltension(a, b, 1)
        s, sm = reltension(a, b, 20)
        lines.append("J-lay top tension %s vs %s: max |dT|/max T = %.2f %% (mean %.2f %%); 1 s averages: "
                     "%.2f %% (mean %.2f %%)" % (a, b, 100 * r, 100 * rm, 100 * s, 100 * sm))
        lines.append("  max |x_A difference| %s vs %s: %.3f m" % (a, b, maxdiff(a, b, "x_end")))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(out, "numbers.txt"), "w") as fh:
        fh.write(text + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/figures")
