"""A launch description source given a keyword its constructor does not take:
SAUVC-RPI 1413970's bottom_camera_pid_fbc_launch.py wrote ``launch_arguments=`` inside
``PythonLaunchDescriptionSource(...)`` (meant for ``IncludeLaunchDescription``).
launch's sources take the launch file's path only (the frontend's also ``method=`` and
``parser=``), so the call raises TypeError when generate_launch_description runs and the
launch file does not load. Said where the call is (LAUNCH_PY_UNSUPPORTED, the Python
error of the interpreted code), and the include's file is not read as if it loaded; the
same arguments given to the include are read as before."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

CAMERA = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node
def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('debug', default_value='true'),
        Node(package='pkg', executable='camera', name='camera'),
    ])
"""

WRONG = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
def generate_launch_description():
    camera = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            os.path.join(get_package_share_directory('pkg'), 'launch', 'camera.launch.py'),
            launch_arguments={'debug': 'false'}.items(),
        )
    )
    return LaunchDescription([camera])
"""

RIGHT = WRONG.replace("""            launch_arguments={'debug': 'false'}.items(),
        )
    )""", """        ),
        launch_arguments={'debug': 'false'}.items(),
    )""")

XML_SOURCE = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
def generate_launch_description():
    path = os.path.join(get_package_share_directory('pkg'), 'launch', 'camera.launch.py')
    return LaunchDescription([
        IncludeLaunchDescription(XMLLaunchDescriptionSource(launch_file_path=path)),
        IncludeLaunchDescription(XMLLaunchDescriptionSource(path, path)),
    ])
"""


def _model(write_tree, text: str):
    root = write_tree({"src/pkg/package.xml": package_xml("pkg", "ament_python"),
                       "src/pkg/launch/camera.launch.py": CAMERA,
                       "src/pkg/launch/main.launch.py": text})
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/pkg/launch/main.launch.py"), ws, {}, {})


def _said(model) -> list[tuple[int, str]]:
    return [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PY_UNSUPPORTED" and "TypeError" in d.message]


def _names(model) -> list[str]:
    return sorted(str(node.name) for node in model.nodes)


def test_launch_arguments_given_to_the_source_fail(write_tree) -> None:
    model = _model(write_tree, WRONG)
    said = _said(model)
    assert len(said) == 1 and said[0][0] == 8  # the source (write_tree drops the first newline)
    assert "PythonLaunchDescriptionSource" in said[0][1]
    assert "launch_arguments" in said[0][1]
    assert _names(model) == []  # the launch file does not load: nothing started


def test_launch_arguments_given_to_the_include_are_read(write_tree) -> None:
    model = _model(write_tree, RIGHT)
    assert _said(model) == []
    assert _names(model) == ["/camera"]


def test_a_source_by_keyword_and_a_second_path(write_tree) -> None:
    said = _said(_model(write_tree, XML_SOURCE))
    assert [line for line, _ in said] == [10]  # the second, given two paths
