"""A ROS 2 parameter file whose every section is for a node name that none of the nodes
it is given to has sets nothing: rcl applies a section only to a node of its name
(clearpath_control's imu_filter.yaml, ``imu_filter:``, given to the node launched as
``imu_filter_node``: use_mag, fixed_frame, ... never reached the filter, and nothing
said so). LAUNCH_PARAMS_NO_NODE; not for a file one of whose sections matches, a file
of ``/**`` entries, nor a section a node of the process has (a made node's)."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

SETUP = """
    from setuptools import setup
    setup(name="imu", packages=["imu"],
          entry_points={"console_scripts": ["filter = imu.filt:main"]})
    """
NODE = """
    import rclpy
    from sensor_msgs.msg import Imu
    def main():
        rclpy.init()
        node = rclpy.create_node("imu_filter_node")
        mag = node.declare_parameter("use_mag", True).value
        node.create_subscription(Imu, "imu/data_raw", print, 10)
    """
LAUNCH = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        config = os.path.join(get_package_share_directory("imu"), "config", "{file}")
        return LaunchDescription([
            Node(package="imu", executable="filter", name="imu_filter_node",
                 parameters=[config]),
        ])
    """


def _check(write_tree, sections: str) -> list[tuple[str, str]]:
    root = write_tree({
        "src/imu/package.xml": package_xml("imu", "ament_python"),
        "src/imu/setup.py": SETUP,
        "src/imu/imu/__init__.py": "",
        "src/imu/imu/filt.py": NODE,
        "src/imu/config/filter.yaml": sections,
        "src/imu/launch/filter.launch.py": LAUNCH.format(file="filter.yaml"),
        "project.yaml": "project: p\nconfigurations:\n  c: [imu/launch/filter.launch.py]\n",
    })
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    return [(d["location"]["file"], d["message"]) for d in report["diagnostics"]
            if d["code"] == "LAUNCH_PARAMS_NO_NODE"]


def test_a_file_for_another_node_name_is_said(write_tree) -> None:
    found = _check(write_tree, "imu_filter:\n  ros__parameters:\n    use_mag: false\n")
    assert len(found) == 1
    file, message = found[0]
    assert file == "imu/launch/filter.launch.py"
    assert "given to /imu_filter_node" in message and "sections are for /imu_filter" in message


def test_a_file_whose_section_matches_or_sets_every_node_is_not(write_tree) -> None:
    assert _check(write_tree, "imu_filter_node:\n  ros__parameters:\n    use_mag: false\n"
                              "other:\n  ros__parameters:\n    x: 1\n") == []
    assert _check(write_tree, "/**:\n  ros__parameters:\n    use_mag: false\n") == []
    assert _check(write_tree, "/**/imu_filter_node:\n  ros__parameters:\n    use_mag: false\n"
                  ) == []


def _outside(write_tree, sections: str) -> list[tuple[str, str]]:
    root = write_tree({
        "src/imu/package.xml": package_xml("imu", "ament_python"),
        "src/imu/setup.py": SETUP,
        "src/imu/imu/__init__.py": "",
        "src/imu/imu/filt.py": NODE,
        "src/imu/config/filter.yaml": sections,
        "src/imu/launch/filter.launch.py": LAUNCH.format(file="filter.yaml"),
        "project.yaml": "project: p\nconfigurations:\n  c: [imu/launch/filter.launch.py]\n",
    })
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    return [(d["severity"], d["message"]) for d in report["diagnostics"]
            if d["code"] == "LAUNCH_PARAMS_OUTSIDE"]


def test_a_value_outside_ros__parameters_is_said(write_tree) -> None:
    """ouster-ros's os_sensor_cloud_image_params.yaml had ``ouster/os_image:`` with
    ``use_system_default_qos: false`` right under it, no ros__parameters level: a value
    of no node, and a file rcl refuses. The reader skipped such a section silently."""
    found = _outside(write_tree, "imu_filter_node:\n  ros__parameters:\n    use_mag: false\n"
                                 "ouster/os_image:\n  use_system_default_qos: false\n")
    assert found == [("error", "parameter file imu/config/filter.yaml: "
                      "ouster/os_image/use_system_default_qos hold a value outside "
                      "ros__parameters, a parameter of no node")]
    assert _outside(write_tree, "imu_filter_node:\n  ros__parameters:\n    use_mag: false\n"
                                "    nested:\n      a: 1\n") == []


