"""A Python ``if`` whose test is not known statically runs both sides, each action
under its side's test. The test is said once: where its value was made when that said
why (ai_worker's model_view.launch.py returns early ``if not is_valid_to_launch()``, an
``os.path.exists`` of ``/sys/firmware/devicetree/base/model``: the info at the path),
else once at the test. It was said again as a LAUNCH_UNSUPPORTED warning "Python test
..." at every action it guards: five warnings at five lines that hold a plain
``Node(...)`` or ``DeclareLaunchArgument(...)``, none of them unsupported."""

from __future__ import annotations

from test_launch_ros2_python import run

EARLY_RETURN = """
def is_valid_to_launch():
    if os.path.exists('/sys/firmware/devicetree/base/model'):
        return False
    return True

def generate_launch_description():
    if not is_valid_to_launch():
        return LaunchDescription([])
    return LaunchDescription([
        DeclareLaunchArgument('use_gui', default_value='true'),
        Node(package='p', executable='a', name='a'),
        Node(package='p', executable='b', name='b'),
    ])
"""


def test_a_test_whose_value_said_why_is_not_said_again(write_tree):
    model, root = run(write_tree, EARLY_RETURN)
    assert [n.name for n in model.nodes] == ["/a", "/b"]
    assert all(n.conditions for n in model.nodes)  # under the test, not decided
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    path_line = next(i + 1 for i, line in enumerate(lines) if "os.path.exists" in line)
    # (use_gui, which nothing reads, is said as such: LAUNCH_ARG_UNUSED, not this test's)
    assert [(d.code, d.severity, d.location.line) for d in model.diagnostics
            if d.code != "LAUNCH_ARG_UNUSED"] == [("LAUNCH_UNKNOWN_VALUE", "info", path_line)]


UNSAID = """
def nodes(serial):
    found = []
    if isinstance(serial, TextSubstitution):
        found.append(Node(package='p', executable='a', name='a'))
        found.append(Node(package='p', executable='b', name='b'))
    return found

def generate_launch_description():
    serial = LaunchConfiguration('serial', default='x')
    return LaunchDescription([*nodes(serial), *nodes(serial)])
"""


def test_a_test_nothing_said_of_is_said_once_at_the_test(write_tree):
    model, root = run(write_tree, UNSAID)
    assert [n.name for n in model.nodes] == ["/a", "/b", "/a", "/b"]
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    test_line = next(i + 1 for i, line in enumerate(lines) if "if isinstance" in line)
    # one warning, at the test, though its function runs twice and guards four nodes
    assert [(d.code, d.location.line, d.message) for d in model.diagnostics] == [
        ("LAUNCH_UNSUPPORTED", test_line,
         "Python test isinstance(serial, TextSubstitution)")]
