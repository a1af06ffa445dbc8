"""Install-space substitutions of ROS 2 launch, resolved from the workspace model.

``$(find-pkg-prefix)`` / ``FindPackagePrefix`` / ``get_package_prefix`` give where colcon
installs a workspace package (``<install>/<pkg>``, ``install`` beside ``src``), and a
file under ``<prefix>/share/<pkg>`` is read from the source the package's install rules
put there; ``$(exec-in-pkg)`` / ``ExecutableInPackage`` give ``lib/<pkg>/<exe>`` for an
executable the package's CMakeLists.txt or setup.py installs; ``$(find-exec)`` /
``FindExecutable`` search the configuration's PATH. What cannot be found stays unknown
with a diagnostic. fixtures/share_ros2/src/gripper_driver/launch/tools.* use them all.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from conftest import FIXTURES, package_xml

from haros_arch.launch import load
from haros_arch.share import install_prefix
from haros_arch.workspace import scan

ROOT = FIXTURES / "share_ros2"
INSTALL = ROOT / "install"


def tool_folder(tmp_path: Path) -> str:
    folder = tmp_path / "bin"
    folder.mkdir()
    flasher = folder / "gripper_flash"
    flasher.write_text("#!/bin/sh\n")
    flasher.chmod(0o755)
    (folder / "no_such_tool").write_text("not executable")  # found only if runnable
    return str(folder)


@pytest.mark.parametrize("name", ["tools.launch.xml", "tools_launch.py"])
def test_prefix_and_executables_of_workspace_packages(name: str, tmp_path: Path) -> None:
    env = {"PATH": tool_folder(tmp_path)}
    workspace = scan([str(ROOT / "src")], env)
    model = load(str(ROOT / "src/gripper_driver/launch" / name), workspace, {}, env)
    params = {p.key: p.value for p in model.params}
    prefix = str(INSTALL / "gripper_driver")
    assert params["prefix"] == prefix
    assert params["driver"] == f"{prefix}/lib/gripper_driver/gripper_node"
    assert params["teleop"] == str(INSTALL / "rover_teleop/lib/rover_teleop/teleop_node")
    assert params["flasher"] == str(tmp_path / "bin" / "gripper_flash")
    # the parameter file under the prefix is the source its install rule names
    assert (params["max_force"], params["port"]) == (12.5, "/dev/ttyUSB0")
    for unknown in ("missing_exe", "missing_pkg", "nowhere"):
        assert params[unknown] is None
    found = sorted((d.code, d.message) for d in model.diagnostics)
    assert [code for code, _ in found] == [
        "LAUNCH_UNKNOWN_VALUE", "LAUNCH_UNKNOWN_VALUE", "PACKAGE_NOT_FOUND"]
    assert "no_such_node" in found[0][1] + found[1][1]
    assert "no_such_tool" in found[0][1] + found[1][1]
    if name.endswith(".py"):
        assert params["lib"] == f"{prefix}/lib"
    assert "gripper_driver/params/gripper.yaml" in model.files


def test_installed_package_prefix_and_lib(tmp_path: Path, write_tree) -> None:
    prefix = tmp_path / "opt"
    (prefix / "share/vendor_arm").mkdir(parents=True)
    (prefix / "share/vendor_arm/package.xml").write_text(package_xml("vendor_arm"))
    (prefix / "lib/vendor_arm").mkdir(parents=True)
    (prefix / "lib/vendor_arm/arm_driver").write_text("")
    root = write_tree({
        "src/cell/package.xml": package_xml("cell", "ament_cmake"),
        "src/cell/launch/cell.launch.xml": """<launch>
  <node pkg="vendor_arm" exec="arm_driver" name="arm">
    <param name="prefix" value="$(find-pkg-prefix vendor_arm)"/>
    <param name="driver" value="$(exec-in-pkg arm_driver vendor_arm)"/>
    <param name="absent" value="$(exec-in-pkg calibrate vendor_arm)"/>
  </node>
</launch>"""})
    env = {"AMENT_PREFIX_PATH": str(prefix)}
    workspace = scan([str(root / "src")], env)
    assert install_prefix(workspace, "vendor_arm") == str(prefix)
    assert install_prefix(workspace, "cell") == str(root / "install" / "cell")
    model = load(str(root / "src/cell/launch/cell.launch.xml"), workspace, {}, env)
    params = {p.key: p.value for p in model.params}
    assert params == {"prefix": str(prefix),
                      "driver": str(prefix / "lib/vendor_arm/arm_driver"), "absent": None}
    assert [d.code for d in model.diagnostics] == ["LAUNCH_UNKNOWN_VALUE"]


def test_include_through_the_prefix_reads_the_installed_source(write_tree) -> None:
    root = write_tree({
        "ws/src/cell/package.xml": package_xml("cell", "ament_cmake"),
        "ws/src/cell/CMakeLists.txt": "project(cell)\n"
                                      "install(DIRECTORY launch/bringup/ DESTINATION "
                                      "share/${PROJECT_NAME}/launch)\n",
        "ws/src/cell/launch/bringup/part.launch.xml":
            '<launch><node pkg="cell" exec="part" name="part"/></launch>',
        "ws/src/cell/launch/main.launch.xml": """<launch>
  <include file="$(find-pkg-prefix cell)/share/cell/launch/part.launch.xml"/>
</launch>"""})
    workspace = scan([str(root / "ws")], {})
    model = load(str(root / "ws/src/cell/launch/main.launch.xml"), workspace, {}, {})
    assert [n.name for n in model.nodes] == ["/part"]
    assert model.files[-1] == os.path.join("src", "cell", "launch", "bringup",
                                           "part.launch.xml")
    assert model.diagnostics == []
