"""A package.xml dependency that is a Python library's import name (``cv2``, ``numpy``)
or a ROS package whose Python binding makes no ROS call (``lanelet2``'s map reading,
projection and routing) hides no ROS call where the node builds one of its classes.
navigation2_dynamic (ros-planning, 6eae17e) kf_hungarian_tracker depends on ``cv2`` and
builds ``cv2.KalmanFilter`` for each obstacle (obstacle_class.py:37); autoware_mini
(UT-ADL, f0a4c3e) builds ``lanelet2.projection.UtmProjector`` and
``lanelet2.routing.RoutingGraph`` in six nodes. Each was partial (PY_CLASS_UNSEEN "of
ROS package cv2"), so nothing it published or subscribed could be said missing; so was
adl-ros2's fr3_interface for ``pinocchio.SE3`` and two of ros2-rover's nodes for
``rknn.api.RKNN`` (bench/README, helper surveyP)."""

from __future__ import annotations

import pytest

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

MANIFEST = """<?xml version="1.0"?>
<package format="2">
  <name>p</name><version>0.0.1</version><description>d</description>
  <maintainer email="a@b.c">a</maintainer><license>MIT</license>
  <buildtool_depend>ament_python</buildtool_depend>
  <exec_depend>rclpy</exec_depend>
  <exec_depend>{dependency}</exec_depend>
</package>
"""


def _codes(tmp_path, dependency: str, built: str) -> list[str]:
    package = tmp_path / "src" / "p"
    (package / "p").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(dependency=dependency))
    source = package / "p" / "n.py"
    source.write_text(
        "import rclpy\n"
        f"import {dependency}\n"
        "from std_msgs.msg import String\n"
        "rclpy.init()\n"
        "node = rclpy.create_node('n')\n"
        f"thing = {built}\n"
        "pub = node.create_publisher(String, 'out', 10)\n")
    result = extract_python([str(source)], scan([str(tmp_path / "src")]), package="p")
    assert [c.name for c in result.calls if c.kind == "publish"] == ["out"]
    return [d.code for d in result.diagnostics]


@pytest.mark.parametrize("dependency,built", [
    ("cv2", "cv2.KalmanFilter(4, 2)"),
    ("lanelet2", "lanelet2.projection.UtmProjector(lanelet2.io.Origin(58.3, 26.7))"),
    # adl-ros2 (McGill ADL, f64e5b1) fr3_interface.py:134: a pose of the arm's model
    ("pinocchio", "pinocchio.SE3(pinocchio.Quaternion(1.0, 0.0, 0.0, 0.0), [0.0, 0.0, 0.0])"),
    ("crocoddyl", "crocoddyl.ShootingProblem(x0, [], terminal)"),
    # ros2-rover (bensonjohnson, f4db791) ppo_manager_rtab.py:414: the policy on the NPU
    ("rknn", "rknn.api.RKNN(verbose=False)")])
def test_a_library_class_hides_no_ros_call(tmp_path, dependency, built) -> None:
    assert "PY_CLASS_UNSEEN" not in _codes(tmp_path, dependency, built)


def test_a_ros_package_class_still_may(tmp_path) -> None:
    assert "PY_CLASS_UNSEEN" in _codes(tmp_path, "other_ros_pkg", "other_ros_pkg.Client()")
