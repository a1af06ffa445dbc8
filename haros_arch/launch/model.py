"""What a launch file declares, before it meets the node models.

Names here are already resolved against the launch namespaces (``/robot/driver``);
remappings are kept as written, because a node resolves them in its own namespace.
"""

from __future__ import annotations

import dataclasses
import shlex
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..model.conditions import Condition
from ..model.launch_tree import LaunchItem, PackageUse
from ..model.location import NOWHERE, Location
from ..model.values import Unknown, Value


def shell_words(line: str) -> list[str]:
    """A command line's words as a shell splits them (on blanks when its quotes do not
    close): a node's ``args``, a substitution's command."""
    try:
        return shlex.split(line)
    except ValueError:
        return line.split()

@dataclass
class NodeDecl:
    """A ``<node>`` (ROS 1) or ``Node`` action (ROS 2): one node instance to start."""

    name: str  # full ROS name, ``?`` for unknown parts
    package: str
    executable: str
    namespace: str = "/"
    args: str = ""
    remaps: list[tuple[str, str]] = field(default_factory=list)
    conditions: tuple[Condition, ...] = ()
    location: Location = NOWHERE
    anonymous: bool = False
    machine: str | None = None
    respawn: bool = False
    required: bool = False
    respawn_delay: float = 0.0
    output: str | None = None
    cwd: str | None = None
    launch_prefix: str | None = None
    env: list[tuple[str, str]] = field(default_factory=list)
    is_test: bool = False
    ros_version: int = 1  # 2: ROS 2 naming rules apply (launch.ros2)
    composable: bool = False  # ROS 2: a component loaded into a container
    # launched without a name and named by the graph after its executable (no code, no
    # model): the real name is the one its code gives, which may differ
    name_guessed: bool = False
    # ROS 2: the launch names the node (``name=``, ``__node:=``), with a value that may
    # not be known statically: a ``?`` there is that value, not a name left to the code
    name_given: bool = False
    # ROS 2: the launch gives the node a namespace (``namespace=``, a
    # ``PushRosNamespace`` around it, ``__ns:=``), which launch_ros passes as ``__ns``
    # and which replaces one the code gives; without one, the code's holds
    namespace_given: bool = False
    container: str | None = None  # ROS 2: full name of the container it is loaded into
    # ROS 2 Python: where the package's name was written, when another file than the
    # action's wrote it (a helper of another package's module, handed the name by the
    # launch file that calls it): that file's package is the one that uses the package
    package_location: Location | None = None
    # ROS 2: the parameter files given to the process, as read (rewritten), with where:
    # they apply by node name to every node the process makes (a nav2 server's costmap)
    # and where each entry is written, by (section pattern, name) (none for a file
    # launch_ros writes of the node's dictionaries)
    param_files: list[tuple[Any, Location, dict[tuple[str, str], Location]]] = field(
        default_factory=list, repr=False)
    # ROS 2: parameter files given to a node whose name is not known, as launch_ros passes
    # them (``--params-file``): the running node applies the sections for its name, of
    # which only the /** entries are applied here
    params_files_given: list[str] = field(default_factory=list)
    # ROS 2: where such a file with entries for particular nodes was given: said
    # (LAUNCH_PARAM_FILE) only if the node is not named from its code after all
    # (``graph.processes.unnamed_param_files``)
    unnamed_param_files: list[Location] = field(default_factory=list, repr=False)
    # ROS 2: the command line of each argument that is a ``Command``'s output (``ros_gz_sim
    # create -string <xacro ...>``), by its index among the words of ``args``
    arg_commands: dict[int, str] = field(default_factory=dict, repr=False)
    # ROS 2: the text of each file an argument names that the launch gives with text
    # replaced (nav2_common's ``ReplaceString``: rviz2's ``-d`` configuration with
    # ``<robot_namespace>`` made the robot's namespace), by the path the argument holds
    rewritten_files: dict[str, str] = field(default_factory=dict, repr=False)
    # ROS 1: where each of ``remaps`` is written (the ``<remap>`` element, in the node or
    # in a scope around it), by its pair
    remap_places: dict[tuple[str, str], Location] = field(default_factory=dict, repr=False)


@dataclass
class ForeignSections:
    """ROS 2: a parameter file whose every section for particular nodes is for a name
    that none of the nodes it is given to has (``nodes.sections_for_no_node``), or a node
    it is given to that none of its sections is for (``lonely``): the graph says so
    (``LAUNCH_PARAMS_NO_NODE``) unless a node its process makes has one of those
    names."""

    path: str
    nodes: list[str]  # full names of the nodes it is given to
    patterns: list[str]  # its sections' node name patterns
    location: Location = NOWHERE  # where it is first given
    # a file other nodes it is given to take sections of: ``nodes`` is the one node
    # it is given to that no section is for (where it is given to that node), and
    # ``patterns`` the sections for none of its nodes; said only for a section named
    # after that node's executable or the name its code gives it, the name the launch
    # file changed (go2_ros2_sdk's ``/teleop_node:`` for teleop_twist_joy's teleop_node,
    # launched as ``go2_teleop_node``)
    lonely: bool = False


