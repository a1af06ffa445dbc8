"""A local that each case of a ``switch`` (or each side of an ``if`` / ``else if``
chain) writes with a known text, and nothing else writes, names one call per written
value, each under the condition of its case or side; a path that leaves it unwritten,
or a side that writes a value not known, keeps the name ``?``."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

NODE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <stdexcept>

    enum class Agv { one, two, any };
    enum Side { LEFT, RIGHT };

    std::string unknown_text();

    Agv pick_agv();
    Side pick_side();
    int pick_mode();
    void callback(const std_msgs::String &);

    int main(int argc, char ** argv) {
      ros::init(argc, argv, "node");
      ros::NodeHandle nh;
      Agv agv = pick_agv();
      int mode = pick_mode();
      std::string given = unknown_text();
      {
        std::string service;
        switch (agv) {
          case Agv::one:
            service = "/agv1/submit";
            break;
          case Agv::two:
            service = "/agv2/submit";
            break;
          case Agv::any:
            throw std::invalid_argument{"any"};
        }
        ros::ServiceClient client = nh.serviceClient<std_msgs::String>(service);
      }
      {
        std::string topic;
        if (mode == 1) {
          topic = "low";
        } else if (mode == 2) {
          topic = "high";
        } else {
          topic = "off";
        }
        ros::Publisher pub = nh.advertise<std_msgs::String>(topic, 1);
      }
      {
        std::string topic;  // no default, not an enumeration: 3 may leave it empty
        switch (mode) {
          case 1: topic = "one"; break;
          case 2: topic = "two"; break;
        }
        ros::Publisher pub = nh.advertise<std_msgs::String>(topic, 1);
      }
      {
        std::string topic;
        if (mode == 1) {
          topic = "first";
        } else if (mode == 2) {
          topic = "second";
        }  // no else: unwritten
        ros::Subscriber sub = nh.subscribe(topic, 1, &callback);
      }
      {
        std::string topic;
        switch (mode) {
          case 1: topic = "known"; break;
          default: topic = given; break;  // not known
        }
        ros::Publisher pub = nh.advertise<std_msgs::String>(topic, 1);
      }
      {
        std::string topic;  // every enumerator a label (the value promoted to int)
        switch (pick_side()) {
          case LEFT: topic = "left/cmd"; break;
          case RIGHT: topic = "right/cmd"; break;
        }
        ros::Subscriber sub = nh.subscribe(topic, 1, &callback);
      }
      {
        std::string topic = "start";
        if (mode == 1) {
          topic = "a";
        } else {
          topic = "b";
        }
        for (int i = 0; i < mode; ++i) {
          nh.getParam("again", topic);  // may write it again
        }
        ros::Publisher pub = nh.advertise<std_msgs::String>(topic, 1);
      }
      {
        std::string topic;  // a case that may leave before its write
        switch (mode) {
          case 1: if (given.empty()) break; topic = "maybe"; break;
          default: topic = "other"; break;
        }
        ros::Publisher pub = nh.advertise<std_msgs::String>(topic, 1);
      }
      {
        std::string topic;  // cases in blocks of their own
        switch (mode) {
          case 1: { topic = "braced/one"; break; }
          case 2: { topic = "braced/two"; } break;
          default: { throw std::runtime_error("mode"); }
        }
        ros::Subscriber sub = nh.subscribe(topic, 1, &callback);
      }
      {
        std::string topic;
        switch (mode) {
          case 1: topic = "uno"; break;
          default: topic = "otro"; break;
        }
        ros::Subscriber sub = nh.subscribe(topic, 1, &callback);
      }
    }
    """


def test_each_written_value_is_a_call_under_its_branch(write_tree):
    root = write_tree({
        "src/demo/package.xml": package_xml("demo", "catkin"),
        "src/demo/CMakeLists.txt": "project(demo)\nadd_executable(node src/node.cpp)\n",
        "src/demo/src/node.cpp": NODE,
    })
    result = extract_cpp([str(root / "src/demo/src/node.cpp")], scan([str(root)]),
                         cache_dir=None)
    found = sorted((c.kind, c.name, tuple((k.statement, k.text) for k in c.conditions))
                   for c in result.calls if c.kind in ("publish", "subscribe", "client"))
    assert found == [
        ("client", "/agv1/submit", (("switch", "agv == Agv::one"),)),
        ("client", "/agv2/submit", (("switch", "agv == Agv::two"),)),
        ("publish", "?", ()),
        ("publish", "?", ()),
        ("publish", "?", ()),
        ("publish", "?", ()),
        ("publish", "high", (("else", "mode == 1"), ("if", "mode == 2"))),
        ("publish", "low", (("if", "mode == 1"),)),
        ("publish", "off", (("else", "mode == 1"), ("else", "mode == 2"))),
        ("subscribe", "?", ()),
        ("subscribe", "braced/one", (("switch", "mode == 1"),)),
        ("subscribe", "braced/two", (("switch", "mode == 2"),)),
        ("subscribe", "left/cmd", (("switch", "pick_side() == LEFT"),)),
        ("subscribe", "otro", (("switch", "mode != 1"),)),
        ("subscribe", "right/cmd", (("switch", "pick_side() == RIGHT"),)),
        ("subscribe", "uno", (("switch", "mode == 1"),)),
    ]


GRAPH_NODE = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    class Camera : public rclcpp::Node {
     public:
      Camera() : Node("camera") {
        int mode = declare_parameter("mode", 1);
        std::string topic;
        switch (mode) {
          case 1: topic = "image/low"; break;
          case 2: topic = "image/high"; break;
          default: topic = "image/off"; break;
        }
        pub_ = create_publisher<std_msgs::msg::String>(topic, 10);
      }
     private:
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Camera>());
    }
    """

GRAPH_LAUNCH = """
    <launch>
      <node pkg="cam" exec="camera" name="plain"/>
      <node pkg="cam" exec="camera" name="high">
        <param name="mode" value="2"/>
      </node>
    </launch>
    """


def test_the_graph_decides_the_case_per_instance(write_tree):
    """A switch over a parameter: each instance publishes the one name its value
    chooses (the default 1 for ``plain``, the launch file's 2 for ``high``)."""
    root = write_tree({
        "src/cam/package.xml": package_xml("cam", "ament_cmake"),
        "src/cam/CMakeLists.txt": ("cmake_minimum_required(VERSION 3.8)\nproject(cam)\n"
                                   "add_executable(camera src/camera.cpp)\n"
                                   "install(TARGETS camera DESTINATION lib/${PROJECT_NAME})\n"),
        "src/cam/src/camera.cpp": GRAPH_NODE,
        "src/cam/launch/two.launch.xml": GRAPH_LAUNCH,
        "project.yaml": "project: p\ndistro: jazzy\nconfigurations:\n"
                        "  c: [cam/launch/two.launch.xml]\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")

    def published(node: str) -> set[str]:
        return {link.rosname.full for link in config.links
                if link.node.name == node and link.kind == "publish"
                and link.rosname.full.startswith("/image")}

    assert published("/plain") == {"/image/low"}
    assert published("/high") == {"/image/high"}
