#!/usr/bin/python3
"""Scripted vessel motion: publishes vessel/pose (geometry_msgs/PoseStamped) for riser_sim_node.

Position of the vessel reference point in the world frame (z up), t [s] of ROS time since start:
  p(t) = origin + e(t) * [surge(t), sway(t), heave(t)] + transit(t) + noise
  surge(t) = surge/amplitude * cos(2 pi t / surge/period + surge/phase)   (paper: x_0 = 10 cos(2 pi t / 27))
  sway(t), heave(t): the same form with their own parameters (sway defaults to 0: the planar demo)
  e(t)     = envelope: rises 0 -> 1 over fade_in and, with duration > 0, falls back to 0 over the last
             fade_out seconds, along u^3 (10 - 15 u + 6 u^2): position, velocity and acceleration stay
             continuous (the riser's top acceleration enters its equations of motion)
  transit  = displacement at transit/velocity [vx, vy, vz] over [transit/start, transit/start +
             transit/duration]; the speed ramps up and down over transit/ramp_time along a smoothstep,
             so the acceleration stays continuous too
Attitude: yaw, pitch, roll [deg] (z-y-x Euler angles: q = Rz(yaw) Ry(pitch) Rx(roll)), each
  e(t) * amplitude * cos(2 pi t / period + phase), yaw also plus yaw/rate [deg/s] * t (a slow turn).
Camera (optional, ~camera/frame non-empty): a tf frame (parent frame_id) at camera/center turned about z by
camera/yaw0 + 360 t / camera/period [deg], for rviz's ThirdPersonFollower view (rviz/riser_3d.rviz) to orbit.
Jitter (optional): jitter/position [m] Gaussian noise per axis, jitter/timing [0..1) relative spread of the
publish period, jitter/seed.
Also publishes vessel/markers (visualization_msgs/MarkerArray: hull box, with ~backdrop a sea backdrop
behind the x-z plane for the planar side view) at ~marker_rate.
With ~wait_for (a topic name, any type) it publishes the rest pose (t = 0) until a first message arrives
there, e.g. the riser node's tension, so the motion starts only once the node is running from rest.
Uses ROS time throughout, so it follows /clock under /use_sim_time. With ~duration > 0 it exits after that
many seconds of motion (mark it required in a launch file to end the whole launch).
"""
import math
import random

import rospy
from geometry_msgs.msg import PoseStamped, TransformStamped
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import Marker, MarkerArray


def _param(name, default, check=None, what=""):
    value = rospy.get_param("~" + name, default)
    try:
        if isinstance(default, list):
            value = [float(v) for v in value]
            if len(value) != len(default):
                raise ValueError
        elif isinstance(default, bool):
            value = bool(value)
        elif isinstance(default, (int, float)):
            value = float(value)
    except (TypeError, ValueError):
        raise ValueError("~%s: expected %s, got %r" % (name, type(default).__name__ + (
            "[%d]" % len(default) if isinstance(default, list) else ""), value))
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError("~%s: must be finite, got %r" % (name, value))
    if check is not None and not check(value):
        raise ValueError("~%s: %s, got %r" % (name, what, value))
    return value


class Oscillation(object):
    """a cos(2 pi t / period + phase) and its derivative."""

    def __init__(self, prefix, amplitude, period):
        self.amplitude = _param(prefix + "/amplitude", amplitude)
        self.period = _param(prefix + "/period", period, lambda v: v > 0, "must be > 0")
        self.phase = _param(prefix + "/phase", 0.0)

    def at(self, t):
        return self.amplitude * math.cos(2.0 * math.pi * t / self.period + self.phase)


def smootherstep(u):
    """0 -> 1 for u in [0, 1] with zero first and second derivatives at both ends."""
    u = min(max(u, 0.0), 1.0)
    return u * u * u * (10.0 + u * (-15.0 + 6.0 * u))


