#!/usr/bin/python3
"""Plots tension, end wrenches and positions over time from a demo bag, and a map of the tension along the
line against time; prints a short summary.

usage: plot_demo.py BAG [-o PNG] [--map PNG] [--tf-prefix PREFIX]
  -o:    top and bottom tension; the end wrenches' forces (*top_wrench, *bottom_wrench if recorded); the
         top end A_0, the vessel and the bottom end over time (default demo_tension.png)
  --map: arc length (top at the top) against time, coloured by axial force (default: -o with _map)

Topics are found by name suffix and type, so any namespace works: */tension (riser_sim/Tension),
*top_wrench, *bottom_wrench (geometry_msgs/WrenchStamped),
*vessel/pose (geometry_msgs/PoseStamped), /tf (frame <prefix>/rfe_0 = top end A_0; <prefix>/end = bottom end, else the last rfe's origin A_n),
/diagnostics (keys "real-time factor" and "compute real-time factor" of riser_sim_node).
Messages are read with the bag's own definitions, so the riser_sim messages need not be built.
"""
import argparse
import math
import os
import sys

import rosbag

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def find_topic(info, suffix, msg_type):
    for name, t in sorted(info.topics.items()):
        if name.endswith(suffix) and t.msg_type == msg_type:
            return name
    return None


def rfe_index(frame, prefix):
    """i of '<prefix>/rfe_<i>' (leading slashes ignored), else None."""
    frame = frame.lstrip("/")
    head, _, tail = frame.rpartition("rfe_")
    if not tail.isdigit() or (prefix and head.strip("/") != prefix.strip("/")):
        return None
    return int(tail)


def is_end(frame, prefix):
    """'<prefix>/end': the end point of the last rfe, where the end mass hangs."""
    head, _, tail = frame.lstrip("/").rpartition("/")
    return tail == "end" and (not prefix or head == prefix.strip("/"))


def as_float(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def read(bag_path, tf_prefix):
    bag = rosbag.Bag(bag_path)
    info = bag.get_type_and_topic_info()
    topics = {
        "tension": find_topic(info, "tension", "riser_sim/Tension"),
        "pose": find_topic(info, "vessel/pose", "geometry_msgs/PoseStamped"),
        "wrench": find_topic(info, "top_wrench", "geometry_msgs/WrenchStamped"),
        "bwrench": find_topic(info, "bottom_wrench", "geometry_msgs/WrenchStamped"),
        "tf": "/tf" if "/tf" in info.topics else None,
        "diag": "/diagnostics" if "/diagnostics" in info.topics else None,
    }
    d = {k: [] for k in ("t_ten", "top", "max", "bottom", "axial", "arc", "t_pose", "px", "py", "pz", "yaw",
                         "t_a0", "a0x", "a0y", "a0z", "t_end", "endx", "endy", "endz", "rtf", "crtf",
                         "t_w", "w", "t_bw", "bw")}
    t0 = None
    wanted = [t for t in topics.values() if t]
    for topic, msg, stamp in bag.read_messages(topics=wanted):
        t0 = stamp.to_sec() if t0 is None else t0
        t = stamp.to_sec() - t0
        if topic == topics["tension"]:
            d["t_ten"].append(t)
            d["top"].append(msg.top)
            d["max"].append(msg.max)
            d["bottom"].append(msg.bottom)
            d["axial"].append(list(msg.axial_force))
            d["arc"] = list(msg.arc_length)
        elif topic in (topics["wrench"], topics["bwrench"]):
            f, m = msg.wrench.force, msg.wrench.torque
            key = "w" if topic == topics["wrench"] else "bw"
            d["t_" + key].append(t)
            d[key].append((f.x, f.y, f.z, math.sqrt(m.x ** 2 + m.y ** 2 + m.z ** 2)))
        elif topic == topics["pose"]:
            d["t_pose"].append(t)
            d["px"].append(msg.pose.position.x)
            d["py"].append(msg.pose.position.y)
            d["pz"].append(msg.pose.position.z)
            q = msg.pose.orientation
            d["yaw"].append(math.degrees(math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y ** 2 + q.z ** 2))))
        elif topic == topics["tf"]:
            last = None
            for tr in msg.transforms:
                if is_end(tr.child_frame_id, tf_prefix):
                    last = (float("inf"), tr)
                    continue
                i = rfe_index(tr.child_frame_id, tf_prefix)
                if i is None:
                    continue
                if i == 0:
                    d["t_a0"].append(t)
                    d["a0x"].append(tr.transform.translation.x)
                    d["a0y"].append(tr.transform.translation.y)
                    d["a0z"].append(tr.transform.translation.z)
                if last is None or i > last[0]:
                    last = (i, tr)
            if last is not None and last[0] > 0:
                d["t_end"].append(t)
                d["endx"].append(last[1].transform.translation.x)
                d["endy"].append(last[1].transform.translation.y)
                d["endz"].append(last[1].transform.translation.z)
        elif topic == topics["diag"]:
            for status in msg.status:
                for kv in status.values:
                    key = {"real-time factor": "rtf", "compute real-time factor": "crtf"}.get(kv.key.strip())
                    v = as_float(kv.value) if key else None
                    if v is not None:
                        d[key].append(v)
    bag.close()
    return topics, d


