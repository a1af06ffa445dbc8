"""Parameter reads whose result (whether the parameter is there) the code tests are
``tested``: they handle the parameter's absence (teleop_twist_joy's
``if (nh.getParam(..))``, interactive_marker_twist_server's ``if (!nh.getParam(..))``)."""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "tested_reads")


def _extract(package: str) -> CppResult:
    source = os.path.join(ROOT, "src", package, "src", package + ".cpp")
    return extract_cpp([source], scan([ROOT]), cache_dir=None)


@pytest.fixture(scope="module")
def ros1() -> dict[str, bool]:
    return {c.name: c.tested for c in _extract("teleop").calls if c.kind == "read"}


@pytest.fixture(scope="module")
def ros2() -> dict[str, bool]:
    return {c.name: c.tested for c in _extract("teleop2").calls if c.kind == "read"}


def test_ros1_reads(ros1: dict[str, bool]) -> None:
    assert ros1 == {
        "~scale_turbo": True,            # if (nh.getParam(..))
        "~scale_linear": True,           # if (!nh.getParam(..))
        "~scale_linear_default": False,  # a read in the else branch, not tested
        "~max_speed": True,              # bool ok = nh.getParam(..); if (!ok)
        "~gain": True,                   # nh.getParam(..) ? gain : 2.0
        "~angular": True,                # argc > 1 && (ros::param::get(..))
        "~frame": True,                  # if (!nh.hasParam(..))
        "~ready": True,                  # while (!nh.getParam(..))
        "~min_speed": True,              # if (nh.getParam(..) == true)
        "~plain": False,                 # result dropped
        "~kept": False,                  # held in a variable never tested
        "~enabled": False,               # param<bool>(name, default): the value
    }


def test_ros2_reads(ros2: dict[str, bool]) -> None:
    assert ros2 == {
        "scale_turbo": True,   # if (node->get_parameter(name, out))
        "scale_linear": True,  # if (!node->get_parameter_or(..))
        "frame": True,         # if (node->has_parameter(..))
        "plain": False,        # result dropped
        "whole": False,        # get_parameter(name) returns the parameter
    }
