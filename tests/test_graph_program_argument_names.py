"""A name built from the process's command-line arguments (kinova_driver's action servers:
``robot_name = argv[argc-1]`` in ``main`` after ``ros::init``, behind an ``if (argc <= 1)
{ ...; return -1; } else``, then ``"/" + robot_name + "_driver/..."`` in a constructor)
carries the argument's index (``PrimitiveCall.name_arg``), and the graph names it with the
``args`` the launch file gives the instance. ROS 1's roslaunch puts its ``:=`` words
(remappings, ``__name:=``, ``__log:=``) after those ``args``; ``ros::init`` takes them off,
so ``argv[argc-1]`` read before it is roslaunch's, not the user's: it stays unknown, as it
does with no argument or with arguments not known statically."""

from __future__ import annotations

import json
import os

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.models.format import ModelFileError, dumps, from_document
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

SERVER = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <iostream>

class Server {
 public:
  Server(ros::NodeHandle& n, std::string& robot_name) {
    pub_ = n.advertise<std_msgs::String>("/" + robot_name + "_driver/command", 1);
    std::string state = "/" + robot_name + "/state";
    sub_ = n.subscribe(state, 1, &Server::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr& msg) {}
 private:
  ros::Publisher pub_;
  ros::Subscriber sub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "server");
  ros::NodeHandle node;
  std::string robot_name = "";
  if ((argc <= 1) || (argv[argc-1] == NULL)) {
    std::cerr << "no robot name" << std::endl;
    return -1;
  } else {
    robot_name = argv[argc-1];
  }
  Server server(node, robot_name);
  ros::spin();
  return 0;
}
"""

# argv read before ros::init: its last word is roslaunch's __log:=, its first the user's
EARLY = """#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv) {
  if (argc < 2) return 1;
  std::string last = argv[argc - 1];
  std::string first(argv[1]);
  ros::init(argc, argv, "early");
  ros::NodeHandle n;
  ros::Publisher a = n.advertise<std_msgs::String>(last + "/last", 1);
  ros::Publisher b = n.advertise<std_msgs::String>(first + "/first", 1);
  ros::Publisher c = n.advertise<std_msgs::String>(std::string(argv[2]) + "/second", 1);
  ros::spin();
  return 0;
}
"""

LAUNCH = """<launch>
  <arg name="robot" default="m1n6s300"/>
  <node pkg="kin" type="server" name="given" args="$(arg robot)"/>
  <node pkg="kin" type="server" name="two" args="first m1n6s300">
    <remap from="a" to="b"/>
  </node>
  <node pkg="kin" type="server" name="remapped_in_args" args="j2n6s300 x:=y"/>
  <node pkg="kin" type="server" name="none"/>
  <node pkg="kin" type="early" name="early" args="one two"/>
  <node pkg="kin" type="early" name="early_remap" args="a:=b one two"/>
</launch>
"""


def _tree(write_tree):
    return write_tree({
        "src/kin/package.xml": package_xml("kin"),
        "src/kin/CMakeLists.txt": "project(kin)\nadd_executable(server src/server.cpp)\n"
                                  "add_executable(early src/early.cpp)\n",
        "src/kin/src/server.cpp": SERVER,
        "src/kin/src/early.cpp": EARLY,
        "src/kin/launch/kin.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [kin/launch/kin.launch]\n",
    })


def test_the_extractor_marks_names_made_of_program_arguments(write_tree) -> None:
    root = _tree(write_tree)
    ws = scan([str(root)])
    server = extract_cpp([str(root / "src/kin/src/server.cpp")], ws, cache_dir=None)
    assert {(c.name, c.name_arg) for c in server.calls} == {
        ("/?_driver/command", -1), ("/?/state", -1)}
    early = extract_cpp([str(root / "src/kin/src/early.cpp")], ws, cache_dir=None)
    # argv[argc - 1] before ros::init is roslaunch's last word: no index
    assert {(c.name, c.name_arg) for c in early.calls} == {
        ("?/last", None), ("?/first", 1), ("?/second", 2)}


def test_the_graph_names_them_with_the_launch_arguments(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    names = {(link.node.name, link.rosname.full) for link in config.links
             if link.kind in ("publish", "subscribe")}
    assert names == {
        ("/given", "/m1n6s300_driver/command"), ("/given", "/m1n6s300/state"),
        # the last of the user's words, not roslaunch's remapping or __name / __log
        ("/two", "/m1n6s300_driver/command"), ("/two", "/m1n6s300/state"),
        # ros::init takes the user's own := word off too
        ("/remapped_in_args", "/j2n6s300_driver/command"),
        ("/remapped_in_args", "/j2n6s300/state"),
        # no argument: unknown, not empty (the code would not even get there)
        ("/none", "/?_driver/command"), ("/none", "/?/state"),
        # a word not known first: in no namespace, as it may begin with "/"
        ("/early", "?/last"), ("/early", "/one/first"), ("/early", "/two/second"),
        # before ros::init, argv[1] is the user's a:=b, after it one: not known which
        ("/early_remap", "?/last"), ("/early_remap", "?/first"),
        ("/early_remap", "?/second"),
    }


def test_a_model_file_carries_the_argument_index() -> None:
    def document(name_arg: object) -> dict:
        return {"schema": "haros-arch-model/1", "package": "kin", "nodes": [
            {"executable": "server", "calls": [
                {"kind": "publish", "name": "/?_driver/command", "type": "std_msgs/String",
                 "name_arg": name_arg}]}]}

    model = from_document(document(-1))
    again = from_document(json.loads(dumps(model)))
    assert [c.name_arg for c in again.nodes[0].calls] == [-1]
    for bad in (0, "1", True):
        with pytest.raises(ModelFileError, match="name_arg"):
            from_document(document(bad))


def test_a_name_the_arguments_do_not_tell_says_why(write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    found = sorted((os.path.basename(d.location.file), d.location.line, d.message)
                   for d in config.diagnostics if d.code == "NAME_ARG_UNSET")
    none = "argv[argc - 1], which its args ('') do not give; it stays unknown"
    remap = ("which differs before and after ros::init takes the ':=' words of its args; "
             "it stays unknown")
    assert found == [
        ("early.cpp", 11, "/early_remap: the name of this publish holds the process's "
         f"command-line argument argv[1], {remap}"),
        ("early.cpp", 12, "/early_remap: the name of this publish holds the process's "
         f"command-line argument argv[2], {remap}"),
        ("server.cpp", 8, "/none: the name of this publish holds the process's "
         f"command-line argument {none}"),
        ("server.cpp", 10, "/none: the name of this subscribe holds the process's "
         f"command-line argument {none}")]


# rospy: sys.argv is every word as given (roslaunch's := words after the user's),
# rospy.myargv() what is left without them
RELAY = """#!/usr/bin/env python
import sys
import rospy
from std_msgs.msg import String

