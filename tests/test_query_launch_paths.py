"""absolute-paths-in-launch on a real launch: $(find) paths are portable, others not."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

LAUNCH = """
<launch>
  <arg name="map" default="$(find nav)/maps/lab.yaml" />
  <node name="map_server" pkg="nav" type="map_server" args="$(arg map)" />
  <param name="map_file" value="$(find nav)/maps/lab.yaml" />
  <param name="calibration" value="/home/alice/calib/camera.yaml" />
</launch>
"""


def test_find_paths_are_not_hard_coded(write_tree):
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/map.launch": LAUNCH,
        "src/nav/maps/lab.yaml": "image: lab.pgm\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/map.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    for found in (run_rule(rule, model), run_rule(rule, reloaded)):
        assert [f.entities for f in found] == [("parameter:/calibration",)]
    assert model.configurations[0].package_paths == [str(root / "src")]


ENVIRONMENT_LAUNCH = """
<launch>
  <node name="map_saver" pkg="nav" type="map_saver" args="-f $(optenv HOME /home/summit)/map" />
  <param name="map_file" value="$(env ROBOT_MAP)" />
  <param name="config" value="$(optenv ROBOT_CONFIG /opt/robot)/config.yaml" />
  <param name="calibration" value="/home/alice/calib/camera.yaml" />
</launch>
"""


def test_environment_paths_are_not_hard_coded(write_tree):
    """A path the launch file takes from the environment ($(env), $(optenv) when the
    variable is set) follows the machine that runs it (summit_xl_localization's
    map_saver.launch: ``-f $(optenv HOME /home/summit)/map``); the default of an
    optenv whose variable is not set is the file's own, hard-coded."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/save.launch": ENVIRONMENT_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/save.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": "", "HOME": "/home/bob/", "ROBOT_MAP": "/srv/maps/lab.yaml"})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    for found in (run_rule(rule, model), run_rule(rule, reloaded)):
        assert sorted(f.entities for f in found) == [
            ("parameter:/calibration",), ("parameter:/config",)]
    assert model.configurations[0].package_paths == ["/home/bob", "/srv/maps/lab.yaml"]


ROS2_LAUNCH = """
<launch>
  <arg name="map_path" description="the map's folder"/>
  <arg name="data_path" default="$(env HOME)/robot_data"/>
  <node pkg="nav" exec="loader" name="loader">
    <param name="map_file" value="$(var map_path)/lanelet2_map.osm"/>
    <param name="model_path" value="$(var data_path)/models/net.onnx"/>
    <param name="socket" value="/opt/robot/reader.sock"/>
  </node>
</launch>
"""


def test_ros2_environment_and_given_arguments_are_not_hard_coded(write_tree):
    """A ROS 2 launch file's ``$(env HOME)`` follows the machine (Autoware's
    ``data_path``, ``$(env HOME)/autoware_data``), and a path the configuration gives a
    launch argument (``map_path:=/tmp/map``, as on the command line) is not one the
    launch file hard-codes; a path written in the file is."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav", "ament_cmake"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/map.launch.xml": ROS2_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c:\n"
                        "    launch: [nav/launch/map.launch.xml]\n"
                        "    args: {map_path: /srv/maps/town}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": "", "HOME": "/home/bob"})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    for found in (run_rule(rule, model), run_rule(rule, reloaded)):
        assert sorted(f.entities for f in found) == [("parameter:/loader/socket",)]


PYTHON_LAUNCH = """
import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    data = os.path.join(os.environ["HOME"], "robot_data")
    maps = os.getenv("ROBOT_MAPS", "/opt/maps")
    return LaunchDescription([Node(package="nav", executable="loader", name="loader",
                                   parameters=[{"model_path": data + "/net.onnx",
                                                "map_file": maps + "/town.yaml",
                                                "socket": "/opt/robot/reader.sock"}])])
