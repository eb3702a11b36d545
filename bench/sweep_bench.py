#!/usr/bin/env python3
"""riser_sim_sweep on this machine (docs/sweep.md, "Speed"): the run phase of the same sweep on a local Dask
cluster of 1 and of 2 worker processes (cases of >= 1 s: the 3D sea riser over 60 s at 8 headings), and the
sweep's overhead per case beyond the CLI process itself (40 cases of a few ms, 1 worker):
  overhead = run phase / cases - mean wall time of the same CLI process started directly.
The CLI process's own start (scene load, statics, exit) is reported beside it: the part of a case a
binding instead of a process would save. Writes out/bench/sweep.csv and a table to stdout."""
import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SCENE = os.path.join(ROOT, "config", "scenes", "spatial_sea_riser.yaml")


def sweep_file(d, name, duration, headings, extra=""):
    path = os.path.join(d, name + ".yaml")
    with open(path, "w") as f:
        f.write("scene: %s\nduration: %g\n%sgrid:\n  environment.waves.heading: %s\nkeep:\n  extremes: [tension_top]\n"
                % (SCENE, duration, extra, headings))
    return path


def run_sweep(tool, cli, sweep, out, workers):
    p = subprocess.run([sys.executable, tool, sweep, "--out", out, "--workers", str(workers), "--quiet",
                        "--no-plots", "--no-check", "--cli", cli], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("sweep failed (exit %d): %s" % (p.returncode, p.stderr[-2000:]))
    m = re.search(r"run phase: (\d+) cases in ([0-9.]+) s", p.stderr)
    with open(os.path.join(out, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    return int(m.group(1)), float(m.group(2)), rows


def direct(cli, overrides, duration, reps):
    """Wall times of the CLI process started directly (as the sweep's case runs it: --summary, CSV every step)."""
    times = []
    with tempfile.TemporaryDirectory() as d:
        for i in range(reps):
            cmd = [cli, "--scene", SCENE, "--summary", "--quiet", "--duration", repr(duration), "--csv",
                   os.path.join(d, "s.csv"), "--output-dt", "1e-9"]
            for k, v in overrides.items():
                cmd += ["--set", "%s=%s" % (k, v)]
            t0 = time.monotonic()
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
            times.append(time.monotonic() - t0)
    return times


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--cli", required=True)
    ap.add_argument("--tool", required=True)
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    res = []
    with tempfile.TemporaryDirectory() as d:
        big = sweep_file(d, "long", 60.0, "{start: 0, stop: 315, step: 45}")
        phase = {}
        for w in (1, 2):
            n, t, rows = run_sweep(a.tool, a.cli, big, os.path.join(d, "long%d" % w), w)
            phase[w] = t
            per_case = statistics.mean(float(r["wall_s"]) for r in rows)
            res.append({"what": "8 cases of 60 s (3D sea riser n = 50), %d worker%s" % (w, "s" if w > 1 else ""),
                        "cases": n, "run_phase_s": t, "per_case_s": t / n, "case_process_s": per_case})
        speedup = phase[1] / phase[2]
        small = sweep_file(d, "short", 0.1, "{start: 0, stop: 195, step: 5}", "set: {line.elements: 6}\n")
        n, t, rows = run_sweep(a.tool, a.cli, small, os.path.join(d, "short"), 1)
        dt = direct(a.cli, {"line.elements": 6, "environment.waves.heading": 30}, 0.1, 20)
        cli_s = statistics.median(dt)
        run_s = statistics.median(float(r["run_wall_s"]) for r in rows)
        overhead = t / n - cli_s
        res.append({"what": "40 cases of 0.1 s (n = 6), 1 worker", "cases": n, "run_phase_s": t, "per_case_s": t / n,
                    "case_process_s": cli_s})
    with open(os.path.join(a.out, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(res[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(res)
    print("| sweep | cases | run phase [s] | per case [s] | CLI process per case [s] |")
    print("|---|---|---|---|---|")
    for r in res:
        print("| %s | %d | %.2f | %.3f | %.3f |" % (r["what"], r["cases"], r["run_phase_s"], r["per_case_s"],
                                                  r["case_process_s"]))
    print("")
    print("speedup 2 workers / 1 worker (cases of >= 1 s): %.2f (nproc %d, load average %.1f)"
          % (speedup, os.cpu_count(), os.getloadavg()[0]))
    print("overhead per case beyond the CLI process (1 worker, 40 short cases): %.1f ms (target <= 50 ms); "
          "the CLI process itself: %.1f ms, of which stepping %.1f ms" % (1e3 * overhead, 1e3 * cli_s, 1e3 * run_s))


if __name__ == "__main__":
    main()
