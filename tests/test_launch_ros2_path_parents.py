"""``pathlib.Path(__file__).parents[N]`` in a ROS 2 Python launch file (dori_ros2's
robot.launch.py walks ``Path(__file__).resolve().parents``): ``ros2 launch`` runs the
file from its package's install share folder (``<install>/<pkg>/share/<pkg>/launch``),
so a folder up to the package's own share folder is the source folder that stands for
it, as ``.parent`` reads it (``parents[1]`` is ``parent.parent``). A folder above it
differs between the install layout (``<install>/<pkg>/share``, ``<install>/share``
merged) and the source one (``src/``, where a symlink install's ``resolve()`` leads):
not known, and said, whether reached by ``parents[N]`` or a chain of ``.parent``, which
was read as the source's folder before."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

PY = """import pathlib
from launch import LaunchDescription
from launch_ros.actions import Node

HERE = pathlib.Path(__file__).resolve()
UP = [HERE, *HERE.parents]

def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='x', name='one',
             parameters=[str(HERE.parents[1] / 'config' / 'a.yaml')]),
        Node(package='p', executable='x', name='two',
             parameters=[str(HERE.parents[0].parent / 'config' / 'a.yaml')]),
        Node(package='p', executable='x', name='three',
             parameters=[str(HERE.parents[2] / 'p' / 'config' / 'a.yaml')]),
        Node(package='p', executable='x', name='four',
             parameters=[str(HERE.parent.parent.parent / 'p' / 'config' / 'a.yaml')]),
    ])
"""


def _model(write_tree):
    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "src/p/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(p)\n"
                                "install(DIRECTORY launch config DESTINATION "
                                "share/${PROJECT_NAME})\n",
        "src/p/config/a.yaml": "/**:\n  ros__parameters:\n    rate: 5\n",
        "src/p/launch/a.launch.py": PY})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/p/launch/a.launch.py"), ws, {}, {})


def _files(model, name):
    """The parameter files read for node ``name``, by the places of their values."""
    (node,) = [n for n in model.nodes if n.name.endswith(name)]
    return sorted({where.file for _, _, places in node.param_files
                   for where in places.values()})


def test_parents_inside_the_package_are_its_folders(write_tree):
    model = _model(write_tree)
    assert _files(model, "one") == ["p/config/a.yaml"]
    assert _files(model, "two") == ["p/config/a.yaml"]


def test_a_folder_above_the_package_is_not_known_and_said(write_tree):
    model = _model(write_tree)
    said = [d for d in model.diagnostics if "above package p" in d.message]
    assert {d.location.line for d in said} == {6, 15, 17}, [d.message for d in said]
    assert "HERE.parents holds folders above" in said[0].message
    assert "HERE.parents[2] is a folder above" in said[1].message
    assert "<install>/p/share/p" in said[1].message
    for name in ("three", "four"):
        assert _files(model, name) == []
