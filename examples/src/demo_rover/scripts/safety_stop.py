#!/usr/bin/env python3
"""Stops the rover when the filtered scan sees something too close."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import LaserScan


class SafetyStop(Node):
    def __init__(self):
        super().__init__("safety_stop")
        self.stop_distance = self.declare_parameter("stop_distance", 0.3).value
        # BUG for the demo: a reliable subscriber never hears a best-effort publisher
        reliable = QoSProfile(depth=5, reliability=ReliabilityPolicy.RELIABLE)
        self.create_subscription(LaserScan, "scan_filtered", self.on_scan, reliable)
        self.cmd = self.create_publisher(Twist, "cmd_vel", 10)

    def on_scan(self, scan):
        if min(scan.ranges) < self.stop_distance:
            self.cmd.publish(Twist())


def main():
    rclpy.init()
    rclpy.spin(SafetyStop())


if __name__ == "__main__":
    main()
