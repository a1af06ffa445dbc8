#!/usr/bin/env python3
"""Battery monitor: warns the driver when the battery runs low."""

import actionlib
import rospy
from demo_robot.msg import DockAction, DockGoal
from std_msgs.msg import Float32
from std_srvs.srv import Empty

LOW_TOPIC = "battery/low"


class BatteryMonitor:
    def __init__(self):
        self.threshold = rospy.get_param("~threshold", 0.2)
        self.low_pub = rospy.Publisher(LOW_TOPIC, Float32, queue_size=1, latch=True)
        self.level_sub = rospy.Subscriber("battery/level", Float32, self.on_level)
        self.reset = rospy.ServiceProxy("driver/reset", Empty)
        self.dock = actionlib.SimpleActionClient("dock", DockAction)

    def on_level(self, msg):
        if msg.data < self.threshold:
            self.low_pub.publish(msg)
            self.dock.send_goal(DockGoal(station="home"))


if __name__ == "__main__":
    rospy.init_node("battery_monitor")
    BatteryMonitor()
    rospy.spin()
