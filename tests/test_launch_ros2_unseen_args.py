"""ROS 2 launch: an argument not seen declared where the reader could not see everything
the launch performs (a helper's DeclareLaunchArguments not read, an include not read) is
undecided, not unset; a value the Python interpreter does not compute is said once, where
it was made, not again at each use."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

HEADER = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from robot_helpers.launch import declare_robot_arguments, sim_time
"""


def run(write_tree, name: str, body: str, extra: dict[str, str] | None = None,
        args: dict[str, str] | None = None):
    files = {"src/pkg/package.xml": package_xml("pkg", "ament_cmake"),
             f"src/pkg/launch/{name}": body}
    files.update(extra or {})
    root = write_tree(files)
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/pkg/launch" / name), ws, args or {}, {})


def line_of(text: str, needle: str) -> int:
    lines = textwrap.dedent(text).lstrip("\n").splitlines()
    return next(n for n, line in enumerate(lines, 1) if needle in line)


def found(model, code: str) -> list[tuple[int, str]]:
    return sorted((d.location.line, d.message) for d in model.diagnostics if d.code == code)


# Interbotix's xsarm_control.launch.py: ``declared_arguments.extend(
# declare_interbotix_xsarm_robot_description_launch_arguments())`` from a module the
# reader does not read, then ``LaunchDescription(declared_arguments + [...])``
EXTENDED = HEADER + """
def generate_launch_description():
    declared = [DeclareLaunchArgument('robot_model', default_value='wx250s')]
    early = [Node(package='p', executable='e', name='early',
                  namespace=LaunchConfiguration('robot_name'))]
    declared.extend(
        declare_robot_arguments())
    return LaunchDescription(early + declared + [
        Node(package='p', executable='e', name='late',
             namespace=LaunchConfiguration('robot_name'),
             parameters=[{'model': LaunchConfiguration('robot_model')}])])
"""


def test_an_argument_a_helper_not_read_may_declare_is_undecided_not_unset(write_tree):
    model = run(write_tree, "main.launch.py", EXTENDED)
    made = line_of(EXTENDED, "declare_robot_arguments())")
    # before the helper's arguments are performed, robot_name is not declared: unset
    assert found(model, "LAUNCH_ARG_UNSET") == [
        (line_of(EXTENDED, "name='early'"),
         "launch argument robot_name has no value; names that use it keep '?'")]
    # after them it may be: undecided, naming where the declarations were not read
    [(line, message)] = found(model, "LAUNCH_UNKNOWN_VALUE")
    assert line == line_of(EXTENDED, "name='late'")
    assert "launch argument robot_name is not seen declared" in message
    assert f"line {made}, call to robot_helpers.launch.declare_robot_arguments" in message
    # the call is said once, where it is; the list's extend is no second complaint
    assert found(model, "LAUNCH_PY_UNSUPPORTED") == [
        (made, "call to robot_helpers.launch.declare_robot_arguments is not interpreted "
               "(never run)")]
    # what the helper returned is an action not seen, at that place, on the launch tree
    [unseen] = [i for i in model.tree[0].children if i.detail == "action"]
    assert unseen.location.line == made
    assert {n.name for n in model.nodes} == {"/?/early", "/?/late"}


def test_a_scoped_group_does_not_see_what_its_includer_left_unseen(write_tree):
    body = HEADER + """
def generate_launch_description():
    return LaunchDescription(declare_robot_arguments() + [
        GroupAction([Node(package='p', executable='e', name='n',
                          namespace=LaunchConfiguration('robot_name'))],
                    forwarding=False)])
"""
    model = run(write_tree, "main.launch.py", body)
    assert [line for line, _ in found(model, "LAUNCH_ARG_UNSET")] == [
        line_of(body, "name='n'")]
    assert found(model, "LAUNCH_UNKNOWN_VALUE") == []


