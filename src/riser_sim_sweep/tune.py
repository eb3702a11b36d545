"""--tune: the speed-accuracy trade on the user's scene. A reference run (fine dt, many elements) whose own
convergence is checked by halving its step's resolution and its elements; candidates integrator x dt x n x
formulation (x rho_inf, Newton tolerance); each candidate's error on one time-series quantity against the
reference; the Pareto front of cost (stepping wall time per simulated second, 1/RTF) against RMS error; the
cheapest candidate within both tolerances as --set lines.

Errors: e_i = q(t_i) - q_ref(t_i) at the candidate's rows (the reference, written every step, interpolated
linearly), RMS = sqrt(mean e_i^2), max = max |e_i|; relative to max |q_ref| unless --absolute.
Reference check: with the error of a second-order method e(h) ~ C h^2 (the integrators' order, docs/
integrators.md) and, assumed alike, e(n) ~ C n^-2, the reference's own error is about a third of its
difference to the run at 2 dt (and n / 2); both estimates must be within a quarter of the tolerance."""
import json
import math
import os
import sys

import numpy as np

from .case_list import Case, expand_cases
from .case_run import run_case
from .cli_locate import locate_cli
from .dask_runner import InterruptGuard, close_client, open_client
from .keep import KeepSpec
from .results_folder import read_table
from .sweep_file import SweepError, SweepSpec
from .sweep_run import open_folder, run_sweep

IMPLICIT = ("midpoint", "generalized_alpha", "rosenbrock2")
ORDER = 2  # midpoint, generalized_alpha, rosenbrock2: second order (docs/integrators.md)


def _log(msg):
    print("riser_sim_sweep: tune: " + msg, file=sys.stderr, flush=True)


