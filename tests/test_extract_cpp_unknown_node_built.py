"""A ROS 2 executable that builds, beside its own node, an object of a class the parse
does not know (its package's header is missing) with a ``NodeOptions``: that object is
a node of its own in the process (a component class, raspimouse_ros2_examples'
``line_follower`` runs ``raspimouse::Raspimouse`` so), whose interface is unseen. The
node is partial (CPP_NODE_TO_UNKNOWN), so the checks that claim an absence do not decide
around it. A local variable named after the class's namespace (``auto raspimouse =
std::make_shared<raspimouse::Raspimouse>(options)``, where C++ looks the name before
``::`` up among namespaces and types only) does not hide the namespace."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

MAIN = """
    #include <memory>
    #include <rclcpp/rclcpp.hpp>
    #include "mouse/mouse_component.hpp"

    class Follower : public rclcpp::Node {
     public:
      explicit Follower(const rclcpp::NodeOptions & options) : Node("follower", options) {
        sub_ = create_subscription<std_msgs::msg::String>(
          "switches", 1, [](std_msgs::msg::String::SharedPtr) {});
      }
     private:
      rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
      MEMBER
    };

    int main(int argc, char * argv[]) {
      rclcpp::init(argc, argv);
      rclcpp::executors::SingleThreadedExecutor exec;
      rclcpp::NodeOptions options;
      auto VAR = std::make_shared<mouse::Mouse>(ARGS);
      auto follower = std::make_shared<Follower>(options);
      exec.add_node(VAR->get_node_base_interface());
      exec.add_node(follower);
      exec.spin();
    }
    """


def _node(write_tree: Any, var: str, args: str = "options", member: str = "") -> Any:
    root = write_tree({
        "src/follow/package.xml": package_xml("follow", build_type="ament_cmake"),
        "src/follow/CMakeLists.txt":
            "project(follow)\nadd_executable(follower src/follower.cpp)\n",
        "src/follow/src/follower.cpp":
            MAIN.replace("VAR", var).replace("ARGS", args).replace("MEMBER", member),
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for p in model.packages for n in p.nodes if n.name == "follow/follower")


def test_an_unknown_class_built_with_node_options_makes_the_node_partial(
        write_tree: Any) -> None:
    # the error on the unknown name is in ``main``, which makes no ROS call but this:
    # no name is declared, the statement that passes the options is read from its text
    node = _node(write_tree, "driver")
    assert node.completeness == "partial", node.completeness_reasons
    assert any("the node (options) is given to mouse::Mouse," in r
               for r in node.completeness_reasons), node.completeness_reasons
    assert any(c.kind == "subscribe" and c.name == "switches" for c in node.calls)


def test_a_variable_named_after_the_namespace_does_not_hide_it(write_tree: Any) -> None:
    node = _node(write_tree, "mouse")
    assert node.completeness == "partial", node.completeness_reasons
    assert any("the node (options) is given to mouse::Mouse," in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_an_unknown_class_declared_permissively_built_with_options(write_tree: Any) -> None:
    # a member of an unknown type (an error in a declaration) gets the unit's unknown
    # names declared: the construction then resolves to the declared class
    node = _node(write_tree, "driver", member="mouse::Config config_;")
    assert node.completeness == "partial", node.completeness_reasons
    assert any("the node (options) is given to mouse::Mouse," in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_an_unknown_class_built_without_options_leaves_it_complete(
        write_tree: Any) -> None:
    node = _node(write_tree, "driver", args="")
    assert node.completeness == "complete", node.completeness_reasons
