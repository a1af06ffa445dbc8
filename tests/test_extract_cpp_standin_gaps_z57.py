"""Stand-in gaps seen on real code (bench/README, survey Z57): consai_ros2's
geometry_tools.hpp keeps ``std::complex<double>`` members, its ControlParams compares two
``std::tie(...)`` tuples, its controller takes gains as ``_Float64`` (glibc's typedef for
a C++ compiler without the type); lidar_localization_ros2 compares a
``steady_clock::time_point`` with a default one. The stand-ins had no ``std::complex``,
no tuple comparison, no ``_Float64`` and no ``==`` / ``!=`` / ``<=`` / ``-=`` of a
time_point: each was a C++ error (or a name declared permissively)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <chrono>
#include <cmath>
#include <complex>
#include <tuple>

struct Params {
  double a = 0.0;
  _Float64 b = 1.0;
  auto tie() const { return std::tie(a, b); }
  bool operator==(const Params & other) const { return tie() == other.tie(); }
  bool operator!=(const Params & other) const { return tie() != other.tie(); }
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
  std::complex<double> center(1.0, 2.0);
  std::complex<double> rotation = std::polar(1.0, 0.5);
  const auto moved = (std::complex<double>(3.0, 4.0) - center) * std::conj(rotation);
  const double angle = std::arg(moved) + std::abs(moved) + moved.real() * 2.0;
  std::chrono::steady_clock::time_point last{};
  last -= std::chrono::milliseconds(5);
  const bool set = last != std::chrono::steady_clock::time_point{} &&
    last <= std::chrono::steady_clock::now();
  Params p, q;
  if (set || p == q || angle > 0.0) {
    auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);
  }
  rclcpp::spin(node);
}
"""


def test_complex_tuple_compare_float64_time_point_equality(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]


EIGEN = """#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/pose.hpp>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <tf2_eigen/tf2_eigen.hpp>

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
  Eigen::Matrix2d information = Eigen::Matrix2d::Identity();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(information);
  const bool solved = solver.info() == Eigen::Success;
  Eigen::MatrixXd a(4, 4);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
  const Eigen::MatrixXd null_space = lu.kernel();
  const auto rows = a.middleRows(1, 2);
  Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();
  const Eigen::Vector3f angles = rotation.eulerAngles(0, 1, 2);
  Eigen::Quaterniond quat(1.0, 0.0, 0.0, 0.0);
  geometry_msgs::msg::Pose pose;
  pose.orientation = tf2::toMsg(quat);
  geometry_msgs::msg::Quaternion q = tf2::toMsg(quat);
  pose.position = tf2::toMsg(Eigen::Vector3d(1.0, 2.0, 3.0));
  geometry_msgs::msg::Pose other = tf2::toMsg(Eigen::Isometry3d::Identity());
  if (solved && lu.dimensionOfKernel() > 0 && rows.rows() == 2 && angles(0) == 0.0 &&
      null_space.cols() > 0 && q.w == 1.0 && other.position.x == 0.0) {
    auto pub = node->create_publisher<geometry_msgs::msg::Pose>("out", 10);
  }
  rclcpp::spin(node);
}
"""


def test_eigen_solver_info_kernel_euler_angles_and_tf2_eigen_to_msg(tmp_path) -> None:
    """lidar_localization_ros2 (617756fe): ``solver.info() != Eigen::Success``
    (localizability_policy.hpp:48), ``lu.kernel()`` / ``dimensionOfKernel()`` and
    ``middleRows`` (exact_quadratic_coreset.hpp), ``R.eulerAngles(0, 1, 2)``
    (diagnostic_ndt_omp.hpp:36) and ``tf2::toMsg(quat_eig)`` to a Quaternion
    (lidar_localization_component.cpp:1673) were C++ errors of the stand-ins."""
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(EIGEN)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
