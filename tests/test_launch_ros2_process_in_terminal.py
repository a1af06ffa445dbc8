"""A ROS 2 launch file's process that opens a terminal emulator or a shell to run
``ros2 run`` / ``ros2 launch`` (lunabot_ros' sim_launch.py: ``gnome-terminal -- bash -c
"ros2 run lunabot_simulation keyboard_teleop.py; exit"``, so the keyboard teleop gets a
terminal of its own) starts that node or launch file, as the command without the
wrapper does (``entities.shell_run``, through ``shell.commands``, the one reading of a
shell line the Python extractor uses too). A wrapper around
any other program, or one with a word not known statically, stays a process that
starts no node the reader can name. (The package of a node so started that is not
there is said when the graph is built, ``NODE_PACKAGE_UNKNOWN``: bench/real_bugs.yaml's
lunabot_ros/0ea91bd9.)"""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
from launch.actions import ExecuteProcess

def generate_launch_description():
    who = LaunchConfiguration('who', default='talker')
    return LaunchDescription([
        ExecuteProcess(cmd=['gnome-terminal', '--', 'bash', '-c',
                            'ros2 run teleop keyboard.py --ros-args -r __node:=keys; exit']),
        ExecuteProcess(cmd=['xterm', '-e', 'bash -c "source /opt/ros/setup.bash && '
                                           'ros2 run demo_nodes_cpp listener"']),
        ExecuteProcess(cmd=['bash', '-c', 'ros2 launch pkg other.launch.py'], shell=False),
        ExecuteProcess(cmd=['gnome-terminal', '--', 'htop']),
        ExecuteProcess(cmd=['gnome-terminal', '--', 'ros2', 'run', 'demo_nodes_cpp', who]),
    ])
"""

OTHER = """
def generate_launch_description():
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',
                                   name='other_talker')])
"""


def test_ros2_run_in_a_terminal_or_a_shell_is_that_node(write_tree):
    model, _ = run(write_tree, BODY, extra={"src/pkg/launch/other.launch.py":
                                            "from launch import LaunchDescription\n"
                                            "from launch_ros.actions import Node\n" + OTHER})
    assert sorted((n.name, n.package, n.executable) for n in model.nodes) == [
        # listener's name is its executable's, known only from its model (none here)
        ("/?", "demo_nodes_cpp", "listener"), ("/keys", "teleop", "keyboard.py"),
        ("/other_talker", "demo_nodes_cpp", "talker")]
    processes = [(d.location.line, d.message) for d in model.diagnostics
                 if d.code == "LAUNCH_PROCESS"]
    assert processes == [
        (22, "process gnome-terminal -- htop started here is no node the reader can name"),
        (23, "process gnome-terminal -- ros2 started here is no node the reader can name")]
