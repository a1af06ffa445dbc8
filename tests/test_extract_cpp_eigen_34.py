"""Eigen 3.4 and array idioms the Eigen stand-in lacked (control_quadrupeds_soft_contacts'
planners and whole-body controller): a range-for over a vector's coefficients (3.4's
STL iterators), a scalar on the left of an array sum or difference (``1 - t``,
``3 - v.array()``), an array's negation, triangular views, a sub-diagonal, FullPivLU's
threshold and permutations. Each was a C++ parse error (a call near one may be lost);
the node's calls are the same with none."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <Eigen/Dense>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

using namespace Eigen;

class Planner : public rclcpp::Node {
public:
  Planner() : Node("planner") {
    pub_ = create_publisher<std_msgs::msg::Float64>("height", 10);
    Vector3d v(1.0, 2.0, 3.0);
    for (double c : v) {
      std_msgs::msg::Float64 m;
      m.data = c;
      pub_->publish(m);
    }
    Array2d t = Vector2d::Zero();
    Array2d b = 1 - t;
    Array2d d = - t + b;
    Vector2d e = 3 - v.head<2>().array() - 2 * t;
    MatrixXd M = MatrixXd::Zero(3, 3);
    M.triangularView<StrictlyLower>() = M.transpose();
    Vector3d x = M.triangularView<Upper>().solve(v);
    M.diagonal(-1).setOnes();
    FullPivLU<MatrixXd> lu(M);
    lu.setThreshold(1e-6);
    MatrixXd P = lu.permutationP() * M * lu.permutationQ();
    (void)d; (void)e; (void)x; (void)P;
  }
private:
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
"""


def test_eigen_34_iterators_array_scalars_and_views_parse(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    errors = [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "height")]
