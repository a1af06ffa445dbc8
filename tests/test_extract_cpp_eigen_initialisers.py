"""Eigen 3.4's constructors from coefficients: a fixed vector of five or more scalars
(MoveIt servo's demo: ``TwistCommand target_twist{"panda_link0", {0.0, 0.0, 0.05, 0.0,
0.0, 0.4}}``, an ``Eigen::Vector<double, 6>`` member) and a matrix from its rows
(``Eigen::Matrix3d m{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}``). Without them each was an
error in a function that makes ROS calls, and the node was partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist_stamped.hpp>
#include <Eigen/Dense>

struct TwistCommand
{
  std::string frame_id;
  Eigen::Vector<double, 6> velocities;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("demo_twist");
  TwistCommand target_twist{"panda_link0", {0.0, 0.0, 0.05, 0.0, 0.0, 0.4}};
  Eigen::Matrix3d m{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  Eigen::Vector3d v(1.0, 2.0, 3.0);
  Eigen::Vector4d w(1.0, 2.0, 3.0, 4.0);
  Eigen::VectorXd x(7);
  auto pub = node->create_publisher<geometry_msgs::msg::TwistStamped>("twist", 1);
  (void)target_twist; (void)m; (void)v; (void)w; (void)x;
}
"""


def test_eigen_vectors_and_matrices_from_coefficients(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("demo", "ament_cmake"))
    source = tmp_path / "demo.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "twist")]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