SHARED_SETUP = """
    from setuptools import setup
    setup(name="imu", packages=["imu"],
          entry_points={"console_scripts": ["filter = imu.filt:main", "mux = imu.mux:main"]})
    """
MUX = """
    import rclpy
    def main():
        rclpy.init()
        node = rclpy.create_node("mux")
        node.declare_parameter("topics", "")
    """
SHARED_LAUNCH = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        config = os.path.join(get_package_share_directory("imu"), "config", "shared.yaml")
        return LaunchDescription([
            Node(package="imu", executable="filter", name="robot_filter",
                 parameters=[config]),
            Node(package="imu", executable="mux", parameters=[config]),
        ])
    """


def _shared(write_tree, sections: str) -> list[str]:
    root = write_tree({
        "src/imu/package.xml": package_xml("imu", "ament_python"),
        "src/imu/setup.py": SHARED_SETUP,
        "src/imu/imu/__init__.py": "",
        "src/imu/imu/filt.py": NODE,
        "src/imu/imu/mux.py": MUX,
        "src/imu/config/shared.yaml": sections,
        "src/imu/launch/shared.launch.py": SHARED_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [imu/launch/shared.launch.py]\n",
    })
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    return [d["message"] for d in report["diagnostics"] if d["code"] == "LAUNCH_PARAMS_NO_NODE"]


MUX_SECTION = "/mux:\n  ros__parameters:\n    topics: cmd\n"


def test_a_shared_file_s_section_under_the_name_the_launch_changed_is_said(write_tree) -> None:
    """go2_ros2_sdk's twist_mux.yaml, given to twist_mux (its ``/twist_mux:`` section)
    and to teleop_twist_joy's ``teleop_node`` launched as ``go2_teleop_node``, kept the
    teleop's axes and buttons under ``/teleop_node:``: the teleop ran on its defaults.
    Said for the node no section is for, where a section no node has is named after its
    executable or the name its code gives it; not for a section of another name (a node
    of another launch file may have it) nor when the node has its own section."""
    filt = ("/robot_filter", "/imu_filter_node")
    for section in ("/imu_filter_node", "/filter"):
        found = _shared(write_tree, f"{section}:\n  ros__parameters:\n    use_mag: false\n"
                                    + MUX_SECTION)
        assert found == [f"parameter file imu/config/shared.yaml is given to {filt[0]}, but "
                         f"its sections are for {section}: rcl gives their parameters to "
                         "none of them"]
    assert _shared(write_tree, "/other:\n  ros__parameters:\n    use_mag: false\n"
                               + MUX_SECTION) == []
    assert _shared(write_tree, "/robot_filter:\n  ros__parameters:\n    use_mag: false\n"
                               "/imu_filter_node:\n  ros__parameters:\n    use_mag: true\n"
                               + MUX_SECTION) == []


def test_a_shared_file_s_section_for_the_node_in_another_namespace_is_said(
        write_tree) -> None:
    """cabot-navigation's cabot2.launch.py started people_speed_control_node without the
    ``namespace='/cabot'`` its neighbours have; the shared cabot2-common.yaml keeps its
    settings under ``cabot: people_speed_control_node:``, so the node at
    ``/people_speed_control_node`` ran on its defaults. Said for the node no section is
    for, where a section no node has is the node's own name in another namespace; not
    for a section of a wildcard namespace (``/*/robot_filter`` is for a namespace the
    file does not name), nor when the node has its own section."""
    filt = "/robot_filter"
    found = _shared(write_tree, "/cabot/robot_filter:\n  ros__parameters:\n"
                                "    use_mag: false\n" + MUX_SECTION)
    assert found == [f"parameter file imu/config/shared.yaml is given to {filt}, but "
                     "its sections are for /cabot/robot_filter: rcl gives their parameters "
                     "to none of them"]
    assert _shared(write_tree, "/*/robot_filter:\n  ros__parameters:\n    use_mag: false\n"
                               + MUX_SECTION) == []
    assert _shared(write_tree, "/cabot/mux:\n  ros__parameters:\n    topics: cmd\n"
                               "/robot_filter:\n  ros__parameters:\n    use_mag: false\n"
                               + MUX_SECTION) == []


