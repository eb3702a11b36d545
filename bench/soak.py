#!/usr/bin/python3
"""Soak run of riser_sim_node: long simulated time under /use_sim_time, driven as fast as the node keeps up.

The driver owns ROS time: it publishes /clock in steps of --chunk seconds and, before each step, the
vessel poses of that step (--pose-rate per simulated second, stamps up to one chunk ahead of the
clock, within the node's max_pose_lead), then waits until the node's ~tension carries the new clock
time (lockstep: nothing is dropped, the node integrates every simulated second). Vessel: at rest at
x = 10 m until the node runs, then x_0 = 10 cos(2 pi t / 27) (the paper's J-lay top motion, eq. 27),
t from the node's first tension. Every output is subscribed (tension, state, top_wrench, /tf).

Every --sample simulated seconds one CSV row: wall time, sim time, the node's VmRSS / VmHWM
(/proc/<pid>/status), its CPU seconds (/proc/<pid>/stat) and CPU seconds per simulated second since the
last row (all its threads: stepping, publishing, callbacks; less sensitive than wall-clock step time
to other load on the machine), the load average, and from its last /diagnostics: step time mean, compute real-time factor, energy, energy balance error, constraint error (now / max), dropped
time. At the end a summary (RSS after warm-up vs end, step time of the first vs the last --window
simulated seconds, error bounds) is printed and written beside the CSV (.txt).
Needs a running master with /use_sim_time unset or true (bench/soak.sh starts a private one).
"""
import argparse
import math
import os
import statistics
import subprocess
import sys
import threading
import time

import rospy
import yaml
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped, WrenchStamped
from rosgraph_msgs.msg import Clock
from tf2_msgs.msg import TFMessage

from riser_sim.msg import LineState, Tension
from proc_util import stop

FIELDS = ["wall_s", "sim_s", "rss_kib", "hwm_kib", "cpu_s", "cpu_per_sim_s", "load1", "step_mean_us", "compute_rtf", "energy_j",
          "energy_balance_error", "constraint_error_m", "max_constraint_error_m", "dropped_total_s", "level"]


def proc_status(pid):
    out = {}
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith(("VmRSS:", "VmHWM:")):
                out[line.split(":")[0]] = int(line.split()[1])
    return out


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / float(os.sysconf("SC_CLK_TCK"))


def fnum(d, key):
    try:
        return float(d.get(key, "nan"))
    except ValueError:
        return float("nan")


class Driver(object):
    def __init__(self, ns):
        self.lock = threading.Condition()
        self.last_tension = None  # stamp [s]
        self.diag = None          # (level, message, {key: value})
        self.name = ns.lstrip("/") + "/riser_sim"
        self.clock_pub = rospy.Publisher("/clock", Clock, queue_size=10)
        self.pose_pub = rospy.Publisher(ns + "/vessel/pose", PoseStamped, queue_size=200)
        self.subs = [rospy.Subscriber(ns + "/riser_sim/tension", Tension, self.on_tension, queue_size=100,
                                      tcp_nodelay=True),
                     rospy.Subscriber(ns + "/riser_sim/state", LineState, lambda m: None, queue_size=10),
                     rospy.Subscriber(ns + "/riser_sim/top_wrench", WrenchStamped, lambda m: None, queue_size=10),
                     rospy.Subscriber("/tf", TFMessage, lambda m: None, queue_size=10),
                     rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diag, queue_size=10)]

    def on_tension(self, msg):
        with self.lock:
            self.last_tension = msg.header.stamp.to_sec()
            self.lock.notify_all()

    def on_diag(self, msg):
        for s in msg.status:
            if s.name.startswith(self.name):
                with self.lock:
                    self.diag = (s.level, s.message, {kv.key: kv.value for kv in s.values})

    def clock(self, t_ns):
        self.clock_pub.publish(Clock(clock=rospy.Time(nsecs=t_ns)))

    def pose(self, t_ns, x):
        msg = PoseStamped()
        msg.header.stamp = rospy.Time(nsecs=t_ns)
        msg.header.frame_id = "world"
        msg.pose.position.x = x
        msg.pose.orientation.w = 1.0
        self.pose_pub.publish(msg)

    def wait_tension(self, t, timeout):
        """True once a tension stamped at >= t [s] arrived."""
        end = time.time() + timeout
        with self.lock:
            while self.last_tension is None or self.last_tension < t:
                left = end - time.time()
                if left <= 0 or rospy.is_shutdown():
                    return False
                self.lock.wait(left)
            return True


