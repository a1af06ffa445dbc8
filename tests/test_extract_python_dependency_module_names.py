"""A ROS package's Python module may be named after the package with a suffix: its
setup.py installs what it likes (mas_common_robotics' mcr_manipulation_pose_selector
installs ``mcr_manipulation_pose_selector_ros``, whose ``PoseSelector`` reads ``~arm``
and ``~move_group`` and waits for the move_group action). mas_industrial_robotics'
pregrasp_planner_node builds that class: the node was complete, and parameter-set-not-
read said its launch file's ``arm`` and ``move_group`` were read by no node (survey
surveyB). A class of a module so named after a dependency the workspace does not hold is
an unseen class (PY_CLASS_UNSEEN, of that package); one of a module named after no
dependency, or of a library known to make no ROS call, is not."""

from __future__ import annotations

import pytest

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

MANIFEST = """<?xml version="1.0"?>
<package format="2">
  <name>p</name><version>0.0.1</version><description>d</description>
  <maintainer email="a@b.c">a</maintainer><license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
  <exec_depend>rospy</exec_depend>
  <exec_depend>mcr_pose_selector</exec_depend>
</package>
"""


def _said(tmp_path, module: str) -> list[str]:
    package = tmp_path / "src" / "p"
    (package / "scripts").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    source = package / "scripts" / "n.py"
    source.write_text(
        "import rospy\n"
        f"import {module}.selector\n"
        "from std_msgs.msg import String\n"
        "rospy.init_node('n')\n"
        f"selector = {module}.selector.PoseSelector()\n"
        "pub = rospy.Publisher('out', String, queue_size=1)\n")
    result = extract_python([str(source)], scan([str(tmp_path / "src")]), package="p")
    assert [c.name for c in result.calls if c.kind == "publish"] == ["out"]
    return [d.message for d in result.diagnostics if d.code == "PY_CLASS_UNSEEN"]


def test_a_module_named_after_a_dependency_with_a_suffix_is_that_package(tmp_path):
    (said,) = _said(tmp_path, "mcr_pose_selector_ros")
    assert "PoseSelector" in said and "ROS package mcr_pose_selector " in said


@pytest.mark.parametrize("module", ["mcr_pose", "other_tools", "numpy_ros"])
def test_a_module_named_after_no_dependency_is_not(tmp_path, module):
    assert _said(tmp_path, module) == []