def test_an_include_not_read_may_declare_arguments_xml(write_tree, tmp_path):
    """ROS 2's IncludeLaunchDescription runs the included file in its includer's launch
    configurations: what a file outside the workspace declares is the includer's too."""
    outside = tmp_path / "elsewhere/robot.launch.xml"
    body = f"""
<launch>
  <node pkg="p" exec="e" name="first" namespace="$(var robot_name)"/>
  <include file="{outside}"/>
  <node pkg="p" exec="e" name="second" namespace="$(var robot_name)"/>
</launch>
"""
    model = run(write_tree, "main.launch.xml", body)
    assert [line for line, _ in found(model, "LAUNCH_ARG_UNSET")] == [
        line_of(body, 'name="first"')]
    undecided = [(line, m) for line, m in found(model, "LAUNCH_UNKNOWN_VALUE")
                 if "robot_name" in m]
    assert [line for line, _ in undecided] == [line_of(body, 'name="second"')]
    assert f"line {line_of(body, '<include')}, the include of " in undecided[0][1]


def test_a_value_not_computed_is_said_once_where_it_is_made(write_tree):
    """Interbotix's ``use_sim_time_param = determine_use_sim_time_param(...)`` given to
    an include and a node: one LAUNCH_PY_UNSUPPORTED at the call, no LAUNCH_UNSUPPORTED
    at each use; an unset argument performed in an OpaqueFunction is LAUNCH_ARG_UNSET
    there, not LAUNCH_UNSUPPORTED "var robot_model" at the node that uses its text."""
    body = HEADER + """
def setup(context):
    use_sim = sim_time(context)
    model = LaunchConfiguration('robot_model').perform(context)
    return [
        Node(package='p', executable='e', name='a', parameters=[{'use_sim_time': use_sim}]),
        Node(package='p', executable='e', name='b', parameters=[{'use_sim_time': use_sim}],
             arguments=['--robot_model', model]),
    ]

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('robot_model'),
                              OpaqueFunction(function=setup)])
"""
    model = run(write_tree, "main.launch.py", body)
    assert found(model, "LAUNCH_PY_UNSUPPORTED") == [
        (line_of(body, "use_sim = sim_time(context)"),
         "call to robot_helpers.launch.sim_time is not interpreted (never run)")]
    assert found(model, "LAUNCH_UNSUPPORTED") == []
    assert {d.code for d in model.diagnostics} == {"LAUNCH_PY_UNSUPPORTED",
                                                   "LAUNCH_ARG_UNSET"}
    params = {p.name: p.value for p in model.params}
    assert params == {"/a/use_sim_time": None, "/b/use_sim_time": None}


def test_constructs_not_interpreted_are_named_and_said_once(write_tree):
    """nav2's tb3_simulation_launch.py reads its URDF in ``with open(urdf) as f`` from a
    package not here: one diagnostic at the read(), none again where robot_description
    is used; ``eval(...)(...)`` is said once, where ``eval`` is (the name its text reads
    not defined: the file may bind it unwritten, as it calls eval); perform() on no
    launch context names the expression; a Command says which command it does not run."""
    body = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import Command, LaunchConfiguration
from launch_ros.actions import Node

def named(context):
    return LaunchConfiguration('name').perform(context)

def generate_launch_description():
    with open('/nowhere/robot.urdf', 'r') as infp:
        robot_description = infp.read()
    urdf = os.path.join(get_package_share_directory('absent'), 'robot.urdf')
    with open(urdf) as other:
        described = other.read()
    with open(where_is_it(), 'r') as unseen:
        described = unseen.read()
    factory = eval('make_' + 'node')
    made = factory('x')
    name = named('no context')
    return LaunchDescription([
        Node(package='p', executable='e', name='a',
             parameters=[{'robot_description': robot_description, 'made': made,
                          'name': name, 'described': described}]),
        Node(package='p', executable='e', name='b',
             parameters=[{'robot_description': robot_description, 'made': made,
                          'xacro': Command(['xacro ', '/nowhere/r.xacro'])}]),
    ])