COMPONENT_CMAKE = """
    cmake_minimum_required(VERSION 3.5)
    project(scan)
    find_package(ament_cmake REQUIRED)
    find_package(rclcpp REQUIRED)
    find_package(rclcpp_components REQUIRED)
    add_library(scan_component SHARED src/scan.cpp)
    ament_target_dependencies(scan_component rclcpp rclcpp_components)
    rclcpp_components_register_node(scan_component PLUGIN "scan::ScanNode"
                                    EXECUTABLE scan_node)
    install(TARGETS scan_component LIBRARY DESTINATION lib)
    ament_package()
    """
COMPONENT_CPP = """
    #include <rclcpp/rclcpp.hpp>
    #include <rclcpp_components/register_node_macro.hpp>
    namespace scan {
    class ScanNode : public rclcpp::Node {
    public:
      explicit ScanNode(const rclcpp::NodeOptions & options) : rclcpp::Node("scan", options) {
        declare_parameter("range_max", 1.0);
      }
    };
    }  // namespace scan
    RCLCPP_COMPONENTS_REGISTER_NODE(scan::ScanNode)
    """
COMPONENT_LAUNCH = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import ComposableNodeContainer
    from launch_ros.descriptions import ComposableNode

    def generate_launch_description():
        config = os.path.join(get_package_share_directory("scan"), "config", "shared.yaml")
        return LaunchDescription([ComposableNodeContainer(
            name="box", namespace="", package="rclcpp_components",
            executable="component_container",
            composable_node_descriptions=[
                ComposableNode(package="scan", plugin="scan::ScanNode", name="front_scan",
                               parameters=[config]),
                ComposableNode(package="scan", plugin="scan::ScanNode", name="rear",
                               parameters=[config]),
            ])])
    """


def _component(write_tree, sections: str) -> list[str]:
    root = write_tree({
        "src/scan/package.xml": package_xml("scan", "ament_cmake"),
        "src/scan/CMakeLists.txt": COMPONENT_CMAKE,
        "src/scan/src/scan.cpp": COMPONENT_CPP,
        "src/scan/config/shared.yaml": sections,
        "src/scan/launch/scan.launch.py": COMPONENT_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [scan/launch/scan.launch.py]\n",
    })
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    return [d["message"] for d in report["diagnostics"] if d["code"] == "LAUNCH_PARAMS_NO_NODE"]


REAR = "rear:\n  ros__parameters:\n    range_max: 2.0\n"


def test_a_component_s_section_under_the_executable_that_runs_it_alone_is_said(
        write_tree) -> None:
    """cabot-navigation's cabot2.launch.py loaded pointcloud_to_laserscan's component as
    ``pointcloud_to_laserscan``; the shared cabot2-common.yaml kept its settings under
    ``pointcloud_to_laserscan_node:``, the executable the package registers for that
    component (rclcpp_components_register_node(... EXECUTABLE ...)), so the component ran
    on its defaults. Said for the component no section is for, where a section no node has
    is named after an executable of the component's own sources; not for a section of
    another name."""
    found = _component(write_tree, "scan_node:\n  ros__parameters:\n    range_max: 4.0\n"
                       + REAR)
    assert found == ["parameter file scan/config/shared.yaml is given to /front_scan, but its "
                     "sections are for /scan_node: rcl gives their parameters to none of "
                     "them"]
    assert _component(write_tree, "other_node:\n  ros__parameters:\n    range_max: 4.0\n"
                      + REAR) == []
