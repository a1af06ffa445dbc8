"""Python launch file shapes the surveys Z20 and Z22 left (2026-12-01)."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_isinstance_of_a_substitution_is_decided(write_tree):
    """panther_ros' welcomeMsg.py flattens a list holding ``LaunchConfiguration`` and
    ``Command`` objects with a helper recursing while ``isinstance(lst, list)``: no
    substitution is a list (nor any builtin type), and neither is a text made when launch
    runs (a share folder found then), so the helper returns ``[lst]`` for each without
    looping over it. A substitution is an instance of its own launch class
    and of ``Substitution``; a class not read stays not known."""
    model, _ = run(write_tree, """
from launch.actions import LogInfo
from launch.substitutions import Command, LaunchConfiguration, Substitution, TextSubstitution
import launch

def flatten(lst):
    if isinstance(lst, list):
        flat = []
        for element in lst:
            flat.extend(flatten(element))
        return flat
    else:
        return [lst]

def generate_launch_description():
    serial = LaunchConfiguration('serial')
    share = get_package_share_directory('not_installed_anywhere')
    parts = flatten([['Serial: ', serial, '\\n'], Command('ros2 pkg xml -t version p'),
                     [share + '/x']])
    nodes = [LogInfo(msg=parts)]
    if len(parts) == 5:
        nodes.append(Node(package='p', executable='e', name='five'))
    if isinstance(serial, (str, int, float, bool, dict, tuple)):
        nodes.append(Node(package='p', executable='e', name='plain'))
    if isinstance(IfCondition('true'), list):
        nodes.append(Node(package='p', executable='e', name='condition'))
    if isinstance(serial, launch.substitutions.LaunchConfiguration) \\
            and isinstance(serial, (str, Substitution)):
        nodes.append(Node(package='p', executable='e', name='own'))
    if isinstance(serial, TextSubstitution):
        nodes.append(Node(package='p', executable='e', name='other'))
    return LaunchDescription(nodes)
""")
    assert codes(model) == ["LAUNCH_UNSUPPORTED"]  # the test on TextSubstitution only
    names = {n.name: n for n in model.nodes}
    assert sorted(names) == ["/five", "/other", "/own"]
    assert not names["/five"].conditions and not names["/own"].conditions
    assert names["/other"].conditions


def test_str_of_a_substitution_is_the_object_text(write_tree):
    """Survey Z20: ``str()`` of a ``PathJoinSubstitution`` was not known. No class of
    launch or launch_ros defines ``__str__`` or ``__repr__`` for substitutions, so
    Python gives ``object``'s text, ``<module.Class object at 0x...>``: never the path the
    substitution stands for, and its address is not known. The ``str`` of a
    ``pathlib`` path is the path."""
    model, _ = run(write_tree, """
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare
from ament_index_python.packages import get_package_share_path

def generate_launch_description():
    path = PathJoinSubstitution([FindPackageShare('pkg'), 'config', 'a.yaml'])
    share = get_package_share_path('not_installed_anywhere')
    return LaunchDescription([
        Node(package='p', executable='e', name='a', parameters=[str(path)]),
        Node(package='p', executable='e', name='b',
             namespace=repr(LaunchConfiguration('ns', default='r'))),
        Node(package='p', executable='e', name='c', parameters=[str(share / 'c.yaml')]),
    ])
""")
    _, b, _ = model.nodes
    files = [d for d in model.diagnostics if d.code == "LAUNCH_PARAM_FILE"]
    assert [d.message for d in files] == [
        "parameter file <launch.substitutions.path_join_substitution.PathJoinSubstitution"
        " object at ?> is not known statically",
        "parameter file ?/c.yaml is not known statically"]
    assert b.name.startswith(
        "/<launch.substitutions.launch_configuration.LaunchConfiguration object at ?>")
    unknown = [d for d in model.diagnostics if d.code == "LAUNCH_UNSUPPORTED"]
    assert len(unknown) == 2 and all(
        d.message.startswith("str() / repr() of a launch object is Python's object text")
        for d in unknown)
    # str() of the pathlib path is the path: nothing said of it but its unknown folder
    assert files[1].location.line not in {d.location.line for d in unknown}


def test_an_f_string_of_a_substitution_is_the_object_text(write_tree):
    """``f"{LaunchConfiguration('ns')}"`` formats the object as Python does, with
    ``object.__format__``: its object text, as ``str()`` gives it (launch's classes define
    no ``__format__``, ``__str__`` nor ``__repr__``), never the configuration's value; we
    gave the value. A format spec on one is a TypeError; a ``pathlib`` path and plain
    values are formatted as before."""
    model, _ = run(write_tree, """