"""


def test_ros2_python_environment_paths_are_not_hard_coded(write_tree):
    """A Python launch file's ``os.environ[...]`` / ``os.getenv(...)`` follow the
    machine; the default of a variable that is not set is the file's own."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav", "ament_cmake"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/map.launch.py": PYTHON_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/map.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": "", "HOME": "/home/bob"})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    found = sorted(f.entities for f in run_rule(rule, model))
    assert found == [("parameter:/loader/map_file",), ("parameter:/loader/socket",)]


MACOS_LAUNCH = """
<launch>
  <arg name="voxblox_file_path" default="/Users/helen/data/voxblox/const_0_05.vxblx" />
  <param name="map_file" value="$(arg voxblox_file_path)" />
  <param name="topic" value="/Users" />
</launch>
"""


def test_a_macos_home_folder_is_an_absolute_path(write_tree):
    """A macOS home, ``/Users/<name>/...``, is as much the author's machine as
    ``/home/<name>/...`` (voxblox's eval launch files: ``/Users/helen/data/...vxblx``
    and ``.ply`` files; survey Z47). ``/Users`` alone is no folder's content."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/eval.launch": MACOS_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/eval.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    assert [f.entities for f in run_rule(rule, model)] == [("parameter:/map_file",)]


WRITING_LAUNCH = """
import yaml
from launch import LaunchDescription
from launch_ros.actions import Node


def bridge_config(robot):
    path = f"/var/lib/robots/{robot}_bridge.yaml"
    with open(path, 'w') as out:
        yaml.dump([{'ros_topic_name': robot + '/scan'}], out)
    return path


def generate_launch_description():
    nodes = []
    for robot in ['tb1', 'tb3']:
        nodes.append(Node(package='nav', executable='bridge', name=robot + '_bridge',
                          parameters=[{'config_file': bridge_config(robot),
                                       'calibration': '/var/lib/calib/camera.yaml'}]))
    return LaunchDescription(nodes)
"""


def _hard_coded_bridges(write_tree, text: str) -> list[tuple[str, ...]]:  # type: ignore[no-untyped-def]
    """The entities of each absolute-paths-in-launch finding of ``text`` as a package's
    ``bridges.launch.py``."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav", "ament_cmake"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/bridges.launch.py": text,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/bridges.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    return sorted(f.entities for f in run_rule(rule, model))


def test_a_file_the_launch_file_writes_is_not_hard_coded(write_tree):
    """tb3_multi_robot's tb3_world.launch.py writes each robot's bridge configuration to
    ``/tmp/<robot>_bridge.yaml`` (``open(path, 'w')``, not run) and gives the bridge that
    path: a file made on the machine that runs the launch, not one of the author's
    (survey F). /tmp is a scratch folder anyway; here the file is written under /var. A
    path it only reads stays hard-coded."""
    assert _hard_coded_bridges(write_tree, WRITING_LAUNCH) == [
        ("parameter:/tb1_bridge/calibration",), ("parameter:/tb3_bridge/calibration",)]


def test_a_file_an_opaque_function_writes_is_not_hard_coded(write_tree):
    """The same bridge configurations written by a function launch runs later, an
    OpaqueFunction's (after the module was read): made on the machine that runs the
    launch too."""
    opaque = WRITING_LAUNCH.replace("def generate_launch_description():\n    nodes = []",
                                    "def setup(context):\n    nodes = []").replace(
        "    return LaunchDescription(nodes)",
        "    return nodes\n\n\ndef generate_launch_description():\n"
        "    return LaunchDescription([OpaqueFunction(function=setup)])").replace(
        "from launch import LaunchDescription",
        "from launch import LaunchDescription\nfrom launch.actions import OpaqueFunction")
    assert "OpaqueFunction(function=setup)" in opaque and "def setup(context):" in opaque
    assert _hard_coded_bridges(write_tree, opaque) == [
        ("parameter:/tb1_bridge/calibration",), ("parameter:/tb3_bridge/calibration",)]


