"""The launch description both front ends produce, before it is run statically.

XML, YAML and Python launch files all become the same tree of ``Action`` values whose
text fields are ``Text`` (a tuple of literal strings and ``Subst`` objects), as the
real ``launch`` package turns every front end into actions and substitutions. The
``runner`` module then performs them in order, as ``LaunchService`` would, without
starting anything.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ...model.diagnostic import Diagnostic
from ...model.location import NOWHERE, Location
from ...model.values import Value
from ...shell import SHELLS, TERMINALS, Wait, run_order


# -- substitutions ---------------------------------------------------------------
@dataclass(frozen=True)
class Subst:
    """A substitution: its value is computed when the action runs."""


Text = tuple[str | Subst, ...]


def text(*parts: str | Subst | Text) -> Text:
    out: list[str | Subst] = []
    for part in parts:
        if isinstance(part, tuple):
            out.extend(part)
        else:
            out.append(part)
    return tuple(out)


@dataclass(frozen=True)
class Var(Subst):  # $(var name [default]) / LaunchConfiguration
    name: Text
    default: Text | None = None
    # the configuration a ``LaunchConfigurationEquals`` / ``NotEquals`` tests: launch
    # takes one nobody set as unequal to any value, with no error (its KeyError path)
    tested: bool = False


@dataclass(frozen=True)
class LoopVar(Subst):
    """``$(for-var name [default])`` / ``ForEachVar``: a value of the ``ForEach``
    iteration being performed; ``$(index name)`` / ``ForLoopIndex``: a ``ForLoop``'s
    index (launch keeps both as the context's locals, as text)."""

    name: Text
    default: Text | None = None


@dataclass(frozen=True)
class Env(Subst):  # $(env NAME [default]) / EnvironmentVariable
    name: Text
    default: Text | None = None


@dataclass(frozen=True)
class FindPackage(Subst):  # $(find-pkg-share) / $(find-pkg-prefix) / FindPackageShare
    package: Text
    share: bool = True
    # asked for by a Python launch file in a ``try`` whose handler catches the package's
    # absence (``get_package_share_directory``): the file runs without it
    tried: bool = False
    # where a Python launch file wrote it (its package's name): the use of the package
    # when launch performs it in another file's action (a node a helper of another
    # package builds with the caller's FindPackageShare among its parameters)
    written: Location | None = field(default=None, compare=False)
    # asked for by a Python launch file's ``get_package_share_directory`` (or
    # ``.find()``), which looks it up when called: a most likely misspelt package was
    # said there (``PACKAGE_NOT_FOUND``), not again where the value is performed
    said: bool = False


@dataclass(frozen=True)
class FindExec(Subst):
    """``$(find-exec name)`` / ``FindExecutable`` (``package`` None: searched on PATH), or
    ``$(exec-in-pkg exe pkg)`` / ``ExecutableInPackage`` (``<prefix>/lib/<pkg>/<exe>``)."""

    name: Text
    package: Text | None = None


@dataclass(frozen=True)
class GlobalParam(Subst):  # $(param name [default]) / launch_ros's Parameter
    name: Text
    default: Text | None = None


@dataclass(frozen=True)
class Eval(Subst):  # $(eval ...) / PythonExpression
    expression: Text
    # python_modules given (``$(eval 'expr' 'numpy')``, ``PythonExpression(..,
    # python_modules=[..])``): names of those modules may be in the expression
    modules: bool = False


@dataclass(frozen=True)
class Anon(Subst):
    name: Text


@dataclass(frozen=True)
class ThisFile(Subst):  # $(filename) / $(dirname) / ThisLaunchFile(Dir)
    directory: bool = False


@dataclass(frozen=True)
class Logic(Subst):  # $(not) $(and) $(or) $(equals) $(if) and their Python classes
    op: str
    operands: tuple[Text, ...]
    frontend: bool = False  # written as $(...) in XML / YAML


@dataclass(frozen=True)
class NodeParamsIn(Subst):  # nav2_common's HasNodeParams: 'True' if the file names node
    path: Text
    node: str


@dataclass(frozen=True)
class PathJoin(Subst):
    parts: tuple[Text, ...]
    # the Python object a launch file's call made: PATHLIB for a ``pathlib`` path, the
    # qualified name of launch's class, or "" (a front end's, not known)
    python: str = field(default="", compare=False)


PATHLIB = "pathlib"


@dataclass(frozen=True)
class FileContent(Subst):
    path: Text


@dataclass(frozen=True)
class Literal(Subst):
    """launch's ``TextSubstitution(text=...)``: in Python a substitution object, not a
    ``str``, whose value is its text. A launch text holds the text, not the object
    (``python_values.to_text``)."""

    text: Text


@dataclass(frozen=True)
class Opaque(Subst):
    """A value we do not compute (``$(command)``, an unknown call): always unknown."""

    origin: str
    report: bool = True  # False when the reason was reported already (a syntax error)
    refused: bool = False  # launch itself raises on it: an error, not a gap of ours


@dataclass(frozen=True)
class Performed(Subst):
    """An object of a substitution class the launch file defines, its ``perform`` not
    interpreted: unknown, but the substitutions its constructor was given (``reads``)
    are performed where it is, as its ``perform`` performs them (a launch configuration
    not set there is said as any other)."""

    origin: str
    reads: tuple[Text, ...] = ()


COMMAND_NOT_RUN = "Command (never run) is not evaluated; its value is unknown"


@dataclass(frozen=True)
class Command(Subst):
    """launch's ``Command``: never run, so its output is unknown; the command line is
    kept for the readers that understand it (robot descriptions read xacro's file)."""

    command: Text
    origin: str = COMMAND_NOT_RUN  # said with the command line when performed


# -- conditions --------------------------------------------------------------------
@dataclass(frozen=True)
class Cond:
    """``IfCondition``/``if=`` (``negate`` for unless) or ``LaunchConfigurationEquals``."""

    expression: Text
    negate: bool = False
    source: str = ""  # as written, for the condition's text
    equals: Text | None = None  # LaunchConfiguration(Not)Equals: compare with this
    # a Python test of the launch code: which runs of its tests (``python_values.Guard``)
    runs: tuple[int, ...] = field(default=(), compare=False)


# -- actions -------------------------------------------------------------------------
@dataclass
class Action:
    condition: Cond | None = field(default=None, kw_only=True)
    location: Location = field(default=NOWHERE, kw_only=True)


@dataclass
class DeclareArg(Action):
    name: str
    default: Text | None = None


@dataclass
class SetConfig(Action):  # <let> / SetLaunchConfiguration
    name: Text
    value: Text


@dataclass
class Group(Action):
    actions: list[Action]
    scoped: bool = True
    forwarding: bool = True
    configs: list[tuple[Text, Text]] = field(default_factory=list)


@dataclass
class ResetConfigs(Action):  # ResetLaunchConfigurations / <reset>
    keeps: list[tuple[Text, Text]] | None = None  # None: clear all


@dataclass
class PushNamespace(Action):
    namespace: Text


@dataclass
class SetRemap(Action):
    source: Text
    target: Text


@dataclass
class SetParam(Action):
    name: Text
    value: Any


@dataclass
class SetParamFile(Action):  # SetParametersFromFile / <set_parameters_from_file>
    path: Text


@dataclass
class SetEnv(Action):
    name: Text
    value: Text | None  # None: unset


@dataclass
class Include(Action):
    path: Text
    args: list[tuple[Text, Text]] = field(default_factory=list)


@dataclass
class ParamFile:
    """A parameter file, maybe rewritten (nav2's ``RewrittenYaml``)."""

    path: Text
    root_key: Text | None = None
    rewrites: list[tuple[Text, Any]] = field(default_factory=list)
    location: Location = NOWHERE
    replacements: list[tuple[Text, Text]] = field(default_factory=list)  # ReplaceString
    condition: Cond | None = None  # ReplaceString(condition=...): replace only if true
    allow_substs: bool = False  # $(...) in the file's text is substituted first
    key_rewrites: list[tuple[Text, Text]] = field(default_factory=list)  # RewrittenYaml
    value_rewrites: list[tuple[Text, Text]] = field(default_factory=list)


@dataclass(frozen=True, eq=False)
class FileRef(Subst):
    """A rewritten parameter file used where a path is expected (its source path)."""

    file: ParamFile


@dataclass(frozen=True)
class ParamValue:
    """``ParameterValue(value, value_type=str)``: a value kept as text, not read as YAML."""

    value: Any
    as_text: bool = False


@dataclass(frozen=True)
class UnknownParams:
    """Node parameters given in a form not known statically (a Python value the launch
    reader cannot follow): the node may get any parameter from it."""

    reason: str
    location: Location = NOWHERE


# A node parameter entry: a ParamFile, parameters not known statically, or (name Text,
# value) where value is a Python literal, Text, or a list of those; dict values are
# flattened with '.'.
ParamEntry = ParamFile | UnknownParams | tuple[Text, Any]


@dataclass
class NodeAction(Action):
    package: Text | None
    executable: Text | None
    name: Text | None = None
    namespace: Text | None = None
    parameters: list[ParamEntry] = field(default_factory=list)
    remaps: list[tuple[Text, Text]] = field(default_factory=list)
    arguments: list[Text] = field(default_factory=list)
    ros_arguments: list[Text] = field(default_factory=list)
    composable: list[ComposableNode] = field(default_factory=list)  # containers only
    container: bool = False
    split: bool = False  # arguments are one text to split on spaces (XML/YAML args=)
    # where the package's name was written, when not in the action's file (NodeDecl's
    # ``package_location``)
    package_written: Location | None = None


@dataclass
class ComposableNode:
    package: Text | None
    plugin: Text | None
    name: Text | None = None
    namespace: Text | None = None
    parameters: list[ParamEntry] = field(default_factory=list)
    remaps: list[tuple[Text, Text]] = field(default_factory=list)
    condition: Cond | None = None
    location: Location = NOWHERE
    package_written: Location | None = None  # as NodeAction's


@dataclass
class LoadComposable(Action):
    target: Text
    nodes: list[ComposableNode]


@dataclass
class Delayed(Action):
    """Actions that run later (``TimerAction``, event handlers): each is conditional."""

    actions: list[Action]
    why: str
    statement: str = "timer"  # the condition's statement: "timer" or "event"


@dataclass
class ForEach(Action):
    """launch's ``ForEach`` (``<for_each values=...>``) and ``ForLoop`` (``<for len=...
    name=...>``), Kilted's: ``values`` performed when the action runs is a
    ``;``-separated list of YAML mappings, one iteration each (``ForLoop``: ``length``,
    the text of a number N, is iterations ``{index: 0}`` to ``{index: N-1}``). A front
    end's loop runs its ``children`` once per iteration, its values read by
    ``$(for-var)`` / ``$(index)``; a Python one calls ``make`` with the iteration's
    values as keyword arguments (None: values not known statically) and runs the
    actions it gives, with the diagnostics the call gave."""

    values: Text
    length: bool = False  # ForLoop: ``values`` is the number of iterations
    index: str | None = None  # ForLoop: the name of its index
    children: list[Action] = field(default_factory=list)
    make: Callable[[dict[str, Any] | None], tuple[list[Action], list[Diagnostic]]] | None \
        = None


@dataclass
class Callback(Action):
    """``OpaqueFunction``: interpreted when reached, with the scope of that moment.

    ``run(perform, configuration)`` gets a function that computes a ``Text`` in that
    scope and one that tells how the scope holds a launch configuration
    (``python_values.Context.configuration``), and returns the actions the function
    made and the diagnostics it gave.
    """

    run: Callable[[Callable[[Text], Value], Callable[[str], tuple[str, Any]]],
                  tuple[list[Action], list[Diagnostic]]]
    # what the last run added to the launch description that holds this action (an
    # argument of the function): run after the rest of that description
    later: list[Action] = field(default_factory=list)


@dataclass
class Process(Action):
    """``<executable cmd="...">``: a process, read when performed; a ROS node only when
    its command line is ``ros2 run PKG EXE ...`` or ``ros2 topic pub ...``
    (``runner.do_Process``). ``words``: a Python ``ExecuteProcess``'s command, known at
    build time to start no node we can name; said (``LAUNCH_PROCESS``) only when the
    action is performed, not where it is made (it may never be added or run)."""

    cmd: Text
    words: list[Text] | None = None
    # the attributes the Python object has that the launch file reads (WebotsLauncher's
    # ``_supervisor``, a node it makes for the file to add: ``python_webots``)
    members: dict[str, Any] = field(default_factory=dict)


@dataclass
class LaunchCommand(Action):
    """A process whose command line is ``ros2 launch PKG FILE [NAME:=VALUE ...]`` (or
    ``ros2 launch PATH ...``): the launch file it runs, in a launch process of its own
    (``runner.do_LaunchCommand``). ``words``: the words after ``ros2 launch``."""

    words: list[Text]


@dataclass
class Unsupported(Action):
    """Something we do not interpret; its effect on the graph is unknown."""

    what: str


@dataclass
class UnknownAction(Action):
    """A value not known statically among a launch description's actions (what a call
    the interpreter does not run made: webots_ros2's ``WebotsController(...)``, an
    ``ExecuteProcess`` of its own); said where it was made, and it may start anything."""

    what: str


def shell_commands(words: list[Text]) -> list[list[Text]]:
    """The commands a process's command line runs: what a terminal emulator or a shell
    it opens runs (``gnome-terminal -- bash -c "source setup.bash && ros2 run pkg
    teleop.py; exit"``: ``source setup.bash``, ``ros2 run pkg teleop.py``, ``exit``;
    ``shell.commands``), else the line itself (a wrapper with a word not known
    statically too)."""
    return [command for command, _ in _shell_order(words)]


def _shell_order(words: list[Text]) -> list[tuple[list[Text], tuple[Wait, ...]]]:
    """``shell_commands`` with what each waits for (``shell.run_order``)."""
    plain = [w[0] if len(w) == 1 and isinstance(w[0], str) else None for w in words]
    if not plain or plain[0] is None or None in plain or (
            plain[0].rsplit("/", 1)[-1] not in TERMINALS | SHELLS):
        return [(words, ())]
    ran = run_order([w for w in plain if w is not None])
    return [([(w,) for w in command], waits) for command, waits in ran] or [(words, ())]


# what a command started after another in a shell line waits for, as its condition
_WAITS = {";": "ends", "&&": "ends with success", "||": "fails"}


def process_actions(words: list[Text], location: Location = NOWHERE) -> list[Action]:
    """What a process's command line starts that the launch reads: each command it runs
    (itself, or every command of the line a terminal emulator or a shell it opens runs,
    ``shell_commands``: ``bash -c "ros2 run a x & ros2 run b y"`` is two nodes) that is
    ``ros2 launch ...`` (a ``LaunchCommand``) or a node (``ros2_command_node``), a
    command that waits for others to end, succeed or fail (``;``, ``&&``, ``||``, not
    for set-up commands: ``shell.run_order``) under that event (``Delayed``), and,
    beside them, any other ``ros2`` command as a process that starts no node we can
    name (``ros2 bag play``). None of them: empty (the line is a process of its own)."""
    made: list[tuple[Action, tuple[Wait, ...]]] = []
    others: list[tuple[Action, tuple[Wait, ...]]] = []
    for command, waits in _shell_order(words):
        launched = ros2_launch_words(command)
        action: Action | None = LaunchCommand(launched, location=location) \
            if launched is not None else ros2_command_node(command)
        if action is not None:
            action.location = location
            made.append((action, waits))
        elif command and command[0] == ("ros2",):
            others.append((Process((), command, location=location), waits))
    if not made:
        return []
    out: list[Action] = []
    for action, waits in made + others:
        for operator, text in reversed(waits):
            action = Delayed([action], f"on event: `{text}` {_WAITS[operator]}", "event",
                             location=location)
        out.append(action)
    return out


def ros2_command_node(words: list[Text]) -> NodeAction | None:
    """The node a process's command line starts, when it is ``ros2 run PKG EXE ...``
    (that node, as ``Node(package=PKG, executable=EXE, arguments=[...])``), ``ros2
    topic pub ...`` (a publisher that ``models.commands`` reads from its arguments,
    named as ros2cli's DirectNode names it, ``_ros2cli_<pid>``, or by ``--node-name``),
    ``ros2 topic echo|hz|bw|delay ...`` (a subscriber, named so),
    ``ros2 service call ...`` (a client, named after the service type), ``ros2
    lifecycle set NODE TRANSITION`` (its DirectNode, a client of NODE's lifecycle
    services) or ``ros2 control load_controller ...`` (its DirectNode, which loads a
    controller);
    None for any other process (a simulator, xacro), or when those words are not known.
    A terminal emulator or a shell that runs such a command runs that node
    (``process_actions``).
    """

    def plain(word: Text) -> str | None:
        return word[0] if len(word) == 1 and isinstance(word[0], str) else None

    head = [plain(w) for w in words[:3]]
    installed = installed_executable(head[0]) if head else None
    if installed is not None:  # what ``ros2 run PKG EXE`` would run, named by its path
        return NodeAction((installed[0],), (installed[1],), arguments=list(words[1:]))
    if len(head) < 3 or head[0] is None or head[0].rsplit("/", 1)[-1] != "ros2":
        return None
    if head[1] == "run" and len(words) >= 4:
        return NodeAction(words[2], words[3], arguments=list(words[4:]))
    if head[1:] == ["topic", "pub"]:
        name: Text = ("_ros2cli_", Opaque("the process id of ros2 topic pub", report=False))
        for index, word in enumerate(words[3:-1], start=3):
            if plain(word) in ("-n", "--node-name"):
                name = words[index + 1]
        return NodeAction(("ros2topic",), ("ros2",), name, arguments=list(words[1:]))
    if head[1] == "topic" and head[2] in ("echo", "hz", "bw", "delay"):
        # a subscriber of the topics it names (``models.commands``), its DirectNode named
        # ``_ros2cli_<pid>`` as pub's
        name = ("_ros2cli_", Opaque("the process id of ros2 topic", report=False))
        return NodeAction(("ros2topic",), ("ros2",), name, arguments=list(words[1:]))
    if head[1:] == ["service", "call"]:
        # ros2service's call verb: a node ``_ros2cli_requester_<package>_<Service>`` of
        # the service type's words (``verb/call.py``, ``requester``) calls the service
        return NodeAction(("ros2service",), ("ros2",), _requester_name(words[3:]),
                          arguments=list(words[1:]))
    if head[1:] == ["lifecycle", "set"]:
        # ros2lifecycle's set verb: its DirectNode (``_ros2cli_<pid>``) calls the named
        # node's lifecycle services (``models.commands``)
        name = ("_ros2cli_", Opaque("the process id of ros2 lifecycle", report=False))
        return NodeAction(("ros2lifecycle",), ("ros2",), name, arguments=list(words[1:]))
    if head[1:] == ["control", "load_controller"]:
        # ros2controlcli's verb: its DirectNode (``_ros2cli_<pid>``) asks the controller
        # manager to load the controller (``models.commands``; the graph attaches the
        # controller to the manager as a spawner's, ``plugins.attach``)
        name = ("_ros2cli_", Opaque("the process id of ros2 control", report=False))
        return NodeAction(("ros2controlcli",), ("ros2",), name, arguments=list(words[1:]))
    return None


def _requester_name(words: list[Text]) -> Text:
    """The name ``ros2 service call`` gives its node: ``_ros2cli_requester_`` with the
    package and the service of its type, the second positional word (``pkg/srv/Name``
    or ``pkg/Name``); ``?`` for those parts when the word is not known statically."""
    positional: list[Text] = []
    skip = False
    for word in words:
        text = word[0] if len(word) == 1 and isinstance(word[0], str) else None
        if skip:
            skip = False
        elif text in ("-r", "--rate"):
            skip = True  # the option's value
        elif text is None or not text.startswith("-"):
            positional.append(word)
    kind = positional[1] if len(positional) > 1 else None
    text = kind[0] if kind is not None and len(kind) == 1 and isinstance(kind[0], str) \
        else None
    parts = text.split("/") if text is not None else []
    if len(parts) in (2, 3) and all(parts):
        return (f"_ros2cli_requester_{parts[0]}_{parts[-1]}",)
    return ("_ros2cli_requester_", Opaque("the service type of ros2 service call",
                                          report=False))


def installed_executable(program: str | None) -> tuple[str, str] | None:
    """(package, executable) of a program path where ament installs a package's
    executables, ``<prefix>/lib/<package>/<executable>``, the file ``ros2 run`` runs:
    the distribution's prefix ``/opt/ros/<distro>`` (orca4's bringup.py runs
    ``/opt/ros/humble/lib/tf2_ros/static_transform_publisher``) or a colcon install's
    per-package prefix ``.../<package>/lib/<package>/<executable>``. Any other path
    (``/usr/lib/...``) is no node we can name."""
    if not program or not program.startswith("/"):
        return None
    parts = program.split("/")
    if len(parts) < 5 or parts[-3] != "lib" or not all(parts[-2:]):
        return None
    package, executable = parts[-2], parts[-1]
    distro_prefix = len(parts) == 7 and parts[1:3] == ["opt", "ros"] and parts[3]
    if distro_prefix or parts[-4] == package:
        return package, executable
    return None


def ros2_launch_words(words: list[Text]) -> list[Text] | None:
    """The words after ``ros2 launch`` when the command line starts so, else None (a
    terminal emulator or a shell that runs it: ``process_actions``)."""
    head = [w[0] if len(w) == 1 and isinstance(w[0], str) else None for w in words[:2]]
    if len(head) == 2 and head[0] is not None and head[0].rsplit("/", 1)[-1] == "ros2" \
            and head[1] == "launch":
        return list(words[2:])
    return None


def command_head(words: list[Text]) -> str:
    """The first words of a command line for a message, the program without its folder
    (``gz sim -r``, ``tool_communication.py`` of a path found at run time); ``?`` for a
    part not known statically."""
    head: list[str] = []
    for word in words[:3]:
        if len(word) == 1 and isinstance(word[0], PathJoin) and word[0].parts:
            word = word[0].parts[-1]  # PathJoinSubstitution([..., 'lib', 'tool.py'])
        text = "".join(p if isinstance(p, str) else "?" for p in word)
        if not text or (head and "?" in text):
            break
        head.append(text.rsplit("/", 1)[-1] if not head else text)
    return " ".join(head) if head and head[0] not in ("", "?") else \
        "(a command not known statically)"
