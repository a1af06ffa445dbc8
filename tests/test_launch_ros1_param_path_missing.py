"""A ROS 1 ``<param>`` whose text value is an absolute path into a package of the
workspace that is not there is said, LAUNCH_PARAM_PATH_MISSING (warning), at the tag:
mas_domestic_robotics 4fafabff's recognize_gesture_action.launch gave its detection
server ``kwargs_file = $(find mdr_recognize_gesture_action)/object_detection_kwargs.yml``,
a file of the package's ``config/`` folder, and nothing said so. A path that is there,
one with a part not known, one outside the workspace, a parameter named for output (a
log or save path), a path with no file extension (a folder the node may make) and a
text that is no path are not said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """<launch>
  <arg name="kwargs_file" default="$(find det)/object_detection_kwargs.yml"/>
  <param name="global_config" value="$(find det)/config/gone.yaml"/>
  <node pkg="det" type="server" name="server">
    <param name="kwargs_file" type="string" value="$(arg kwargs_file)"/>
    <param name="classes" value="$(find det)/config/classes.yml"/>
    <param name="unknown" value="$(find det)/config/$(arg other)"/>
    <param name="outside" value="/opt/elsewhere/file.yaml"/>
    <param name="save_path" value="$(find det)/maps/new_map"/>
    <param name="log_file" value="$(find det)/logs/run.log"/>
    <param name="frame" value="base_link"/>
    <param name="data_dir" value="$(find det)/recordings"/>
  </node>
</launch>
"""


def _said(model) -> list[tuple[int, str]]:
    return sorted((d.location.line, d.message) for d in model.diagnostics
                  if d.code == "LAUNCH_PARAM_PATH_MISSING")


def test_a_parameter_given_a_file_that_is_not_there(write_tree) -> None:
    root = write_tree({"src/det/package.xml": package_xml("det", "catkin"),
                       "src/det/launch/run.launch": LAUNCH,
                       "src/det/config/classes.yml": "a: 1\n",
                       "src/det/config/object_detection_kwargs.yml": "b: 2\n"})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/det/launch/run.launch"), ws, {}, {})
    assert _said(model) == [
        (3, "parameter global_config is given the path det/config/gone.yaml, which is "
            "not there"),
        (5, "parameter kwargs_file is given the path "
            "det/object_detection_kwargs.yml, which is not there")], _said(model)


def test_the_file_at_its_place_is_not_said(write_tree) -> None:
    text = LAUNCH.replace("$(find det)/object_detection_kwargs.yml",
                          "$(find det)/config/object_detection_kwargs.yml")
    text = text.replace("config/gone.yaml", "config/classes.yml")
    root = write_tree({"src/det/package.xml": package_xml("det", "catkin"),
                       "src/det/launch/run.launch": text,
                       "src/det/config/classes.yml": "a: 1\n",
                       "src/det/config/object_detection_kwargs.yml": "b: 2\n"})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/det/launch/run.launch"), ws, {}, {})
    assert _said(model) == []