TEXTFILE_LAUNCH = """<launch>
  <param name="robot_description" textfile="$(find nav)/urdf/robot.urdf" />
  <param name="other_description" textfile="$(find nav)/urdf/hard.urdf" />
</launch>
"""

COMMENTED_URDF = """<?xml version="1.0" ?>
<!-- Install the meshes in /opt/ros/... or from the source repository,
     or copy them to /home/me/meshes/base.urdf -->
<robot name="r"><link name="base"/></robot>
"""

HARD_URDF = """<?xml version="1.0" ?>
<robot name="r"><link name="base"><visual><geometry>
  <mesh filename="/home/me/meshes/base.stl"/></geometry></visual></link></robot>
"""


def test_the_words_of_an_xml_comment_are_no_path(write_tree):
    """A parameter loaded with ``textfile`` holds the document: amr-ros-config's
    pioneer-lx-devil.urdf says in a comment where to install meshes ("/opt/ros/... or
    from source repository"), which is no value any program reads; a mesh the document
    names by an absolute path still is one."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/urdf/robot.urdf": COMMENTED_URDF,
        "src/nav/urdf/hard.urdf": HARD_URDF,
        "src/nav/launch/desc.launch": TEXTFILE_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/desc.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    assert [f.entities for f in run_rule(rule, model)] == [("parameter:/other_description",)]


SYSTEM_FOLDERS_LAUNCH = """
<launch>
  <node name="ekf" pkg="nav" type="ekf" args="--port /dev/ttyUSB0 --log /tmp/ekf.log">
    <param name="debug_out_file" value="/tmp/robot_localization_debug.txt" />
    <param name="cache" value="/var/tmp/nav/cache.yaml" />
    <param name="lock" value="/run/nav/nav.json" />
    <param name="gpio" value="/sys/class/gpio/gpio17/value.txt" />
    <param name="stat" value="/proc/self/status.txt" />
    <param name="device" value="/dev/serial/by-id/usb-FTDI.cfg" />
    <param name="escape" value="/tmp/../home/alice/calib.yaml" />
    <param name="tmp_like" value="/tmpdata/calib.yaml" />
    <param name="calibration" value="/home/alice/ws/calib.yaml" />
  </node>
  <node name="driver" pkg="nav" type="driver" args="/home/alice/ws/driver.yaml" />
</launch>
"""


def test_scratch_device_and_kernel_folders_are_no_machine_s_paths(write_tree):
    """robot_localization's launch files give ``debug_out_file:
    /tmp/robot_localization_debug.txt`` (a file ekf writes when ``debug`` is true; survey
    R, nono): /tmp, /var/tmp, /run, /dev (``/dev/ttyUSB0``), /proc and /sys are the same
    folders on every Linux machine, no path of the author's. A user's home still is,
    also reached through ``..`` or behind a name that only begins like /tmp."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/ekf.launch": SYSTEM_FOLDERS_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/ekf.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    for found in (run_rule(rule, model), run_rule(rule, reloaded)):
        assert sorted(f.entities for f in found) == [
            ("node:/driver",), ("parameter:/ekf/calibration",),
            ("parameter:/ekf/escape",), ("parameter:/ekf/tmp_like",)]


DOUBLED_LAUNCH = """
<launch>
  <param name="camera_info_url" value="/$(find nav)/launch/camera.yaml" />
  <param name="map_file" value="$(find nav)//maps/lab.yaml" />
  <param name="calibration" value="/home/alice//calib/camera.yaml" />
</launch>
"""


def test_a_find_path_written_with_a_doubled_slash_is_not_hard_coded(write_tree):
    # cusub (848e8a0) cusub_common/drivers/occam/launch/occam_onecam.launch:3 writes
    # "/$(find ros_indigosdk)/launch/camera.yaml": "//<the package>/..." is the package's
    # folder (POSIX reads repeated slashes as one), no path of the author's machine
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/map.launch": DOUBLED_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/map.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "absolute-paths-in-launch"]
    assert [f.entities for f in run_rule(rule, model)] == [("parameter:/calibration",)]
