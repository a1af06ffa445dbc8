"""Python launch file shapes met on real workspaces (survey Z19, 2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_global_name_set_under_an_unknown_test_is_not_known(write_tree):
    """neo_simulation2's multi_robot_simulation.py: ``global N`` then ``if int(N) > 5:
    N = '5'`` with N from an environment variable not set. After the ``if`` N is the
    module's value or '5', not known: the loop over ``range(int(N))`` runs an unknown
    number of times, not five."""
    model, _ = run(write_tree, """
N = os.environ['NUMBER_OF_ROBOTS']

def generate_launch_description():
    global N
    if int(N) > 5:
        N = '5'
    ld = LaunchDescription()
    for i in range(0, int(N)):
        ld.add_action(Node(package='p', executable='spawn', name='spawn'))
    return ld
""")
    assert len(model.nodes) == 1
    assert model.nodes[0].conditions[0].text == "for i in range(0, int(N))"
    assert not any("Global" in d.message for d in model.diagnostics)


def test_global_name_set_in_a_function_is_seen_after_it(write_tree):
    """A helper that sets a module name it declares ``global``: the launch function
    reads the new value."""
    model, _ = run(write_tree, """
COUNT = 1

def bump():
    global COUNT
    COUNT = 2

def generate_launch_description():
    bump()
    return LaunchDescription([Node(package='p', executable='e', name='n' + str(COUNT))])
""")
    assert [n.name for n in model.nodes] == ["/n2"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_nonlocal_name_set_in_a_nested_function(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    name = 'a'
    def rename():
        nonlocal name
        name = 'b'
    rename()
    return LaunchDescription([Node(package='p', executable='e', name=name)])
""")
    assert [n.name for n in model.nodes] == ["/b"]


def test_missing_key_is_caught_by_its_handler(write_tree):
    """``try: v = d['key'] except KeyError: v = default``: a dict of known keys that
    lacks the key raises, and the handler gives the value (the error is not said)."""
    model, _ = run(write_tree, """
def generate_launch_description():
    robot = {'name': 'r1'}
    try:
        marker = robot['marker']
    except KeyError:
        marker = 'default'
    return LaunchDescription([Node(package='p', executable='e', name=marker)])
""")
    assert [n.name for n in model.nodes] == ["/default"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_missing_key_not_caught_says_why(write_tree):
    """crazyswarm2's launch_teleop2.py reads ``type['marker']`` of a robot type whose
    YAML has no such key: Python stops there (KeyError), which is said as such."""
    model, _ = run(write_tree, """
def generate_launch_description():
    kind = {'motion_capture': {'marker': 'm'}}
    marker = kind['marker']
    return LaunchDescription([Node(package='p', executable='e', name='n')])
""")
    found = [d for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert [d.message for d in found] == [
        "kind['marker'] fails: KeyError: the key is not there"]


HELPER = """
def robot_params(name):
    return {'robot_name': name, 'rate': 10}
"""


def test_file_loaded_as_module_and_its_function_taken_with_getattr(write_tree):
    """xarm_ros2's launch files: ``mod = load_python_launch_file_as_module(path)`` of a
    helper file in the package's share folder, ``f = getattr(mod, 'robot_params')``,
    then ``f(...)`` gives the node's parameters."""
    model, _ = run(write_tree, """
from launch.launch_description_sources import load_python_launch_file_as_module

def generate_launch_description():
    mod = load_python_launch_file_as_module(os.path.join(
        get_package_share_directory('pkg'), 'launch', 'lib', 'helper.py'))
    robot_params = getattr(mod, 'robot_params')
    return LaunchDescription([Node(package='p', executable='e', name='driver',
                                   parameters=[robot_params('arm')])])
""", extra={"src/pkg/launch/lib/helper.py": HELPER})
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    params = {p.name: p.value for p in model.params}
    assert params == {"/driver/robot_name": "arm", "/driver/rate": 10}


def test_key_not_known_is_no_missing_key(write_tree):
    """``d[k]`` with ``k`` not known: not known, not a KeyError."""
    model, _ = run(write_tree, """
def generate_launch_description():
    names = {'a': 'x'}
    return LaunchDescription([Node(package='p', executable='e',
                                   name=names[os.environ['ROBOT']])])
""")
    assert not any("fails" in d.message for d in model.diagnostics)


def test_actions_made_in_one_loop_and_added_by_index_in_another(write_tree):
    """neo_simulation2: a loop over robots whose number is not known appends a node to
    a list; a second loop adds ``nodes[i]`` to the description. The item is one of the
    list's actions: the node stays, under the first loop's test, not lost."""
    model, _ = run(write_tree, """
def generate_launch_description():
    count = int(os.environ['NUMBER_OF_ROBOTS'])
    spawners = []
    for i in range(count):
        spawners.append(Node(package='p', executable='spawn', name='spawn' + str(i)))
    ld = LaunchDescription()
    for i in range(count):
        ld.add_action(spawners[i])
    return ld
""")
    assert [n.executable for n in model.nodes] == ["spawn"]
    assert [c.text for c in model.nodes[0].conditions] == ["for i in range(count)"]


def test_global_name_set_before_a_call_is_seen_by_the_function_called(write_tree):
    """control_quadrupeds_soft_contacts' robot.launch.py: generate_launch_description
    declares ``global terrain``, sets it, then calls helpers that read it before it
    returns; Python writes a global at once, so the helpers see it (they said ``name
    terrain is not defined here``), and a global the helper sets is the caller's after
    the call."""
    model, _ = run(write_tree, """
def spawn(ld):
    global count
    ld.add_action(Node(package='p', executable='e', name=terrain))
    count = count + 1

def generate_launch_description():
    global terrain, count
    terrain = 'rigid'
    count = 1
    ld = LaunchDescription()
    spawn(ld)
    terrain = 'soft'
    spawn(ld)
    ld.add_action(Node(package='p', executable='e', name='n' + str(count)))
    return ld
""")
    assert [n.name for n in model.nodes] == ["/rigid", "/soft", "/n3"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_nonlocal_name_set_before_a_call_is_seen_by_the_nested_function(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    name = 'a'
    def setup():
        nonlocal name
        name = 'b'
        return make()
    def make():
        return Node(package='p', executable='e', name=name)
    return LaunchDescription([setup()])
""")
    assert [n.name for n in model.nodes] == ["/b"]
