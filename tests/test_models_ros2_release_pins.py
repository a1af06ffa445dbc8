"""ROS 2 models pinned away from the release their distribution ships are rebuilt at it.

Jazzy's distribution.yaml releases rosbridge_suite 2.7.1 and humble's 2.0.8, both of which
declare ``default_call_service_timeout``; the one shipped model was of 2.1.0 (the newest
tag the upstream mirror has), which does not, and PoliTOcean/nereo_ros2_code's humble
launch file that sets it got a false parameter-set-not-read. They come from the release
repository's ``upstream/`` tags now, and humble has its own. The others were of commits
after the release: jazzy ublox 2.3.0 publishes ``fix`` and ``navpvt`` on the node's
namespace, not ``~/fix``; jazzy usb_cam 0.8.1 declares no ``skip_device_check``; jazzy
ouster_ros 0.14.1 no sync pulse or NMEA settings; humble navigation2 1.1.20's goal checkers
and MPPI's goal angle critic no ``symmetric_yaw_tolerance``. And some were of commits before
it, which lack what the release reads: humble slam_toolbox 2.6.10's ``min_laser_range``,
humble robot_localization 3.5.4's ``stamped_control``, jazzy teleop_twist_keyboard 2.4.1's
``stamped`` (a launch file setting it got parameter-set-not-read), teleop_twist_joy 2.6.5's
``publish_stamped_twist``, interactive_marker_twist_server 2.1.1's ``use_stamped_msgs``;
jazzy openni2_camera 2.2.2 publishes ``depth_raw/image``, not ``depth/image_raw``."""

from __future__ import annotations

import pytest
from conftest import package_xml, unread_parameters

from haros_arch.models.library import Library

LAUNCH = """\
<launch>
  <node pkg="rosbridge_server" exec="rosbridge_websocket" name="rosbridge_websocket">
    <param name="port" value="9090"/>
    <param name="default_call_service_timeout" value="5.0"/>
    <param name="not_a_rosbridge_parameter" value="1"/>
  </node>
</launch>
"""


@pytest.mark.parametrize("distro", ["humble", "jazzy"])
def test_rosbridge_of_the_release_reads_its_service_call_timeout(write_tree, distro):
    root = write_tree({
        "src/web/package.xml": package_xml("web", "ament_cmake"),
        "src/web/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(web)\n",
        "src/web/launch/web.launch.xml": LAUNCH,
        "project.yaml": f"project: p\ndistro: {distro}\nconfigurations:\n"
                        "  c: [web/launch/web.launch.xml]\n",
    })
    unread = unread_parameters(root)
    assert unread == ["/rosbridge_websocket/not_a_rosbridge_parameter"]


def _calls(package: str, distro: str, executable: str) -> set[tuple[str, str]]:
    model = Library().find(package, distro)
    assert model is not None
    assert model.distro == distro
    (node,) = [n for n in model.nodes if n.executable == executable]
    return {(c.kind, c.name) for c in node.calls}


@pytest.mark.parametrize(("package", "distro", "executable", "present", "absent"), [
    ("ublox_gps", "jazzy", "ublox_gps_node", [("publish", "fix"), ("publish", "navpvt")],
     [("publish", "~fix"), ("publish", "nmea"), ("read", "publish.nmea")]),
    ("usb_cam", "jazzy", "usb_cam_node_exe", [("declare", "video_device")],
     [("declare", "skip_device_check")]),
    ("ouster_ros", "jazzy", "os_driver", [("declare", "sensor_hostname")],
     [("declare", "sync_pulse_out_angle"), ("declare", "columns_per_packet")]),
    ("nav2_controller", "humble", "nav2_controller::SimpleGoalChecker",
     [("read", "?.xy_goal_tolerance")], [("read", "?.symmetric_yaw_tolerance")]),
    # pins before the release, rebuilt from the release repository's upstream/ tag
    ("slam_toolbox", "humble", "async_slam_toolbox_node",
     [("declare", "min_laser_range"), ("declare", "occupancy_threshold")], []),
    ("robot_localization", "humble", "ekf_node", [("declare", "stamped_control")], []),
    ("teleop_twist_keyboard", "jazzy", "teleop_twist_keyboard",
     [("declare", "stamped"), ("declare", "frame_id")], []),
    ("teleop_twist_joy", "jazzy", "teleop_node", [("declare", "publish_stamped_twist")], []),
    ("interactive_marker_twist_server", "jazzy", "marker_server",
     [("read", "use_stamped_msgs")], []),
    ("openni2_camera", "jazzy", "openni2_camera_driver", [("publish", "depth_raw/image")],
     [("publish", "depth/image_raw")]),
])
def test_the_ros2_release_models_offer_what_the_release_does(package, distro, executable,
                                                            present, absent):
    calls = _calls(package, distro, executable)
    for call in present:
        assert call in calls, call
    for call in absent:
        assert call not in calls, call
