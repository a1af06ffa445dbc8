"""Where a Python launch file stops: ``sys.exit()`` / ``exit()`` or a ``raise`` that no
``try`` catches ends ``generate_launch_description`` there. Under a test not known
statically that branch ends, as after a ``return``, and the rest of the function runs
under the other branch's test (Leishen's lslidar drivers pick the node's keywords by
the output of ``echo $ROS_DISTRO`` and ``exit()`` in the ``else``: no node at all was
read); reached under no such test, the launch starts nothing and it is said. The tests
an ``if`` nested in a branch adds for the rest of that branch (a ``return`` in it) end
with the branch: they do not hold after the outer ``if``."""

from __future__ import annotations

from test_launch_ros2_python import run

DISTRO_CHOICE = """
import subprocess

def generate_launch_description():
    p = subprocess.Popen("echo $ROS_DISTRO", stdout=subprocess.PIPE, shell=True)
    driver_node = ""
    ros_version = p.communicate()[0]
    if ros_version == b'dashing\\n' or ros_version == b'eloquent\\n':
        driver_node = Node(package='drv', executable='driver_node', name='old_driver')
    elif ros_version == b'foxy\\n' or ros_version == b'humble\\n':
        driver_node = Node(package='drv', executable='driver_node', name='driver')
    else:
        print("Please configure the ros environment")
        %s
    return LaunchDescription([driver_node])
"""


def test_an_else_that_exits_ends_its_branch_only(write_tree):
    for stop in ("exit()", "sys.exit(1)", "quit()", "raise RuntimeError('no ROS')"):
        body = DISTRO_CHOICE % stop
        if stop.startswith("sys."):
            body = "import sys\n" + body
        model, _ = run(write_tree, body)
        nodes = {n.name: n for n in model.nodes}
        assert sorted(nodes) == ["/driver", "/old_driver"], stop
        assert all(n.conditions for n in nodes.values())
        assert "foxy" in nodes["/driver"].conditions[0].text
        said = [d.message for d in model.diagnostics]
        assert not any("not defined" in m or ("not interpreted" in m and "Popen" not in m)
                       for m in said), said
        assert not any(d.code == "LAUNCH_PY_EXIT" for d in model.diagnostics)


def test_a_launch_file_that_always_exits_is_said(write_tree):
    model, _ = run(write_tree, """
import sys

def generate_launch_description():
    nodes = [Node(package='p', executable='e', name='first')]
    sys.exit('not supported any more')
    return LaunchDescription(nodes)
""")
    assert model.nodes == []
    stops = [d for d in model.diagnostics if d.code == "LAUNCH_PY_EXIT"]
    assert [(d.location.line, d.severity) for d in stops] == [(16, "warning")]
    assert "sys.exit('not supported any more')" in stops[0].message


def test_a_raise_a_handler_catches_runs_the_handler(write_tree):
    model, _ = run(write_tree, """
class Missing(Exception):
    pass

def generate_launch_description():
    try:
        raise ValueError('no camera')
        name = 'camera'
    except ValueError:
        name = 'fallback'
    try:
        raise Missing('x')
    except Missing:
        pass
    return LaunchDescription([Node(package='p', executable='e', name=name)])
""")
    assert [n.name for n in model.nodes] == ["/fallback"]
    assert not model.nodes[0].conditions
    said = [(d.code, d.location.line) for d in model.diagnostics]
    # a class of the file: whether the handler catches it is not known here, said
    assert said == [("LAUNCH_PY_UNSUPPORTED", 22)]


def test_a_return_in_a_nested_if_does_not_condition_what_follows_the_outer_if(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    nodes = []
    if os.environ.get('A') == '1':
        if os.environ.get('B') == '1':
            return LaunchDescription([])
        nodes.append(Node(package='p', executable='e', name='inner'))
    nodes.append(Node(package='p', executable='e', name='after'))
    return LaunchDescription(nodes)
""")
    conditions = {n.name: [c.text for c in n.conditions] for n in model.nodes}
    inner, = conditions["/inner"]
    assert "'A') == '1'" in inner and "not (os.environ.get('B')" in inner
    # not "A == '1'": it runs where A is not 1, and where B is not 1
    after, = conditions["/after"]
    assert after.startswith("not (os.environ.get('A') == '1') or (")


def test_tests_joined_by_and_keep_an_or_in_parentheses(write_tree):
    """The condition of what an ``elif`` makes is the ``if``'s test not holding and the
    ``elif``'s holding: an ``or`` among them is written in parentheses, as Python would
    read ``not (a or b) and c or d`` otherwise."""
    model, _ = run(write_tree, DISTRO_CHOICE % "exit()")
    conditions = {n.name: [c.text for c in n.conditions] for n in model.nodes}
    assert conditions["/driver"] == [
        "not (ros_version == b'dashing\\n' or ros_version == b'eloquent\\n') and "
        "(ros_version == b'foxy\\n' or ros_version == b'humble\\n')"]
    assert conditions["/old_driver"] == [
        "ros_version == b'dashing\\n' or ros_version == b'eloquent\\n'"]


def test_an_exit_in_a_helper_module_is_said_where_it_is(write_tree):
    """A helper module of the workspace whose function exits: said at its line in the
    helper's file, not at that line of the launch file."""
    helper = "import sys\n\n\ndef nodes():\n    sys.exit('no robot')\n"
    model, _ = run(write_tree, """
import sys
sys.path.append(os.path.dirname(__file__))
import robot_helpers

def generate_launch_description():
    return LaunchDescription(robot_helpers.nodes())
""", extra={"src/pkg/launch/robot_helpers.py": helper})
    assert model.nodes == []
    (stop,) = [d for d in model.diagnostics if d.code == "LAUNCH_PY_EXIT"]
    assert stop.location.file.endswith("launch/robot_helpers.py")
    assert stop.location.line == 5


def test_a_raise_after_a_possible_return_ends_that_path_only(write_tree):
    """A helper that returns from a loop over a value not known statically (perseus-v2's
    livox.launch.py reads the host address from ``ip addr`` output line by line) or
    from an ``if`` whose test is not known, and raises after it, gives what it may
    return: the raise ends only the path where it did not return, so the launch file
    goes on with that value rather than stopping."""
    for returning in ("""
    for line in subprocess.run(['ip', 'addr'], capture_output=True).stdout.splitlines():
        if line.startswith('inet '):
            return 'eth_' + 'host'
""", """
    if subprocess.run(['ip', 'addr'], capture_output=True).returncode == 0:
        return 'eth_' + 'host'
"""):
        model, _ = run(write_tree, """
import subprocess

def host_name():
""" + returning + """
    raise RuntimeError('no address')

def generate_launch_description():
    name = host_name()
    return LaunchDescription([Node(package='p', executable='e', name=name)])
""")
        assert [n.name for n in model.nodes] == ["/eth_host"], returning
        assert not any(d.code == "LAUNCH_PY_EXIT" for d in model.diagnostics), returning