@dataclass
class ParamDecl:
    """A parameter given a value by the launch file."""

    name: str  # full ROS name
    value: Any = None
    type: str | None = None
    conditions: tuple[Condition, ...] = ()
    location: Location = NOWHERE
    node: str | None = None  # ROS 2: full name of the node that owns the parameter
    key: str | None = None  # ROS 2: the parameter's dotted name within that node
    # index in LaunchModel.nodes of the node declaration it was given to (ROS 2: several
    # unnamed nodes share the name ``/?`` until the graph names them from their code;
    # ROS 1: a parameter of a <node> element, two ``$(anon x)`` both ``/x_?``)
    owner: int | None = None
    # ROS 2: a parameter file's entry for particular nodes (``turtlebot3_node:``,
    # ``/**/amcl:``) given to a node whose name is not known yet: the rcl node name
    # pattern it is for; the graph gives it to the node only when the name it finds
    # for the node (from its code or model) matches
    pattern: str | None = None
    # a private parameter of a ``<test>`` that a roslaunch run leaves out
    # (``without_tests``): its name; roslaunch sets the parameter, its reader is not run
    test: str | None = None
    # the setting for several nodes that gave it, not one for this node alone: ROS 2's
    # ``SetParameter`` (its place, ``file:line:column``: every node of its scope) or
    # the ``/**`` entries of a parameter file (its path: every node it is given to, by
    # ``SetParametersFromFile`` or a node's own parameters), where each node gets the
    # value and takes it only if it declares it; ROS 1's ``<rosparam file>`` inside a
    # ``<node>`` (its path: every node it is loaded into, each reading what it needs)
    setting: str | None = None
    # ROS 1 ``command=`` / ``textfile=`` (``cat FILE``), ROS 2 ``Command()`` /
    # ``$(command)``: the command line the value comes from, ``?`` for unknown parts
    # (it is never run; robot descriptions read the xacro file it names)
    command: str | None = None


@dataclass
class UnreadInclude:
    """A ROS 1 ``<include>`` whose file is not known statically (its package is not
    found): what it would start would be in this namespace and take these remaps (the
    Gazebo a ``$(find gazebo_ros)`` launch file starts, ``robot.attach``)."""

    file: str  # as written
    namespace: str
    remaps: list[tuple[str, str]]
    conditions: tuple[Condition, ...] = ()
    location: Location = NOWHERE


@dataclass
class LaunchModel:
    files: list[str] = field(default_factory=list)  # every file read, includes too
    nodes: list[NodeDecl] = field(default_factory=list)
    params: list[ParamDecl] = field(default_factory=list)
    args: dict[str, str | None] = field(default_factory=dict)  # top-level arguments
    diagnostics: list[Diagnostic] = field(default_factory=list)
    clear_params: list[str] = field(default_factory=list)  # namespaces cleared first
    deleted_params: list[str] = field(default_factory=list)  # <rosparam command="delete">
    machines: dict[str, str] = field(default_factory=dict)  # name -> address
    tree: list[LaunchItem] = field(default_factory=list)  # the files as written
    # the files an include could name with another value of its arguments, as
    # regular expressions over absolute paths (``$(arg pipeline)_planning_pipeline.
    # launch.xml``: MoveIt's chomp pipeline is included when ``pipeline`` is chomp)
    include_patterns: list[str] = field(default_factory=list)
    # the packages whose folders a substitution asked for, where (``$(find pkg)``,
    # ``FindPackageShare``); the nodes' packages are in ``nodes``
    package_uses: list[PackageUse] = field(default_factory=list)
    # the values substitutions read from the environment (``$(env HOME)``,
    # ``$(optenv ROBOT_CONFIG /opt/robot)`` when set): paths under them follow the
    # machine that runs the launch file, not a folder the file hard-codes
    # (and, per configuration, the values it gives the launch arguments: they come
    # from its command line too; and the files a Python launch file opens for writing,
    # made on that machine as it runs: tb3_multi_robot's /tmp/<robot>_bridge.yaml)
    environment_values: list[str] = field(default_factory=list)
    unread_includes: list[UnreadInclude] = field(default_factory=list)
    foreign_sections: list[ForeignSections] = field(default_factory=list)


