"""A member the parse does not know that takes a node made with a NodeOptions is not a
class the node is given to.

tf2_ros' TransformListener(buffer) makes a node of its own:
``optional_default_node_ = rclcpp::Node::make_shared("_", options);``. When tf2_ros itself
is extracted (its interface models), its header is our stand-in, which has no such
member: the name is unknown, and the statement passes a NodeOptions, so it read as the
options given to a class the parse does not know (CPP_NODE_TO_UNKNOWN): tf2_echo and
buffer_server partial for it, though ``rclcpp::Node::make_shared`` is known and the name
only receives its result. A name the statement assigns to is not what it passes the
node to; its own error still says what the parse missed."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

MAIN = """
    #include <memory>
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    class Echo : public rclcpp::Node {
     public:
      explicit Echo(const rclcpp::NodeOptions & options) : Node("echo", options) {
        sub_ = create_subscription<std_msgs::msg::String>(
          "in", 1, [](std_msgs::msg::String::SharedPtr) {});
        rclcpp::NodeOptions own;
        own.start_parameter_services(false);
        STATEMENT
      }
     private:
      rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
    };

    int main(int argc, char * argv[]) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Echo>(rclcpp::NodeOptions()));
    }
    """


def _node(write_tree: Any, statement: str) -> Any:
    root = write_tree({
        "src/e/package.xml": package_xml("e", build_type="ament_cmake"),
        "src/e/CMakeLists.txt": "project(e)\nadd_executable(echo src/echo.cpp)\n",
        "src/e/src/echo.cpp": MAIN.replace("STATEMENT", statement),
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for p in model.packages for n in p.nodes if n.name == "e/echo")


def test_an_unknown_member_assigned_a_node_is_not_given_the_options(write_tree: Any) -> None:
    node = _node(write_tree, 'helper_node_ = rclcpp::Node::make_shared("_", own);')
    assert not any("is given to" in r for r in node.completeness_reasons), \
        node.completeness_reasons
    # the unknown name is still an error in a function that calls the ROS API
    assert any("undeclared identifier 'helper_node_'" in r
               for r in node.completeness_reasons), node.completeness_reasons
    assert any(c.kind == "subscribe" and c.name == "in" for c in node.calls)


def test_an_unknown_class_built_with_the_options_is_still_given_them(
        write_tree: Any) -> None:
    node = _node(write_tree, "auto other = std::make_shared<vendor::Driver>(own);")
    assert any("the node (own) is given to vendor::Driver," in r
               for r in node.completeness_reasons), node.completeness_reasons