def quaternion_zyx(yaw, pitch, roll):
    """(x, y, z, w) of Rz(yaw) Ry(pitch) Rx(roll) [rad]."""
    cy, sy = math.cos(0.5 * yaw), math.sin(0.5 * yaw)
    cp, sp = math.cos(0.5 * pitch), math.sin(0.5 * pitch)
    cr, sr = math.cos(0.5 * roll), math.sin(0.5 * roll)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


class Transit(object):
    """Displacement of a smoothly ramped constant-velocity window (exact integral)."""

    def __init__(self):
        self.velocity = _param("transit/velocity", [0.0, 0.0, 0.0])
        self.start = _param("transit/start", 0.0)
        self.duration = _param("transit/duration", 0.0, lambda v: v >= 0, "must be >= 0")
        self.ramp = _param("transit/ramp_time", 2.0, lambda v: v >= 0, "must be >= 0")
        self.ramp = min(self.ramp, 0.5 * self.duration)

    def _distance(self, t):
        """Distance covered at unit cruise speed after time t since the start of the window. The speed
        follows 3u^2 - 2u^3 over each ramp (u = time into the ramp / ramp_time), whose integral is
        r (u^3 - u^4 / 2), r / 2 over a whole ramp."""
        T, r = self.duration, self.ramp
        t = min(max(t, 0.0), T)
        if r <= 0.0:
            return t
        ramp = lambda u: r * (u ** 3 - 0.5 * u ** 4)
        if t <= r:  # speeding up
            return ramp(t / r)
        if t <= T - r:  # cruising
            return 0.5 * r + (t - r)
        return (T - r) - ramp((T - t) / r)  # slowing down: the whole window minus what is left

    def at(self, t):
        s = self._distance(t - self.start)
        return [v * s for v in self.velocity]