def without_tests(model: LaunchModel) -> LaunchModel:
    """``model`` as roslaunch runs it: ``<test>`` nodes are started by rostest only, so
    they are left out (each said in an info diagnostic); their parameters stay, as
    roslaunch sets them all the same, each private one marked with its test (whose
    reads are not seen)."""
    if not any(node.is_test for node in model.nodes):
        return model
    kept: list[NodeDecl] = []
    index: dict[int, int] = {}
    notes: list[Diagnostic] = []
    for number, node in enumerate(model.nodes):
        if node.is_test:
            notes.append(diag.make("LAUNCH_TEST_LEFT_OUT", node.location, name=node.name))
            continue
        index[number] = len(kept)
        kept.append(node)
    tests = {number: node.name for number, node in enumerate(model.nodes) if node.is_test}
    params = [p if p.owner is None else dataclasses.replace(
        p, owner=index.get(p.owner), test=tests.get(p.owner)) for p in model.params]
    params = [p if p.test is not None or p.owner is not None else dataclasses.replace(
        p, test=next((name for name in tests.values()
                      if p.name.startswith(name.rstrip("/") + "/")), None))
              for p in params]
    return dataclasses.replace(model, nodes=kept, params=params,
                               diagnostics=[*model.diagnostics, *notes])


class RecordedEnvironment(Mapping[str, str]):
    """The environment, noting in ``read`` each value a launch file takes from it
    (``LaunchModel.environment_values``); asking whether a variable is set notes nothing."""

    def __init__(self, environment: Mapping[str, str], read: list[str]) -> None:
        self._environment = environment
        self._read = read

    def __getitem__(self, key: str) -> str:
        value = self._environment[key]
        if value not in self._read:
            self._read.append(value)
        return value

    def __iter__(self) -> Iterator[str]:
        return iter(self._environment)

    def __len__(self) -> int:
        return len(self._environment)


# the origin of a package's folder that is neither in the workspace nor installed here
_NOT_FOUND = "find "


def package_not_found(package: str) -> Value:
    """The folder of ``package`` when it is neither in the workspace nor installed here
    (``$(find pkg)``, ``FindPackageShare``, ``get_package_share_directory``); the
    substitution says so where it is performed (``LAUNCH_UNKNOWN_VALUE``)."""
    return Value.unknown(_NOT_FOUND + package)


def program_not_found(value: Value) -> tuple[str | None, set[str]]:
    """Of a command line that is never run, what is not known only because its program
    lies in the folder of a package neither in the workspace nor installed here
    (``package_not_found``; roslaunch runs ``$(find xacro)/xacro`` from xacro's ``lib``
    folder, and no run here needs it): the line with that program written as the launch
    file finds it (``$(find xacro)/xacro '/ws/src/robot/urdf/r.urdf.xacro'``), None when
    something else of it is not known too (an argument's folder: the file the command
    reads); and those packages, not said (none when another word needs them too)."""
    shown = ""
    program: set[str] = set()
    elsewhere: set[str] = set()
    other = False  # a part not known for another reason, or outside the program
    for part in value.parts:
        if isinstance(part, str):
            shown += part
            continue
        package = part.origin[len(_NOT_FOUND):] if part.origin.startswith(_NOT_FOUND) \
            else None
        if package is not None and not any(c.isspace() for c in shown.lstrip()):
            program.add(package)
            shown += f"$(find {package})"
        else:
            other = True
            elsewhere.update([package] if package is not None else [])
    program -= elsewhere
    whole = bool(program) and not other
    return (shown if whole else None), program


# the origin of a ROS 1 ``$(env NAME)`` whose variable the configuration does not set
_ENV_UNSET = "env "


def found_nowhere(value: Value, environment: bool = False) -> bool:
    """Whether every unknown part of ``value`` is such a folder (``package_not_found``),
    or, with ``environment``, a variable the configuration does not set (ROS 1's
    ``$(env NAME)``, which says so where it is substituted): an include of such a path
    is not said again."""
    causes = (_NOT_FOUND, _ENV_UNSET) if environment else (_NOT_FOUND,)
    unknown = [p for p in value.parts if isinstance(p, Unknown)]
    return bool(unknown) and all(p.origin.startswith(causes) for p in unknown)


def unset_variables(value: Value) -> list[str]:
    """The environment variables whose value ``value`` lacks (``$(env NAME)`` with no
    default, ROS 1's and ROS 2's, where the configuration does not set NAME), in order."""
    return list(dict.fromkeys(p.origin[len(_ENV_UNSET):] for p in value.parts
                              if isinstance(p, Unknown) and p.origin.startswith(_ENV_UNSET)))

