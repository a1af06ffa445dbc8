"""A folder inside a package that holds a package.xml of its own is part of that
package (packages do not nest: catkin, colcon and the workspace scan stop at the outer
one), and roslaunch finds a package's launch file anywhere below it.
ros_control_boilerplate (0f9cd01) keeps its example robot in ``rrbot_control/`` (with a
package.xml, built by the outer CMakeLists.txt's ``add_subdirectory``) and its launch
files in ``rrbot_control/launch``: the workspace had one package and no launch file, so
nothing was checked. A launch file of another package's folder is that package's, and
one behind an ignore marker stays out."""

from __future__ import annotations

import textwrap
from pathlib import Path

from haros_arch.autoproject import choose

PKG = """<package format="2"><name>{name}</name><version>0.1.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>BSD</license>
<buildtool_depend>catkin</buildtool_depend></package>"""


def write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))


def test_launch_files_below_a_nested_manifest_are_the_package_s(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    outer = src / "boilerplate"
    write(outer / "package.xml", PKG.format(name="boilerplate"))
    write(outer / "CMakeLists.txt", "project(boilerplate)\nadd_subdirectory(rrbot_control)\n")
    write(outer / "rrbot_control" / "package.xml", PKG.format(name="rrbot_control"))
    write(outer / "rrbot_control" / "launch" / "rrbot_simulation.launch",
          '<launch><node pkg="boilerplate" type="sim_hw_main" name="hw"/></launch>')
    write(outer / "ignored" / "CATKIN_IGNORE", "")
    write(outer / "ignored" / "launch" / "old.launch",
          '<launch><node pkg="boilerplate" type="old" name="old"/></launch>')
    other = src / "other"
    write(other / "package.xml", PKG.format(name="other"))
    write(other / "launch" / "other.launch",
          '<launch><node pkg="other" type="o" name="o"/></launch>')
    choice = choose(str(tmp_path / "ws"), environment={})
    configs = {c.name: c.launch for c in choice.project.configurations}
    assert configs == {
        "boilerplate/rrbot_simulation":
            ["boilerplate/rrbot_control/launch/rrbot_simulation.launch"],
        "other/other": ["other/launch/other.launch"]}