def summary(topics, d):
    lines = []
    if d["top"]:
        lines.append("top tension: %.1f .. %.1f kN (mean %.1f kN); max along the line %.1f kN; %d samples"
                     % (min(d["top"]) / 1e3, max(d["top"]) / 1e3, sum(d["top"]) / len(d["top"]) / 1e3,
                        max(d["max"]) / 1e3, len(d["top"])))
    else:
        lines.append("top tension: no riser_sim/Tension messages in the bag")
    if d["rtf"]:
        lines.append("real-time factor (/diagnostics): mean %.2f, min %.2f, max %.2f over %d reports"
                     % (sum(d["rtf"]) / len(d["rtf"]), min(d["rtf"]), max(d["rtf"]), len(d["rtf"])))
    else:
        lines.append("real-time factor: no value in /diagnostics")
    if d["crtf"]:
        lines.append("compute real-time factor (simulated / wall time spent stepping): mean %.1f, min %.1f"
                     % (sum(d["crtf"]) / len(d["crtf"]), min(d["crtf"])))
    if d["px"]:
        lines.append("vessel x: %.1f .. %.1f m, y: %.1f .. %.1f m, z: %.1f .. %.1f m, yaw: %.1f .. %.1f deg"
                     % (min(d["px"]), max(d["px"]), min(d["py"]), max(d["py"]), min(d["pz"]), max(d["pz"]),
                        min(d["yaw"]), max(d["yaw"])))
    if d["endx"]:
        lines.append("bottom end x: %.1f .. %.1f m, y: %.1f .. %.1f m, z: %.1f .. %.1f m"
                     % (min(d["endx"]), max(d["endx"]), min(d["endy"]), max(d["endy"]), min(d["endz"]),
                        max(d["endz"])))
    for key, name in (("w", "top"), ("bw", "bottom")):
        if d[key]:
            mags = [math.sqrt(w[0] ** 2 + w[1] ** 2 + w[2] ** 2) / 1e3 for w in d[key]]
            lines.append("%s wrench |F|: %.1f .. %.1f kN, |M| max %.1f kN m; %d samples"
                         % (name, min(mags), max(mags), max(w[3] for w in d[key]) / 1e3, len(mags)))
    return lines


