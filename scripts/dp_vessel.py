#!/usr/bin/python3
"""A dynamically positioned vessel for launch/dp_station_keeping.launch: surge, sway and yaw of a rigid
body (mass ~mass, yaw inertia ~yaw_inertia, linear damping ~damping / ~yaw_damping) under the riser's pull
(~top_wrench, geometry_msgs/WrenchStamped in the world frame, applied at ~hangoff_offset) and a PD
station-keeping controller towards ~setpoint [x, y, yaw deg] (gains ~kp, ~kd, ~kp_yaw, ~kd_yaw).
Semi-implicit Euler at ~rate in ROS time; publishes vessel/pose (PoseStamped, ~frame_id, z = 0).
"""
import math

import rospy
from geometry_msgs.msg import PoseStamped, WrenchStamped


def _number(name, default, positive=False):
    v = rospy.get_param("~" + name, default)
    v = [float(x) for x in v] if isinstance(default, list) else float(v)
    for x in (v if isinstance(v, list) else [v]):
        if not math.isfinite(x) or (positive and x <= 0.0):
            raise ValueError("~%s: must be finite%s, got %r" % (name, " and > 0" if positive else "", v))
    return v


class DpVessel(object):
    def __init__(self):
        self.rate = _number("rate", 50.0, True)
        self.frame_id = rospy.get_param("~frame_id", "world")
        self.mass = _number("mass", 1.0e6, True)             # [kg]
        self.inertia = _number("yaw_inertia", 1.0e9, True)   # [kg m^2]
        self.damping = _number("damping", 5.0e4)             # [N s/m]
        self.yaw_damping = _number("yaw_damping", 5.0e7)     # [N m s/rad]
        self.kp, self.kd = _number("kp", 2.0e4), _number("kd", 2.2e5)
        self.kp_yaw, self.kd_yaw = _number("kp_yaw", 2.0e7), _number("kd_yaw", 2.2e8)
        sp = _number("setpoint", [0.0, 0.0, 0.0])
        self.setpoint = (sp[0], sp[1], math.radians(sp[2]))
        self.offset = _number("hangoff_offset", [0.0, 0.0, 0.0])
        self.x, self.y, self.psi = self.setpoint
        self.u = self.v = self.r = 0.0
        self.force = (0.0, 0.0)
        self.pub = rospy.Publisher("vessel/pose", PoseStamped, queue_size=10)
        self.sub = rospy.Subscriber("riser_sim/top_wrench", WrenchStamped, self.on_wrench, queue_size=5)

    def on_wrench(self, m):
        f = m.wrench.force
        if math.isfinite(f.x) and math.isfinite(f.y):
            self.force = (f.x, f.y)

    def step(self, dt):
        fx, fy = self.force
        c, s = math.cos(self.psi), math.sin(self.psi)
        rx, ry = c * self.offset[0] - s * self.offset[1], s * self.offset[0] + c * self.offset[1]
        mz = rx * fy - ry * fx  # the riser's yaw moment about the vessel's origin
        ex, ey = self.x - self.setpoint[0], self.y - self.setpoint[1]
        epsi = math.atan2(math.sin(self.psi - self.setpoint[2]), math.cos(self.psi - self.setpoint[2]))
        ax = (fx - self.kp * ex - (self.kd + self.damping) * self.u) / self.mass
        ay = (fy - self.kp * ey - (self.kd + self.damping) * self.v) / self.mass
        ar = (mz - self.kp_yaw * epsi - (self.kd_yaw + self.yaw_damping) * self.r) / self.inertia
        self.u += ax * dt
        self.v += ay * dt
        self.r += ar * dt
        self.x += self.u * dt
        self.y += self.v * dt
        self.psi += self.r * dt

    def publish(self, stamp):
        m = PoseStamped()
        m.header.stamp = stamp
        m.header.frame_id = self.frame_id
        m.pose.position.x, m.pose.position.y = self.x, self.y
        m.pose.orientation.w = math.cos(0.5 * self.psi)
        m.pose.orientation.z = math.sin(0.5 * self.psi)
        self.pub.publish(m)

    def run(self):
        rate = rospy.Rate(self.rate)
        last = rospy.Time.now()
        while not rospy.is_shutdown():
            now = rospy.Time.now()
            dt = min((now - last).to_sec(), 0.1)  # a stalled clock: no catch-up jump
            last = now
            if dt > 0.0:
                self.step(dt)
                self.publish(now)
            rate.sleep()


def main():
    rospy.init_node("dp_vessel")
    try:
        node = DpVessel()
    except ValueError as e:
        rospy.logfatal("dp_vessel: %s", e)
        raise SystemExit(2)
    try:
        node.run()
    except rospy.ROSInterruptException:
        pass


if __name__ == "__main__":
    main()
