"""A sweep from checked spec to finished table: the scene check of every pending case (CLI --duration 0,
on the cluster), the kept names against what the CLI writes, then the runs, each row written as it
finishes. Cases already in the table are skipped (resume)."""
import os
import sys
import time

from .case_list import override_keys
from .case_run import run_case
from .dask_runner import run_tasks
from .progress import Progress
from .results_folder import ResultsFolder
from .sweep_file import SweepError


class SweepOutcome:
    def __init__(self):
        self.ran = self.refused = self.failed = self.skipped = 0
        self.interrupted = False
        self.wall_s = 0.0
        self.run_phase_s = 0.0  # from the first case submitted to the last row written [s]


def open_folder(spec, cases, out):
    keys = override_keys(cases)
    manifest = {"tool": "riser_sim_sweep", "sweep_file": spec.source, "scene": spec.scene,
                "duration": spec.duration, "set": spec.base, "keep": spec.keep.describe()}
    return ResultsFolder(out, spec.fingerprint(keys), keys, spec.keep.columns(), manifest)


def _task(spec, cli, case, check):
    with open(spec.scene) as f:
        text = f.read()
    return {"cli": cli, "scene_name": os.path.basename(spec.scene), "scene_text": text, "case_id": case.case_id,
            "set_args": case.set_args(), "duration": spec.duration, "keep": spec.keep.describe(), "check": check}


def run_sweep(spec, cases, folder, client, cli, guard, check=True, retry_failed=False, quiet=False, log=None):
    log = log or (lambda msg: print("riser_sim_sweep: " + msg, file=sys.stderr, flush=True))
    out = SweepOutcome()
    t0 = time.monotonic()
    folder.create()
    done = folder.done
    pending = [c for c in cases if c.case_id not in done or (retry_failed and done[c.case_id] != "ok"
                                                             and done[c.case_id] != "warning")]
    if retry_failed:  # a retried case gets a new row: its old one leaves the table first
        with guard.hold():
            folder.drop([c.case_id for c in pending if c.case_id in done])
    out.skipped = len(cases) - len(pending)
    if out.skipped:
        log("%d of %d cases already in %s: skipped" % (out.skipped, len(cases), folder.table))
    if not pending:
        out.wall_s = time.monotonic() - t0
        return out
    try:
        if check:
            pending = _check(spec, pending, folder, client, cli, guard, out, quiet, log)
        progress = Progress(len(cases), len(cases) - len(pending), "cases", quiet=quiet)
        by_id = {}

        def on_result(case, result):
            if result.get("exit_code") == -2:  # the CLI got the terminal's Ctrl-C: not the case's result
                raise KeyboardInterrupt
            if folder.write(case, result):
                out.ran += 1
                if result["status"] not in ("ok", "warning"):
                    out.failed += 1
                progress.update(result["status"])
            by_id[case.case_id] = result

        items = [(c, _task(spec, cli, c, False)) for c in pending]
        t_run = time.monotonic()
        try:
            run_tasks(client, run_case, items, on_result, guard, "case")
        finally:
            progress.finish()
            out.run_phase_s = time.monotonic() - t_run
    except KeyboardInterrupt:
        out.interrupted = True
    out.wall_s = time.monotonic() - t0
    return out


def _check(spec, pending, folder, client, cli, guard, out, quiet, log):
    """The scene check: refused cases (exit 2) and failed statics (exit 3) get their rows now; the kept names
    are checked against the first good case's summary keys and CSV columns. Returns the cases to run."""
    results = {}
    progress = Progress(len(pending), 0, "scene check", quiet=quiet)

    def on_check(case, result):
        results[case.case_id] = (case, result)
        progress.update(result["status"] if result["status"] in ("refused", "failed") else "ok")

    items = [(c, _task(spec, cli, c, True)) for c in pending]
    try:
        run_tasks(client, run_case, items, on_result=on_check, guard=guard, label="check")
    finally:
        progress.finish()
    good = [results[c.case_id][1] for c in pending if results[c.case_id][1]["status"] in ("ok", "warning")]
    if good:
        spec.keep.validate(set(good[0]["summary"]), good[0]["csv_header"])
    refused = [results[c.case_id] for c in pending if results[c.case_id][1]["status"] == "refused"]
    failed = [results[c.case_id] for c in pending if results[c.case_id][1]["status"] not in ("ok", "warning", "refused")]
    if refused:
        log("%d of %d cases refused by the scene check (not run):" % (len(refused), len(pending)))
        for case, r in refused:
            log("  case %d %s: %s" % (case.index, " ".join(case.set_args()[1::2]), r["reason"]))
    if failed:
        log("%d cases failed their initial statics (not run):" % len(failed))
        for case, r in failed:
            log("  case %d %s: %s" % (case.index, " ".join(case.set_args()[1::2]), r["reason"]))
    for case, r in refused + failed:
        r = dict(r, values={}, wall_s=None, cpu_s=None, run_wall_s=None, rtf=None)
        with guard.hold():
            folder.write(case, r)
        if r["status"] == "refused":
            out.refused += 1
        else:
            out.failed += 1
    if not good:
        raise SweepError("every pending case failed the scene check (their rows are in %s); nothing to run "
                         "(first: %s)" % (folder.table, (refused or failed)[0][1]["reason"]))
    return [c for c in pending if results[c.case_id][1]["status"] in ("ok", "warning")]
