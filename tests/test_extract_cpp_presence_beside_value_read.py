"""A ROS 1 wrapper that tests a parameter's presence and then reads its value
(costmap_2d's ``move_parameter``: ``if (!old_h.hasParam(name)) return;`` then
``old_h.getParam(name, value)`` of an ``XmlRpcValue`` it hands on whole) makes, at its
call site, two reads of one name at one place. The node kept the first, the presence
test, which reads the keys alone (``keys_only``): the namespace read whole read nothing
under it, and a pre-Hydro costmap's every source setting was "set but never read"
(navigation_tutorials 115e46e). One copy reading the values makes the call read them."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """
    #include <ros/ros.h>
    #include <sstream>

    void move_parameter(ros::NodeHandle& old_h, ros::NodeHandle& new_h, std::string name,
                        bool should_delete = true) {
      if (!old_h.hasParam(name))
        return;
      XmlRpc::XmlRpcValue value;
      old_h.getParam(name, value);
      new_h.setParam(name, value);
      if (should_delete) old_h.deleteParam(name);
    }

    bool present(ros::NodeHandle& nh, const std::string& name) {
      return nh.hasParam(name);
    }

    int main(int argc, char** argv) {
      ros::init(argc, argv, "mp");
      ros::NodeHandle nh("~");
      ros::NodeHandle obstacles(nh, "obstacle_layer");
      std::string s;
      nh.param("observation_sources", s, std::string(""));
      std::stringstream ss(s);
      std::string source;
      while (ss >> source) {
        move_parameter(nh, obstacles, source);
      }
      if (present(nh, "probe")) {
        ROS_INFO("probe set");
      }
      ros::spin();
      return 0;
    }
    """

LAUNCH = """
    <launch>
      <node pkg="mp" type="mp" name="mp">
        <rosparam>
          observation_sources: base_scan
          base_scan: {data_type: LaserScan, marking: true}
          probe: {a: 1}
        </rosparam>
      </node>
    </launch>
    """


def test_a_value_read_beside_a_presence_test_reads_the_values(write_tree):
    root = write_tree({
        "src/mp/package.xml": package_xml("mp").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/mp/CMakeLists.txt": ("project(mp)\nfind_package(catkin REQUIRED)\n"
                                  "catkin_package()\nadd_executable(mp src/mp.cpp)\n"),
        "src/mp/src/mp.cpp": textwrap.dedent(NODE),
        "src/mp/launch/mp.launch": textwrap.dedent(LAUNCH),
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [mp/launch/mp.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    reads = {(c.name, c.keys_only) for n in model.nodes for c in n.calls if c.kind == "read"}
    # the moved source: its value read (and handed on); the probe: its presence alone
    assert ("~?", False) in reads and ("~probe", True) in reads
    moved = [p for p in config.parameters if p.name.startswith("/mp/base_scan/")]
    assert moved and all(p.read_as_part_of is not None for p in moved)
    unread = sorted(f.entities[0] for f in run_catalogue(model)
                    if f.rule == "parameter-set-not-read")
    assert unread == ["parameter:/mp/probe/a"]


TESTED = """
    #include <ros/ros.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "dep");
      ros::NodeHandle nh("~");
      double bias = 0.6;
      nh.param("path_distance_bias", bias, 0.6);
      if (nh.hasParam("pdist_scale") & !nh.hasParam("path_distance_bias")) {
        nh.setParam("path_distance_bias", bias);
      }
      if (nh.hasParam("old_rate") | nh.hasParam("older_rate")) {
        ROS_WARN("deprecated");
      }
      ros::spin();
      return 0;
    }
    """


def test_a_presence_test_joined_by_a_bitwise_operator_is_tested(write_tree):
    """base_local_planner's TrajectoryPlannerROS tests a deprecated name with ``&``, not
    ``&&`` (``hasParam("pdist_scale") & !hasParam("path_distance_bias")``): the test of
    presence is still a test, the parameter's absence handled; it was "read but never
    set" in every ROS 1 navigation configuration that does not set it."""
    root = write_tree({
        "src/dep/package.xml": package_xml("dep").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/dep/CMakeLists.txt": ("project(dep)\nfind_package(catkin REQUIRED)\n"
                                   "catkin_package()\nadd_executable(dep src/dep.cpp)\n"),
        "src/dep/src/dep.cpp": textwrap.dedent(TESTED),
        "src/dep/launch/dep.launch": "<launch><node pkg='dep' type='dep' name='dep'/></launch>",
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [dep/launch/dep.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    tested = {c.name: c.tested for n in model.nodes for c in n.calls
              if c.kind == "read" and ("rate" in c.name or "pdist" in c.name)}
    assert tested == {"~pdist_scale": True, "~old_rate": True, "~older_rate": True}
    assert [f.entities[0] for f in run_catalogue(model)
            if f.rule == "parameter-read-not-set"] == []
