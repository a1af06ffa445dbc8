"""Python launch file shapes met on real workspaces (survey Z36, 2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_a_process_on_exit_starts_its_actions_after_it_ends(write_tree):
    """spot_ros2's spot_ros2_control.launch.py: ``Node(executable='hardware_spawner',
    on_exit=[Node(executable='spawner', ...)], condition=...)``. launch registers the
    ``on_exit`` actions as an OnProcessExit handler of that process: the spawner runs
    once it has ended, and only when the process runs at all (its condition). The
    spawner was missing, with the controllers it loads."""
    model, _ = run(write_tree, """
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('auto_start', default_value='true'),
        DeclareLaunchArgument('extra', default_value='false'),
        Node(package='p', executable='first', name='first',
             on_exit=[Node(package='p', executable='second', name='second')],
             condition=IfCondition(LaunchConfiguration('auto_start'))),
        Node(package='p', executable='never', name='never',
             on_exit=Node(package='p', executable='after_never', name='after_never'),
             condition=IfCondition(LaunchConfiguration('extra'))),
        ExecuteProcess(cmd=['sleep', '1'],
                       on_exit=[Node(package='p', executable='third', name='third')]),
    ])
""")
    nodes = {n.name: [(c.statement, c.text) for c in n.conditions] for n in model.nodes}
    assert sorted(nodes) == ["/first", "/second", "/third"]
    assert nodes["/first"] == []
    [(statement, text)] = nodes["/second"]
    assert statement == "event"
    assert text == "on event OnProcessExit of the process at pkg/launch/main.launch.py:18:9"
    assert [s for s, _ in nodes["/third"]] == ["event"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_an_on_exit_callable_is_said(write_tree):
    """``on_exit`` given a function (launch calls it with the event): not interpreted,
    said where the process is made; the process itself stays."""
    model, _ = run(write_tree, """
def later(event, context):
    return [Node(package='p', executable='second', name='second')]

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='first', name='first',
                                   on_exit=later)])
""")
    assert [n.name for n in model.nodes] == ["/first"]
    assert any(d.code == "LAUNCH_PY_UNSUPPORTED" and "on_exit" in d.message
               for d in model.diagnostics)


LEASING = """
from launch.utilities.type_utils import coerce_to_type

def setup(context, flag):
    params = {'mode': 'direct', 'mock': True}
    if flag:
        params.update({'mode': 'proxied', 'take': False})
        params['mock'] = False
    return [Node(package='p', executable='e', name='n', parameters=[params])]

def known(context):
    value = LaunchConfiguration('controllable').perform(context)
    return setup(context, coerce_to_type(value.lower(), bool))

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('controllable', default_value='False'),
        OpaqueFunction(function=known),
    ])
"""


def test_items_a_branch_of_an_unknown_test_sets_are_not_known(write_tree):
    """spot_ros2's spot_driver.launch.py: ``if controllable: params.update({...})`` with
    ``controllable`` not known set the parameters whatever it was (the body changed
    the dict in place, and the ``else`` ran on with it changed): the driver's
    ``leasing_mode`` was ``proxied``, so the lease clients it makes only then were
    taken as always made (4 false client-without-server). An item a branch alone
    sets, or sets otherwise than the other, is not known after the ``if``."""
    model, _ = run(write_tree, """
from robot_api import has_lease_manager

def generate_launch_description():
    params = {'mode': 'direct', 'mock': True, 'rate': 1.0, 'nested': {'a': 1}}
    if has_lease_manager():
        params.update({'mode': 'proxied', 'take': False})
        params['mock'] = False
        params['rate'] = 1.0
        params['nested']['a'] = 2
        made = {'n': 1}
        made['n'] = 2
    else:
        made = {'n': 3}
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[params, {'made': made['n']}])])
""")
    params = {p.name: p.value for p in model.params}
    assert params["/n/mode"] is None and params["/n/take"] is None
    assert params["/n/mock"] is None and params["/n/nested.a"] is None
    assert params["/n/rate"] == 1.0  # set alike in both branches
    assert params["/n/made"] is None  # a dict each branch made: either's item


def test_coerce_to_type_of_a_known_text(write_tree):
    """synchros2's ``convert_to_bool``: ``coerce_to_type(value.lower(), bool)`` of a
    launch argument, as launch converts it; the test it gives is decided."""
    model, _ = run(write_tree, LEASING, args={"controllable": "1"})
    params = {p.name: p.value for p in model.params}
    assert params == {"/n/mode": "proxied", "/n/mock": False, "/n/take": False}
    model, _ = run(write_tree, LEASING)
    assert {p.name: p.value for p in model.params} == {"/n/mode": "direct", "/n/mock": True}
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_an_attribute_a_branch_of_an_unknown_test_sets_is_not_known(write_tree):
    """``self.rate = ...`` in one branch of a test not known statically, in a class
    of the file: after the ``if``, the attribute may hold either value."""
    model, _ = run(write_tree, """
