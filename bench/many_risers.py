#!/usr/bin/python3
"""How many risers run in real time on this machine: launch/many_risers.launch with k risers, as separate
riser_sim_node processes (--mode nodes) or as nodelets in one manager (--mode nodelets), the vessel
(VesselMotionNodelet, surge 10 m / 27 s) publishing /vessel/pose at --vessel-rate Hz.

For each k: waits until every riser runs, lets --warmup seconds pass, then over --window seconds reads
each riser's /diagnostics (1 Hz): its real-time factor over the window (simulated time advanced /
ROS time passed, from `sim time [s]` and the message stamps), the time it dropped, its step time, and
the CPU time of all the launched processes (/proc, in cores: CPU seconds per wall second). A k passes when every riser has real-time factor
>= --min-rtf and dropped nothing. k doubles from 1 until a k fails (or --max-count passes), then
bisects down to the largest passing k (--start: the first k; --max-count: the last). --vessel-last starts the
vessel only once every riser waits for its first pose (with --vessel-param fade_in=60: every riser starts from a
vessel at rest; a 3D sea riser started against a moving vessel can diverge). --set overrides scene keys,
--loop-rate the risers' ~loop_rate, --spacing the hang-offs' spacing, --tag names the output files. Nobody subscribes to the risers' data topics (roscpp does not
serialise for no subscriber): a consumer's cost comes on top. Appends rows to <out>/many_risers<tag>.csv.
Needs a running master (bench/many_risers.sh starts a private one).
"""
import argparse
import csv
import os
import signal
import subprocess
import sys
import threading
import time

import rospy
import yaml
from diagnostic_msgs.msg import DiagnosticArray

FIELDS = ["scene", "mode", "count", "pass", "min_rtf", "median_rtf", "dropped_s", "step_mean_us", "cpu_cores", "load1",
          "window_s", "note"]


def proc_stat(pid):
    with open("/proc/%s/stat" % pid) as f:
        return f.read().rsplit(")", 1)[1].split()  # [0] is field 3 of stat (state)


def descendants(root):
    """pids of every process below root (roslaunch gives each child a session of its own)."""
    children = {}
    for pid in os.listdir("/proc"):
        if pid.isdigit():
            try:
                children.setdefault(int(proc_stat(pid)[1]), []).append(int(pid))
            except (IOError, OSError, IndexError):
                pass
    out, todo = [], [root]
    while todo:
        for c in children.get(todo.pop(), []):
            out.append(c)
            todo.append(c)
    return out


def cpu_seconds(pids):
    """utime + stime of the processes in pids that still exist [s]."""
    total = 0.0
    for pid in pids:
        try:
            fields = proc_stat(pid)
        except (IOError, OSError):
            continue
        total += (int(fields[11]) + int(fields[12])) / float(os.sysconf("SC_CLK_TCK"))
    return total


class Diagnostics(object):
    def __init__(self):
        self.lock = threading.Lock()
        self.by_riser = {}
        self.sub = rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diag, queue_size=200)

    def on_diag(self, msg):
        now = time.time()
        with self.lock:
            for s in msg.status:
                if s.name.startswith("riser_") and s.name.endswith(": riser simulation"):
                    riser = s.name.split("/")[0]
                    self.by_riser.setdefault(riser, []).append(
                        (now, msg.header.stamp.to_sec(), s.level, {kv.key: kv.value for kv in s.values}))

    def clear(self):
        with self.lock:
            self.by_riser = {}

    def running(self, mode="running"):
        with self.lock:
            return sum(1 for v in self.by_riser.values() if v and v[-1][3].get("mode") == mode)

    def between(self, t0, t1):
        with self.lock:
            return {r: [d for d in v if t0 <= d[0] <= t1] for r, v in self.by_riser.items()}


def num(d, key):
    try:
        return float(d[3].get(key, "nan"))
    except ValueError:
        return float("nan")


def stop(proc):
    left = descendants(proc.pid)
    if proc.poll() is None:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(timeout=40)
        except subprocess.TimeoutExpired:
            pass
    if proc.poll() is None:
        proc.kill()
    proc.wait()
    for pid in left:  # whatever of this launch roslaunch did not end
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass


def trial(args, k, diags, scene_file, params_file):
    diags.clear()
    log = open(os.path.join(args.out, "many_risers%s_%s_%d.log" % (args.tag, args.mode, k)), "w")
    cmd = ["roslaunch", "riser_sim", "many_risers.launch", "count:=%d" % k,
           "nodelets:=%s" % ("true" if args.mode == "nodelets" else "false"), "scene:=" + scene_file,
           "vessel_rate:=%g" % args.vessel_rate, "vessel:=%s" % ("false" if args.vessel_last else "true"), "spacing:=%g" % args.spacing, "output:=log",
           "params:=" + params_file, "bind:=" + os.environ.get("ROS_HOSTNAME", "localhost")]
    proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
    vessel = None
    row = {"scene": os.path.splitext(os.path.basename(args.scene))[0], "mode": args.mode, "count": k, "pass": False, "window_s": args.window, "note": ""}
    try:
        deadline = time.time() + 60.0 + 3.0 * k
        if args.vessel_last:
            # Every riser up and waiting for its first pose, then the vessel (as the launch would start it), so
            # that all start from a vessel at rest, within its fade-in.
            while diags.running("waiting for vessel pose") < k:
                if proc.poll() is not None or time.time() > deadline:
                    row["note"] = "only %d of %d risers waiting for the vessel" % (
                        diags.running("waiting for vessel pose"), k)
                    return row
                time.sleep(0.2)
            how = ["load", "riser_sim/VesselMotionNodelet", "/riser_manager"] if args.mode == "nodelets" else \
                ["standalone", "riser_sim/VesselMotionNodelet"]
            vessel = subprocess.Popen(["rosrun", "nodelet", "nodelet"] + how +
                                      ["__name:=vessel_motion", "_rate:=%g" % args.vessel_rate], stdout=log,
                                      stderr=subprocess.STDOUT)
        while diags.running() < k:
            if proc.poll() is not None:
                row["note"] = "roslaunch exited (%d)" % proc.returncode
                return row
            if time.time() > deadline:
                row["note"] = "only %d of %d risers running after %.0f s" % (diags.running(), k, 60.0 + 3.0 * k)
                return row
            time.sleep(0.2)
        time.sleep(args.warmup)
        pids = descendants(proc.pid) + ([vessel.pid] + descendants(vessel.pid) if vessel else [])
        t0, cpu0 = time.time(), cpu_seconds(pids)
        time.sleep(args.window)
        t1, cpu1 = time.time(), cpu_seconds(pids)
        row["cpu_cores"] = (cpu1 - cpu0) / (t1 - t0)
        row["load1"] = os.getloadavg()[0]
        rtfs, dropped, steps, notes = [], 0.0, [], []
        for riser, ds in sorted(diags.between(t0, t1).items()):
            if len(ds) < 2:
                notes.append("%s: %d diagnostics in the window" % (riser, len(ds)))
                rtfs.append(0.0)
                continue
            span = ds[-1][1] - ds[0][1]
            rtfs.append((num(ds[-1], "sim time [s]") - num(ds[0], "sim time [s]")) / span if span > 0 else 0.0)
            dropped += sum(num(d, "time dropped in window [s]") for d in ds[1:])
            steps += [num(d, "step time mean [us]") for d in ds[1:]]
            if max(d[2] for d in ds) >= 2:
                notes.append("%s: ERROR" % riser)
        if len(rtfs) < k:
            notes.append("%d of %d risers reported" % (len(rtfs), k))
        rtfs.sort()
        row["min_rtf"] = rtfs[0] if rtfs else float("nan")
        row["median_rtf"] = rtfs[len(rtfs) // 2] if rtfs else float("nan")
        row["dropped_s"] = dropped
        steps = sorted(s for s in steps if s == s)
        row["step_mean_us"] = steps[len(steps) // 2] if steps else float("nan")
        row["pass"] = len(rtfs) == k and not notes and row["min_rtf"] >= args.min_rtf and dropped == 0.0
        row["note"] = "; ".join(notes)
        return row
    finally:
        if vessel is not None:
            stop(vessel)
        stop(proc)
        log.close()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mode", choices=["nodes", "nodelets"], required=True)
    ap.add_argument("--scene", required=True, help="scene YAML (its top motion is replaced by the vessel's)")
    ap.add_argument("--max-count", type=int, default=64)
    ap.add_argument("--start", type=int, default=1, help="first k of the doubling")
    ap.add_argument("--spacing", type=float, default=10.0,
                    help="hang-off x of riser i in the vessel frame: (i - 1) * spacing [m] (many_risers.launch)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="override a scene key (dotted path, YAML value), e.g. bottom.position=[90,5,-100]")
    ap.add_argument("--loop-rate", type=float, default=None,
                    help="the risers' ~loop_rate [Hz] (default: config/node_defaults.yaml's, 500)")
    ap.add_argument("--vessel-param", action="append", default=[], metavar="KEY=VALUE",
                    help="a private parameter of the vessel nodelet (YAML value), e.g. fade_in=120")
    ap.add_argument("--vessel-last", action="store_true",
                    help="start the vessel only when every riser waits for its first pose (all start from rest)")
    ap.add_argument("--tag", default="", help="suffix of the output files (many_risers<tag>.csv, ...)")
    ap.add_argument("--window", type=float, default=20.0, help="measurement window [s]")
    ap.add_argument("--warmup", type=float, default=5.0, help="seconds after every riser runs")
    ap.add_argument("--vessel-rate", type=float, default=100.0)
    ap.add_argument("--min-rtf", type=float, default=0.99, help="a riser keeps up when its real-time factor >= this")
    ap.add_argument("--out", required=True, help="directory for the CSV, logs and the scene used")
    args = ap.parse_args()

    os.makedirs(args.out, exist_ok=True)
    with open(args.scene) as f:
        scene = yaml.safe_load(f)
    for kv in args.set:
        key, _, value = kv.partition("=")
        node = scene
        for part in key.split(".")[:-1]:
            node = node.setdefault(part, {})
        node[key.split(".")[-1]] = yaml.safe_load(value)
    scene.setdefault("top", {})["motion"] = {"type": "external"}
    scene_file = os.path.join(args.out, "many_risers%s_scene.yaml" % args.tag)
    with open(scene_file, "w") as f:
        yaml.safe_dump(scene, f)

    params_file = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "config/node_defaults.yaml")
    if args.loop_rate is not None:
        with open(params_file) as f:
            params = yaml.safe_load(f)
        params["loop_rate"] = args.loop_rate
        params_file = os.path.join(args.out, "many_risers%s_params.yaml" % args.tag)
        with open(params_file, "w") as f:
            yaml.safe_dump(params, f)
    rospy.init_node("many_risers_bench", disable_signals=True)
    for kv in args.vessel_param:  # roslaunch sets only ~rate: the rest stays on the parameter server
        key, _, value = kv.partition("=")
        rospy.set_param("/vessel_motion/" + key, yaml.safe_load(value))
    diags = Diagnostics()
    csv_path = os.path.join(args.out, "many_risers%s.csv" % args.tag)
    new = not os.path.exists(csv_path)
    results = {}

    def run(k):
        row = trial(args, k, diags, scene_file, params_file)
        results[k] = row
        print("many_risers: %-8s k = %2d  %s  min rtf %.3f  median %.3f  dropped %.3f s  step %.1f us  CPU %.2f cores  "
              "load %.1f  %s" % (args.mode, k, "pass" if row["pass"] else "FAIL", row.get("min_rtf", float("nan")),
                                 row.get("median_rtf", float("nan")), row.get("dropped_s", float("nan")),
                                 row.get("step_mean_us", float("nan")), row.get("cpu_cores", float("nan")),
                                 row.get("load1", float("nan")), row["note"]))
        sys.stdout.flush()
        with open(csv_path, "a", newline="") as f:
            w = csv.DictWriter(f, fieldnames=FIELDS)
            if run.new:
                w.writeheader()
                run.new = False
            w.writerow({key: (("%.4g" % v) if isinstance(v, float) else v) for key, v in row.items()})
        return row["pass"]
    run.new = new

    good, bad, k = 0, None, max(1, min(args.start, args.max_count))
    while k <= args.max_count:
        if not run(k):
            bad = k
            break
        good = k
        k = min(2 * k, args.max_count) if k < args.max_count else args.max_count + 1
    while bad is not None and bad - good > 1:
        mid = (good + bad) // 2
        if run(mid):
            good = mid
        else:
            bad = mid
    print("many_risers: %s: largest k with every riser at real-time factor >= %g: %d%s" %
          (args.mode, args.min_rtf, good, " (the most tried)" if bad is None else ""))
    with open(os.path.join(args.out, "many_risers%s_%s.txt" % (args.tag, args.mode)), "w") as f:
        f.write("%d\n" % good)
    return 0


if __name__ == "__main__":
    sys.exit(main())
