"""``ament_index_python.packages.get_package_share_path``: the share folder as a
``pathlib.Path`` (stretch_core's stretch_driver.launch.py: ``str(stretch_core_path /
'config' / 'controller_calibration_head.yaml')`` as a launch argument's default, and the
robot description's xacro file). It was a call not interpreted, every value built on it
unknown."""

from __future__ import annotations

from test_launch_ros2_python import run


def test_the_share_path_of_a_workspace_package_is_a_path(write_tree) -> None:
    model, root = run(write_tree, """
from ament_index_python.packages import get_package_share_path

def generate_launch_description():
    share = get_package_share_path('pkg')
    calibration = str(share / 'config' / 'head.yaml')
    return LaunchDescription([
        DeclareLaunchArgument('calibration', default_value=calibration),
        Node(package='pkg', executable='driver', name='driver',
             parameters=[{'calibration': LaunchConfiguration('calibration'),
                          'urdf': str(get_package_share_path('pkg') / 'urdf' / 'r.urdf')}]),
    ])
""")
    values = {p.name: p.value for p in model.params}
    assert values == {"/driver/calibration": str(root / "src/pkg/config/head.yaml"),
                      "/driver/urdf": str(root / "src/pkg/urdf/r.urdf")}
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]


def test_the_share_path_of_another_package_is_found_at_launch_time(write_tree) -> None:
    model, _ = run(write_tree, """
from ament_index_python.packages import get_package_share_path

def generate_launch_description():
    rviz = get_package_share_path('elsewhere') / 'rviz' / 'view.rviz'
    return LaunchDescription([
        Node(package='rviz2', executable='rviz2', name='rviz', arguments=['-d', rviz]),
    ])
""")
    assert [n.name for n in model.nodes] == ["/rviz"]
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]


def test_a_pathlib_path_of_a_share_folder_found_at_launch_time_keeps_its_parts(
        write_tree) -> None:
    # ardupilot_gz's bringup: ``f'{Path(get_package_share_directory("ros_gz_sim")) /
    # "launch" / "gz_sim.launch.py"}'`` with ros_gz_sim not installed here was "arithmetic
    # on an unknown value" and an include of ``?`` (two warnings); it is the package's
    # file, found at launch time (an include not read, an info)
    model, _ = run(write_tree, """
from pathlib import Path

def generate_launch_description():
    sim = get_package_share_directory('elsewhere')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            f'{Path(sim) / "launch" / "sim.launch.py"}')),
        Node(package='rviz2', executable='rviz2', name='rviz',
             arguments=['-d', f"{Path(sim, 'rviz') / 'view.rviz'}"]),
    ])
""")
    assert [n.name for n in model.nodes] == ["/rviz"]
    assert not [d for d in model.diagnostics if d.severity != "info"]
    assert [n.args for n in model.nodes] == ["-d ?/rviz/view.rviz"]
