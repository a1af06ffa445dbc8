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
    # a package that is not here may be installed where the robot runs: unknown, not an
    # error (as $(find) in ROS 1)
    assert [code for code, _ in found] == ["LAUNCH_UNKNOWN_VALUE"] * 3
    said = " ".join(message for _, message in found)
    assert "no_such_node" in said and "no_such_tool" in said
    assert "is not in the workspace nor installed here" in said
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


def test_symlink_install_reads_the_sources_it_links(tmp_path: Path) -> None:
    # colcon build --symlink-install: install/<pkg>/share/<pkg>/... are links into src/;
    # what they lead to is read (a workspace folder), a link leading out of the
    # workspace is not
    src = tmp_path / "ws/src/bot"
    (src / "launch").mkdir(parents=True)
    (src / "config").mkdir()
    (src / "package.xml").write_text(package_xml("bot", "ament_cmake"))
    (src / "config/names.yaml").write_text("names: [left, right]\n")
    (src / "config/desc.txt").write_text("<robot/>")
    (tmp_path / "secret.yaml").write_text("names: [stolen]\n")
    (src / "launch/bot.launch.py").write_text(
        "import os, yaml\n"
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    here = os.path.dirname(os.path.realpath(__file__))\n"
        "    with open(os.path.join(here, '..', 'config', 'names.yaml')) as f:\n"
        "        names = yaml.safe_load(f)['names']\n"
        "    return LaunchDescription([Node(package='bot', executable='e', name=n)\n"
        "                              for n in names])\n")
    (src / "launch/desc.launch.xml").write_text(
        '<launch><node pkg="bot" exec="e" name="d">'
        '<param name="desc" value="$(file-content $(dirname)/../config/desc.txt)"/>'
        "</node></launch>")
    share = tmp_path / "ws/install/bot/share/bot"
    share.mkdir(parents=True)
    for entry in ("launch", "package.xml"):
        (share / entry).symlink_to(src / entry)
    (share / "config").mkdir()
    for entry in ("names.yaml", "desc.txt"):
        (share / "config" / entry).symlink_to(src / "config" / entry)
    (share / "config/leak.yaml").symlink_to(tmp_path / "secret.yaml")
    env = {"AMENT_PREFIX_PATH": str(tmp_path / "ws/install/bot")}
    workspace = scan([str(tmp_path / "ws/src")], env)
    model = load(str(share / "launch/bot.launch.py"), workspace, {}, env)
    assert [n.name for n in model.nodes] == ["/left", "/right"]
    assert model.diagnostics == []
    assert workspace.readable(str(share / "config/names.yaml"))
    assert not workspace.readable(str(share / "config/leak.yaml"))
    model = load(str(share / "launch/desc.launch.xml"), workspace, {}, env)
    assert [(p.name, p.value) for p in model.params] == [("/d/desc", "<robot/>")]
