"""pip_libraries.yaml lists import names only. A rosdep key ``python3-X`` that some
platform installs as the Python interpreter itself (rosdep/python.yaml of
github:ros/rosdistro 8468e88c: ``python3-dev``, ``python3-interpreter``, ``python3-venv``,
``python-support``, ``python3-tk``, whose Arch, Fedora or Gentoo rule is ``python`` /
``python3`` / ``dev-lang/python``) names a part of Python, not a library: its ``X``
(``dev``, ``interpreter``, ``support``, ``tk``) was taken for a library, so a ROS 1
node's call into a ROS package of that name was read as a call that makes no ROS call.
The standard library's own modules stay known whatever Python runs the tool, also those
a later Python removed (``distutils``, ``imp``: a Noetic node runs Python 3.8)."""

from __future__ import annotations

import sys

import pytest
from conftest import package_xml

from haros_arch.extract.python import NOT_CLIENTS, _pip_libraries, extract_python
from haros_arch.workspace import scan

NODE = """#!/usr/bin/env python3
import rospy
import {module}

rospy.init_node('worker')
{module}.{call}
rospy.spin()
"""


def _said(write_tree, module: str, call: str) -> list[str]:
    root = write_tree({
        "src/worker/package.xml": package_xml("worker"),
        "src/worker/CMakeLists.txt": "project(worker)\n",
        "src/worker/scripts/worker.py": NODE.format(module=module, call=call),
    })
    source = root / "src/worker/scripts/worker.py"
    result = extract_python([str(source)], scan([str(root / "src")]), package="worker")
    return [d.message for d in result.diagnostics if d.code == "PY_MODULE_UNSEEN"]


def test_interpreter_keys_name_no_library() -> None:
    libraries = _pip_libraries()
    assert not {"dev", "interpreter", "support", "tk", "venv"} & libraries
    # keys of libraries whose import name is the key's (python-box, pypa's build,
    # VPython's visual), and a backport named by its pip rule
    assert {"box", "build", "visual", "importlib_metadata", "requests"} <= libraries


@pytest.mark.parametrize("module", ["support", "interpreter"])
def test_a_ros_package_of_such_a_name_is_not_a_library(write_tree, module: str) -> None:
    assert module not in NOT_CLIENTS
    assert len(_said(write_tree, module, "start()")) == 1


@pytest.mark.parametrize(("module", "call"), [
    ("distutils", "version.LooseVersion('1.2')"),
    ("imp", "load_source('m', '/tmp/m.py')"),
    ("box", "Box()"),  # a library of a python3-X key, a guard
])
def test_the_standard_library_of_older_pythons_stays_known(write_tree, monkeypatch,
                                                           module: str, call: str) -> None:
    # as on Python 3.12, whose standard library has neither distutils nor imp
    monkeypatch.setattr(sys, "stdlib_module_names",
                        frozenset(sys.stdlib_module_names) - {"distutils", "imp"})
    assert _said(write_tree, module, call) == []
