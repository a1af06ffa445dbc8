"""ROS 1 ros_control: a hardware node builds its own ``controller_manager::
ControllerManager(&robot, nh)``, which serves ``controller_manager/load_controller``
(and the other manager services) in the namespace of the handle given (by default the
node's). controller_manager is installed, not in the workspace: its header is a stand-in
of FALLBACK, so the spawners' controllers are loaded into that node (plugins.attach.
ros1_controllers) instead of standing for instances of their own, and the node is not
partial for a class of another package it builds (ridgeback_base's ridgeback_node,
husky_base's husky_node)."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

HARDWARE = """
    #include <ros/ros.h>
    #include <controller_manager/controller_manager.h>
    #include <hardware_interface/robot_hw.h>
    #include <hardware_interface/joint_command_interface.h>

    class Robot : public hardware_interface::RobotHW {
     public:
      explicit Robot(ros::NodeHandle& pnh) { pnh.param("rate", rate_, 25.0); }
      void read() {}
      void write() {}
     private:
      double rate_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "base_node");
      ros::NodeHandle nh, pnh("~");
      Robot robot(pnh);
      ros::NodeHandle controller_nh("base");
      controller_manager::ControllerManager cm(&robot, controller_nh);
      controller_manager::ControllerManager other(&robot, ros::NodeHandle("arm"));
      controller_manager::ControllerManager third(&robot);
      ros::Rate rate(25.0);
      while (ros::ok()) {
        robot.read();
        cm.update(ros::Time::now(), ros::Duration(0.04));
        third.update(ros::Time::now(), ros::Duration(0.04), false);
        robot.write();
        rate.sleep();
      }
      return 0;
    }
    """

MANAGER = ("list_controllers", "list_controller_types", "load_controller",
           "unload_controller", "switch_controller", "reload_controller_libraries")


def _node(write_tree: Any) -> Any:
    xml = package_xml("robot_base", None).replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("roscpp", "controller_manager",
                                          "hardware_interface")) + "</package>")
    root = write_tree({
        "src/robot_base/package.xml": xml,
        "src/robot_base/CMakeLists.txt":
            "project(robot_base)\nadd_executable(base_node src/base.cpp)\n",
        "src/robot_base/src/base.cpp": HARDWARE,
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for p in model.packages for n in p.nodes if n.name == "robot_base/base_node")


def test_a_ros1_controller_manager_built_by_a_node_serves_its_services(write_tree: Any) -> None:
    node = _node(write_tree)
    servers = sorted((c.name, c.type) for c in node.calls if c.kind == "server")
    assert servers == sorted(
        [(f"{ns}controller_manager/{s}", "controller_manager_msgs/" + "".join(
            w.capitalize() for w in s.split("_"))) for s in MANAGER
         for ns in ("base/", "arm/", "")])
    assert ("read", "~rate") in [(c.kind, c.name) for c in node.calls]
    assert not any("ControllerManager" in r for r in node.completeness_reasons), \
        node.completeness_reasons


def test_ros2_code_naming_a_controller_manager_makes_no_ros1_service(write_tree: Any) -> None:
    # ros2_control's ControllerManager is a node of its own, modelled from its sources
    # or its interface model: the ROS 1 row makes no call in ROS 2 code
    root = write_tree({
        "src/cm/package.xml": package_xml("cm", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/cm/CMakeLists.txt": "project(cm)\nadd_executable(cm src/cm.cpp)\n",
        "src/cm/include/controller_manager/controller_manager.hpp":
            "#include <rclcpp/rclcpp.hpp>\nnamespace controller_manager {\n"
            "class ControllerManager : public rclcpp::Node {\n public:\n"
            "  explicit ControllerManager(const std::string& name = \"controller_manager\")"
            " : rclcpp::Node(name) {}\n};\n}\n",
        "src/cm/src/cm.cpp":
            "#include <controller_manager/controller_manager.hpp>\n"
            "int main(int argc, char** argv) {\n  rclcpp::init(argc, argv);\n"
            "  auto cm = std::make_shared<controller_manager::ControllerManager>();\n"
            "  controller_manager::ControllerManager other(\"other\");\n"
            "  rclcpp::spin(cm);\n}\n",
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.name == "cm/cm")
    assert [c for c in node.calls if c.kind == "server"] == []


def test_controller_manager_sources_in_the_workspace_are_read_instead(write_tree: Any) -> None:
    # with ros_control's sources in the workspace its header is no stand-in: the node
    # takes the services its code advertises, not the stand-in's row as well
    xml = package_xml("controller_manager", None).replace(
        "</package>", "<depend>roscpp</depend></package>")
    root = write_tree({
        "src/controller_manager/package.xml": xml,
        "src/controller_manager/CMakeLists.txt":
            "project(controller_manager)\nfind_package(catkin REQUIRED)\n"
            "catkin_package(INCLUDE_DIRS include LIBRARIES controller_manager)\n"
            "add_library(controller_manager src/controller_manager.cpp)\n",
        "src/controller_manager/include/controller_manager/controller_manager.h":
            "#include <ros/ros.h>\n#include <std_srvs/Empty.h>\n"
            "namespace controller_manager {\nclass ControllerManager {\n public:\n"
            "  ControllerManager(void* hw, const ros::NodeHandle& nh = ros::NodeHandle());\n"
            "  bool load(std_srvs::Empty::Request&, std_srvs::Empty::Response&);\n"
            " private:\n  ros::NodeHandle cm_node_;\n  ros::ServiceServer srv_;\n};\n}\n",
        "src/controller_manager/src/controller_manager.cpp":
            "#include <controller_manager/controller_manager.h>\n"
            "namespace controller_manager {\n"
            "ControllerManager::ControllerManager(void* hw, const ros::NodeHandle& nh)\n"
            "    : cm_node_(nh, \"controller_manager\") {\n"
            "  srv_ = cm_node_.advertiseService(\"load_controller\",\n"
            "                                   &ControllerManager::load, this);\n"
            "}\n"
            "bool ControllerManager::load(std_srvs::Empty::Request&, std_srvs::Empty::Response&)"
            " { return true; }\n}\n",
        "src/robot_base/package.xml": package_xml("robot_base", None).replace(
            "</package>", "<depend>roscpp</depend><depend>controller_manager</depend>"
                          "</package>"),
        "src/robot_base/CMakeLists.txt":
            "project(robot_base)\nfind_package(catkin REQUIRED COMPONENTS controller_manager)\n"
            "add_executable(base_node src/base.cpp)\n"
            "target_link_libraries(base_node ${catkin_LIBRARIES})\n",
        "src/robot_base/src/base.cpp":
            "#include <ros/ros.h>\n#include <controller_manager/controller_manager.h>\n"
            "int main(int argc, char** argv) {\n  ros::init(argc, argv, \"base_node\");\n"
            "  ros::NodeHandle nh;\n  int robot = 0;\n"
            "  controller_manager::ControllerManager cm(&robot, nh);\n  ros::spin();\n}\n",
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.name == "robot_base/base_node")
    servers = [c for c in node.calls if c.kind == "server"]
    assert servers and all(c.location.file.endswith("controller_manager.cpp")
                           for c in servers), [(c.name, c.location.file) for c in servers]