def _list(text, conv, where):
    if text is None:
        return None
    try:
        vals = [conv(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise SweepError("%s: expected a comma list, got '%s'" % (where, text))
    if not vals:
        raise SweepError("%s: empty list" % where)
    return vals


def _parse_sets(sets):
    import yaml
    out = {}
    for s in sets:
        if "=" not in s:
            raise SweepError("--set: expected KEY=VALUE, got '%s'" % s)
        k, v = s.split("=", 1)
        out[k] = yaml.safe_load(v)
    return out


def _probe(cli, scene, base, n):
    """The scene's statics at n elements: its summary (dt, integrator, space, stable_dt_estimate)."""
    with open(scene) as f:
        text = f.read()
    case = Case(0, dict(base, **({"line.elements": n} if n else {})))
    r = run_case({"cli": cli, "scene_name": os.path.basename(scene), "scene_text": text, "case_id": case.case_id,
                  "set_args": case.set_args(), "duration": 0, "keep": KeepSpec(extremes=[]).describe(),
                  "check": True})
    if r["status"] not in ("ok", "warning"):
        raise SweepError("the scene check of %s%s failed: %s" % (scene, " at line.elements=%d" % n if n else "",
                                                                  r["reason"]))
    return r["summary"]


def candidates(args, base_summary, stable_dt_of_n, base):
    planar = base_summary.get("space") != "spatial"
    n0 = int(base_summary["n"])
    ns = _list(args.ns, int, "--ns") or sorted({max(2, n0 // 2), n0, max(2, (3 * n0) // 2)})
    integ = _list(args.integrators, str, "--integrators") or ["rk4", "midpoint", "generalized_alpha", "rosenbrock2"]
    forms = _list(args.formulations, str, "--formulations") or (["absolute", "recursive"] if planar else [None])
    dts = _list(args.dts, float, "--dts") or [0.005, 0.01, 0.02, 0.05, 0.1]
    rhos = _list(args.rho_infs, float, "--rho-infs") or [None]
    newton = _list(args.newton_tolerances, float, "--newton-tolerances") or [None]
    out = []
    for n in ns:
        for form in forms:
            for scheme in integ:
                if scheme in ("rk4", "dopri5"):  # explicit: below the stability limit the CLI reports at this n
                    steps = [round(f * stable_dt_of_n(n), 8) for f in (0.9, 0.45)] if scheme == "rk4" else dts
                    extra = [{}]
                else:
                    steps = dts
                    extra = [{}]
                    if scheme == "generalized_alpha":
                        extra = [{"solver.rho_inf": r} if r is not None else {} for r in rhos]
                    extra = [dict(e, **({"solver.newton_tolerance": t} if t is not None else {}))
                             for e in extra for t in newton]
                for dt in steps:
                    for e in extra:
                        c = {"line.elements": n, "solver.integrator": scheme, "solver.dt": dt}
                        if form is not None:
                            c["solver.formulation"] = form
                        c.update(e)
                        out.append(c)
    return out


def _series(folder, case_id, quantity):
    path = os.path.join(folder, "cases", case_id + ".csv")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return data[:, 0], data[:, 1]


def errors(t, q, t_ref, q_ref, scale):
    """(RMS, max) of q - q_ref at t (reference interpolated linearly), divided by scale."""
    mask = (t >= t_ref[0] - 1e-12) & (t <= t_ref[-1] + 1e-12)
    if not mask.any():
        return math.inf, math.inf
    e = q[mask] - np.interp(t[mask], t_ref, q_ref)
    return float(np.sqrt(np.mean(e * e)) / scale), float(np.max(np.abs(e)) / scale)


def pareto(points):
    """Indices of the non-dominated (cost, error) points."""
    front = []
    for i, (c, e) in enumerate(points):
        if not any((c2 <= c and e2 <= e) and (c2 < c or e2 < e) for c2, e2 in points):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def _run(spec, cases, out, client, cli, guard, quiet):
    folder = open_folder(spec, cases, out)
    res = run_sweep(spec, cases, folder, client, cli, guard, quiet=quiet,
                    log=lambda m: print("riser_sim_sweep: " + m, file=sys.stderr, flush=True))
    if res.interrupted:
        raise KeyboardInterrupt
    return {r["case_id"]: r for r in read_table(out)}


def tune_main(args):
    if not args.out:
        raise SweepError("--out DIR is required (the tune's folder)")
    scene = os.path.abspath(args.tune)
    if not os.path.isfile(scene):
        raise SweepError("--tune: scene file '%s' not found" % scene)
    for name, v in (("--tol-rms", args.tol_rms), ("--tol-max", args.tol_max)):
        if not v > 0:
            raise SweepError("%s: expected > 0" % name)
    cli = locate_cli(args.cli)
    base = _parse_sets(args.set)
    q = args.quantity
    if "_rfe" in q:
        raise SweepError("--quantity %s: an rfe index means another point at another n; use a quantity of the "
                         "ends or the whole line (tension_top, tension_max, x_end, z_end, top_fx, ...)" % q)
    s0 = _probe(cli, scene, base, None)
    stable = {}

    def stable_dt(n):
        if n not in stable:
            stable[n] = float(_probe(cli, scene, base, n)["stable_dt_estimate"])
        return stable[n]

    cand = candidates(args, s0, stable_dt, base)
    planar = s0.get("space") != "spatial"
    max_n = max(c["line.elements"] for c in cand)
    min_dt = min(c["solver.dt"] for c in cand)
    ref_n = args.ref_n or 2 * max_n
    ref_dt = args.ref_dt or min_dt / 4
    ref = {"line.elements": ref_n, "solver.integrator": args.ref_integrator, "solver.dt": ref_dt}
    if planar:
        ref["solver.formulation"] = "recursive"
    # n held: every candidate at the reference's n, so their errors are the time integration's at that n and
    # the reference's own check is in dt alone (a scene whose model changes with n, e.g. seabed springs per
    # contact point, converges in dt, not in n).
    n_held = all(c["line.elements"] == ref_n for c in cand)
    refs = [ref, dict(ref, **{"solver.dt": 2 * ref_dt})]
    if not n_held:
        refs.append(dict(ref, **{"line.elements": max(2, ref_n // 2)}))
    duration = args.duration
    keep = KeepSpec(summary=["rtf", "wall_s"], extremes=[], series=[q], output_dt=ref_dt)
    os.makedirs(args.out, exist_ok=True)
    with InterruptGuard() as guard:
        client = cluster = None
        try:
            client, cluster = open_client(args.workers, args.scheduler, args.connect_timeout)
            # The reference and its two coarsenings.
            spec_r = SweepSpec(scene, duration, base, cases=refs, keep=keep, source="--tune reference")
            cases_r = expand_cases(spec_r)
            rows_r = _run(spec_r, cases_r, os.path.join(args.out, "reference"), client, cli, guard, args.quiet)
            for c in cases_r:
                if rows_r[c.case_id]["status"] not in ("ok", "warning"):
                    raise SweepError("reference run %s: %s %s" % (" ".join(c.set_args()[1::2]),
                                                                  rows_r[c.case_id]["status"],
                                                                  rows_r[c.case_id]["reason"]))
            rdir = os.path.join(args.out, "reference")
            t_ref, q_ref = _series(rdir, cases_r[0].case_id, q)
            scale = 1.0 if args.absolute else float(np.max(np.abs(q_ref)))
            if not scale > 0:
                raise SweepError("--quantity %s: the reference is 0 throughout; use --absolute" % q)
            conv = []
            checks = [(cases_r[1], "dt %g -> %g s" % (2 * ref_dt, ref_dt))]
            if not n_held:
                checks.append((cases_r[2], "n %d -> %d" % (max(2, ref_n // 2), ref_n)))
            for c, what in checks:
                t, v = _series(rdir, c.case_id, q)
                rms, mx = errors(t, v, t_ref, q_ref, scale)
                est_rms, est_max = rms / (2 ** ORDER - 1), mx / (2 ** ORDER - 1)
                conv.append((what, rms, mx, est_rms, est_max))
            converged = all(e_rms <= args.tol_rms / 4 and e_max <= args.tol_max / 4 for _, _, _, e_rms, e_max in conv)
            unit = "" if args.absolute else ", relative to max|ref|"
            lines = ["reference: %s (%s s simulated)" % (" ".join(cases_r[0].set_args()[1::2]),
                                                         duration if duration is not None else "run.duration")]
            for what, rms, mx, er, em in conv:
                lines.append("  convergence in %s: change RMS %.3g, max %.3g%s; estimated reference error RMS %.3g, "
                             "max %.3g" % (what, rms, mx, unit, er, em))
            verdict = ("converged: both estimates within a quarter of the tolerance (RMS %g, max %g%s)"
                       % (args.tol_rms, args.tol_max, unit)) if converged else (
                "NOT converged to a quarter of the tolerance (RMS %g, max %g%s): refine with --ref-dt / --ref-n"
                % (args.tol_rms, args.tol_max, unit))
            if n_held:
                lines.append("  n held at %d by every candidate: the errors are the time integration's at that n "
                             "(no check in n)" % ref_n)
            lines.append("  " + verdict)
            for ln in lines:
                _log(ln)
            if not converged and not args.accept_reference:
                raise SweepError("the reference is not converged (see above); --accept-reference goes on anyway")
            # The candidates.
            spec_c = SweepSpec(scene, duration, base, cases=cand, keep=keep, source="--tune candidates")
            cases_c = expand_cases(spec_c)
            _log("%d candidates" % len(cases_c))
            cdir = os.path.join(args.out, "candidates")
            rows_c = _run(spec_c, cases_c, cdir, client, cli, guard, args.quiet)
        except KeyboardInterrupt:
            _log("interrupted; rerun the same command to resume")
            return 130
        finally:
            if client is not None:
                close_client(client, cluster)
    table = []
    for c in cases_c:
        r = rows_c[c.case_id]
        row = {"case_id": c.case_id, "status": r["status"], "reason": r["reason"], "warning": r["warning"],
               "set": c.set_args()[1::2]}
        row.update(c.overrides)
        rtf = float(r["rtf"]) if r.get("rtf") not in (None, "") else math.nan
        row["rtf"] = rtf
        row["cost"] = 1.0 / rtf if rtf > 0 else math.inf
        row["rms"] = row["max"] = math.inf
        if r["status"] in ("ok", "warning"):
            t, v = _series(cdir, c.case_id, q)
            row["rms"], row["max"] = errors(t, v, t_ref, q_ref, scale)
        row["within"] = row["rms"] <= args.tol_rms and row["max"] <= args.tol_max
        table.append(row)
    finite = [r for r in table if math.isfinite(r["rms"]) and math.isfinite(r["cost"])]
    front = [finite[i] for i in pareto([(r["cost"], r["rms"]) for r in finite])]
    for r in front:
        r["pareto"] = True
    ok = [r for r in table if r["within"] and math.isfinite(r["cost"])]
    best = min(ok, key=lambda r: r["cost"]) if ok else None
    _write_table(args.out, table, best)
    plot = _plot(args.out, table, front, best, args, q, unit)
    result = {"quantity": q, "tol_rms": args.tol_rms, "tol_max": args.tol_max, "absolute": args.absolute,
              "scale": scale, "reference": ref, "reference_converged": converged, "n_held": n_held, "reference_lines": lines,
              "duration": duration, "base_set": base,
              "best": None if best is None else {k: best[k] for k in ("set", "rtf", "rms", "max", "status")}}
    with open(os.path.join(args.out, "tune.json"), "w") as f:
        json.dump(result, f, indent=1, default=str)
    _log("Pareto front (cost = 1/RTF, RMS error%s): %d of %d candidates; plot %s" % (unit, len(front), len(table),
                                                                                    plot))
    if best is None:
        _log("no candidate within RMS %g and max %g%s of %s; the most accurate: %s (RMS %.3g)"
             % (args.tol_rms, args.tol_max, unit, q, " ".join(min(finite, key=lambda r: r["rms"])["set"])
                if finite else "none", min((r["rms"] for r in finite), default=math.nan)))
        return 3
    _log("cheapest within RMS %g, max %g%s, on %s: RTF %.3g, error RMS %.3g, max %.3g%s"
         % (args.tol_rms, args.tol_max, unit, q, best["rtf"], best["rms"], best["max"],
            "" if best["status"] == "ok" else " (the CLI warns: %s)" % best["warning"]))
    print(" ".join("--set %s" % s for s in best["set"]))
    return 0


def _write_table(out, table, best):
    import csv
    keys = ["case_id", "status", "line.elements", "solver.integrator", "solver.dt", "solver.formulation",
            "solver.rho_inf", "solver.newton_tolerance", "rtf", "cost", "rms", "max", "within", "pareto", "best",
            "reason"]
    with open(os.path.join(out, "tune.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore", lineterminator="\n")
        w.writeheader()
        for r in sorted(table, key=lambda r: r["cost"]):
            w.writerow(dict(r, best=r is best, pareto=r.get("pareto", False)))


def _plot(out, table, front, best, args, q, unit):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    for scheme in sorted({r["solver.integrator"] for r in table}):
        pts = [(r["cost"], r["rms"]) for r in table if r["solver.integrator"] == scheme
               and math.isfinite(r["rms"]) and math.isfinite(r["cost"]) and r["rms"] > 0]
        if pts:
            ax.scatter(*zip(*pts), label=scheme, s=25)
    fp = [(r["cost"], r["rms"]) for r in front if r["rms"] > 0]
    if fp:
        ax.plot(*zip(*fp), "k-", lw=1, label="Pareto front")
    ax.axhline(args.tol_rms, color="gray", ls="--", lw=1, label="RMS tolerance")
    if best is not None and best["rms"] > 0:
        ax.scatter([best["cost"]], [best["rms"]], marker="*", s=250, c="gold", edgecolors="k", zorder=5,
                   label="cheapest within tolerance (RTF %.3g)" % best["rtf"])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cost: stepping wall time per simulated second [s/s] (1/RTF)")
    ax.set_ylabel("RMS error of %s%s" % (q, unit))
    ax.legend(fontsize=8)
    ax.set_title("%s: cost against error" % os.path.basename(args.tune), fontsize=9)
    path = os.path.join(out, "pareto.png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path
