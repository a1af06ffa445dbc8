"""A parameter file given by a relative path: launch_ros opens it from the folder
``ros2 launch`` runs in, which nothing in the workspace says. nanosaur_control's
teleop.launch.py (rnanosaur/nanosaur 186f96d0) passes ``parameters=[config_filepath]``
whose default is 'ps3': the tool took the path from its own working folder (and read a
file of that name there, had the workspace one)."""

from __future__ import annotations

import pytest
from test_launch_ros2_python import HEADER, run

BODY = """
def generate_launch_description():
    return LaunchDescription([
        Node(package='pkg', executable='e', name='teleop',
             parameters=['config/params.yaml', {'rate': 5}]),
    ])
"""

PARAMS = "/**:\n  ros__parameters:\n    speed: 2.0\n"


def test_a_relative_parameter_file_is_not_read_from_the_tools_folder(write_tree,
                                                                     monkeypatch):
    root = write_tree({"src/pkg/config/params.yaml": PARAMS})
    # the tool runs in the package's folder: a file by that name is there
    monkeypatch.chdir(root / "src/pkg")
    model, _ = run(write_tree, BODY)
    names = {p.name for p in model.params}
    assert "/teleop/rate" in names and "/teleop/speed" not in names, names
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
    assert any("'config/params.yaml' is a relative path" in m for m in said), said


INCLUDE = """
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource

def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource('launch/other.launch.py')),
    ])
"""

OTHER = HEADER + """
def generate_launch_description():
    return LaunchDescription([Node(package='pkg', executable='e', name='other')])
"""


@pytest.mark.parametrize("folder", ["src/pkg", "."])
def test_a_relative_include_is_unknown_wherever_the_tool_runs(write_tree, monkeypatch,
                                                              folder):
    """From the package's folder the include was read (its node started), from another
    one it was LAUNCH_FILE_MISSING, an error: either way a fact of the tool's folder."""
    root = write_tree({"src/pkg/launch/other.launch.py": OTHER})
    monkeypatch.chdir(root / folder)
    model, _ = run(write_tree, INCLUDE)
    assert [n.name for n in model.nodes] == []
    codes = [d.code for d in model.diagnostics]
    assert "LAUNCH_FILE_MISSING" not in codes
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
    assert any("'launch/other.launch.py' is a relative path" in m for m in said), said
