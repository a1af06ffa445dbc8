"""A ROS 2 XML ``<node>`` without ``exec=`` is skipped, as LAUNCH_MISSING_ATTRIBUTE says:
utra-robosoccer's soccerbot, soccer_firmware_interface/launch/sensors_2.launch:17-42,
half ported from ROS 1, keeps four ``<node pkg=... type=...>``. launch_ros' Node.parse
asks for ``exec`` (``get_attr('exec')``) and ros2 launch stops. Each element was kept as
a node of type ``pkg/?``, which then drew a NODE_TYPE_UNKNOWN and a MODEL_NODE_MISSING
warning, a node in the graph and a dependency the launch file never reaches. The
attributes ros2 launch refuses (ROS 1's ``type=``) are still reported: they say why."""

from __future__ import annotations

from test_launch_ros2 import run


def test_a_node_without_exec_is_skipped(write_tree) -> None:
    model, _ = run(write_tree, "sensors.launch", """
        <launch>
          <node pkg="usb_cam" type="usb_cam_node" name="camera" output="screen">
            <param name="video_device" value="/dev/video4"/>
          </node>
          <node pkg="pkg" exec="firmware" name="firmware"/>
        </launch>
        """)
    assert [n.name for n in model.nodes] == ["/firmware"]
    assert sorted((d.code, d.location.line) for d in model.diagnostics) == [
        ("LAUNCH_MISSING_ATTRIBUTE", 2), ("LAUNCH_UNEXPECTED_ATTRIBUTE", 2)]
    assert not [p for p in model.params if p.name.startswith("/camera")]


def test_a_node_with_exec_is_kept(write_tree) -> None:
    # (guard) the element as ROS 2 writes it, with its parameter
    model, _ = run(write_tree, "sensors.launch.xml", """
        <launch>
          <node pkg="usb_cam" exec="usb_cam_node_exe" name="camera">
            <param name="video_device" value="/dev/video4"/>
          </node>
        </launch>
        """)
    assert [n.name for n in model.nodes] == ["/camera"]
    assert [(p.name, p.value) for p in model.params] == [("/camera/video_device",
                                                          "/dev/video4")]
    assert model.diagnostics == []
