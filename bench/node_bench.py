#!/usr/bin/python3
"""Benchmark of riser_sim_node in real time, with every output published and subscribed.

For one line size n: sets the scene (a YAML scene file with line.elements and solver.dt overridden)
under <ns>/riser_sim/scene, starts the node binary, drives it with a vessel surging as in the paper
(x_0 = 10 cos(2 pi t / 27), 50 Hz, t from the node's first tension, at rest before; --motion ax,ay,az,T: x, y, z = a cos(2 pi t / T), e.g. the 3D sea
scene's own 2, 1, 0.5 m at 10 s), subscribes to ~tension, ~state, ~markers, ~top_wrench and /tf,
and over a measurement window reads
  - the node's real-time factor and compute real-time factor, step time, work per publish period
    (p99) and publish time (p99) from its /diagnostics,
  - its CPU share from /proc/<pid>/stat (utime + stime over wall time, % of one core),
  - the achieved tension rate.
Appends one row to the CSV file. Needs a running master (bench/node_bench.sh starts one).
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

import rospy
import yaml
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped, WrenchStamped
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import MarkerArray

from riser_sim.msg import LineState, Tension
from proc_util import stop

FIELDS = ["scene", "n", "dt", "status", "real_time_factor", "compute_real_time_factor", "cpu_percent", "step_mean_us",
          "step_max_us", "work_per_publish_period_p99_ms", "publish_period_ms", "publish_p99_ms", "tension_hz",
          "window_s"]


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    # fields[0] is the state (field 3 of stat); utime and stime are fields 14 and 15.
    return (int(fields[11]) + int(fields[12])) / float(os.sysconf("SC_CLK_TCK"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--node", required=True, help="path of the riser_sim_node binary")
    ap.add_argument("--scene", required=True, help="scene YAML file")
    ap.add_argument("--n", type=int, required=True, help="line.elements")
    ap.add_argument("--dt", type=float, required=True, help="solver.dt [s]")
    ap.add_argument("--motion", default="10,0,0,27",
                    help="vessel motion ax,ay,az,T: position a cos(2 pi t / T) per axis [m, s] (default: the paper's surge)")
    ap.add_argument("--param", action="append", default=[], metavar="KEY=VALUE",
                    help="a private parameter of the node (YAML value), e.g. loop_rate=50")
    ap.add_argument("--window", type=float, default=10.0, help="measurement window [s]")
    ap.add_argument("--warmup", type=float, default=3.0, help="seconds after the first tension before measuring")
    ap.add_argument("--moving-start", action="store_true",
                    help="the vessel moves from the bench's start, so the node starts against a moving vessel")
    ap.add_argument("--csv", required=True)
    args = ap.parse_args()
    motion = [float(v) for v in args.motion.split(",")]
    if len(motion) != 4 or not motion[3] > 0.0:
        ap.error("--motion: expected ax,ay,az,T with T > 0, got %r" % args.motion)

    ns = "/bench_n%d" % args.n
    rospy.init_node("node_bench_n%d" % args.n)
    with open(args.scene) as f:
        scene = yaml.safe_load(f)
    scene.setdefault("line", {})["elements"] = args.n
    scene.setdefault("solver", {})["dt"] = args.dt
    rospy.set_param(ns + "/riser_sim/scene", scene)
    for kv in args.param:
        key, _, value = kv.partition("=")
        rospy.set_param(ns + "/riser_sim/" + key, yaml.safe_load(value))

    counts = {"tension": 0}
    diags = []
    start_wall = [None]

    def on_tension(_):
        counts["tension"] += 1

    def on_diag(msg):
        for s in msg.status:
            if s.name.startswith(ns.lstrip("/") + "/riser_sim"):
                diags.append((time.time(), s.level, s.message, {kv.key: kv.value for kv in s.values}))

    subs = [rospy.Subscriber(ns + "/riser_sim/tension", Tension, on_tension, queue_size=50),
            rospy.Subscriber(ns + "/riser_sim/state", LineState, lambda m: None, queue_size=5),
            rospy.Subscriber(ns + "/riser_sim/markers", MarkerArray, lambda m: None, queue_size=5),
            rospy.Subscriber(ns + "/riser_sim/top_wrench", WrenchStamped, lambda m: None, queue_size=5),
            rospy.Subscriber("/tf", TFMessage, lambda m: None, queue_size=50),
            rospy.Subscriber("/diagnostics", DiagnosticArray, on_diag, queue_size=10)]
    pose_pub = rospy.Publisher(ns + "/vessel/pose", PoseStamped, queue_size=10)

    env = dict(os.environ, ROS_NAMESPACE=ns)
    node = subprocess.Popen([args.node, "__name:=riser_sim"], env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    row = {"scene": os.path.splitext(os.path.basename(args.scene))[0], "n": args.n, "dt": args.dt, "status": "ok", "window_s": args.window}
    try:
        t0 = rospy.Time.now()
        rate = rospy.Rate(50.0)
        phase = "starting"
        first = None
        measure_from = None
        cpu0 = None
        while not rospy.is_shutdown():
            if node.poll() is not None:
                row["status"] = "node exited (%d): %s" % (node.returncode, node.stderr.read().decode()[-300:])
                break
            now = rospy.Time.now()
            t = (now - t0).to_sec()
            # The vessel holds its t = 0 pose (at rest) until the node has started: the node starts from the statics
            # at rest, and a 3D sea riser jolted into a vessel already moving can diverge (docs/benchmarks.md).
            tm = (now - motion_t0).to_sec() if first is not None else 0.0
            if args.moving_start:
                tm = t
            msg = PoseStamped()
            msg.header.stamp = now
            msg.header.frame_id = "world"
            c = math.cos(2.0 * math.pi * tm / motion[3])
            msg.pose.position.x, msg.pose.position.y, msg.pose.position.z = motion[0] * c, motion[1] * c, motion[2] * c
            msg.pose.orientation.w = 1.0
            pose_pub.publish(msg)
            wall = time.time()
            if first is None and counts["tension"] > 0:
                first, motion_t0 = wall, now
            if first is not None and measure_from is None and wall - first >= args.warmup:
                measure_from, cpu0, tension0, ndiag0 = wall, cpu_seconds(node.pid), counts["tension"], len(diags)
            if measure_from is not None and wall - measure_from >= args.window:
                cpu1 = cpu_seconds(node.pid)
                span = wall - measure_from
                window_diags = [d for d in diags[ndiag0:]]
                break
            if first is None and t > 60.0:
                row["status"] = "no tension within 60 s"
                break
            rate.sleep()
        if measure_from is not None and row["status"] == "ok":
            row["cpu_percent"] = 100.0 * (cpu1 - cpu0) / span
            row["tension_hz"] = (counts["tension"] - tension0) / span
            if not window_diags:
                row["status"] = "no diagnostics in the window"
            else:
                def mean(key):
                    vals = [float(d[3][key]) for d in window_diags if key in d[3] and d[3][key] != "n/a"]
                    return sum(vals) / len(vals) if vals else float("nan")
                last = window_diags[-1][3]
                row["real_time_factor"] = mean("real-time factor")
                row["compute_real_time_factor"] = mean("compute real-time factor")
                row["step_mean_us"] = mean("step time mean [us]")
                row["step_max_us"] = max(float(d[3].get("step time max [us]", "nan")) for d in window_diags)
                row["work_per_publish_period_p99_ms"] = float(last.get("work per publish period p99 [ms]", "nan"))
                row["publish_period_ms"] = float(last.get("publish period [ms]", "nan"))
                row["publish_p99_ms"] = float(last.get("publish time p99 [ms]", "nan"))
                worst = max(d[1] for d in window_diags)
                if worst >= 2:
                    row["status"] = "ERROR: " + window_diags[-1][2]
                elif worst == 1:
                    row["status"] = "WARN: " + [d for d in window_diags if d[1] == 1][-1][2]
    finally:
        stop(node)
        for s in subs:
            s.unregister()
        rospy.delete_param(ns)

    new = not os.path.exists(args.csv) or os.path.getsize(args.csv) == 0
    with open(args.csv, "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        if new:
            w.writeheader()
        w.writerow({k: (("%.4g" % v) if isinstance(v, float) else v) for k, v in row.items()})
    return 0 if row["status"] == "ok" else 1


if __name__ == "__main__":
    sys.exit(main())
