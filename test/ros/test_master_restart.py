#!/usr/bin/env python3
"""Master restart and security checks of riser_sim_node, outside rostest (the test kills and
restarts the master, which rostest owns). Writes a JUnit file (one test case per check) for
catkin_test_results; registered in cmake/node.cmake, run by tools/test.sh.

On a private master (free port, temporary ROS_HOME): starts the node as the launch files do
(ROS_HOSTNAME=localhost) with HOME, ROS_HOME and its working directory in empty temporary directories,
drives it with vessel poses, then
  - sockets: the node listens on roscpp's XML-RPC and TCPROS ports and one UDPROS socket, nothing else;
    TCPROS/UDPROS on the loopback interface (XML-RPC: where xmlrpcpp binds, reported),
  - kills the master, starts a new one on the same port: the node re-registers its publications,
    subscriptions and services (MasterWatch), a new subscriber receives tension, a new vessel publisher
    moves the top, ~modes answers; the parameters are gone from the new master,
  - riser_sim.launch with its default bind: the launched node's TCPROS port is on loopback too,
  - the node wrote no file (HOME, ROS_HOME, working directory still empty).
Every wait polls a condition with a timeout; every process started here is stopped at the end.
"""
import argparse
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
import traceback
import xml.etree.ElementTree as ET
import xmlrpc.client

import yaml

CALLER = "/test_master_restart"


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def wait_for(cond, timeout, what):
    end = time.monotonic() + timeout
    while True:
        value = cond()
        if value:
            return value
        if time.monotonic() > end:
            raise AssertionError("timed out after %.0f s waiting for %s" % (timeout, what))
        time.sleep(0.05)


class Procs:
    """Processes started here, each in its own process group; stopped in reverse order."""

    def __init__(self):
        self.procs = []

    def start(self, args, log, **kw):
        p = subprocess.Popen(args, stdout=open(log, "w"), stderr=subprocess.STDOUT, start_new_session=True, **kw)
        self.procs.append(p)
        return p

    @staticmethod
    def stop(p, sig=signal.SIGINT):
        if p.poll() is not None:
            return
        try:
            os.killpg(p.pid, sig)
            p.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(timeout=5)
        except ProcessLookupError:
            pass

    def stop_all(self):
        for p in reversed(self.procs):
            self.stop(p)


class Master:
    def __init__(self, uri):
        self.proxy = xmlrpc.client.ServerProxy(uri)

    def call(self, method, *args):
        code, msg, value = getattr(self.proxy, method)(CALLER, *args)
        return code, msg, value

    def up(self):
        try:
            return self.call("getPid")[0] == 1
        except OSError:
            return False

    def state(self):
        return self.call("getSystemState")[2]

    def provides(self, kind, name, node):
        """kind 0 publishers, 1 subscribers, 2 services."""
        return any(n == name and node in nodes for n, nodes in self.state()[kind])

    def node_pid(self, node):
        code, _, uri = self.call("lookupNode", node)
        if code != 1:
            return None
        return xmlrpc.client.ServerProxy(uri).getPid(CALLER)[2]


def write_junit(suite_name, results, path):
    """JUnit file of (name, failure or None, seconds) results, counted by catkin_test_results."""
    suite = ET.Element("testsuite", name=suite_name, tests=str(len(results)),
                       failures=str(sum(1 for _, f, _ in results if f)), errors="0")
    for name, failure, secs in results:
        case = ET.SubElement(suite, "testcase", classname="riser_sim." + suite_name, name=name, time="%.2f" % secs)
        if failure:
            ET.SubElement(case, "failure", message=failure.split("\n")[0]).text = failure
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def sockets_of(pid):
    """(proto, local address, port) of every TCP listening and UDP socket the process holds."""
    inodes = set()
    for fd in os.listdir("/proc/%d/fd" % pid):
        try:
            link = os.readlink("/proc/%d/fd/%s" % (pid, fd))
        except OSError:
            continue
        if link.startswith("socket:["):
            inodes.add(link[8:-1])
    out = []
    for proto in ("tcp", "tcp6", "udp", "udp6"):
        with open("/proc/%d/net/%s" % (pid, proto)) as f:
            next(f)
            for line in f:
                cols = line.split()
                local, st, inode = cols[1], cols[3], cols[9]
                if inode not in inodes or (proto.startswith("tcp") and st != "0A"):  # 0A = LISTEN
                    continue
                addr_hex, port_hex = local.split(":")
                if len(addr_hex) == 8:
                    addr = socket.inet_ntop(socket.AF_INET, bytes.fromhex(addr_hex)[::-1])
                else:
                    raw = bytes.fromhex(addr_hex)
                    addr = socket.inet_ntop(socket.AF_INET6, b"".join(raw[i:i + 4][::-1] for i in range(0, 16, 4)))
                out.append((proto, addr, int(port_hex, 16)))
    return out


