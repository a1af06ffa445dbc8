"""A ROS 1 node given, on its command line, an absolute path into the workspace that is
not there is said, LAUNCH_NODE_ARG_PATH_MISSING (warning), at the node: gazebo_ros
a2cbcb5's range_world.launch handed empty_world.launch the world
``$(find gazebo_plugins)/test/test_worlds/$(arg world).W()orld``, which its gzserver
node then got among its args. A path that is there, one with a part not known, one
outside the workspace and one given to an option of output (map_saver's ``-f``) are
not said."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

WORLD = """<launch>
  <arg name="world" default="range"/>
  <include file="$(find sim)/launch/empty.launch">
    <arg name="world_name" value="$(find sim)/worlds/$(arg world).W()orld"/>
  </include>
  <node pkg="sim" type="viewer" name="viewer"
        args="-d $(find sim)/worlds/range.world --config=$(find sim)/cfg/missing.yaml"/>
  <node pkg="sim" type="viewer" name="unknown" args="$(find sim)/worlds/$(arg other)"/>
  <node pkg="map_server" type="map_saver" name="saver" args="-f $(find sim)/maps/new"/>
  <node pkg="sim" type="viewer" name="outside" args="/opt/elsewhere/file.yaml"/>
</launch>
"""

EMPTY = """<launch>
  <arg name="world_name" default="worlds/empty.world"/>
  <node pkg="sim" type="gzserver" name="gazebo" args="-e ode $(arg world_name)"/>
</launch>
"""


def _said(model) -> list[tuple[str, str, int]]:
    return sorted((d.location.file.rsplit("/", 1)[-1], d.message, d.location.line)
                  for d in model.diagnostics if d.code == "LAUNCH_NODE_ARG_PATH_MISSING")


def test_missing_world_file_handed_to_an_included_node(write_tree) -> None:
    root = write_tree({"src/sim/package.xml": package_xml("sim", "catkin"),
                       "src/sim/launch/range.launch": WORLD,
                       "src/sim/launch/empty.launch": EMPTY,
                       "src/sim/worlds/range.world": "<sdf/>\n"})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/sim/launch/range.launch"), ws, {}, {})
    assert _said(model) == [
        ("empty.launch", "node gazebo is given the path sim/worlds/range.W()orld on its "
         "command line, which is not there", 3),
        ("range.launch", "node viewer is given the path sim/cfg/missing.yaml on its "
         "command line, which is not there", 6)]


def test_world_file_that_is_there_is_not_said(write_tree) -> None:
    root = write_tree({"src/sim/package.xml": package_xml("sim", "catkin"),
                       "src/sim/launch/range.launch": WORLD.replace(".W()orld", ".world")
                       .replace(" --config=$(find sim)/cfg/missing.yaml", ""),
                       "src/sim/launch/empty.launch": EMPTY,
                       "src/sim/worlds/range.world": "<sdf/>\n"})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/sim/launch/range.launch"), ws, {}, {})
    assert _said(model) == []


# mbzirc2020 (e474cee)'s challenge launch files make their world with xacro and hand it
# to Gazebo's launcher with a search path of model folders joined by ``:``
XACRO_WORLD = """<launch>
  <node name="xacro" pkg="xacro" type="xacro"
        args="--inorder -o $(find sim)/worlds/arena.world $(find sim)/worlds/arena.world.xacro"/>
  <node pkg="sim" type="launch_world" name="world"
        args="-world=$(find sim)/worlds/arena.world
              -add_model_path=$(find sim)/models:$(find sim)/urdf:$(find sim)/meshes"/>
  <node pkg="sim" type="launch_world" name="other"
        args="-world=$(find sim)/worlds/other.world
              -add_model_path=$(find sim)/models:$(find sim)/gone"/>
</launch>
"""


def test_a_file_another_node_writes_and_a_search_path_are_judged_by_their_parts(
        write_tree) -> None:
    """The world xacro's ``-o`` writes is there for the node given it; each folder of a
    search path is judged on its own: only the world no node writes and the folder that
    is not there are said."""
    root = write_tree({"src/sim/package.xml": package_xml("sim", "catkin"),
                       "src/sim/launch/arena.launch": XACRO_WORLD,
                       "src/sim/worlds/arena.world.xacro": "<sdf/>\n",
                       "src/sim/models/box/model.sdf": "<sdf/>\n",
                       "src/sim/urdf/robot.urdf": "<robot/>\n",
                       "src/sim/meshes/base.dae": "<dae/>\n"})
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/sim/launch/arena.launch"), ws, {}, {})
    assert _said(model) == [
        ("arena.launch", "node other is given the path sim/gone on its command line, "
         "which is not there", 7),
        ("arena.launch", "node other is given the path sim/worlds/other.world on its "
         "command line, which is not there", 7)]


XACRO_CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(sim)
find_package(catkin REQUIRED COMPONENTS xacro)
catkin_package()
xacro_add_files(
  worlds/ocean.world.xacro
  worlds/dock.world.xacro
  INORDER INSTALL DESTINATION worlds)
xacro_add_files(worlds/lake.world.xacro INORDER)
xacro_add_xacro_file(worlds/river.world.xacro)
xacro_install(river ${XACRO_OUTPUT_FILE} DESTINATION worlds)
"""

MADE = """<launch>
  <node pkg="sim" type="gzserver" name="ocean" args="$(find sim)/worlds/ocean.world"/>
  <node pkg="sim" type="gzserver" name="dock" args="$(find sim)/worlds/dock.world"/>
  <node pkg="sim" type="gzserver" name="river" args="$(find sim)/worlds/river.world"/>
  <node pkg="sim" type="gzserver" name="lake" args="$(find sim)/worlds/lake.world"/>
  <node pkg="sim" type="gzserver" name="pond" args="$(find sim)/worlds/pond.world"/>
</launch>
"""


def test_a_world_the_build_makes_with_xacro_into_the_share_folder(write_tree) -> None:
    # vrx_gazebo (as SINGABOAT-VRX's copy has it): xacro_add_files(worlds/*.world.xacro
    # INSTALL DESTINATION worlds) makes the worlds its launch files give gzserver as
    # $(find vrx_gazebo)/worlds/x.world, which roslaunch finds in the devel or install
    # share folder; one made but not installed (lake) stays in the build folder
    files = {"src/sim/package.xml": package_xml("sim", "catkin"),
             "src/sim/CMakeLists.txt": XACRO_CMAKE,
             "src/sim/launch/sea.launch": MADE}
    for name in ("ocean", "dock", "lake", "river", "pond"):
        files[f"src/sim/worlds/{name}.world.xacro"] = "<sdf/>\n"
    root = write_tree(files)
    ws = scan([str(root / "src")], {})
    model = load(str(root / "src/sim/launch/sea.launch"), ws, {}, {})
    assert [(m.split(" is given")[0], line) for _, m, line in _said(model)] == [
        ("node lake", 5), ("node pond", 6)]
