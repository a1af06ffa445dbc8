"""A program whose code, with the package's modules it imports, imports no ROS client
(the standard library, numpy, pandas) makes no ROS call: the walk cut by its budget
loses nothing, and is not said (``PY_TOO_COMPLEX`` made the node partial).
lidar_localization_ros2 (617756fe) installs make_localization_comparison_report.py as a
program: argparse, csv, pandas and plotly, and more evaluation than the budget."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.evaluate.operations import Limits
from haros_arch.extract.python import extract_python, values
from haros_arch.workspace import scan

FAN = ["def f0(x):", "    return x + 1"]
for _level in range(1, 5):
    FAN += [f"def f{_level}(x):", "    return " + " + ".join([f"f{_level - 1}(x)"] * 8)]

REPORT = "\n".join([
    "import argparse", "import csv", "import numpy as np", "from pathlib import Path",
    "from helpers import fmt", *FAN, "print(fmt(f4(1)))", ""])


@pytest.mark.parametrize(("helper", "said"), [
    ("import math\nimport pandas as pd\n\ndef fmt(x):\n    return str(x)\n", False),
    # the helper imports a client library: its code may be where a call is
    ("import rclpy\n\ndef fmt(x):\n    return str(x)\n", True),
    # a module named at run time may be anything
    ("import importlib\n\ndef fmt(x):\n    return str(x)\n", True),
])
def test_a_cut_is_said_only_where_a_ros_call_may_be(write_tree, monkeypatch, helper,
                                                    said) -> None:
    monkeypatch.setattr(values.Evaluator, "limits", Limits(steps=20_000))
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/report.py": REPORT,
                         "pkg/scripts/helpers.py": helper})
    result = extract_python([str(folder / "pkg" / "scripts" / "report.py")],
                            scan([str(folder)]), package="pkg")
    assert result.calls == []
    assert ("PY_TOO_COMPLEX" in [d.code for d in result.diagnostics]) is said
