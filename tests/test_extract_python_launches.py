"""A Python program that runs roslaunch in its own process starts nodes we cannot see
(magni's launch_core.py fills a launch file from a template and calls
``roslaunch.main(sys.argv)``): it is no node without an interface but a partial one,
with PY_LAUNCHES at the call, so checks do not take the robot's base as absent."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import Workspace

LAUNCHER = """#!/usr/bin/env python3
import sys
import roslaunch

def main():
    path = "/tmp/generated_core.launch"
    with open(path, "w") as out:
        out.write("<launch/>")
    sys.argv = ["roslaunch", path]
    roslaunch.main(sys.argv)

if __name__ == "__main__":
    main()
"""

SCRIPTAPI = """import rospy
import roslaunch
from roslaunch.parent import ROSLaunchParent
rospy.init_node("starter")
parent = ROSLaunchParent(roslaunch.rlutil.get_or_generate_uuid(None, False), ["a.launch"])
parent.start()
"""


def test_roslaunch_in_process_is_said(tmp_path) -> None:
    for name, text, line in (("core.py", LAUNCHER, 10), ("starter.py", SCRIPTAPI, 5)):
        source = tmp_path / name
        source.write_text(text)
        result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
        said = [(d.code, d.location.line) for d in result.diagnostics
                if d.code == "PY_LAUNCHES"]
        assert said == [("PY_LAUNCHES", line)]  # once, though main() is walked twice


def test_a_launcher_node_is_partial(write_tree) -> None:
    root = write_tree({
        "src/bringup/package.xml": package_xml("bringup"),
        "src/bringup/CMakeLists.txt": "project(bringup)\n",
        "src/bringup/scripts/launch_core.py": LAUNCHER,
        "src/bringup/launch/base.launch": (
            '<launch>\n  <node name="core" pkg="bringup" type="launch_core.py"/>\n'
            '</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [bringup/launch/base.launch]\n",
    })
    os.chmod(root / "src/bringup/scripts/launch_core.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (node,) = model.configuration("c").nodes
    assert node.completeness == "partial"
