"""A dependency of package.xml that names a Python library (jsk_fetch_startup's
``<run_depend>pyquaternion</run_depend>``, a rosdep key) is no ROS package: building
its class (``Quaternion(...)``) hides no ROS call, so the node is not partial
(PY_CLASS_UNSEEN "of ROS package pyquaternion" before)."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

MANIFEST = """<?xml version="1.0"?>
<package format="2">
  <name>p</name><version>0.0.1</version><description>d</description>
  <maintainer email="a@b.c">a</maintainer><license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
  <exec_depend>rospy</exec_depend>
  <exec_depend>pyquaternion</exec_depend>
  <exec_depend>other_ros_pkg</exec_depend>
</package>
"""


def _codes(tmp_path, module: str) -> list[str]:
    package = tmp_path / "src" / "p"
    (package / "scripts").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    (package / "CMakeLists.txt").write_text("project(p)\nfind_package(catkin REQUIRED)\n")
    source = package / "scripts" / "n.py"
    source.write_text(
        "import rospy\n"
        f"from {module} import Quaternion\n"
        "rospy.init_node('n')\n"
        "q = Quaternion(axis=[0, 0, 1], angle=0.5)\n"
        "pub = rospy.Publisher('out', rospy.AnyMsg, queue_size=1)\n")
    result = extract_python([str(source)], scan([str(tmp_path / "src")]), package="p")
    return [d.code for d in result.diagnostics]


def test_a_python_library_dependency_hides_no_ros_call(tmp_path):
    assert "PY_CLASS_UNSEEN" not in _codes(tmp_path, "pyquaternion")


def test_a_ros_package_dependency_still_may(tmp_path):
    assert "PY_CLASS_UNSEEN" in _codes(tmp_path, "other_ros_pkg")
