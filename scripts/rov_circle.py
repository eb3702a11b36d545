#!/usr/bin/python3
"""Scripted vessel and ROV for launch/rov_tether.launch: publishes vessel/pose and rov/pose
(geometry_msgs/PoseStamped, ~frame_id, ROS time) at ~rate.

t [s] of ROS time since the start, g(t) the ramped time (speed 0 -> 1 along 3u^2 - 2u^3 over ~ramp, so
positions, velocities and accelerations stay continuous):
  vessel:  xy = ~vessel/drift [vx, vy] * g(t), z = 0; yaw = ~vessel/yaw_amplitude [deg] * e(t) *
           sin(2 pi t / ~vessel/yaw_period), e = smoothstep(t / ramp)
  ROV:     circles the vessel at ~rov/radius, depth ~rov/depth, angle theta = 2 pi g(t) / ~rov/period
           (counter-clockwise seen from above), heading along its path (yaw = theta + 90 deg)
With ~wait_for (a topic name) it publishes the poses at t = 0 until a message arrives there (the riser
node's tension), so the motion starts once the node runs from rest.
"""
import math

import rospy
from geometry_msgs.msg import PoseStamped


def _number(name, default):
    v = rospy.get_param("~" + name, default)
    if isinstance(default, list):
        v = [float(x) for x in v]
        if len(v) != len(default) or not all(math.isfinite(x) for x in v):
            raise ValueError("~%s: expected %d finite numbers, got %r" % (name, len(default), v))
        return v
    v = float(v)
    if not math.isfinite(v):
        raise ValueError("~%s: must be finite, got %r" % (name, v))
    return v


class RovCircle(object):
    def __init__(self):
        self.rate = _number("rate", 20.0)
        self.frame_id = rospy.get_param("~frame_id", "world")
        self.ramp = _number("ramp", 10.0)
        self.drift = _number("vessel/drift", [0.2, 0.0])
        self.yaw_amplitude = math.radians(_number("vessel/yaw_amplitude", 10.0))
        self.yaw_period = _number("vessel/yaw_period", 60.0)
        self.radius = _number("rov/radius", 25.0)
        self.depth = _number("rov/depth", 30.0)
        self.period = _number("rov/period", 180.0)
        for name, v in (("rate", self.rate), ("vessel/yaw_period", self.yaw_period), ("rov/period", self.period)):
            if v <= 0.0:
                raise ValueError("~%s: must be > 0, got %r" % (name, v))
        if self.ramp < 0.0:
            raise ValueError("~ramp: must be >= 0, got %r" % self.ramp)
        self.wait_for = rospy.get_param("~wait_for", "")
        self.vessel_pub = rospy.Publisher("vessel/pose", PoseStamped, queue_size=10)
        self.rov_pub = rospy.Publisher("rov/pose", PoseStamped, queue_size=10)

    def ramped(self, t):
        """Integral of the speed ramp: r (u^3 - u^4 / 2) over the ramp, then r / 2 + (t - r)."""
        t = max(t, 0.0)
        r = self.ramp
        if r <= 0.0:
            return t
        if t <= r:
            u = t / r
            return r * (u ** 3 - 0.5 * u ** 4)
        return 0.5 * r + (t - r)

    def poses(self, t):
        """((x, y, z, yaw) of the vessel, (x, y, z, yaw) of the ROV) at t."""
        g = self.ramped(t)
        u = min(max(t / self.ramp, 0.0), 1.0) if self.ramp > 0.0 else 1.0
        e = u * u * (3.0 - 2.0 * u)
        vx, vy = self.drift[0] * g, self.drift[1] * g
        vyaw = self.yaw_amplitude * e * math.sin(2.0 * math.pi * t / self.yaw_period)
        theta = 2.0 * math.pi * g / self.period
        rov = (vx + self.radius * math.cos(theta), vy + self.radius * math.sin(theta), -self.depth,
               theta + 0.5 * math.pi)
        return (vx, vy, 0.0, vyaw), rov

    def message(self, stamp, pose):
        m = PoseStamped()
        m.header.stamp = stamp
        m.header.frame_id = self.frame_id
        m.pose.position.x, m.pose.position.y, m.pose.position.z = pose[0], pose[1], pose[2]
        m.pose.orientation.w = math.cos(0.5 * pose[3])
        m.pose.orientation.z = math.sin(0.5 * pose[3])
        return m

    def publish(self, t):
        stamp = rospy.Time.now()
        vessel, rov = self.poses(t)
        self.vessel_pub.publish(self.message(stamp, vessel))
        self.rov_pub.publish(self.message(stamp, rov))

    def run(self):
        rate = rospy.Rate(self.rate)
        if self.wait_for:
            got = []
            sub = rospy.Subscriber(self.wait_for, rospy.AnyMsg, lambda _: got.append(True), queue_size=1)
            rospy.loginfo("rov_circle: holding still until %s publishes", sub.resolved_name)
            while not got and not rospy.is_shutdown():
                self.publish(0.0)
                rate.sleep()
            sub.unregister()
        start = rospy.Time.now()
        rospy.loginfo("rov_circle: vessel drift %s m/s, ROV radius %.1f m at %.1f m depth, %.0f s per turn",
                      self.drift, self.radius, self.depth, self.period)
        while not rospy.is_shutdown():
            self.publish((rospy.Time.now() - start).to_sec())
            rate.sleep()


def main():
    rospy.init_node("rov_circle")
    try:
        node = RovCircle()
    except ValueError as e:
        rospy.logfatal("rov_circle: %s", e)
        raise SystemExit(2)
    try:
        node.run()
    except rospy.ROSInterruptException:
        pass


if __name__ == "__main__":
    main()
