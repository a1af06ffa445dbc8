"""A ROS 1 struct parameter read whole whose members the code hands, one by one, to a
constructor in another file that reads each member's keys by name (mocap_optitrack
a140078: ``getParam("rigid_bodies", body_list)``, ``for (i = body_list.begin(); ...)``
then ``PublishedRigidBody body(i->second)``, whose constructor in mocap_config.cpp reads
``config_node["child_frame_id"]``, through a helper ``validateParam(config_node, name)``
too) reads those keys of each member, not every key under the namespace: a key no
member reads (rigid body 2's ``frame_id``) is set and never read. A member used whole
(converted, passed to code not read) still reads everything under it; a struct the code
makes is no parameter's, and what its receiver takes from it no read."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.model.values import UNKNOWN_MARK
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

HEADER = """
    #include <ros/ros.h>
    #include <string>

    class Body {
     public:
      explicit Body(XmlRpc::XmlRpcValue& config_node);
      std::string child, parent;
     private:
      bool valid(XmlRpc::XmlRpcValue& config_node, const std::string& name);
    };

    void whole(XmlRpc::XmlRpcValue& gains);
    """
CONFIG = """
    #include "bodies/body.h"

    const std::string CHILD = "child_frame_id";
    const std::string PARENT = "parent_frame_id";

    Body::Body(XmlRpc::XmlRpcValue& config_node) {
      if (valid(config_node, CHILD) && valid(config_node, PARENT)) {
        child = (std::string&) config_node[CHILD];
        parent = (std::string&) config_node[PARENT];
      }
    }

    bool Body::valid(XmlRpc::XmlRpcValue& config_node, const std::string& name) {
      if (!config_node.hasMember(name))
        return false;
      return config_node[name].getType() == XmlRpc::XmlRpcValue::TypeString;
    }

    void whole(XmlRpc::XmlRpcValue& gains) {
      std::string text = gains.toXml();
      ROS_INFO("%s", text.c_str());
    }
    """
NODE = """
    #include "bodies/body.h"
    #include <vector>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "bodies");
      ros::NodeHandle n("~");
      std::vector<Body> bodies;
      XmlRpc::XmlRpcValue body_list;
      if (n.hasParam("rigid_bodies"))
        n.getParam("rigid_bodies", body_list);
      if (body_list.getType() == XmlRpc::XmlRpcValue::TypeStruct && body_list.size() > 0) {
        XmlRpc::XmlRpcValue::iterator i;
        for (i = body_list.begin(); i != body_list.end(); ++i) {
          if (i->second.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
            Body body(i->second);
            bodies.push_back(body);
          }
        }
      }
      XmlRpc::XmlRpcValue made;
      made["child_frame_id"] = std::string("c");
      Body other(made);
      XmlRpc::XmlRpcValue gain_list;
      n.getParam("gain_sets", gain_list);
      for (auto& pair : gain_list) {
        whole(pair.second);
      }
      ros::spin();
      return 0;
    }
    """
LAUNCH = """
    <launch>
      <node pkg="bodies" type="bodies" name="bodies">
        <rosparam>
          rigid_bodies:
            '1': {child_frame_id: a/base_link, parent_frame_id: world}
            '2': {frame_id: b/base_link, parent_frame_id: world}
          gain_sets:
            fast: {p: 1.0}
        </rosparam>
      </node>
    </launch>
    """


def test_struct_members_handed_to_a_constructor_read_their_keys(write_tree):
    root = write_tree({
        "src/bodies/package.xml": package_xml("bodies").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/bodies/CMakeLists.txt": (
            "project(bodies)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
            "include_directories(include)\n"
            "add_executable(bodies src/node.cpp src/config.cpp)\n"),
        "src/bodies/include/bodies/body.h": textwrap.dedent(HEADER),
        "src/bodies/src/config.cpp": textwrap.dedent(CONFIG),
        "src/bodies/src/node.cpp": textwrap.dedent(NODE),
        "src/bodies/launch/bodies.launch": textwrap.dedent(LAUNCH),
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [bodies/launch/bodies.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    reads = {(c.name, c.keys_only) for n in model.nodes for c in n.calls if c.kind == "read"}
    assert ("~rigid_bodies", True) in reads and ("~rigid_bodies", False) not in reads
    # the members of gain_sets are read whole where they are handed
    assert ("~gain_sets/?", False) in reads
    assert {"~rigid_bodies/?/child_frame_id", "~rigid_bodies/?/parent_frame_id"} <= {
        name for name, _ in reads}
    # a struct the code makes itself is no parameter: the constructor reads none there
    assert not [name for name, _ in reads if name.startswith("?")]
    unread = sorted(f.entities[0] for f in run_catalogue(model)
                    if f.rule == "parameter-set-not-read")
    assert unread == ["parameter:/bodies/rigid_bodies/2/frame_id"]


def test_each_member_the_launch_file_sets_is_read_by_name(write_tree):
    """The reads of the members' keys were ``~rigid_bodies/?/child_frame_id``: one
    ``unresolved-names`` finding per key, and every key the launch file sets under a
    member was undecided for ``parameter-set-not-read``. The graph reads each member the
    launch file sets, as it does a list's elements (``graph.build.element_calls``)."""
    root = write_tree({
        "src/bodies/package.xml": package_xml("bodies").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "src/bodies/CMakeLists.txt": (
            "project(bodies)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
            "include_directories(include)\n"
            "add_executable(bodies src/node.cpp src/config.cpp)\n"),
        "src/bodies/include/bodies/body.h": textwrap.dedent(HEADER),
        "src/bodies/src/config.cpp": textwrap.dedent(CONFIG),
        "src/bodies/src/node.cpp": textwrap.dedent(NODE),
        "src/bodies/launch/bodies.launch": textwrap.dedent(LAUNCH),
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [bodies/launch/bodies.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    config = model.configurations[0]
    reads = {link.name for link in config.links if link.kind == "read"}
    assert {"/bodies/rigid_bodies/1/child_frame_id", "/bodies/rigid_bodies/2/child_frame_id",
            "/bodies/rigid_bodies/1/parent_frame_id",
            "/bodies/rigid_bodies/2/parent_frame_id", "/bodies/gain_sets/fast"} <= reads
    assert not [name for name in reads if UNKNOWN_MARK in name]
    findings = run_catalogue(model)
    assert [f.entities[0] for f in findings if f.rule == "unresolved-names"] == []
    assert sorted(f.entities[0] for f in findings if f.rule == "parameter-set-not-read") == [
        "parameter:/bodies/rigid_bodies/2/frame_id"]
    # nothing set under it: the read keeps its '?'
    (root / "src/bodies/launch/bodies.launch").write_text(
        '<launch><node pkg="bodies" type="bodies" name="bodies"/></launch>\n')
    config = analyse(load(str(root / "project.yaml")), {}).configurations[0]
    assert "/bodies/rigid_bodies/?/child_frame_id" in {
        link.name for link in config.links if link.kind == "read"}
