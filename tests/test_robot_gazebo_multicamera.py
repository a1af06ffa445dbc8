"""gazebo_ros' ``libgazebo_ros_multicamera.so`` (noetic, gazebo_ros_multicamera.cpp:
Load) loads one camera utility per <camera> of its multicamera sensor whose name holds
``left`` (``<cameraName>/left``) or else ``right`` (``<cameraName>/right``), each with the
image and camera_info topics of a camera plugin; a camera named neither gets none.
rotors_description's stereo_camera_macro (component_snippets.xacro:232) uses it, which
was GAZEBO_PLUGIN_UNKNOWN and the gazebo node partial."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

DESCRIPTION = """\
<?xml version="1.0"?>
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"/>
  <gazebo reference="base_link">
    <sensor type="multicamera" name="stereo">
      <camera name="cam_left"><image><width>10</width></image></camera>
      <camera name="cam_right"><image><width>10</width></image></camera>
      <camera name="middle"><image><width>10</width></image></camera>
      <plugin name="stereo_controller" filename="libgazebo_ros_multicamera.so">
        <robotNamespace>bot</robotNamespace>
        <cameraName>stereo</cameraName>
        <imageTopicName>image</imageTopicName>
      </plugin>
    </sensor>
  </gazebo>
</robot>
"""

LAUNCH = """\
<launch>
  <param name="robot_description" command="$(find xacro)/xacro '$(find desc)/urdf/bot.xacro'"/>
  <node name="spawn" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -param robot_description -model bot"/>
</launch>
"""


def test_multicamera_publishes_a_left_and_a_right_camera(write_tree) -> None:
    root = str(write_tree({
        "desc/package.xml": package_xml("desc", "catkin"),
        "desc/CMakeLists.txt": "project(desc)\n",
        "desc/urdf/bot.xacro": DESCRIPTION,
        "desc/launch/sim.launch": LAUNCH}))
    project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", ["desc/launch/sim.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    config = model.configurations[0]
    made = sorted((link.node.name, link.kind, link.resource.name, link.type)
                  for link in config.links if link.origin == "description"
                  and "/image/" not in link.resource.name)  # not the transports' own
    assert made == [
        ("/gazebo", "publish", "/bot/stereo/left/camera_info", "sensor_msgs/CameraInfo"),
        ("/gazebo", "publish", "/bot/stereo/left/image", "sensor_msgs/Image"),
        ("/gazebo", "publish", "/bot/stereo/right/camera_info", "sensor_msgs/CameraInfo"),
        ("/gazebo", "publish", "/bot/stereo/right/image", "sensor_msgs/Image")]
    assert not [d for d in config.diagnostics if d.code == "GAZEBO_PLUGIN_UNKNOWN"]


def test_a_camera_name_not_known_makes_its_topics_conditional(write_tree) -> None:
    root = str(write_tree({
        "desc/package.xml": package_xml("desc", "catkin"),
        "desc/CMakeLists.txt": "project(desc)\n",
        "desc/urdf/bot.xacro": DESCRIPTION.replace('"cam_right"', '"$(env SIDE)"'),
        "desc/launch/sim.launch": LAUNCH}))
    project = Project("p", os.path.join(root, "project.yaml"), workspace=[root],
                      configurations=[ConfigurationSpec("c", ["desc/launch/sim.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    made = sorted((link.resource.name, [c.text for c in link.conditions])
                  for link in model.configurations[0].links
                  if link.origin == "description" and link.resource.name.endswith("/image"))
    assert made == [
        ("/bot/stereo/left/image", []),
        ("/bot/stereo/right/image", ["a <camera> of the sensor is named with right"])]


# gazebo_ros_camera_utils.cpp (noetic, LoadThread) makes its topics on
# ``ros::NodeHandle(robot_namespace_ + "/" + camera_name_)``; roscpp remaps a handle's
# namespace before it resolves a name in it, so a remap of ``<cameraName>/left`` on the
# gazebo node renames the camera's topics (AutoRally's autoRallyTrackWorld.launch:
# ``camera/left:=left_camera``, "to the same topics as the actual robot"); it was
# ``remap-unused`` and the topics kept their names (survey Z47).
REMAPPED_DESCRIPTION = DESCRIPTION.replace("<robotNamespace>bot</robotNamespace>", "") \
    .replace("<cameraName>stereo</cameraName>", "<cameraName>camera</cameraName>")
REMAPPED_LAUNCH = """\
<launch>
  <param name="robot_description" command="$(find xacro)/xacro '$(find desc)/urdf/bot.xacro'"/>
  <node name="gazebo" pkg="gazebo_ros" type="gzserver" args="-e ode worlds/empty.world">
    <remap from="camera/left" to="left_camera"/>
    <remap from="camera/right" to="/right_camera"/>
    <remap from="camera/middle" to="middle_camera"/>
  </node>
  <node name="spawn" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -param robot_description -model bot"/>
</launch>
"""


def test_a_remap_of_the_cameras_handle_renames_its_topics(write_tree) -> None:
    from haros_arch.project import load
    from haros_arch.query import run_catalogue
    root = write_tree({
        "src/desc/package.xml": package_xml("desc", "catkin"),
        "src/desc/CMakeLists.txt": "project(desc)\n",
        "src/desc/urdf/bot.xacro": REMAPPED_DESCRIPTION,
        "src/desc/launch/sim.launch": REMAPPED_LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [desc/launch/sim.launch]\n"})
    project = load(str(root / "project.yaml"))
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    config = model.configurations[0]
    made = sorted(link.resource.name for link in config.links
                  if link.origin == "description" and link.resource.name.endswith(
                      ("/image", "/camera_info")))
    assert made == ["/left_camera/camera_info", "/left_camera/image",
                    "/right_camera/camera_info", "/right_camera/image"]
    # the image's transports lie below the remapped topic too
    assert any(link.resource.name == "/left_camera/image/compressed"
               for link in config.links)
    unused = [f.message for f in run_catalogue(model, project) if f.rule == "remap-unused"]
    # the middle camera has no side: no handle of that name, the remap changes nothing
    assert len(unused) == 1 and "camera/middle" in unused[0], unused