def summarize(rows, args):
    def window(a, b):
        return [r for r in rows if a <= r["sim_s"] <= b]
    end = rows[-1]["sim_s"]
    warmup, span = min(args.warmup, 0.5 * end), min(args.window, 0.25 * end)  # short runs
    warm = min(rows, key=lambda r: abs(r["sim_s"] - warmup))
    first = window(0.0, span)
    last = window(end - span, end)
    after = [r for r in rows if r["sim_s"] >= warm["sim_s"]]
    def med(rs, k):
        vals = [r[k] for r in rs if math.isfinite(r[k])]
        return statistics.median(vals) if vals else float("nan")
    mx = lambda rs, k: max([abs(r[k]) for r in rs if math.isfinite(r[k])] or [float("nan")])
    wall = rows[-1]["wall_s"]
    lines = [
        "soak: scene %s, %.0f s simulated in %.0f s wall (%.2fx real time, lockstep, nothing dropped: %s)"
        % (os.path.basename(args.scene), end, wall, end / wall if wall > 0 else float("nan"),
           "yes" if rows[-1]["dropped_total_s"] == 0 else "no, %.3f s" % rows[-1]["dropped_total_s"]),
        "  node CPU %.0f s (%.0f %% of one core over the wall time); load average at the end %.2f %.2f %.2f"
        % ((rows[-1]["cpu_s"], 100.0 * rows[-1]["cpu_s"] / wall) + os.getloadavg()),
        "  RSS: %d KiB after warm-up (t = %.0f s), %d KiB at the end, max %d KiB after warm-up; growth %+d KiB"
        % (warm["rss_kib"], warm["sim_s"], rows[-1]["rss_kib"], max(r["rss_kib"] for r in after),
           rows[-1]["rss_kib"] - warm["rss_kib"]),
        "  step time (median of the 1 s diagnostics windows, wall clock): first %.0f s %.2f us, last %.0f s %.2f us "
        "(ratio %.3f); load average (1 min) median %.1f and %.1f"
        % (span, med(first, "step_mean_us"), span, med(last, "step_mean_us"),
           med(last, "step_mean_us") / med(first, "step_mean_us"), med(first, "load1"), med(last, "load1")),
        "  node CPU per simulated second (median of the rows): first %.0f s %.4f s, last %.0f s %.4f s (ratio %.3f)"
        % (span, med(first[1:], "cpu_per_sim_s"), span, med(last, "cpu_per_sim_s"),
           med(last, "cpu_per_sim_s") / med(first[1:], "cpu_per_sim_s")),
        "  energy balance error (relative): max |.| %.3e, at the end %.3e"
        % (mx(rows, "energy_balance_error"), rows[-1]["energy_balance_error"]),
        "  constraint error: max over the run %.3e m (node's running max %.3e m), at the end %.3e m"
        % (mx(rows, "constraint_error_m"), rows[-1]["max_constraint_error_m"], rows[-1]["constraint_error_m"]),
        "  worst diagnostics level while running %d (0 OK, 1 WARN, 2 ERROR)" % max(r["level"] for r in rows[1:] or rows),
    ]
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--node", required=True, help="riser_sim_node binary")
    ap.add_argument("--scene", required=True, help="scene YAML (top motion replaced by the vessel's)")
    ap.add_argument("--duration", type=float, default=3600.0, help="simulated seconds")
    ap.add_argument("--chunk", type=float, default=0.05, help="/clock step [s] (one tension period)")
    ap.add_argument("--pose-rate", type=float, default=100.0, help="vessel poses per simulated second")
    ap.add_argument("--sample", type=float, default=10.0, help="simulated seconds between CSV rows")
    ap.add_argument("--warmup", type=float, default=300.0, help="RSS reference time [s simulated]")
    ap.add_argument("--window", type=float, default=300.0, help="step time: first vs last this many s")
    ap.add_argument("--csv", required=True)
    args = ap.parse_args()

    ns = "/soak"
    rospy.init_node("soak_driver")
    if not rospy.get_param("/use_sim_time", False):
        sys.exit("soak: set /use_sim_time true on the master before starting (bench/soak.sh does)")
    with open(args.scene) as f:
        scene = yaml.safe_load(f)
    scene["top"]["motion"] = {"type": "external"}
    rospy.set_param(ns + "/riser_sim/scene", scene)
    rospy.set_param(ns + "/riser_sim/rates", {"tension": 20.0, "state": 10.0, "tf": 20.0, "wrench": 20.0,
                                              "markers": 0.0, "diagnostics": 1.0})
    rospy.set_param(ns + "/riser_sim/clock_timeout", 10.0)  # the driver's own hiccups are not stalls

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)

    def write_row(r, first):
        with open(args.csv, "w" if first else "a") as f:
            if first:
                f.write(",".join(FIELDS) + "\n")
            f.write(",".join(("%.6g" % r[k]) if isinstance(r[k], float) else str(r[k]) for k in FIELDS) + "\n")

    drv = Driver(ns)
    chunk_ns = int(round(args.chunk * 1e9))
    per_chunk = max(1, int(round(args.pose_rate * args.chunk)))
    t_ns = 1000 * 10**9  # ROS time starts at 1000 s
    drv.clock(t_ns)
    env = dict(os.environ, ROS_NAMESPACE=ns)
    node = subprocess.Popen([args.node, "__name:=riser_sim"], env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    rows = []
    wall0 = time.time()
    status = 0
    try:
        # Until the node runs: the vessel rests at x = 10 m; ROS time creeps on (the node only looks at
        # poses while ROS time advances).
        deadline = time.time() + 120.0
        while drv.last_tension is None:
            if node.poll() is not None or time.time() > deadline:
                raise RuntimeError("node did not start: %s" % node.stderr.read().decode()[-500:])
            t_ns += 10**6
            drv.pose(t_ns, 10.0)
            drv.clock(t_ns)
            time.sleep(0.005)
        origin_ns = int(round(drv.last_tension * 1e9))  # the node's start; ROS time never goes back
        print("soak: node running at ROS time %.3f s; driving %.0f s of simulated time" % (t_ns * 1e-9, args.duration))
        cpu0 = cpu_seconds(node.pid)
        next_sample = 0.0
        stalls = 0
        while not rospy.is_shutdown():
            sim = (t_ns - origin_ns) * 1e-9
            if sim >= next_sample:
                st = proc_status(node.pid)
                with drv.lock:
                    d = drv.diag
                level, vals = (d[0], d[2]) if d else (0, {})
                cpu = cpu_seconds(node.pid) - cpu0
                per_sim = (cpu - rows[-1]["cpu_s"]) / (sim - rows[-1]["sim_s"]) if rows else float("nan")
                row = {"wall_s": time.time() - wall0, "sim_s": sim, "rss_kib": st["VmRSS"], "hwm_kib": st["VmHWM"],
                       "cpu_s": cpu, "cpu_per_sim_s": per_sim, "load1": os.getloadavg()[0],
                       "step_mean_us": fnum(vals, "step time mean [us]"),
                       "compute_rtf": fnum(vals, "compute real-time factor"), "energy_j": fnum(vals, "energy [J]"),
                       "energy_balance_error": fnum(vals, "energy balance error (relative)"),
                       "constraint_error_m": fnum(vals, "constraint error [m]"),
                       "max_constraint_error_m": fnum(vals, "max constraint error [m]"),
                       "dropped_total_s": fnum(vals, "time dropped total [s]"), "level": level}
                rows.append(row)
                write_row(row, first=len(rows) == 1)
                if level >= 2:
                    print("soak: node reports ERROR: %s" % d[1])
                    status = 1
                    break
                if len(rows) % 30 == 1:
                    print("soak: t = %6.0f s  wall %6.0f s  RSS %d KiB  step %.1f us  CPU/sim s %.4f  load %.1f  "
                          "energy err %.2e  constraint %.2e m"
                          % (sim, row["wall_s"], row["rss_kib"], row["step_mean_us"], row["cpu_per_sim_s"],
                             row["load1"], row["energy_balance_error"], row["constraint_error_m"]))
                    sys.stdout.flush()
                next_sample += args.sample
            if sim >= args.duration:
                break
            for i in range(1, per_chunk + 1):
                ts = t_ns + chunk_ns * i // per_chunk
                tt = (ts - origin_ns) * 1e-9
                drv.pose(ts, 10.0 * math.cos(2.0 * math.pi * tt / 27.0))
            t_ns += chunk_ns
            drv.clock(t_ns)
            if not drv.wait_tension(t_ns * 1e-9 - 1e-3, 5.0):
                stalls += 1
                if node.poll() is not None:
                    raise RuntimeError("node exited (%d)" % node.returncode)
                if stalls > 20:
                    raise RuntimeError("node stopped answering (no tension for the clock's time)")
        if stalls:
            print("soak: %d clock steps waited > 5 s for the node" % stalls)
    except RuntimeError as e:
        print("soak: %s" % e)
        status = 1
    finally:
        stop(node)
    if rows:
        text = summarize(rows, args)
        print(text)
        with open(os.path.splitext(args.csv)[0] + ".txt", "w") as f:
            f.write(text + "\n")
        print("wrote %s" % args.csv)
    return status


if __name__ == "__main__":
    sys.exit(main())