"""
    model = run(write_tree, "main.launch.py", body)
    said = found(model, "LAUNCH_PY_UNSUPPORTED")
    assert said == [
        (line_of(body, ".perform("), "LaunchConfiguration('name').perform(context): "
                                     "perform() outside an OpaqueFunction is not interpreted"),
        (line_of(body, "where_is_it"), "name where_is_it is not defined here"),
        (line_of(body, "eval("), "name make_node is not defined here")]
    # a file not read is data not known, said as such (it hides no configuration)
    # (and so is one whose path launch finds when it runs, in a package not here)
    assert found(model, "LAUNCH_PY_FILE_UNKNOWN") == [
        (line_of(body, "infp.read()"), "/nowhere/robot.urdf is outside the workspace; "
                                       "not read"),
        (line_of(body, "with open(urdf)"), "open(urdf): a file whose path is known only "
                                           "when launch runs; not read")]
    assert found(model, "LAUNCH_UNSUPPORTED") == []
    # never run, as a ROS 1 command= is not: an unknown value, not a construct not read
    assert (line_of(body, "name='b'"), 'command "xacro /nowhere/r.xacro" is not run; what '
            "depends on it keeps '?'") in \
        found(model, "LAUNCH_UNKNOWN_VALUE")


def test_every_way_a_list_takes_a_helpers_unknown_items(write_tree):
    """Unpacked, looped over, added in place or given as the description: the helper's
    items are unknown, not none, and the loop over them is not said again."""
    shapes = {
        "star": "return LaunchDescription([*declare_robot_arguments(), N])",
        "loop": "d = []\n    for a in declare_robot_arguments():\n        d.append(a)\n"
                "    return LaunchDescription(d + [N])",
        "comprehension": "return LaunchDescription([a for a in declare_robot_arguments()]"
                         " + [N])",
        "in place": "d = []\n    d += declare_robot_arguments()\n"
                    "    return LaunchDescription(d + [N])",
        "add_action": "ld = LaunchDescription()\n    ld.add_action(declare_robot_arguments())"
                      "\n    ld.add_action(N)\n    return ld",
    }
    for shape, statements in shapes.items():
        body = HEADER + f"""
N = Node(package='p', executable='e', name='n', namespace=LaunchConfiguration('robot_name'))

def generate_launch_description():
    {statements}
"""
        model = run(write_tree, f"{shape.replace(' ', '_')}.launch.py", body)
        assert [d.code for d in model.diagnostics] == [
            "LAUNCH_PY_UNSUPPORTED", "LAUNCH_UNKNOWN_VALUE"], shape


def test_a_name_of_a_star_import_not_found_says_the_module(write_tree):
    """isaac_ros_nvblox's example launch files: ``from isaac_ros_launch_utils.all_types
    import *`` (isaac_ros_common, not in the workspace), then ``IfCondition(...)``,
    ``SetParameter(...)``, ``LaunchDescription(...)``: each "name IfCondition is not
    defined here", as though the file were wrong. Now the message names the star import
    it may come from; a name with none, bound nowhere in the file, is a NameError."""
    body = """
from launch import LaunchDescription
from vendor_launch_utils.all_types import *

def generate_launch_description():
    actions = [SetParameter('use_sim_time', True)]
    return LaunchDescription(actions + [where_is_it()])
"""
    model = run(write_tree, "main.launch.py", body)
    said = found(model, "LAUNCH_PY_UNSUPPORTED")
    assert (line_of(body, "SetParameter("), "name SetParameter is not defined here; it may "
            "be one of 'from vendor_launch_utils.all_types import *', a module not "
            "found") in said
    plain = run(write_tree, "plain.launch.py", body.replace(
        "from vendor_launch_utils.all_types import *\n", ""))
    # with none, and bound nowhere in the file: Python's NameError there
    assert (line_of(body, "SetParameter(") - 1, "name SetParameter is not defined anywhere "
            "in the file: Python raises NameError here, and launch stops") in \
        found(plain, "LAUNCH_PY_UNSUPPORTED")
