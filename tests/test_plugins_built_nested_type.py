"""A plugin that builds an object of a type nested in a name (``make_shared<
SpinAction::Feedback>()``) builds that nested type, not the class the name may also be
in another package: nav2_behaviors' Spin (``using SpinAction = nav2_msgs::action::Spin;
feedback_(std::make_shared<SpinAction::Feedback>())``, spin.cpp:33) was given the file of
nav2_behavior_tree's BT node ``SpinAction`` (spin_action.cpp), and with it that node's
action client and C++ errors (``inherit.built_sources``)."""

from __future__ import annotations

from haros_arch.plugins.inherit import built_sources
from haros_arch.workspace import scan

MANIFEST = ("<package format='2'><name>{}</name><version>1.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
            "<license>BSD</license></package>")


def test_a_type_nested_in_a_name_does_not_build_the_class_of_that_name(write_tree):
    root = write_tree({
        "tree/package.xml": MANIFEST.format("tree"),
        "tree/src/spin_action.cpp": (
            "#include <rclcpp/rclcpp.hpp>\nnamespace tree {\n"
            "SpinAction::SpinAction(rclcpp::Node::SharedPtr node) {\n"
            "  node->declare_parameter(\"spin_dist\", 1.57);\n}\n}\n"),
        "tree/src/helper.cpp": (
            "#include <rclcpp/rclcpp.hpp>\nnamespace tree {\n"
            "Helper::Helper(rclcpp::Node::SharedPtr node) {\n"
            "  node->declare_parameter(\"helper\", 1);\n}\n}\n"),
        "behaviors/package.xml": MANIFEST.format("behaviors"),
        "behaviors/src/spin.cpp": (
            "#include <rclcpp/rclcpp.hpp>\n"
            "using SpinAction = actions::Spin;\n"
            "class Spin {\n public:\n"
            "  Spin() : feedback_(std::make_shared<SpinAction::Feedback>()),\n"
            "    helper_(std::make_shared<tree::Helper>(nullptr)) {}\n"
            "  std::shared_ptr<SpinAction::Feedback> feedback_;\n"
            "  std::shared_ptr<tree::Helper> helper_;\n};\n"),
    })
    workspace = scan([str(root)])
    files = ["tree/src/spin_action.cpp", "tree/src/helper.cpp"]
    # the class it does build is followed; the one only a qualifier names is not
    assert built_sources(["behaviors/src/spin.cpp"], workspace,
                         lambda: [files]) == ["tree/src/helper.cpp"]