def plot(topics, d, out):
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, sharex=True, figsize=(10, 8.5))
    if d["top"]:
        ax1.plot(d["t_ten"], [v / 1e3 for v in d["top"]], label="top tension", color="C3")
        ax1.plot(d["t_ten"], [v / 1e3 for v in d["bottom"]], label="bottom tension", color="C0", lw=0.8)
    ax1.set_ylabel("axial force [kN]")
    ax1.set_title("riser_sim demo: %s" % (topics["tension"] or "no tension topic"))
    ax1.grid(True, alpha=0.4)
    ax1.legend(loc="upper right")
    for key, name, style in (("w", "top", "-"), ("bw", "bottom", "--")):
        for k, axis in enumerate("xyz"):
            if d[key]:
                ax2.plot(d["t_" + key], [w[k] / 1e3 for w in d[key]], style, color="C%d" % k, lw=0.9,
                         label="%s F%s" % (name, axis))
    ax2.set_ylabel("force on the end [kN]\n(world frame)")
    ax2.grid(True, alpha=0.4)
    if d["w"] or d["bw"]:
        ax2.legend(loc="upper right", fontsize="small", ncol=2)
    else:
        ax2.text(0.5, 0.5, "no top_wrench / bottom_wrench in the bag", ha="center", transform=ax2.transAxes)
    if d["a0x"]:
        ax3.plot(d["t_a0"], d["a0x"], label="top end A_0 x", color="C1")
        ax3.plot(d["t_a0"], d["a0y"], label="top end A_0 y", color="C0")
        ax3.plot(d["t_a0"], d["a0z"], label="top end A_0 z", color="C2")
    if d["px"]:
        ax3.plot(d["t_pose"], d["px"], "--", label="vessel x", color="C1", lw=0.8, alpha=0.7)
        ax3.plot(d["t_pose"], d["py"], "--", label="vessel y", color="C0", lw=0.8, alpha=0.7)
        ax3.plot(d["t_pose"], d["pz"], "--", label="vessel z", color="C2", lw=0.8, alpha=0.7)
    if d["endx"] and max(d["endx"]) - min(d["endx"]) > 1e-3:  # not a fixed anchor
        ax3.plot(d["t_end"], d["endx"], label="bottom end x", color="C4", lw=0.8)
    ax3.set_xlabel("time since start of the bag [s]")
    ax3.set_ylabel("position in world [m]")
    ax3.grid(True, alpha=0.4)
    ax3.legend(loc="upper right", fontsize="small", ncol=3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_map(topics, d, out):
    """Arc length (top at the top) against time, coloured by the axial force of each rfe."""
    rows = [a for a in d["axial"] if len(a) == len(d["arc"])]
    if not rows or len(d["arc"]) < 2:
        return False
    times = [t for t, a in zip(d["t_ten"], d["axial"]) if len(a) == len(d["arc"])]
    force_kn = np.array(rows).T / 1e3  # [rfe, time]
    fig, ax = plt.subplots(figsize=(10, 4.5))
    mesh = ax.pcolormesh(times, d["arc"], force_kn, shading="nearest", cmap="turbo")
    ax.invert_yaxis()
    ax.set_xlabel("time since start of the bag [s]")
    ax.set_ylabel("arc length from the top [m]")
    ax.set_title("axial force along the line: %s" % topics["tension"])
    fig.colorbar(mesh, ax=ax, label="axial force [kN]")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bag")
    ap.add_argument("-o", "--output", default="demo_tension.png")
    ap.add_argument("--map", default="", help="tension map PNG (default: the output's name with _map)")
    ap.add_argument("--tf-prefix", default="", help="only rfe frames under this prefix (default: any)")
    args = ap.parse_args()
    topics, d = read(args.bag, args.tf_prefix)
    plot(topics, d, args.output)
    map_out = args.map or os.path.splitext(args.output)[0] + "_map.png"
    for line in summary(topics, d):
        print(line)
    print("plot: %s" % args.output)
    if plot_map(topics, d, map_out):
        print("tension map: %s" % map_out)
    return 0 if d["top"] else 1


if __name__ == "__main__":
    sys.exit(main())