from robot_api import fast

class Config:
    def __init__(self):
        self.rate = 10
        if fast():
            self.rate = 50

def generate_launch_description():
    config = Config()
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{'rate': config.rate}])])
""")
    assert {p.name: p.value for p in model.params} == {"/n/rate": None}


def test_an_enum_called_with_a_value_is_its_member(write_tree):
    """spot_ros2's spot_image_publishers.launch.py: ``DepthRegisteredMode(text)`` of an
    Enum of the workspace gives the member of that value, so ``if mode is not
    DepthRegisteredMode.FROM_SPOT:`` is decided; a loop over the Enum gives its members
    (the argument's ``choices``); a value no member has fails as in Python (said,
    unknown)."""
    model, _ = run(write_tree, """
from enum import Enum

class Mode(Enum):
    DISABLE = 'disable'
    FROM_SPOT = 'from_spot'
    OFF = 'disable'  # an alias of DISABLE

def setup(context):
    mode = Mode(LaunchConfiguration('mode').perform(context).lower())
    params = {'registered': True, 'same': Mode(Mode.DISABLE) is Mode.DISABLE,
              'choices': [m.value for m in Mode]}
    if mode is not Mode.FROM_SPOT:
        params.update({'registered': False})
    return [Node(package='p', executable='e', name='n', parameters=[params])]

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('mode', default_value='From_Spot'),
                              OpaqueFunction(function=setup)])
""")
    assert {p.name: p.value for p in model.params} == {
        "/n/registered": True, "/n/same": True, "/n/choices": ["disable", "from_spot"]}
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    model, _ = run(write_tree, """
from enum import Enum

class Mode(Enum):
    DISABLE = 'disable'

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{'mode': Mode('other')}])])
""")
    assert any(d.code == "LAUNCH_PY_UNSUPPORTED" and "Mode('other') fails" in d.message
               for d in model.diagnostics)


def test_an_and_with_an_unknown_operand_and_a_false_one_is_false(write_tree):
    """spot_ros2's get_login_parameters: ``if not username and 'username' in params:``
    with ``username`` an environment variable not known and ``params`` empty: false
    whatever the variable is, so the body (a lookup that would fail) does not run; an
    ``or`` with a true operand after an unknown one is true. An operand after the
    unknown one runs under it: a node it makes is conditional."""
    model, _ = run(write_tree, """
def generate_launch_description():
    username = os.getenv('ROBOT_USER')
    params = {}
    nodes = []
    if not username and 'username' in params:
        username = params['username']
        nodes.append(Node(package='p', executable='e', name='never'))
    if username or 'x' not in params:
        nodes.append(Node(package='p', executable='e', name='always'))
    if username and nodes.append(Node(package='p', executable='e', name='maybe')):
        pass
    return LaunchDescription(nodes)
""")
    conditions = {n.name: [c.text for c in n.conditions] for n in model.nodes}
    assert list(conditions) == ["/always", "/maybe"]
    assert conditions["/always"] == [] and conditions["/maybe"] != []
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_a_with_statement_not_run_that_returns_gives_an_unknown(write_tree):
    """spot_ros2's create_rviz_config: ``with NamedTemporaryFile(...) as out: ...;
    return out.name``. The body is not run, so the function ran past the ``return``
    and gave ``None`` (a "NoneType value" warning, ``-d`` of nothing): its value is
    not known, said once where the ``with`` is; one that may return (under a test) is
    one of the function's values."""
    model, _ = run(write_tree, """
from tempfile import NamedTemporaryFile

def config(name):
    with NamedTemporaryFile(suffix='.rviz', mode='w', delete=False) as out:
        out.write(name)
        return out.name

def maybe(name):
    with NamedTemporaryFile(mode='w') as out:
        if name:
            return out.name
    return 'plain'

def generate_launch_description():
    return LaunchDescription([
        Node(package='rviz2', executable='rviz2', name='a', arguments=['-d', config('x')]),
        Node(package='p', executable='e', name='b', parameters=[{'f': maybe('x')}])])
""")
    messages = [d.message for d in model.diagnostics]
    assert not any("NoneType" in m for m in messages), messages
    [a] = [n for n in model.nodes if n.name == "/a"]
    assert "?" in " ".join(a.args)
    assert {p.name: p.value for p in model.params} == {"/b/f": None}
