"""A ROS 1 <node> named with a character a ROS name may not hold: roslaunch warns
("illegal <node> name"), roscpp's ros::init throws InvalidNameException, rospy warns.
cob_bringup's pc_monitor.launch names a monitor ``$(anon net_monitor)_$(arg pc)``, and
the robots' host names hold dashes (``cob4-10-b1``): nothing said it, and
parameter-name-illegal reported its legal private keys instead."""

from __future__ import annotations

from test_launch_ros1 import load_launch


def test_an_illegal_node_name_is_said_where_it_is_written(write_tree):
    model = load_launch(write_tree, """<launch>
          <arg name="pc" default="cob4-10-b1"/>
          <node pkg="mon" type="net_monitor.py" name="$(anon net_monitor)_$(arg pc)"/>
          <node pkg="mon" type="cpu_monitor.py" name="cpu_monitor_b1"/>
          <node pkg="mon" type="hd_monitor.py" name="$(anon hd_monitor)"/>
        </launch>""")
    said = [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_NODE_NAME_ILLEGAL"]
    assert len(said) == 1 and said[0][0] == 3
    assert said[0][1].startswith("node name net_monitor_")
    assert "_cob4-10-b1 is not a legal ROS name" in said[0][1]
    # the node is still started, as roslaunch starts it
    assert len(model.nodes) == 3