from launch.substitutions import LaunchConfiguration
from launch.conditions import IfCondition
from ament_index_python.packages import get_package_share_path

def generate_launch_description():
    ns = LaunchConfiguration('ns', default='r')
    share = get_package_share_path('not_installed_anywhere')
    return LaunchDescription([
        Node(package='p', executable='e', name='a', namespace=f"{ns}"),
        Node(package='p', executable='e', name='b', namespace=f"x_{ns!r}"),
        Node(package='p', executable='e', name='c', namespace=f"{IfCondition('true')}"),
        Node(package='p', executable='e', name='d', namespace=f"{ns:>4}"),
        Node(package='p', executable='e', name='e', namespace=f"{'r':>2}_{3}",
             parameters=[f"{share / 'e.yaml'}"]),
    ])
""")
    a, b, c, d, e = model.nodes
    assert a.name.startswith(
        "/<launch.substitutions.launch_configuration.LaunchConfiguration object at ?>")
    assert b.name.startswith(
        "/x_<launch.substitutions.launch_configuration.LaunchConfiguration object at ?>")
    assert c.name.startswith("/<?")
    assert e.name == "/r_3/e"  # plain values formatted as before
    files = [d.message for d in model.diagnostics if d.code == "LAUNCH_PARAM_FILE"]
    assert files == ["parameter file ?/e.yaml is not known statically"]
    unsupported = [x.message for x in model.diagnostics if x.code == "LAUNCH_PY_UNSUPPORTED"]
    assert any("takes no format spec" in m for m in unsupported)
    assert d.name == "/?/d"


def test_a_text_substitution_is_a_substitution_object(write_tree):
    """launch's ``TextSubstitution(text=...)`` is a ``Substitution``, not a ``str``: no
    ``isinstance(_, str)``, ``==`` by identity, true even when its text is empty; its
    ``text`` is the string; given to an action it is its text, and as a parameter value
    it is performed and read as YAML, as any substitution (an int here), where a plain
    ``'10'`` stays a string; a list of them is one string (launch_ros'
    normalize_parameters joins a list holding a substitution)."""
    model, _ = run(write_tree, """
from launch.substitutions import Substitution, TextSubstitution

def generate_launch_description():
    word = TextSubstitution(text='relay')
    nodes = [Node(package='p', executable='e', name=word, namespace=word.text + '_ns',
                  parameters=[{'rate': TextSubstitution(text='10'), 'plain': '10',
                               'joined': [TextSubstitution(text='a'), 'b']}])]
    if isinstance(word, str):
        nodes.append(Node(package='p', executable='e', name='plain'))
    if isinstance(word, TextSubstitution) and isinstance(word, Substitution):
        nodes.append(Node(package='p', executable='e', name='own'))
    if TextSubstitution(text=''):
        nodes.append(Node(package='p', executable='e', name='empty'))
    if word == 'relay':
        nodes.append(Node(package='p', executable='e', name='equal'))
    return LaunchDescription(nodes)
""")
    assert sorted(n.name for n in model.nodes) == ["/empty", "/own", "/relay_ns/relay"]
    params = {p.name: p.value for p in model.params}
    assert params["/relay_ns/relay/rate"] == 10
    assert params["/relay_ns/relay/plain"] == "10"
    assert params["/relay_ns/relay/joined"] == "ab"


def test_a_text_substitution_takes_a_str_by_keyword(write_tree):
    """launch raises a TypeError for ``TextSubstitution('a')`` and for a substitution as
    its text: said, and the value is not known (not taken as the text)."""
    model, _ = run(write_tree, """
def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='e', name=TextSubstitution('positional')),
        Node(package='p', executable='e',
             name=TextSubstitution(text=LaunchConfiguration('who', default='w'))),
    ])
""")
    assert codes(model) == ["LAUNCH_PY_UNSUPPORTED"]
    assert [n.name for n in model.nodes] == ["/?", "/?"]
    assert sum("TextSubstitution" in d.message for d in model.diagnostics) == 2
