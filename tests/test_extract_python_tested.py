"""rospy.has_param / rclpy has_parameter whose result is a condition are ``tested``:
the code handles the parameter's absence. A value read in a condition is not."""

from __future__ import annotations

import os

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "python", "tested_params")


def _reads(package: str, path: str) -> list[tuple[str, bool]]:
    result = extract_python([os.path.join(ROOT, "src", package, path)], scan([ROOT]),
                            package=package)
    return [(c.name, c.tested) for c in result.calls if c.kind == "read"]


def test_rospy_has_param_tested() -> None:
    assert _reads("pyteleop", "scripts/teleop.py") == [
        ("~turbo", True),    # if rospy.has_param(..)
        ("~turbo", False),   # the get_param under it
        ("~frame", True),    # if not rospy.has_param(..)
        ("~scale", True),    # x if rospy.has_param(..) else y
        ("~ready", True),    # ... or rospy.has_param(..)
        ("~known", False),   # held, never tested
        ("~plain", False),
    ]


def test_rclpy_has_parameter_tested() -> None:
    assert _reads("pyteleop2", "pyteleop2/teleop.py") == [
        ("turbo", True),   # while not self.has_parameter(..)
        ("frame", False),  # result dropped
        ("scale", False),  # get_parameter_or: a default instead
        ("plain", False),  # get_parameter(..).value: the value, not whether it is set
    ]
