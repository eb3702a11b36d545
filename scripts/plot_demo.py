#!/usr/bin/python3
"""Plots top tension and top-end position over time from a demo bag; prints a short summary.

usage: plot_demo.py BAG [-o PNG] [--tf-prefix PREFIX]

Topics are found by name suffix and type, so any namespace works: */tension (riser_sim/Tension),
*vessel/pose (geometry_msgs/PoseStamped), /tf (frame <prefix>/rfe_0 = top end A_0; <prefix>/end = bottom end, else the last rfe's origin A_n),
/diagnostics (keys "real-time factor" and "compute real-time factor" of riser_sim_node).
Messages are read with the bag's own definitions, so the riser_sim messages need not be built.
"""
import argparse
import math
import sys

import rosbag

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


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
        "tf": "/tf" if "/tf" in info.topics else None,
        "diag": "/diagnostics" if "/diagnostics" in info.topics else None,
    }
    d = {k: [] for k in ("t_ten", "top", "max", "bottom", "t_pose", "px", "pz",
                         "t_a0", "a0x", "a0z", "t_end", "endx", "endz", "rtf", "crtf")}
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
        elif topic == topics["pose"]:
            d["t_pose"].append(t)
            d["px"].append(msg.pose.position.x)
            d["pz"].append(msg.pose.position.z)
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
                    d["a0z"].append(tr.transform.translation.z)
                if last is None or i > last[0]:
                    last = (i, tr)
            if last is not None and last[0] > 0:
                d["t_end"].append(t)
                d["endx"].append(last[1].transform.translation.x)
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
        lines.append("vessel x: %.1f .. %.1f m, z: %.1f .. %.1f m" % (min(d["px"]), max(d["px"]),
                                                                   min(d["pz"]), max(d["pz"])))
    if d["endx"]:
        lines.append("bottom end x: %.1f .. %.1f m, z: %.1f .. %.1f m" % (min(d["endx"]), max(d["endx"]),
                                                                       min(d["endz"]), max(d["endz"])))
    return lines


def plot(topics, d, out):
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(10, 6.5))
    if d["top"]:
        ax1.plot(d["t_ten"], [v / 1e3 for v in d["top"]], label="top tension", color="C3")
        ax1.plot(d["t_ten"], [v / 1e3 for v in d["bottom"]], label="bottom tension", color="C0", lw=0.8)
    ax1.set_ylabel("axial force [kN]")
    ax1.set_title("riser_sim demo: %s" % (topics["tension"] or "no tension topic"))
    ax1.grid(True, alpha=0.4)
    ax1.legend(loc="upper right")
    if d["a0x"]:
        ax2.plot(d["t_a0"], d["a0x"], label="top end A_0 x", color="C1")
        ax2.plot(d["t_a0"], d["a0z"], label="top end A_0 z", color="C2")
    if d["px"]:
        ax2.plot(d["t_pose"], d["px"], "--", label="vessel x", color="C1", lw=0.8, alpha=0.7)
        ax2.plot(d["t_pose"], d["pz"], "--", label="vessel z", color="C2", lw=0.8, alpha=0.7)
    if d["endx"]:
        ax2.plot(d["t_end"], d["endx"], label="bottom end x", color="C4", lw=0.8)
    ax2.set_xlabel("time since start of the bag [s]")
    ax2.set_ylabel("position in world [m]")
    ax2.grid(True, alpha=0.4)
    ax2.legend(loc="upper right", fontsize="small", ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bag")
    ap.add_argument("-o", "--output", default="demo_tension.png")
    ap.add_argument("--tf-prefix", default="", help="only rfe frames under this prefix (default: any)")
    args = ap.parse_args()
    topics, d = read(args.bag, args.tf_prefix)
    plot(topics, d, args.output)
    for line in summary(topics, d):
        print(line)
    print("plot: %s" % args.output)
    return 0 if d["top"] else 1


if __name__ == "__main__":
    sys.exit(main())
