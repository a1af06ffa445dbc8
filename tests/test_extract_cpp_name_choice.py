"""A name chosen by a test the code leaves to run time, ``rectify ? "image_rect" :
"image_raw"`` (written in the call, or the value of a local written once), is one call
per side, each under its side of the test as an ``if`` / ``else`` condition; the graph
decides them from the parameter the test reads, where the name was ``?``."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

NODE = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    class Camera : public rclcpp::Node {
     public:
      Camera() : Node("camera") {
        bool rectify = declare_parameter("rectify", false);
        color_ = declare_parameter("color", true);
        right_ = create_publisher<std_msgs::msg::String>(
          rectify ? "right/image_rect" : "right/image_raw", 10);
        std::string left = color_ ? "left/color" : "left/mono";
        left_ = create_publisher<std_msgs::msg::String>(left, 10);
        std::string prefix = get_name();
        other_ = create_publisher<std_msgs::msg::String>(rectify ? prefix : "plain", 10);
      }
     private:
      bool color_;
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr right_, left_, other_;
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Camera>());
    }
    """

LAUNCH = """
    <launch>
      <node pkg="cam" exec="camera" name="plain"/>
      <node pkg="cam" exec="camera" name="rectified">
        <param name="rectify" value="true"/>
        <param name="color" value="false"/>
      </node>
    </launch>
    """


def _workspace(write_tree):
    return write_tree({
        "src/cam/package.xml": package_xml("cam", "ament_cmake"),
        "src/cam/CMakeLists.txt": ("cmake_minimum_required(VERSION 3.8)\nproject(cam)\n"
                                   "add_executable(camera src/camera.cpp)\n"
                                   "install(TARGETS camera DESTINATION lib/${PROJECT_NAME})\n"),
        "src/cam/src/camera.cpp": NODE,
        "src/cam/launch/two.launch.xml": LAUNCH,
        "project.yaml": "project: p\ndistro: jazzy\nconfigurations:\n"
                        "  c: [cam/launch/two.launch.xml]\n",
    })


def test_each_side_is_a_call_under_its_side_of_the_test(write_tree):
    root = _workspace(write_tree)
    result = extract_cpp([str(root / "src/cam/src/camera.cpp")], scan([str(root)]),
                         cache_dir=None)
    found = sorted((c.name, tuple((k.statement, k.text) for k in c.conditions))
                   for c in result.calls if c.kind == "publish")
    assert found == [
        ("?", ()),  # a side that is not known: one call, its name not known
        ("left/color", (("if", "color_"),)),
        ("left/mono", (("else", "color_"),)),
        ("right/image_raw", (("else", "rectify"),)),
        ("right/image_rect", (("if", "rectify"),)),
    ]
    rectified = next(c for c in result.calls if c.name == "right/image_rect")
    assert rectified.conditions[0].parameters == (("rectify", "rectify"),)


def test_the_graph_decides_the_side_per_instance(write_tree):
    model = analyse(load(str(_workspace(write_tree) / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configuration("c")

    def published(node: str) -> set[str]:
        return {link.rosname.full for link in config.links
                if link.node.name == node and link.kind == "publish"
                and "?" not in link.rosname.full}

    assert published("/plain") >= {"/right/image_raw", "/left/color"}
    assert not published("/plain") & {"/right/image_rect", "/left/mono"}
    assert published("/rectified") >= {"/right/image_rect", "/left/mono"}
    assert not published("/rectified") & {"/right/image_raw", "/left/color"}


PREFIXED = """
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    class Broadcaster : public rclcpp::Node {
     public:
      Broadcaster() : Node("broadcaster") {
        bool local = declare_parameter("use_local_topics", false);
        const std::string prefix = local ? "~/" : "";
        states_ = create_publisher<std_msgs::msg::String>(prefix + "joint_states", 10);
        std::string unknown = get_name();
        other_ = create_publisher<std_msgs::msg::String>(unknown + prefix + "x", 10);
      }
     private:
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr states_, other_;
    };
    """


def test_a_name_made_of_a_chosen_value_and_text_is_a_call_per_side(write_tree):
    """ros2_controllers' joint_state_broadcaster: ``topic_name_prefix + "joint_states"``,
    the prefix a local written once with ``params_.use_local_topics ? "~/" : ""``. Its
    ``/joint_states`` was ``?joint_states``; a name with another unknown part stays one
    call."""
    root = write_tree({"src/b/package.xml": package_xml("b", "ament_cmake"),
                       "src/b/src/b.cpp": PREFIXED})
    result = extract_cpp([str(root / "src/b/src/b.cpp")], scan([str(root)]), cache_dir=None)
    found = sorted((c.name, tuple((k.statement, k.text) for k in c.conditions))
                   for c in result.calls if c.kind == "publish")
    assert found == [
        ("?x", ()),  # ``unknown`` is not known: one call, as before
        ("joint_states", (("else", "local"),)),
        ("~joint_states", (("if", "local"),)),
    ]
    local = next(c for c in result.calls if c.name == "~joint_states")
    assert local.conditions[0].parameters == (("local", "use_local_topics"),)
