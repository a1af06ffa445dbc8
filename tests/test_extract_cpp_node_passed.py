"""A node that builds a class of another package with itself (``*this``, its handle) runs
that class's constructor, whose ROS calls are not read when its code is in the other
package's sources: the node is partial there (CPP_NODE_PASSED). A constructor whose code
the unit has (a header's inline one) or a class of the node's own package is read as
usual. Autoware's trajectory follower builds its MPC and PID controllers so, and they
declare the node's parameters."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LIB_HEADER = """
    #include <rclcpp/rclcpp.hpp>
    namespace lateral {
    class Mpc {
     public:
      explicit Mpc(rclcpp::Node & node)BODY
     private:
      double horizon_{0.0};
    };
    }  // namespace lateral
    """

LIB_SOURCE = """
    #include "lateral/mpc.hpp"
    namespace lateral {
    Mpc::Mpc(rclcpp::Node & node) { horizon_ = node.declare_parameter<double>("horizon"); }
    }  // namespace lateral
    """

NODE = """
    #include <memory>
    #include <rclcpp/rclcpp.hpp>
    #include "lateral/mpc.hpp"

    class Controller : public rclcpp::Node {
     public:
      Controller() : Node("controller") {
        rate_ = declare_parameter<double>("rate", 30.0);
        mpc_ = std::make_shared<lateral::Mpc>(*this);
      }
     private:
      double rate_;
      std::shared_ptr<lateral::Mpc> mpc_;
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Controller>());
    }
    """


def _node(write_tree: Any, body: str, with_source: bool) -> Any:
    files = {
        "src/lateral/package.xml": package_xml("lateral", build_type="ament_cmake"),
        "src/lateral/CMakeLists.txt": "project(lateral)\nadd_library(lateral src/mpc.cpp)\n",
        "src/lateral/include/lateral/mpc.hpp": LIB_HEADER.replace("BODY", body),
        "src/control/package.xml": package_xml("control", build_type="ament_cmake"),
        "src/control/CMakeLists.txt":
            "project(control)\nadd_executable(controller src/controller.cpp)\n"
            "install(TARGETS controller DESTINATION lib/${PROJECT_NAME})\n",
        "src/control/src/controller.cpp": NODE,
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    }
    if with_source:
        files["src/lateral/src/mpc.cpp"] = LIB_SOURCE
    root = write_tree(files)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for p in model.packages for n in p.nodes if n.name == "control/controller")


def test_a_node_given_to_another_packages_constructor_is_partial(write_tree: Any) -> None:
    node = _node(write_tree, ";", True)
    assert node.completeness == "partial"
    assert any("lateral::Mpc of package lateral is built with the node (*this)" in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_a_constructor_the_unit_reads_leaves_the_node_complete(write_tree: Any) -> None:
    node = _node(write_tree, ' { horizon_ = node.declare_parameter<double>("horizon"); }',
                 False)
    assert node.completeness == "complete", node.completeness_reasons
    # the inline constructor's call is read as the node's
    assert "horizon" in [c.name for c in node.calls]


TEMPLATE_HEADER = """
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    namespace lateral {
    template<typename NodeT>
    class Mpc {
     public:
      template<typename T>
      Mpc(NodeT * node, T gain) { horizon_ = node->template declare_parameter<double>("horizon"); }
     private:
      double horizon_{0.0};
    };
    }  // namespace lateral
    """


def test_a_header_template_constructor_is_read(write_tree: Any) -> None:
    # nav2's TwistSubscriber, Autoware's PlanningFactorInterfaceT: class templates and
    # template constructors whose code is in the header the unit includes
    files = {
        "src/lateral/package.xml": package_xml("lateral", build_type="ament_cmake"),
        "src/lateral/CMakeLists.txt": "project(lateral)\n",
        "src/lateral/include/lateral/mpc.hpp": TEMPLATE_HEADER,
        "src/control/package.xml": package_xml("control", build_type="ament_cmake"),
        "src/control/CMakeLists.txt":
            "project(control)\nadd_executable(controller src/controller.cpp)\n",
        "src/control/src/controller.cpp": NODE.replace(
            "std::shared_ptr<lateral::Mpc> mpc_", "std::shared_ptr<lateral::Mpc<Controller>> mpc_"
        ).replace("std::make_shared<lateral::Mpc>(*this)",
                  "std::make_shared<lateral::Mpc<Controller>>(this, 2.0)"),
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    }
    root = write_tree(files)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.name == "control/controller")
    assert node.completeness == "complete", node.completeness_reasons


def test_a_ros1_node_handle_given_to_another_packages_constructor(write_tree: Any) -> None:
    files = {
        "src/driver/package.xml": package_xml("driver"),
        "src/driver/CMakeLists.txt": "project(driver)\nadd_library(driver src/driver.cpp)\n",
        "src/driver/include/driver/driver.h":
            "#include <ros/ros.h>\nnamespace driver {\nclass Driver {\n public:\n"
            "  Driver(ros::NodeHandle nh, ros::NodeHandle private_nh);\n};\n}\n",
        "src/driver/src/driver.cpp":
            '#include "driver/driver.h"\nnamespace driver {\n'
            "Driver::Driver(ros::NodeHandle nh, ros::NodeHandle private_nh) {\n"
            '  int rate; private_nh.param("rate", rate, 10);\n}\n}\n',
        "src/bringup/package.xml": package_xml("bringup"),
        "src/bringup/CMakeLists.txt":
            "project(bringup)\nadd_executable(driver_node src/node.cpp)\n",
        "src/bringup/src/node.cpp":
            '#include <ros/ros.h>\n#include "driver/driver.h"\n'
            "int main(int argc, char** argv) {\n"
            '  ros::init(argc, argv, "driver");\n'
            '  ros::NodeHandle nh, private_nh("~");\n'
            "  driver::Driver d(nh, private_nh);\n  ros::spin();\n}\n",
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    }
    root = write_tree(files)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.name == "bringup/driver_node")
    assert node.completeness == "partial"
    assert any("driver::Driver of package driver is built with the node (nh)" in r
               for r in node.completeness_reasons), node.completeness_reasons


# A vendor library's helper the workspace does not have (Autoware's autoware_utils:
# ``get_or_declare_parameter<T>(node, name)``) is given the node: what it reads or
# declares on it is unseen (CPP_NODE_TO_UNKNOWN), the node is partial.
UNKNOWN_HELPER = """
    #include <rclcpp/rclcpp.hpp>
    #include <vendor_utils/parameter.hpp>

    class Checker : public rclcpp::Node {
     public:
      Checker() : Node("checker") {
        rate_ = declare_parameter<double>("rate", 10.0);
        load(*this);
      }
     private:
      void load(rclcpp::Node & node) {
        threshold_ = vendor_utils::get_or_declare_parameter<double>(node, "threshold");
      }
      double rate_{0.0};
      double threshold_{0.0};
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Checker>());
    }
    """


def _checker(write_tree: Any, code: str) -> Any:
    root = write_tree({
        "src/check/package.xml": package_xml("check", build_type="ament_cmake"),
        "src/check/CMakeLists.txt":
            "project(check)\nadd_executable(checker src/checker.cpp)\n",
        "src/check/src/checker.cpp": code,
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for p in model.packages for n in p.nodes if n.name == "check/checker")


def test_the_node_given_to_an_undeclared_helper_makes_it_partial(write_tree: Any) -> None:
    # the helper's error is in a function that calls no ROS API: no name is declared,
    # the statement that passes the node is read from the text around the error
    node = _checker(write_tree, UNKNOWN_HELPER)
    assert node.completeness == "partial"
    assert any("the node (node) is given to vendor_utils" in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_the_node_given_to_a_name_declared_permissively(write_tree: Any) -> None:
    # a member of an unknown type (an error in a declaration) gets the unit's unknown names
    # declared; the helper's call then resolves to a declared name and is said so
    code = UNKNOWN_HELPER.replace("      double rate_{0.0};\n",
                                  "      double rate_{0.0};\n      vendor_utils::Logger log_;\n")
    node = _checker(write_tree, code)
    assert node.completeness == "partial"
    assert any("is given to vendor_utils::get_or_declare_parameter<double>" in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_an_undeclared_name_without_the_node_leaves_it_complete(write_tree: Any) -> None:
    code = UNKNOWN_HELPER.replace(
        'vendor_utils::get_or_declare_parameter<double>(node, "threshold")',
        'vendor_utils::clamp(rate_, 0.0)')
    node = _checker(write_tree, code)
    assert node.completeness == "complete", node.completeness_reasons


# a node builds a vendor's marker server (as interactive_marker_twist_server built
# interactive_markers' before its stand-in) with ``std::make_unique<...>("twist_server",
# get_node_base_interface(), ..., get_node_topics_interface(), ...)``: the class, declared
# permissively (its library is not in the workspace), publishes and subscribes on the node
# through the interfaces the factory hands its constructor
FACTORY_MADE = """
    #include <rclcpp/rclcpp.hpp>
    #include <vendor_markers/marker_server.hpp>

    class Checker : public rclcpp::Node {
     public:
      Checker()
      : Node("checker"),
        server_(std::make_unique<vendor_markers::MarkerServer>(
          "twist_server", get_node_base_interface(), get_node_topics_interface()))
      {
        rate_ = declare_parameter<double>("rate", 10.0);
      }
     private:
      std::unique_ptr<vendor_markers::MarkerServer> server_;
      double rate_{0.0};
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Checker>());
    }
    """


def test_the_node_given_to_a_factory_of_a_class_declared_permissively(
        write_tree: Any) -> None:
    node = _checker(write_tree, FACTORY_MADE)
    assert node.completeness == "partial"
    assert any("is given to vendor_markers::MarkerServer" in r
               for r in node.completeness_reasons), node.completeness_reasons
    # a factory of a class the parse knows is read as before
    known = _checker(write_tree, FACTORY_MADE.replace(
        "#include <vendor_markers/marker_server.hpp>",
        "namespace vendor_markers { struct MarkerServer {\n"
        "  template <class... A> MarkerServer(A &&...) {} }; }"))
    assert known.completeness == "complete", known.completeness_reasons