rospy.init_node("relay")
args = rospy.myargv(argv=sys.argv)
pub = rospy.Publisher("/" + sys.argv[1] + "/out", String, queue_size=1)
sub = rospy.Subscriber(args[-1] + "/in", String, lambda m: pub.publish(m))
raw = rospy.Publisher(sys.argv[-1] + "/raw", String, queue_size=1)
rospy.spin()
"""

RELAY_LAUNCH = """<launch>
  <node pkg="rel" type="relay.py" name="relay" args="left right"/>
  <node pkg="rel" type="relay.py" name="bare"/>
</launch>
"""


def test_rospy_names_from_sys_argv_and_myargv(write_tree) -> None:
    root = write_tree({
        "src/rel/package.xml": package_xml("rel"),
        "src/rel/CMakeLists.txt": "project(rel)\n"
                                  "catkin_install_python(PROGRAMS scripts/relay.py)\n",
        "src/rel/scripts/relay.py": RELAY,
        "src/rel/launch/rel.launch": RELAY_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [rel/launch/rel.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    config = model.configuration("c")
    names = {(link.node.name, link.kind, link.rosname.full) for link in config.links
             if link.kind in ("publish", "subscribe")}
    assert names == {
        ("/relay", "publish", "/left/out"), ("/relay", "subscribe", "/right/in"),
        # the last word as given is roslaunch's __log:=: unknown, and first in the name:
        # in no namespace, as it may begin with "/"
        ("/relay", "publish", "?/raw"),
        ("/bare", "publish", "/?/out"), ("/bare", "subscribe", "?/in"),
        ("/bare", "publish", "?/raw"),
    }


# baxter_sim_kinematics' position_kinematics: the side is ``argc > 1 ? argv[1] : ""``,
# passed on to the function that names the topic
SIDE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

ros::Publisher start(const std::string& side) {
  ros::NodeHandle n;
  return n.advertise<std_msgs::String>("/robot/limb/" + side + "/endpoint_state", 1);
}

int main(int argc, char** argv) {
  std::string side = argc > 1 ? argv[1] : "";
  std::string third = 2 < argc ? argv[3] : "none";  // argv[3] may not be there
  std::string second = 2 < argc ? argv[2] : "none";
  ros::init(argc, argv, "kinematics_" + side);
  ros::Publisher p = start(side);
  ros::NodeHandle n;
  ros::Publisher q = n.advertise<std_msgs::String>("/" + third + "/third", 1);
  ros::Publisher r = n.advertise<std_msgs::String>("/" + second + "/second", 1);
  ros::spin();
  return 0;
}
"""


def test_an_argument_chosen_when_argc_has_it_is_that_argument(write_tree) -> None:
    root = write_tree({
        "src/kin/package.xml": package_xml("kin"),
        "src/kin/CMakeLists.txt": "project(kin)\nadd_executable(side src/side.cpp)\n",
        "src/kin/src/side.cpp": SIDE,
        "src/kin/launch/kin.launch": '<launch>\n'
                                     '  <node pkg="kin" type="side" name="left" args="left"/>\n'
                                     '  <node pkg="kin" type="side" name="bare"/>\n'
                                     '</launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [kin/launch/kin.launch]\n",
    })
    side = extract_cpp([str(root / "src/kin/src/side.cpp")], scan([str(root)]),
                       cache_dir=None)
    # ``2 < argc`` says argv[2] is there, not argv[3]
    assert {(c.name, c.name_arg) for c in side.calls} == {
        ("/robot/limb/?/endpoint_state", 1), ("/?/third", None), ("/?/second", 2)}
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    names = {(link.node.name, link.rosname.full) for link in
             model.configuration("c").links if link.name.endswith("endpoint_state")}
    # no argument: unknown, as for argv[1] itself
    assert names == {("/left", "/robot/limb/left/endpoint_state"),
                     ("/bare", "/robot/limb/?/endpoint_state")}
