"""Stand-in gaps seen on robot_localization 1cb9533 (fiftieth session): ``std::setiosflags``
(filter_utilities.cpp), a ``boost::circular_buffer`` walked backwards
(robot_localization_estimator.cpp), ``Eigen::Translation3d`` times a quaternion
(ros_robot_localization_listener.cpp: Translation3d is ``Translation<double, 3>``) and
``applyOnTheLeft`` (ukf.cpp). Each left a C++ error in a function of the node, so a
call after it could be missed."""

from __future__ import annotations

import pytest
from conftest import package_xml
from standin_gap_checks import assert_call_found, ros1_main

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEAD = "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"

CASES = {
    "setiosflags": (
        "#include <iomanip>\n#include <sstream>\n",
        "  std::stringstream out;\n"
        "  out << std::setiosflags(std::ios::fixed) << std::setprecision(3) << 1.5\n"
        "      << std::resetiosflags(std::ios::fixed) << std::setbase(16) << 10;\n"),
    "circular_buffer_reverse": (
        "#include <boost/circular_buffer.hpp>\n",
        "  boost::circular_buffer<double> states(10);\n"
        "  for (boost::circular_buffer<double>::const_reverse_iterator it = states.rbegin();\n"
        "       it != states.rend(); ++it) ROS_INFO(\"%f\", *it);\n"),
    "translation_times_quaternion": (
        "#include <Eigen/Dense>\n#include <Eigen/Geometry>\n",
        "  Eigen::Vector3d position(1.0, 2.0, 3.0);\n"
        "  Eigen::Quaterniond orientation(1.0, 0.0, 0.0, 0.0);\n"
        "  Eigen::Affine3d pose(Eigen::Translation3d(position) * orientation);\n"
        "  Eigen::Translation3d shift(1.0, 0.0, 0.0);\n"),
    # ros_controllers' trajectory_interface.h: ``typename std::iterator_traits<It>::
    # value_type`` (every member of joint_trajectory_controller's class template after
    # it was an error)
    "iterator_traits": (
        "#include <iterator>\n#include <vector>\n",
        "  std::vector<double> values(3, 1.0);\n"
        "  typedef std::iterator_traits<std::vector<double>::iterator>::value_type Value;\n"
        "  typedef std::iterator_traits<const double*>::difference_type Distance;\n"
        "  Value first = values[0];\n  Distance d = 2;\n"),
    "apply_on_the_left": (
        "#include <Eigen/Dense>\n",
        "  Eigen::MatrixXd transfer(3, 3);\n"
        "  Eigen::VectorXd point(3);\n"
        "  point.applyOnTheLeft(transfer);\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros1_main(include, body))


def test_a_logger_level_set_before_the_node_s_calls_leaves_no_error(tmp_path) -> None:
    # m-explore 712bdd4's map_merge.cpp: ``ros::console::set_logger_level(
    # ROSCONSOLE_DEFAULT_NAME, ros::console::levels::Debug)`` then
    # ``ros::console::notifyLoggerLevelsChanged()`` at the top of main
    (tmp_path / "package.xml").write_text(package_xml("node"))
    source = tmp_path / "node.cpp"
    source.write_text(
        HEAD + "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"node\");\n"
        "  if (ros::console::set_logger_level(ROSCONSOLE_DEFAULT_NAME,\n"
        "                                     ros::console::levels::Debug)) {\n"
        "    ros::console::notifyLoggerLevelsChanged();\n  }\n"
        "  ros::console::Level level = ros::console::Warn;\n"
        "  ros::NodeHandle nh;\n"
        "  ros::Publisher pub = nh.advertise<std_msgs::String>(\"out\", 1);\n}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]


def test_glibc_s_sincos_leaves_no_error(tmp_path) -> None:
    # hector_quadrotor 9ba4441's attitude_controller.cpp: ``sincos(yaw, &sin_yaw,
    # &cos_yaw)`` (a GNU extension of <math.h>) beside its controller's calls
    (tmp_path / "package.xml").write_text(package_xml("node"))
    source = tmp_path / "node.cpp"
    source.write_text(
        HEAD + "#include <cmath>\nint main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"node\");\n  ros::NodeHandle nh;\n"
        "  double s, c;\n  sincos(0.5, &s, &c);\n  float sf, cf;\n  sincosf(0.5f, &sf, &cf);\n"
        "  ros::Publisher pub = nh.advertise<std_msgs::String>(\"out\", 1);\n}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
