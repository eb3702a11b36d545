"""One case on a worker: riser_sim_cli as a process on the base scene's text (shipped with the task, so a
worker needs no shared file system) with the case's --set overrides; the result is a plain dict.

Status: ok / warning (the CLI finished, with its warning) / diverged (exit 3 with a summary) / failed (exit 3
without one: the initial statics; exit 4; a signal) / refused (exit 2: the scene check). A worker that dies
raises nothing here: Dask reschedules the task on another worker."""
import os
import shutil
import socket
import subprocess
import tempfile
import time

from .keep import KeepSpec

try:  # Linux: a CLI process dies with the thread that waits for it (a killed worker, a closed cluster)
    import ctypes
    import signal
    _LIBC = ctypes.CDLL(None, use_errno=True)
    _PR_SET_PDEATHSIG = 1
except (OSError, AttributeError):
    _LIBC = None


def _die_with_parent(parent):
    """preexec_fn: SIGKILL when the starting thread ends; the thread waits for the process, so only the
    worker's death or shutdown ends it early."""
    if _LIBC is not None:
        _LIBC.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
        if os.getppid() != parent:
            os._exit(1)


EXIT_STATUS = {0: "ok", 2: "refused", 3: "diverged", 4: "failed"}


def _cli_path(cli):
    if os.path.isfile(cli) and os.access(cli, os.X_OK):
        return cli
    return shutil.which("riser_sim_cli") or cli  # another machine: its own riser_sim_cli on PATH


def _last_error(stderr):
    lines = [ln.strip() for ln in stderr.splitlines() if ln.strip()]
    for ln in reversed(lines):
        if "error:" in ln:
            return ln.split("error:", 1)[1].strip()
    return lines[-1] if lines else ""


def run_case(task):
    """task: cli, scene_name, scene_text, set_args, duration (or None), keep (KeepSpec.describe()),
    check (bool: statics alone, --duration 0, no outputs but the summary)."""
    import json

    keep = KeepSpec(**task["keep"])
    tmp = tempfile.mkdtemp(prefix="riser_sim_sweep_")
    try:
        scene = os.path.join(tmp, task["scene_name"])
        with open(scene, "w") as f:
            f.write(task["scene_text"])
        csv_path = os.path.join(tmp, "series.csv")
        range_path = os.path.join(tmp, "range.csv")
        cmd = [_cli_path(task["cli"]), "--scene", scene] + list(task["set_args"])
        if task.get("check"):
            cmd += ["--duration", "0", "--summary", "--quiet"] + (["--csv", csv_path] if keep.needs_csv() else [])
            cmd += [a for k in keep.probes for a in ("--probe-rfe", str(k))]
        else:
            if task.get("duration") is not None:
                cmd += ["--duration", repr(float(task["duration"]))]
            cmd += keep.cli_args(csv_path, range_path)
        out_path, err_path = os.path.join(tmp, "stdout"), os.path.join(tmp, "stderr")
        t0 = time.monotonic()
        with open(out_path, "wb") as out, open(err_path, "wb") as err:
            parent = os.getpid()
            p = subprocess.Popen(cmd, stdout=out, stderr=err, stdin=subprocess.DEVNULL,
                                 preexec_fn=lambda: _die_with_parent(parent))
            _, wstatus, usage = os.wait4(p.pid, 0)
            p.returncode = os.waitstatus_to_exitcode(wstatus)
        wall = time.monotonic() - t0
        rc = p.returncode
        with open(out_path, errors="replace") as f:
            stdout = f.read()
        with open(err_path, errors="replace") as f:
            stderr = f.read()
        summary = {}
        for line in reversed(stdout.splitlines()):
            if line.startswith("{"):
                try:
                    summary = json.loads(line)
                except ValueError:
                    pass
                break
        csv_text = None
        if os.path.isfile(csv_path):
            with open(csv_path) as f:
                csv_text = f.read()
        if rc < 0:
            status, reason = "failed", "riser_sim_cli killed by signal %d" % -rc
        else:
            status = EXIT_STATUS.get(rc, "failed")
            if rc == 0:
                status = summary.get("status", "failed") if summary else "failed"
            if rc == 3 and not summary:
                status = "failed"  # the initial statics: no run, no summary
            reason = "" if status in ("ok", "warning") else (summary.get("reason") or _last_error(stderr)
                                                              or "exit code %d" % rc)
        range_text = None
        if os.path.isfile(range_path):
            with open(range_path) as f:
                range_text = f.read()
        values, series = ({}, None)
        if status in ("ok", "warning", "diverged") and not task.get("check"):
            try:
                values, series = keep.extract(summary, csv_text)
            except Exception as e:  # noqa: a CSV the CLI cut short
                status, reason = "failed", "reading the time series: %s" % e
            try:
                values.update(keep.extract_range(range_text))
            except Exception as e:  # noqa
                status, reason = "failed", "reading the range graph: %s" % e
        header = csv_text.split("\n", 1)[0].strip().split(",") if csv_text else []
        return {
            "case_id": task["case_id"], "status": status, "reason": reason, "warning": summary.get("warning", ""),
            "exit_code": rc, "wall_s": wall, "cpu_s": usage.ru_utime + usage.ru_stime,
            "run_wall_s": summary.get("wall_s"), "rtf": summary.get("rtf"), "values": values, "series": series,
            "range_graph": range_text,
            "summary": summary, "csv_header": header, "stderr_tail": stderr[-2000:], "command": cmd,
            "worker": "%s:%d" % (socket.gethostname(), os.getpid()),
        }
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
