"""A process whose shell line runs more than one ``ros2`` command (``bash -c "ros2 run
a x & ros2 run b y"``, ``gnome-terminal -- bash -c "ros2 launch ...; ros2 run ..."``)
starts each of them, as the shell runs the line (``shell.run_order``,
``entities.process_actions``): after ``&`` at once; after ``;`` once the command before
has ended, after ``&&`` once it succeeded, after ``||`` once it failed, each an event
the node waits for (its condition, as an event handler's); a wait for set-up commands
(``source setup.bash &&``, ``sleep 2;``) is none. Before, only the first ``ros2``
command of the line was read and the others were missing from the graph. ROS 2 XML's
``<executable cmd=...>`` is read so too."""

from __future__ import annotations

from conftest import package_xml
from test_launch_ros2_python import run

from haros_arch.launch import load
from haros_arch.workspace import scan

BODY = """
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['bash', '-c', 'ros2 run demo talker & ros2 run demo listener']),
        ExecuteProcess(cmd=['gnome-terminal', '--', 'bash', '-c',
                            'source /opt/ros/setup.bash && sleep 2; '
                            'ros2 launch pkg other.launch.py; '
                            'ros2 run teleop keys --ros-args -r __node:=keys; exec bash']),
        ExecuteProcess(cmd=['bash', '-c', 'ros2 run a first && ros2 run b second '
                                          '|| ros2 run c third']),
        ExecuteProcess(cmd=['bash', '-c', 'exec ros2 run d replaced; ros2 run d never']),
        ExecuteProcess(cmd=['bash', '-c', 'ros2 run e one & ros2 bag play /tmp/bag']),
    ])
"""

OTHER = """
def generate_launch_description():
    return LaunchDescription([Node(package='demo', executable='talker',
                                   name='other_talker')])
"""


def started(model) -> dict[tuple[str | None, str | None], list[str]]:
    return {(n.package, n.executable): [c.text for c in n.conditions] for n in model.nodes}


def test_every_ros2_command_of_a_shell_line_is_started(write_tree):
    model, _ = run(write_tree, BODY, extra={"src/pkg/launch/other.launch.py":
                                            "from launch import LaunchDescription\n"
                                            "from launch_ros.actions import Node\n" + OTHER})
    assert started(model) == {
        ("demo", "listener"): [], ("a", "first"): [], ("d", "replaced"): [],
        ("e", "one"): [],
        ("demo", "talker"): [],  # talker and other_talker: the same executable
        ("teleop", "keys"): ["on event: `ros2 launch pkg other.launch.py` ends"],
        ("b", "second"): ["on event: `ros2 run a first` ends with success"],
        ("c", "third"): ["on event: `ros2 run a first && ros2 run b second` fails"],
    }
    assert sorted(n.name for n in model.nodes if n.executable == "talker") == [
        "/?", "/other_talker"]  # talker's name is its executable's, no model here
    processes = [d.message for d in model.diagnostics if d.code == "LAUNCH_PROCESS"]
    assert processes == ["process ros2 bag play started here is no node the reader can "
                         "name"]


def test_xml_executable_runs_each_command(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "src/pkg/launch/main.launch.xml":
            "<launch><executable cmd=\"bash -c 'ros2 run a x; ros2 run b y'\"/></launch>"})
    model = load(str(root / "src/pkg/launch/main.launch.xml"), scan([str(root / "src")], {}),
                 {}, {})
    assert started(model) == {("a", "x"): [], ("b", "y"): ["on event: `ros2 run a x` ends"]}


def test_run_order_waits():
    from haros_arch.shell import run_order, split_words

    order = run_order(split_words("x; bash -c 'y && z' & w | v; cd d && u"))
    assert order == [
        (["x"], ()), (["y"], ((";", "x"),)), (["z"], ((";", "x"), ("&&", "y"))),
        (["w"], ((";", "x"),)), (["v"], ((";", "x"),)),
        (["cd", "d"], ((";", "x"), (";", "w | v"))),
        (["u"], ((";", "x"), (";", "w | v")))]
