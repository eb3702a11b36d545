#!/usr/bin/env python3
"""Plots of the paper's section 4 runs (out/figures/*.csv from tools/figures.sh) and the numbers
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
            ax[0].plot(d["x_end"], d["z_end"], label=label)
            ax[1].plot(d["t"], d["x_end"], label=label)
        ax[1].plot(d["t"], d["x_top"], "k--", lw=0.8, label="vessel x_0")
        ax[0].set_xlabel("x_A [m]"); ax[0].set_ylabel("z_A [m] (the paper's y_A)"); ax[0].set_title("lower end A, " + title)
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
        maxdiff("riser_D0.7_CM2", "riser_D1.3_CM2", "z_end"), maxdiff("riser_D0.7_CM1", "riser_D0.7_CM2", "z_end")))

    # J-lay (Figs. 13, 14): rfe 0 and rfe 20 axial forces, the middle point's trajectory.
    def style(a):
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)

    # Release vs hold of the statics' end force, and the damped variant: the first 10 s.
    f, ax = plt.subplots(1, 2, figsize=(12, 4.2))
    for name, label in (("jlay_release_u0", "end force released at t = 0"),
                        ("jlay_u0", "end force held (scene)"),
                        ("jlay_damped_u0", "held, 1 % axial damping")):
        d = load(out, name)
        m = d["t"] <= 10.0
        ax[0].plot(d["t"][m], d["tension_rfe0"][m] / 1e3, lw=0.5, label=label)
        m = d["t"] <= 2.0
        ax[1].plot(d["t"][m], d["tension_rfe0"][m] / 1e3, lw=0.8, label=label)
    ax[0].set_title("J-lay, u = 0: axial force in rfe 0, first 10 s")
    ax[1].set_title("same, first 2 s")
    for a in ax:
        a.set_xlabel("t [s]"); a.set_ylabel("axial force [kN]"); style(a)
    f.tight_layout(); f.savefig(os.path.join(out, "jlay_release_hold.png"), dpi=110); plt.close(f)

    # Fig. 13: rho_f = 0 vs 840 at u = 0.
    f, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    for name, label in (("jlay_rf0_u0", "rho_f = 0"), ("jlay_u0", "rho_f = 840, u = 0")):
        d = load(out, name)
        ax[0].plot(d["t"], d["tension_rfe0"] / 1e3, lw=0.5, label=label)
        ax[1].plot(d["t"], d["tension_rfe20"] / 1e3, lw=0.5, label=label)
        ax[2].plot(d["x_rfe20"], d["z_rfe20"], label=label)
    ax[0].set_title("Fig. 13a: axial force in rfe 0 (top)")
    ax[1].set_title("axial force in rfe 20 (middle)")
    ax[2].set_title("Fig. 13b: trajectory of the middle point (rfe 20)")
    for a in ax[:2]:
        a.set_xlabel("t [s]"); a.set_ylabel("axial force [kN]")
    ax[2].set_xlabel("x [m]"); ax[2].set_ylabel("z [m]")
    for a in ax:
        style(a)
    f.tight_layout(); f.savefig(os.path.join(out, "fig13_fluid_mass.png"), dpi=110); plt.close(f)

    # Fig. 14: u = 0, 5, 10 m/s, one figure per flow model; the third panel: T(u) - T(0), 1 s averages.
    n1 = 100  # samples per second (--output-dt 0.01)
    for model, title in (("paper", "paper's closed-system model"), ("pipe", "pipe_flow (open system)")):
        f, ax = plt.subplots(1, 3, figsize=(15, 4.2))
        d0 = load(out, "jlay_u0")
        for name, label, c in (("jlay_u0", "u = 0", "C0"), ("jlay_%s_u5" % model, "u = 5 m/s", "C1"),
                               ("jlay_%s_u10" % model, "u = 10 m/s", "C2")):
            d = load(out, name)
            ax[0].plot(d["t"], d["tension_rfe0"] / 1e3, c, lw=0.5, label=label)
            ax[1].plot(d["t"], d["tension_rfe20"] / 1e3, c, lw=0.5, label=label)
            if name != "jlay_u0":
                m = min(len(d), len(d0))
                for col, ls in (("tension_rfe0", "-"), ("tension_rfe20", "--")):
                    diff = smooth(d[col][:m] - d0[col][:m], n1)[n1:-n1]
                    ax[2].plot(d["t"][:m][n1:-n1], diff / 1e3, c + ls, label="%s, rfe %s" % (label, col[11:]))
        ax[0].set_title("Fig. 14a, %s: rfe 0" % title)
        ax[1].set_title("Fig. 14b: rfe 20")
        ax[2].set_title("T(u) - T(0), 1 s averages (rfe 20 dashed)")
        for a in ax:
            a.set_xlabel("t [s]"); a.set_ylabel("axial force [kN]"); style(a)
        f.tight_layout(); f.savefig(os.path.join(out, "fig14_flow_%s.png" % model), dpi=110); plt.close(f)

    # Numbers: the flow's effect on the axial force at rfe 0 and 20, and the same measures between h and h/2.
    def effect(a, b, col):
        """(mean(T_a - T_b) / mean(T_b), max |1 s average of T_a - T_b| / max T_b, max |T_a - T_b| / max T_b)."""
        A, B = load(out, a), load(out, b)
        m = min(len(A), len(B))
        ta, tb = A[col][:m], B[col][:m]
        d = ta - tb
        avg = smooth(d, n1)[n1:-n1]
        return (np.mean(d) / np.mean(tb), np.max(np.abs(avg)) / np.max(np.abs(tb)),
                np.max(np.abs(d)) / np.max(np.abs(tb)))

    def row(label, a, b):
        for col in ("tension_rfe0", "tension_rfe20"):
            e = effect(a, b, col)
            lines.append("  %-34s rfe %-2s mean %+7.2f %%  1 s avg max %6.2f %%  raw max %6.2f %%" % (
                label, col[11:], 100 * e[0], 100 * e[1], 100 * e[2]))

    def diffconv(a, b, a2, b2, col):
        """max |(T_a - T_b) - (T_a2 - T_b2)| / max T_b: is the u effect itself converged in h?"""
        A, B, A2, B2 = (load(out, x) for x in (a, b, a2, b2))
        m = min(len(A), len(B), len(A2), len(B2))
        dd = (A[col][:m] - B[col][:m]) - (A2[col][:m] - B2[col][:m])
        return np.max(np.abs(dd)) / np.max(np.abs(B[col][:m]))

    lines.append("J-lay axial force (rfe 0 top, rfe 20 middle): effect of X vs Y, in % of mean T_Y (mean) or max T_Y:")
    lines.append(" scene (end force held, no structural damping, h = 5e-4 s):")
    row("rho_f 0 vs 840 (u = 0)", "jlay_rf0_u0", "jlay_u0")
    row("paper u 5 vs 0", "jlay_paper_u5", "jlay_u0")
    row("paper u 10 vs 0", "jlay_paper_u10", "jlay_u0")
    row("pipe_flow u 5 vs 0", "jlay_pipe_u5", "jlay_u0")
    row("pipe_flow u 10 vs 0", "jlay_pipe_u10", "jlay_u0")
    row("end force released vs held", "jlay_release_u0", "jlay_u0")
    lines.append(" same scene, h = 5e-4 vs 2.5e-4 s:")
    row("u 0", "jlay_u0", "jlay_u0_h2")
    row("paper u 10", "jlay_paper_u10", "jlay_paper_u10_h2")
    for col in ("tension_rfe0", "tension_rfe20"):
        lines.append("  paper u-10 effect, h vs h/2: max |difference| %.3f %% (rfe %s)" % (
            100 * diffconv("jlay_paper_u10", "jlay_u0", "jlay_paper_u10_h2", "jlay_u0_h2", col), col[11:]))
    lines.append(" variant with 1 % axial damping (zeta at the first axial mode), h = 5e-4 s:")
    row("paper u 10 vs 0", "jlay_damped_paper_u10", "jlay_damped_u0")
    row("pipe_flow u 10 vs 0", "jlay_damped_pipe_u10", "jlay_damped_u0")
    row("damped vs undamped (u = 0)", "jlay_damped_u0", "jlay_u0")
    lines.append(" damped, h = 5e-4 vs 2.5e-4 s:")
    row("u 0", "jlay_damped_u0", "jlay_damped_u0_h2")
    row("paper u 10", "jlay_damped_paper_u10", "jlay_damped_paper_u10_h2")
    for col in ("tension_rfe0", "tension_rfe20"):
        lines.append("  paper u-10 effect, h vs h/2: max |difference| %.4f %% (rfe %s)" % (
            100 * diffconv("jlay_damped_paper_u10", "jlay_damped_u0", "jlay_damped_paper_u10_h2",
                           "jlay_damped_u0_h2", col), col[11:]))
    rho_l = 840.0 * np.pi / 4 * 0.26 ** 2
    for name in ("jlay_u0", "jlay_pipe_u10"):
        d = load(out, name)
        lines.append("  %s: mean axial force rfe 0 %.0f N, rfe 20 %.0f N" % (
            name, np.mean(d["tension_rfe0"]), np.mean(d["tension_rfe20"])))
    lines.append("  rho_f A_f u^2 at u = 10 m/s: %.0f N" % (rho_l * 100.0))
    lines.append("  max |x difference| of the middle point rho_f 0 vs 840: %.3f m" % maxdiff("jlay_rf0_u0", "jlay_u0",
                                                                                          "x_rfe20"))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(out, "numbers.txt"), "w") as fh:
        fh.write(text + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/figures")
