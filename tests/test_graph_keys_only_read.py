"""A ROS 1 namespace read whole whose value the code uses for its keys alone (mavros'
distance_sensor: ``dist_nh.getParam("", map_dict)``, then ``for (auto &pair :
map_dict)`` naming only ``pair.first`` and reading each sensor's parameters by name)
reads no value under it: ROBUST's mavros ff581a0 (``sensor_position/x`` read three
times, ``sensor_position/y`` and ``/z`` set and never read) was missed, every key under
the namespace taken as read as part of it. A read whose values the code uses still
reads them all."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """
    #include <ros/ros.h>

    void sensors(ros::NodeHandle& nh) {
      XmlRpc::XmlRpcValue map_dict;
      if (!nh.getParam("sensors", map_dict))
        return;
      ROS_ASSERT(map_dict.getType() == XmlRpc::XmlRpcValue::TypeStruct);
      for (auto &pair : map_dict) {
        ros::NodeHandle pnh(nh, "sensors/" + pair.first);
        double x, y;
        pnh.param("position/x", x, 0.0);
        pnh.param("position/x", y, 0.0);
      }
    }

    void gains(ros::NodeHandle& nh) {
      XmlRpc::XmlRpcValue gains;
      nh.getParam("gains", gains);
      for (auto &pair : gains) {
        double v = pair.second;
        (void)v;
      }
    }

    int main(int argc, char** argv) {
      ros::init(argc, argv, "dist");
      ros::NodeHandle nh("~");
      sensors(nh);
      gains(nh);
      ros::spin();
      return 0;
    }
    """
LAUNCH = """
    <launch>
      <node pkg="dist" type="dist" name="dist">
        <rosparam>
          sensors:
            sonar: {position: {x: 0.0, y: 0.1}}
          gains: {p: 1.0, i: 0.1}
        </rosparam>
      </node>
    </launch>
    """


def test_a_namespace_read_for_its_keys_reads_no_value_under_it(write_tree):
    root = write_tree({
        "src/dist/package.xml": package_xml("dist").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/dist/CMakeLists.txt": ("project(dist)\nfind_package(catkin REQUIRED)\n"
                                    "catkin_package()\nadd_executable(dist src/dist.cpp)\n"),
        "src/dist/src/dist.cpp": textwrap.dedent(NODE),
        "src/dist/launch/dist.launch": textwrap.dedent(LAUNCH),
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [dist/launch/dist.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    config = model.configurations[0]
    calls = {(c.name, c.keys_only) for n in model.nodes for c in n.calls if c.kind == "read"}
    assert ("~sensors", True) in calls and ("~gains", False) in calls
    unread = sorted(f.entities[0] for f in run_catalogue(model)
                    if f.rule == "parameter-set-not-read")
    assert unread == ["parameter:/dist/sensors/sonar/position/y"]
    gains = {p.name: p.read_as_part_of for p in config.parameters
             if p.name.startswith("/dist/gains/")}
    assert gains and all(whole is not None for whole in gains.values())