def files_under(path):
    return sorted(os.path.relpath(os.path.join(d, f), path) for d, _, fs in os.walk(path) for f in fs)


def echo_once(topic, env, timeout=10.0):
    """One message (or field: /topic/field) via rostopic, a fresh subscriber; None on timeout."""
    try:
        r = subprocess.run(["rostopic", "echo", "-n", "1", topic], env=env, capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    return r.stdout.split("\n---")[0].strip() if r.returncode == 0 else None


def pose_publisher(procs, x, env, log):
    msg = "{header: {stamp: now, frame_id: world}, pose: {position: {x: %g}, orientation: {w: 1.0}}}" % x
    return procs.start(["rostopic", "pub", "-r", "20", "-s", "/vessel/pose", "geometry_msgs/PoseStamped", msg], log,
                       env=env)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--node", required=True, help="riser_sim_node executable")
    ap.add_argument("--scene", required=True)
    ap.add_argument("--xml", required=True, help="JUnit result file")
    ap.add_argument("--keep", action="store_true", help="keep the temporary directory")
    a = ap.parse_args()

    tmp = tempfile.mkdtemp(prefix="riser_sim_master_restart_")
    port = free_port()
    uri = "http://127.0.0.1:%d" % port
    env = dict(os.environ, ROS_MASTER_URI=uri, ROS_HOME=os.path.join(tmp, "tools_home"),
               ROS_LOG_DIR=os.path.join(tmp, "tools_log"))
    env.pop("ROS_HOSTNAME", None)
    env.pop("ROS_IP", None)
    node_home, node_cwd = os.path.join(tmp, "node_home"), os.path.join(tmp, "node_cwd")
    for d in (node_home, node_cwd):
        os.makedirs(d)
    node_env = dict(env, HOME=node_home, ROS_HOME=node_home, ROS_HOSTNAME="localhost")
    node_env.pop("ROS_LOG_DIR", None)
    node_log = os.path.join(tmp, "node.log")

    procs = Procs()
    master = Master(uri)
    results = []  # (name, failure message or None, seconds)
    ctx = {}

    def check(name, fn):
        t0 = time.monotonic()
        if any(f for _, f, _ in results):
            results.append((name, "not run: an earlier check failed", 0.0))
            return
        try:
            fn()
            results.append((name, None, time.monotonic() - t0))
            print("[master_restart] ok   %s (%.1f s)" % (name, time.monotonic() - t0))
        except Exception as e:  # noqa: BLE001 - every failure becomes a test failure
            results.append((name, "%s\n%s" % (e, traceback.format_exc()), time.monotonic() - t0))
            print("[master_restart] FAIL %s: %s" % (name, e))

    def start_master(log):
        ctx["master"] = procs.start(["rosmaster", "--core", "-p", str(port)], os.path.join(tmp, log), env=env)
        wait_for(master.up, 15, "the master on port %d" % port)

    def start_node():
        start_master("master1.log")
        with open(a.scene) as f:
            scene = yaml.safe_load(f)
        master.call("setParam", "/riser_sim/scene", scene)
        master.call("setParam", "/riser_sim/rates", {"tension": 20.0, "state": 20.0, "diagnostics": 2.0})
        ctx["node"] = procs.start([a.node, "__name:=riser_sim"], node_log, env=node_env, cwd=node_cwd)
        wait_for(lambda: master.provides(0, "/riser_sim/tension", "/riser_sim"), 20, "the node's publishers")
        ctx["pub"] = pose_publisher(procs, 0.0, env, os.path.join(tmp, "pub1.log"))
        top = wait_for(lambda: echo_once("/riser_sim/tension/top", env), 20, "tension")
        assert abs(float(top) - 1471.5) < 1e-3, "static top tension %s, expected 1471.5 N" % top

    def listens_only_on_roscpp_ports():
        pid = ctx["node"].pid
        socks = sockets_of(pid)
        code, _, node_uri = master.call("lookupNode", "/riser_sim")
        xmlrpc_port = int(node_uri.rstrip("/").rsplit(":", 1)[1])
        code, _, srv_uri = master.call("lookupService", "/riser_sim/reset")
        tcpros_port = int(srv_uri.rsplit(":", 1)[1])
        print("[master_restart] node sockets: %s (XML-RPC %s, TCPROS %d)" % (socks, node_uri, tcpros_port))
        tcp = sorted(s for s in socks if s[0].startswith("tcp"))
        udp = [s for s in socks if s[0].startswith("udp")]
        assert sorted(p for _, _, p in tcp) == sorted([xmlrpc_port, tcpros_port]), "TCP listeners %s" % tcp
        assert len(udp) == 1, "UDP sockets %s (expected roscpp's UDPROS only)" % udp
        tcpros = [s for s in tcp if s[2] == tcpros_port][0]
        assert tcpros[1] in ("127.0.0.1", "::1"), "TCPROS bound to %s, expected loopback" % tcpros[1]
        assert udp[0][1] in ("127.0.0.1", "::1"), "UDPROS bound to %s, expected loopback" % udp[0][1]
        assert node_uri.startswith("http://localhost:"), "advertised %s" % node_uri
        ctx["xmlrpc_bind"] = [s for s in tcp if s[2] == xmlrpc_port][0][1]

    def master_restart_reregisters():
        Procs.stop(ctx["pub"])
        Procs.stop(ctx["master"], signal.SIGTERM)
        wait_for(lambda: "unreachable" in open(node_log).read(), 10, "the node noticing the master is gone")
        assert ctx["node"].poll() is None, "the node exited when the master went away"
        start_master("master2.log")
        wait_for(lambda: master.provides(0, "/riser_sim/tension", "/riser_sim"), 15, "tension re-registered")
        for kind, name in ((0, "/riser_sim/state"), (0, "/diagnostics"), (0, "/rosout"), (1, "/vessel/pose"),
                           (2, "/riser_sim/reset"), (2, "/riser_sim/modes")):
            assert master.provides(kind, name, "/riser_sim"), "%s not registered again" % name
        assert "registered again" in open(node_log).read()

    def new_subscriber_gets_tension():
        top = wait_for(lambda: echo_once("/riser_sim/tension/top", env), 20, "tension after the restart")
        assert abs(float(top) - 1471.5) < 1e-3, top

    def new_publisher_moves_the_top():
        ctx["pub"] = pose_publisher(procs, 3.0, env, os.path.join(tmp, "pub2.log"))
        wait_for(lambda: abs(float(echo_once("/riser_sim/state/points[0]/x", env) or "nan") - 3.0) < 1e-3, 30,
                 "the top at the new vessel x = 3 m")

    def modes_service_answers():
        r = subprocess.run(["rosservice", "call", "/riser_sim/modes", "2"], env=env, capture_output=True, text=True,
                           timeout=30)
        assert r.returncode == 0 and "success: True" in r.stdout, r.stdout + r.stderr

    def parameters_are_lost():
        code, _, _ = master.call("getParam", "/riser_sim/scene")
        assert code != 1, "the new master has the old ~scene"
        assert ctx["node"].poll() is None

    def launch_binds_to_loopback():
        launch_home = os.path.join(tmp, "launch_home")
        launched = procs.start(["roslaunch", "riser_sim", "riser_sim.launch", "scene:=" + a.scene,
                                "name:=launched", "output:=log"], os.path.join(tmp, "roslaunch.log"),
                               env=dict(env, ROS_HOME=launch_home, ROS_LOG_DIR=os.path.join(launch_home, "log")))
        pid = wait_for(lambda: master.node_pid("/launched"), 30, "the launched node")
        srv_uri = wait_for(lambda: master.call("lookupService", "/launched/reset")[2], 15, "/launched/reset")
        tcpros_port = int(srv_uri.rsplit(":", 1)[1])
        tcp = [s for s in sockets_of(pid) if s[0].startswith("tcp") and s[2] == tcpros_port]
        print("[master_restart] launched node: TCPROS %s, service URI %s" % (tcp, srv_uri))
        assert tcp and tcp[0][1] in ("127.0.0.1", "::1"), "TCPROS of the launched node on %s" % tcp
        assert srv_uri.startswith("rosrpc://localhost:"), srv_uri
        Procs.stop(launched)

    def writes_no_files():
        Procs.stop(ctx["node"])
        assert ctx["node"].returncode == 0, "exit code %s" % ctx["node"].returncode
        written = files_under(node_home) + files_under(node_cwd)
        assert not written, "the node wrote %s" % written

    try:
        check("node_starts_on_private_master", start_node)
        check("listens_only_on_roscpp_ports_tcpros_on_loopback", listens_only_on_roscpp_ports)
        check("master_restart_reregisters_publishers_subscribers_services", master_restart_reregisters)
        check("new_subscriber_gets_tension_after_restart", new_subscriber_gets_tension)
        check("new_vessel_publisher_moves_the_top_after_restart", new_publisher_moves_the_top)
        check("modes_service_answers_after_restart", modes_service_answers)
        check("parameters_are_lost_with_the_master", parameters_are_lost)
        check("launch_file_binds_tcpros_to_loopback", launch_binds_to_loopback)
        check("node_writes_no_files", writes_no_files)
    finally:
        procs.stop_all()
    if "xmlrpc_bind" in ctx:
        print("[master_restart] the node's XML-RPC server listens on %s (xmlrpcpp binds every interface)"
              % ctx["xmlrpc_bind"])

    write_junit("master_restart", results, a.xml)
    failed = [n for n, f, _ in results if f]
    if failed or a.keep:
        print("[master_restart] logs kept in %s" % tmp)
    else:
        subprocess.run(["rm", "-rf", tmp])
    print("[master_restart] %d passed, %d failed" % (len(results) - len(failed), len(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
