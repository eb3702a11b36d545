#!/usr/bin/env python3
"""A launch loads exactly the scene it names, also when the master stays up between launches.

On a private master (free port): riser_sim.launch and riser_nodelet.launch each launched with the J-lay
scene (seabed, internal fluid, initial.end_force), stopped, a stale misspelt private parameter set
(as an earlier params file would leave it), then launched again with demo_riser.yaml. Asserted: the
private namespace holds the demo scene only (no seabed, no internal_fluid, no end_force left from the
J-lay) and not the stale parameter. Writes a JUnit file like test_master_restart.py (registered in
cmake/node.cmake). Every wait polls a condition; every process started here is stopped at the end.
"""
import argparse
import os
import signal
import subprocess
import sys
import tempfile
import time
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_master_restart import Master, Procs, free_port, wait_for, write_junit  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenes", required=True, help="config/scenes")
    ap.add_argument("--xml", required=True, help="JUnit result file")
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="riser_sim_relaunch_")
    port = free_port()
    uri = "http://127.0.0.1:%d" % port
    env = dict(os.environ, ROS_MASTER_URI=uri, ROS_HOME=tmp, ROS_LOG_DIR=os.path.join(tmp, "log"))
    procs, master = Procs(), Master(uri)
    started = set()  # pids of the launched processes
    results = []

    def param(name):
        code, _, value = master.call("getParam", name)
        return value if code == 1 else None

    def launch(launch_file, ns, scene, log):
        args = ["roslaunch", "riser_sim", launch_file, "scene:=" + os.path.join(a.scenes, scene + ".yaml"),
                "namespace:=" + ns, "output:=log"]
        if launch_file == "riser_nodelet.launch":
            args.append("manager:=/no_manager")  # the loader waits for it; the parameters are set before
        p = procs.start(args, os.path.join(tmp, log), env=env)
        wait_for(lambda: param("/%s/riser_sim/scene/name" % ns) == scene, 30, "%s loaded by %s" % (scene, launch_file))
        # Stopped only once its process is up: roslaunch interrupted while it spawns leaves the process
        # running on its own (each child has a session of its own), so it is also ended by pid.
        p.child = wait_for(lambda: new_pid("/%s/riser_sim" % ns), 30, "the process of " + launch_file)
        started.add(p.child)
        return p

    def new_pid(node):
        """pid of `node` once the process launched last registered (not one of an earlier launch)."""
        try:
            pid = master.node_pid(node)
        except OSError:  # the master still lists the ended process of the earlier launch
            return None
        return pid if pid and pid not in started else None

    def stop(p):
        Procs.stop(p)
        try:
            os.kill(p.child, signal.SIGKILL)  # only if roslaunch did not end it
        except ProcessLookupError:
            pass

    def relaunch_keeps_nothing(launch_file, ns):
        private = "/%s/riser_sim" % ns
        stop(launch(launch_file, ns, "paper_jlay_170m", ns + "_1.log"))
        assert param(private + "/scene/seabed/level") == -80.0, "the J-lay scene was not loaded"
        master.call("setParam", private + "/loop_rat", 100.0)  # left by an earlier params file
        p = launch(launch_file, ns, "demo_riser", ns + "_2.log")
        try:
            scene = param(private + "/scene")
            for stale in ("seabed", "internal_fluid", "bottom"):
                assert stale not in scene, "~scene/%s of the earlier J-lay scene is still there" % stale
            assert "end_force" not in scene["initial"], "~scene/initial/end_force of the J-lay is still there"
            assert param(private + "/loop_rat") is None, "the stale ~loop_rat is still there"
        finally:
            stop(p)

    def check(name, fn, *args):
        t0 = time.monotonic()
        try:
            fn(*args)
            results.append((name, None, time.monotonic() - t0))
            print("[relaunch_scene] ok   %s (%.1f s)" % (name, time.monotonic() - t0))
        except Exception as e:  # noqa: BLE001 - every failure becomes a test failure
            results.append((name, "%s\n%s" % (e, traceback.format_exc()), time.monotonic() - t0))
            print("[relaunch_scene] FAIL %s: %s" % (name, e))

    try:
        procs.start(["rosmaster", "--core", "-p", str(port)], os.path.join(tmp, "master.log"), env=env)
        wait_for(master.up, 15, "the master on port %d" % port)
        check("riser_sim_launch_loads_only_its_scene", relaunch_keeps_nothing, "riser_sim.launch", "node")
        check("riser_nodelet_launch_loads_only_its_scene", relaunch_keeps_nothing, "riser_nodelet.launch", "nodelet")
    finally:
        procs.stop_all()

    write_junit("relaunch_scene", results, a.xml)
    failed = [n for n, f, _ in results if f]
    if failed:
        print("[relaunch_scene] logs kept in %s" % tmp)
    else:
        subprocess.run(["rm", "-rf", tmp])
    print("[relaunch_scene] %d passed, %d failed" % (len(results) - len(failed), len(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
