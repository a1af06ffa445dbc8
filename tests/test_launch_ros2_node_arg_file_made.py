"""A file the launch file itself writes before it starts the node it hands the file to
is no missing file: QUT-Motorsport's QUTMS_Driverless, vehicle_urdf/launch/
robot_description.launch.py:26-49, writes the processed URDF into its share folder
with ``xacro.open_output(urdf_path)`` (after ``os.mknod``) and gives joint_state_publisher
``arguments=[urdf_path]``: LAUNCH_NODE_ARG_PATH_MISSING said it was not there. Those
writers, like ``open(path, 'w')``, are not run here; the paths they are handed are files
the launch makes as it runs, which the check leaves alone. A path no writer is handed is
still judged."""

from __future__ import annotations

from test_launch_ros2 import run

LAUNCH = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node
    import xacro

    def generate_launch_description():
        made = os.path.join(get_package_share_directory('pkg'), 'urdf', 'processed.urdf')
        doc = xacro.process_file(os.path.join(get_package_share_directory('pkg'),
                                              'urdf', 'car.xacro'))
        out = xacro.open_output(made)
        out.write(doc.toprettyxml(indent='  '))
        other = os.path.join(get_package_share_directory('pkg'), 'urdf', 'gone.urdf')
        return LaunchDescription([
            Node(package='joint_state_publisher', executable='joint_state_publisher',
                 arguments=[made]),
            Node(package='pkg', executable='viewer', name='viewer', arguments=[other]),
        ])
    """

FILES = {"src/pkg/urdf/car.xacro": "<robot name='car'/>\n",
         "src/pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
         "find_package(ament_cmake REQUIRED)\n"
         "install(DIRECTORY launch urdf DESTINATION share/${PROJECT_NAME})\n"
         "ament_package()\n"}


def _missing(write_tree) -> list[str]:
    model, _ = run(write_tree, "car.launch.py", LAUNCH, extra=FILES)
    return sorted(d.message for d in model.diagnostics
                  if d.code == "LAUNCH_NODE_ARG_PATH_MISSING")


def test_a_file_the_launch_file_writes_is_not_missing(write_tree) -> None:
    assert not [m for m in _missing(write_tree) if "processed.urdf" in m]


def test_a_file_nothing_writes_is_still_missing(write_tree) -> None:
    # (guard) the other path, which no writer is handed
    assert [m for m in _missing(write_tree) if "gone.urdf" in m]


PROCESS = """
    import os
    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch.actions import ExecuteProcess

    def generate_launch_description():
        share = get_package_share_directory('pkg')
        made = os.path.join(share, 'urdf', 'processed.urdf')
        with open(made, 'w') as out:
            out.write('<robot name="car"/>')
        other = os.path.join(share, 'urdf', 'gone.urdf')
        return LaunchDescription([
            ExecuteProcess(cmd=['check_urdf', made]),
            ExecuteProcess(cmd=['check_urdf', other]),
        ])
    """


def test_a_file_the_launch_file_writes_is_no_missing_process_argument(write_tree) -> None:
    """The same for a process that is no node (its ExecuteProcess arguments,
    LAUNCH_PROCESS_ARG_PATH_MISSING): the file it is handed is written first."""
    model, _ = run(write_tree, "check.launch.py", PROCESS, extra=FILES)
    missing = [d.message for d in model.diagnostics
               if d.code == "LAUNCH_PROCESS_ARG_PATH_MISSING"]
    assert not [m for m in missing if "processed.urdf" in m]
    assert [m for m in missing if "gone.urdf" in m]  # (guard) nothing writes that one
