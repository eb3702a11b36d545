"""riser_sim_sweep's command line (docs/sweep.md).

Exit codes: 0 every case ok or warning; 1 internal error; 2 bad input (sweep file, scene check of every
case, results folder of another sweep, scheduler not reachable, CLI not found); 3 the sweep finished with
failed, diverged or refused cases (in the table); 130 interrupted (the table holds the finished cases; a
rerun resumes)."""
import argparse
import sys

from .sweep_file import SweepError

EXIT_OK, EXIT_INTERNAL, EXIT_BAD_INPUT, EXIT_CASES_FAILED, EXIT_INTERRUPTED = 0, 1, 2, 3, 130

DESCRIPTION = """Runs the cases of a sweep file through riser_sim_cli on Dask and writes one results table.

  riser_sim_sweep SWEEP.yaml --out DIR [--workers N | --scheduler tcp://HOST:PORT]
  riser_sim_sweep --tune SCENE --quantity tension_top --tol-rms 0.01 --tol-max 0.03 --out DIR
  riser_sim_sweep --plot DIR

The results folder holds results.csv (one row per case: overrides, status, reason, warning, wall/CPU time,
kept values), cases/<case_id>.json (the CLI's summary, command, stderr) and the plots. A rerun on the same
folder runs only the cases not in the table. Keys of the sweep file: docs/sweep.md.

exit codes: 0 every case ok or warning, 2 bad input (nothing run but the listed cases), 3 finished with
failed, diverged or refused cases, 130 interrupted (rerun to resume), 1 internal error"""


def _log(msg):
    print("riser_sim_sweep: " + msg, file=sys.stderr, flush=True)


def parser():
    p = argparse.ArgumentParser(prog="riser_sim_sweep", description=DESCRIPTION,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("sweep", nargs="?", help="sweep file (YAML)")
    p.add_argument("--out", help="results folder (created; a rerun resumes it)")
    p.add_argument("--workers", type=int, help="worker processes of the local cluster (default: every core)")
    p.add_argument("--scheduler", help="address of an existing Dask scheduler, tcp://HOST:PORT")
    p.add_argument("--connect-timeout", type=float, default=10.0, help="seconds to reach --scheduler (10)")
    p.add_argument("--cli", help="riser_sim_cli to run (default: $RISER_SIM_CLI, beside this program, PATH)")
    p.add_argument("--no-check", action="store_true", help="skip the up-front scene check (--duration 0) of the cases")
    p.add_argument("--retry-failed", action="store_true", help="rerun the cases whose row is not ok/warning")
    p.add_argument("--no-plots", action="store_true", help="no PNG plots at the end")
    p.add_argument("--plot", metavar="DIR", help="only (re)draw the plots of a results folder")
    p.add_argument("--polar-column", help="column of the polar plot (default max_tension_max)")
    p.add_argument("--quiet", action="store_true", help="no progress")
    t = p.add_argument_group("--tune: the cheapest setting within a tolerance on a quantity (docs/sweep.md)")
    t.add_argument("--tune", metavar="SCENE", help="scene file to tune")
    t.add_argument("--quantity", default="tension_top",
                   help="time-series column compared with the reference: tension_top, tension_max, x_end, z_end, "
                        "top_fx, ... (default tension_top)")
    t.add_argument("--tol-rms", type=float, default=0.01, help="RMS error bound, relative to max|reference| (0.01)")
    t.add_argument("--tol-max", type=float, default=0.05, help="largest error bound, relative to max|reference| (0.05)")
    t.add_argument("--absolute", action="store_true", help="tolerances in the quantity's units instead")
    t.add_argument("--duration", type=float, help="simulated time of each tune run [s] (default: the scene's)")
    t.add_argument("--integrators", help="comma list (default rk4,midpoint,generalized_alpha,rosenbrock2)")
    t.add_argument("--dts", help="comma list of solver.dt for the implicit integrators [s] (default from the scene)")
    t.add_argument("--ns", help="comma list of line.elements (default n/2, n, 3n/2 of the scene)")
    t.add_argument("--formulations", help="comma list (planar: absolute,recursive; 3D: natural only)")
    t.add_argument("--rho-infs", help="comma list of solver.rho_inf for generalized_alpha (default 0.5)")
    t.add_argument("--newton-tolerances", help="comma list of solver.newton_tolerance for the implicit schemes")
    t.add_argument("--ref-dt", type=float, help="reference solver.dt (default: a quarter of the finest candidate)")
    t.add_argument("--ref-n", type=int, help="reference line.elements (default: twice the largest candidate)")
    t.add_argument("--ref-integrator", default="midpoint", help="reference integrator (midpoint)")
    t.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="override of the tuned scene for every run (repeatable)")
    t.add_argument("--accept-reference", action="store_true",
                   help="go on when the reference's own convergence check fails (reported in the table)")
    return p


def main(argv):
    args = parser().parse_args(argv)
    try:
        if args.plot:
            from .plots import plot_folder
            for path in plot_folder(args.plot, args.polar_column):
                _log("plot: " + path)
            return EXIT_OK
        if args.tune:
            from .tune import tune_main
            return tune_main(args)
        if not args.sweep:
            raise SweepError("a sweep file is required (or --tune SCENE, --plot DIR); see --help")
        if not args.out:
            raise SweepError("--out DIR is required (the results folder)")
        return sweep_main(args)
    except SweepError as e:
        _log("error: %s" % e)
        return EXIT_BAD_INPUT


def sweep_main(args):
    from .case_list import expand_cases
    from .cli_locate import locate_cli
    from .dask_runner import InterruptGuard, close_client, open_client
    from .sweep_file import load_sweep
    from .sweep_run import open_folder, run_sweep

    spec = load_sweep(args.sweep)
    cases = expand_cases(spec)
    cli = locate_cli(args.cli)
    folder = open_folder(spec, cases, args.out)
    if args.workers is not None and args.workers < 1:
        raise SweepError("--workers: expected >= 1")
    _log("%d cases of %s on %s, results in %s" % (len(cases), spec.scene, args.scheduler or "a local cluster",
                                                  args.out))
    with InterruptGuard() as guard:
        client = cluster = None
        try:
            client, cluster = open_client(args.workers, args.scheduler, args.connect_timeout)
            out = run_sweep(spec, cases, folder, client, cli, guard, check=not args.no_check,
                            retry_failed=args.retry_failed, quiet=args.quiet, log=_log)
        except KeyboardInterrupt:
            from .sweep_run import SweepOutcome
            out = SweepOutcome()
            out.interrupted = True
        finally:
            if client is not None:
                close_client(client, cluster)
    statuses = list(folder.done.values())
    n_bad = sum(s not in ("ok", "warning") for s in statuses)
    _log("%d of %d cases in %s (%d ran now, %d skipped as done; %d not ok: failed, diverged or refused)"
         % (len(statuses), len(cases), folder.table, out.ran, out.skipped, n_bad))
    if out.ran:
        _log("run phase: %d cases in %.3f s of wall time" % (out.ran, out.run_phase_s))
    if out.interrupted:
        _log("interrupted: %d cases left; rerun the same command to run only them" % (len(cases) - len(statuses)))
        return EXIT_INTERRUPTED
    if not args.no_plots:
        from .plots import plot_folder
        for path in plot_folder(args.out, args.polar_column):
            _log("plot: " + path)
    return EXIT_CASES_FAILED if n_bad else EXIT_OK
