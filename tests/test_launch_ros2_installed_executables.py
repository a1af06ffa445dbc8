"""A process whose program is a path where ament installs a package's executables,
``<prefix>/lib/<package>/<executable>``, runs what ``ros2 run PKG EXE`` runs: orca4's
bringup.py starts ``/opt/ros/humble/lib/tf2_ros/static_transform_publisher`` with
ExecuteProcess, which was no node (LAUNCH_PROCESS) and left its /tf_static out."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.launch.ros2.entities import installed_executable
from haros_arch.workspace import scan

LAUNCH = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['/opt/ros/humble/lib/tf2_ros/static_transform_publisher',
                            '--frame-id', 'map', '--child-frame-id', 'odom']),
        ExecuteProcess(cmd=['/home/me/ws/install/driver/lib/driver/driver_node',
                            '--ros-args', '-r', '__node:=front']),
        ExecuteProcess(cmd=['/usr/lib/gz/gz-sim', '-r']),
    ])
"""


def test_a_program_installed_by_ament_is_its_node(write_tree):
    root = write_tree({
        "src/bringup/package.xml": package_xml("bringup", "ament_cmake"),
        "src/bringup/launch/sim.launch.py": LAUNCH,
    })
    model = load(str(root / "src/bringup/launch/sim.launch.py"),
                 scan([str(root / "src")], {}), {}, {})
    started = sorted((n.package, n.executable, n.name) for n in model.nodes)
    assert [s[:2] for s in started] == [("driver", "driver_node"),
                                       ("tf2_ros", "static_transform_publisher")]
    assert ("driver", "driver_node", "/front") in started
    tf = next(n for n in model.nodes if n.package == "tf2_ros")
    assert "--frame-id map --child-frame-id odom" in tf.args
    processes = [d.message for d in model.diagnostics if d.code == "LAUNCH_PROCESS"]
    assert len(processes) == 1 and "gz-sim" in processes[0]


def test_only_an_install_layout_names_a_package():
    assert installed_executable("/opt/ros/jazzy/lib/tf2_ros/static_transform_publisher") \
        == ("tf2_ros", "static_transform_publisher")
    assert installed_executable("/ws/install/driver/lib/driver/node") == ("driver", "node")
    for other in ("/usr/lib/python3/tool", "/opt/ros/jazzy/lib/libfoo.so",
                  "lib/tf2_ros/static_transform_publisher", "/ws/install/lib/driver/node",
                  "/opt/ros/jazzy/lib/tf2_ros/", None, ""):
        assert installed_executable(other) is None, other