class VesselMotion(object):
    def __init__(self):
        self.rate = _param("rate", 50.0, lambda v: v > 0, "must be > 0")
        self.frame_id = rospy.get_param("~frame_id", "world")
        self.origin = _param("origin", [0.0, 0.0, 0.0])
        self.fade_in = _param("fade_in", 5.0, lambda v: v >= 0, "must be >= 0")
        self.duration = _param("duration", 0.0, lambda v: v >= 0, "must be >= 0 (0 = run forever)")
        self.wait_for = rospy.get_param("~wait_for", "")
        self.fade_out = _param("fade_out", 0.0, lambda v: v >= 0, "must be >= 0 (used when duration > 0)")
        self.surge = Oscillation("surge", 10.0, 27.0)
        self.sway = Oscillation("sway", 0.0, 27.0)
        self.heave = Oscillation("heave", 0.0, 10.0)
        self.yaw = Oscillation("yaw", 0.0, 60.0)
        self.yaw_rate = _param("yaw/rate", 0.0)
        self.pitch = Oscillation("pitch", 0.0, 10.0)
        self.roll = Oscillation("roll", 0.0, 10.0)
        self.backdrop = _param("backdrop", True)
        self.camera_frame = rospy.get_param("~camera/frame", "")
        self.camera_center = _param("camera/center", [0.0, 0.0, 0.0])
        self.camera_period = _param("camera/period", 60.0, lambda v: v > 0, "must be > 0")
        self.camera_yaw0 = _param("camera/yaw0", 0.0)
        self.tf_pub = rospy.Publisher("/tf", TFMessage, queue_size=10) if self.camera_frame else None
        self.transit = Transit()
        self.jitter_position = _param("jitter/position", 0.0, lambda v: v >= 0, "must be >= 0")
        self.jitter_timing = _param("jitter/timing", 0.0, lambda v: 0 <= v < 1, "must be in [0, 1)")
        self.rng = random.Random(int(rospy.get_param("~jitter/seed", 1)))
        self.marker_rate = _param("marker_rate", 10.0, lambda v: v >= 0, "must be >= 0 (0 = no markers)")
        self.pub = rospy.Publisher("vessel/pose", PoseStamped, queue_size=10)
        self.marker_pub = rospy.Publisher("vessel/markers", MarkerArray, queue_size=2, latch=True) \
            if self.marker_rate > 0 else None

    def envelope(self, t):
        e = 1.0
        if self.fade_in > 0.0:
            e *= smootherstep(t / self.fade_in)
        if self.duration > 0.0 and self.fade_out > 0.0:
            e *= smootherstep((self.duration - t) / self.fade_out)
        return e

    def pose(self, t):
        """(x, y, z, yaw, pitch, roll [rad]) at time t since start, without jitter."""
        e = self.envelope(t)
        shift = self.transit.at(t)
        x = self.origin[0] + e * self.surge.at(t) + shift[0]
        y = self.origin[1] + e * self.sway.at(t) + shift[1]
        z = self.origin[2] + e * self.heave.at(t) + shift[2]
        yaw = e * self.yaw.at(t) + self.yaw_rate * self.turn(t)
        return x, y, z, math.radians(yaw), math.radians(e * self.pitch.at(t)), math.radians(e * self.roll.at(t))

    def turn(self, t):
        """Time integral of the fade-in envelope: the turn at yaw/rate starts with zero acceleration."""
        if self.fade_in <= 0.0:
            return t
        u = min(t / self.fade_in, 1.0)  # integral of u^3 (10 - 15 u + 6 u^2) du: u^4 (5/2 - 3 u + u^2)
        return self.fade_in * u ** 4 * (2.5 - 3.0 * u + u * u) + max(t - self.fade_in, 0.0)

    def message(self, stamp, t):
        x, y, z, yaw, pitch, roll = self.pose(t)
        if self.jitter_position > 0.0:
            x += self.rng.gauss(0.0, self.jitter_position)
            y += self.rng.gauss(0.0, self.jitter_position)
            z += self.rng.gauss(0.0, self.jitter_position)
        msg = PoseStamped()
        msg.header.stamp = stamp
        msg.header.frame_id = self.frame_id
        msg.pose.position.x, msg.pose.position.y, msg.pose.position.z = x, y, z
        q = msg.pose.orientation
        q.x, q.y, q.z, q.w = quaternion_zyx(yaw, pitch, roll)
        return msg

    def camera(self, stamp, t):
        """world -> camera/frame: at camera/center, turned about z by the orbit angle."""
        tr = TransformStamped()
        tr.header.stamp = stamp
        tr.header.frame_id = self.frame_id
        tr.child_frame_id = self.camera_frame
        tr.transform.translation.x, tr.transform.translation.y, tr.transform.translation.z = self.camera_center
        a = math.radians(self.camera_yaw0) + 2.0 * math.pi * t / self.camera_period
        tr.transform.rotation.z, tr.transform.rotation.w = math.sin(0.5 * a), math.cos(0.5 * a)
        return TFMessage(transforms=[tr])

    def markers(self, pose_msg):
        """Hull (a box around the hang-off point) and a translucent sea behind the x-z plane."""
        hull = Marker()
        hull.header = pose_msg.header
        hull.ns, hull.id, hull.type, hull.action = "vessel", 0, Marker.CUBE, Marker.ADD
        hull.pose.orientation = pose_msg.pose.orientation
        hull.pose.position.x = pose_msg.pose.position.x
        hull.pose.position.y = pose_msg.pose.position.y
        hull.pose.position.z = pose_msg.pose.position.z - 0.5  # 4 m draft, 3 m freeboard
        hull.scale.x, hull.scale.y, hull.scale.z = 40.0, 12.0, 7.0
        hull.color.r, hull.color.g, hull.color.b, hull.color.a = 0.75, 0.75, 0.78, 0.85
        sea = Marker()
        sea.header = pose_msg.header
        sea.ns, sea.id, sea.type, sea.action = "sea", 0, Marker.CUBE, Marker.ADD
        sea.pose.orientation.w = 1.0
        sea.pose.position.x = self.origin[0]
        sea.pose.position.y = self.origin[1] + 10.0  # behind the riser plane seen from -y
        sea.pose.position.z = self.origin[2] - 150.0
        sea.scale.x, sea.scale.y, sea.scale.z = 1000.0, 1.0, 300.0
        sea.color.r, sea.color.g, sea.color.b, sea.color.a = 0.05, 0.3, 0.55, 0.5
        return MarkerArray(markers=[hull, sea] if self.backdrop else [hull])

    def next_period(self):
        period = 1.0 / self.rate
        if self.jitter_timing > 0.0:
            period *= 1.0 + self.jitter_timing * self.rng.uniform(-1.0, 1.0)
        return rospy.Duration.from_sec(period)

    def wait_for_topic(self):
        """Publishes the rest pose until a message arrives on ~wait_for."""
        got = []
        sub = rospy.Subscriber(self.wait_for, rospy.AnyMsg, lambda _: got.append(True), queue_size=1)
        rospy.loginfo("vessel_motion: holding still until %s publishes", sub.resolved_name)
        last_info = rospy.Time.now()
        while not got and not rospy.is_shutdown():
            now = rospy.Time.now()
            self.pub.publish(self.message(now, 0.0))
            if self.tf_pub is not None:
                self.tf_pub.publish(self.camera(now, 0.0))
            if self.marker_pub is not None:
                self.marker_pub.publish(self.markers(self.message(now, 0.0)))
            if (now - last_info).to_sec() > 10.0:
                rospy.logwarn("vessel_motion: still waiting for %s", sub.resolved_name)
                last_info = now
            rospy.sleep(1.0 / self.rate)
        sub.unregister()

    def run(self):
        # Under /use_sim_time the clock reads 0 until /clock arrives: wait for a real time base.
        while not rospy.is_shutdown() and rospy.Time.now().is_zero():
            rospy.sleep(0.01)
        if self.wait_for:
            self.wait_for_topic()
        start = rospy.Time.now()
        rospy.loginfo("vessel_motion: surge %.2f m / %.1f s, sway %.2f m / %.1f s, heave %.2f m / %.1f s, "
                      "yaw %.1f deg + %.2f deg/s, pitch %.2f deg, roll %.2f deg, "
                      "transit %s m/s for %.1f s from t=%.1f s, %.0f Hz%s",
                      self.surge.amplitude, self.surge.period, self.sway.amplitude, self.sway.period,
                      self.heave.amplitude, self.heave.period, self.yaw.amplitude, self.yaw_rate,
                      self.pitch.amplitude, self.roll.amplitude, self.transit.velocity, self.transit.duration,
                      self.transit.start, self.rate,
                      ", duration %.1f s" % self.duration if self.duration > 0 else "")
        wake = start
        last_marker = None
        while not rospy.is_shutdown():
            now = rospy.Time.now()
            t = (now - start).to_sec()
            if self.duration > 0.0 and t >= self.duration:
                rospy.loginfo("vessel_motion: %.1f s done", t)
                break
            msg = self.message(now, t)
            self.pub.publish(msg)
            if self.tf_pub is not None:
                self.tf_pub.publish(self.camera(now, t))
            if self.marker_pub is not None and (last_marker is None or
                                                (now - last_marker).to_sec() >= 1.0 / self.marker_rate):
                self.marker_pub.publish(self.markers(msg))
                last_marker = now
            wake = max(wake + self.next_period(), now)
            try:
                rospy.sleep(wake - rospy.Time.now())
            except rospy.ROSInterruptException:
                break
            except rospy.ROSTimeMovedBackwardsException:  # sim clock restarted (e.g. bag loop)
                start = wake = rospy.Time.now()


def main():
    rospy.init_node("vessel_motion")
    try:
        node = VesselMotion()
    except ValueError as e:
        rospy.logfatal("vessel_motion: %s", e)
        raise SystemExit(2)
    node.run()


if __name__ == "__main__":
    main()
