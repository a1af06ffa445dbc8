"""What the static Python interpreter knows of the launch API: data, one row per name.

``API`` maps the last component of a qualified name (``Node``, ``IfCondition``,
``get_package_share_directory``, ...) to a builder that makes our action, substitution
or condition from the evaluated arguments; only names imported from the launch
packages, ``os``, ``ament_index_python``, ``nav2_common``, ``controller_manager``
(its ``launch_utils``), ``launch_pal``, ``robotnik_common`` and ``moveit_configs_utils``
reach it. ``METHODS`` holds
the methods of known values (``str.format``, ``list.append``, ``LaunchDescription.
add_action``, ``LaunchConfiguration.perform``...). Calls not listed are never made.
"""

from __future__ import annotations

import ast
import os
from collections.abc import Callable
from pathlib import PurePosixPath
from typing import Any

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...model.conditions import exit_event
from ...model.launch_tree import PackageUse, installed_check
from ...model.location import Location
from ...model.values import Unknown, Value
from ...share import climbed, install_prefix
from .. import expression
from . import entities as e
from .naming import yaml_value
from .package_actions import PACKAGE_ACTIONS, PackageAction, node_action
from .python import Interpreter
from .python_controller_manager import CONTROLLER_MANAGER
from .python_expressions import unsure_variable
from .python_launch_pal import LAUNCH_PAL
from .python_methods import METHODS as BASE_METHODS
from .python_methods import (
    Args,
    Builder,
    Kwargs,
    Method,
    arg,
    bounded_range,
    builtin,
    chained,
    cond,
    default_dict,
    get_attribute,
    is_instance,
    json_load,
    module_of_file,
    nested_entities,
    open_file,
    safe_load,
    summed,
    text_or_none,
    type_of,
    xacro_parse,
    xacro_process,
    xacro_process_doc,
    xacro_process_file,
    yaml_load,
)
from .python_moveit import METHODS as MOVEIT_METHODS
from .python_moveit import MOVEIT_CONFIGS_UTILS
from .python_nav2 import NAV2_COMMON, NAV2_METHODS
from .python_robotnik import ROBOTNIK_COMMON, ROBOTNIK_METHODS
from .python_values import (
    MAX_DEPTH,
    PLAIN,
    Context,
    Func,
    InstalledPackages,
    LaunchDescription,
    Lazy,
    Ref,
    conjunction,
    launch_object,
    object_text,
    printable,
    to_text,
)
from .python_values import Method as BoundMethod
from .python_webots import WEBOTS


def finish(interp: Interpreter, action: e.Action, kwargs: Kwargs, node: ast.AST) -> e.Action:
    action.condition = cond(interp, kwargs.get("condition"), node)
    action.location = interp.where(node)
    return action


def actions(interp: Interpreter, value: Any, node: ast.AST) -> list[e.Action]:
    return [] if value is None else interp.actions_of(value, node)


# -- substitutions ----------------------------------------------------------------------
def launch_configuration(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    default = arg(a, k, 1, "default")
    return e.Var(to_text(arg(a, k, 0, "variable_name")), configuration_default(default))


def configuration_default(value: Any) -> e.Text | None:
    """``LaunchConfiguration``'s ``default`` as launch keeps it: a str as it is, else each
    item of it (the value itself when it is not iterable), a str or substitution as it
    is and any other value as Python's ``str`` of it (``default=True`` is "True", which a
    ``PythonExpression`` over it reads as Python's ``True``; an action or condition is
    its object text, ``<launch.actions...DeclareLaunchArgument object at 0x...>``:
    limo_ros2's ``LaunchConfiguration("speaker_index", default=declare_speaker_index)``,
    no TypeError)."""
    if value is None or isinstance(value, str):
        return text_or_none(value)
    items = value if isinstance(value, (list, tuple)) else [value]
    return e.text(*(to_text(str(item)) if isinstance(item, PLAIN) else
                    to_text(object_text(item)) if isinstance(item, (e.Action, e.Cond))
                    else to_text(item) for item in items))


def perform_substitutions(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``launch.utilities.perform_substitutions(context, subs)``: the values of ``subs``
    (a list of substitutions and strings) performed in ``context``, joined."""
    context, subs = arg(a, k, 0, "context"), arg(a, k, 1, "subs")
    if isinstance(context, Context) and subs is not None:
        return context.perform(to_text(subs))
    return i.unsupported(n, "perform_substitutions() outside an OpaqueFunction")


def coerce_to_type(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``launch.utilities.type_utils.coerce_to_type(value, data_type)`` of a text known
    statically: ``str`` as it is, ``int`` / ``float`` by Python's, ``bool`` as YAML reads
    it (``'1'`` and ``'0'`` too), no type as YAML reads it (``naming.yaml_value``); what
    launch would refuse fails with its ``ValueError``. synchros2's ``convert_to_bool``
    (spot_ros2's ``controllable``) reads a launch argument so."""
    value, kind = arg(a, k, 0, "value"), arg(a, k, 1, "data_type")
    kind = kind.qualified if isinstance(kind, Ref) else kind
    if not isinstance(value, str) or k.get("can_be_str") or kind not in (
            None, "str", "int", "float", "bool"):
        return Unknown("coerce_to_type() of a value or type not known statically")
    if kind in ("int", "float"):
        try:
            return int(value) if kind == "int" else float(value)
        except ValueError:
            return i.failed(n, f"coerce_to_type({value!r}, {kind}) fails",
                            f"ValueError: {value!r} is no {kind}")
    if kind == "str" or not value:
        return value
    if kind == "bool":
        value = {"1": "true", "0": "false"}.get(value, value)
    out = yaml_value(value)
    if (kind == "bool" and not isinstance(out, bool)) or not isinstance(out, SCALARS):
        return i.failed(n, f"coerce_to_type({value!r}, {kind}) fails",
                        f"ValueError: {value!r} is no {kind or 'YAML value'}")
    return out


def environment_variable(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return e.Env(to_text(arg(a, k, 0, "name")), text_or_none(arg(a, k, 1, "default_value")))


def launch_context(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``LaunchContext()`` made by the launch file itself to perform a substitution while
    it builds its description (turtlebot4's bringup: ``EnvironmentVariable(
    'TURTLEBOT4_DIAGNOSTICS', default_value='1').perform(lc) == '1'``): a new context,
    which has no launch configurations (a ``LaunchConfiguration`` is its default) and the
    configuration's environment. Anything else it performs is unknown."""

    def known(text: e.Text | None) -> str | None:
        if text is None:
            return None
        parts = [fresh(part) for part in text]
        return None if any(p is None for p in parts) else "".join(parts)  # type: ignore[arg-type]

    def fresh(part: str | e.Subst) -> str | None:
        if isinstance(part, str):
            return part
        if isinstance(part, e.Env):
            name = known(part.name)
            if name is not None and name in i.environment:
                return i.environment[name]
            return known(part.default) if name is not None else None
        if isinstance(part, e.Var):
            return known(part.default)
        return None

    def perform(text: e.Text) -> Any:
        value = known(text)
        return Unknown("perform() in a new LaunchContext of a value not known statically"
                       ) if value is None else value

    return Context(perform)


def find_package(share: bool) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        given = (n.args[0] if isinstance(n, ast.Call) and n.args
                 else next((kw.value for kw in getattr(n, "keywords", ())
                            if kw.arg == "package"), None))
        return e.FindPackage(to_text(arg(a, k, 0, "package")), share,
                             written=i.written(n, given))
    return build


def package_directory(share: bool) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        name = arg(a, k, 0, "package_name")
        if isinstance(name, str):
            written = (n.args[0] if isinstance(n, ast.Call) and n.args
                       else next((kw.value for kw in getattr(n, "keywords", ())
                                  if kw.arg == "package_name"), None))
            # in a ``try`` whose handler catches PackageNotFoundError, the file runs
            # without it: a use where it is installed (usv_workspace's domain bridge
            # asks for common_interfaces' folder so, for an optional library path)
            i.uses.append(PackageUse(name, i.written(n, written), guard=installed_check(
                i.guards) or (name if any(i.missing_caught) else None)))
            found = i.workspace.find(name) if share else install_prefix(i.workspace, name)
            if found is not None:
                return found
            return Lazy((e.FindPackage(to_text(name), share, tried=any(i.missing_caught),
                                       said=i.misspelt_package(name, i.written(n, written))),))
        return Lazy((e.FindPackage(to_text(name), share, tried=any(i.missing_caught)),))
    return build



def has_resource(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """ament_index_python's ``has_resource('packages', name)``: whether a package is
    installed (camera_ros adds image_view's viewer only then): ``package_installed``."""
    kind, name = arg(a, k, 0, "resource_type"), arg(a, k, 1, "resource_name")
    if kind != "packages" or not isinstance(name, str):
        return i.unsupported(n, "has_resource() of a resource other than a package named "
                             "statically")
    return package_installed(i, name, n, f"has_resource('packages', '{name}')")


def package_installed(i: Interpreter, name: str, n: ast.AST, asked: str) -> Any:
    """Whether package ``name`` is installed where the launch file runs (``asked``: the
    expression that asks): True when the workspace has it or it is installed here; else
    not known (it may be on the robot), an info, and an ``if`` on it takes both
    branches, each under its test."""
    if i.workspace.find(name) is not None:
        return True
    i.unknown_value(n, f"whether package {name} is installed where the launch file runs "
                       "is not known here")
    return Unknown(asked)


def packages_with_prefixes(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """ament_index_python's ``get_packages_with_prefixes()``: the packages installed
    where the launch file runs; ``'nav2_bringup' in get_packages_with_prefixes()``
    (webots_ros2's robot launch files start navigation only then) asks as
    ``has_resource`` does, anything else of it is not known."""
    return InstalledPackages("get_packages_with_prefixes()")


_DICT = builtin(dict, list, tuple, dict)


def dict_of(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``dict(...)``: of a known mapping or pairs, then the keyword items over it, as
    Python makes it (``dict(use_sim_time=use_sim_time)``, ``dict(common, name='x')``:
    aerostack2-style launch helpers); a keyword's value may be any launch value."""
    made = _DICT(i, list(a), {}, n)
    if not k or not isinstance(made, dict):
        return made
    return {**made, **k}


def package_share_path(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``get_package_share_path(name)``: ``get_package_share_directory`` as a
    ``pathlib.Path`` (a pure path, grown with ``/``); a package not in the workspace is
    its share folder found at launch time, a path join of one part."""
    found = package_directory(True)(i, a, k, n)
    if isinstance(found, str):
        return PurePosixPath(found)
    return e.PathJoin((to_text(found),), e.PATHLIB)


def path_join(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    parts = arg(a, k, 0, "substitutions", default=[])
    if not isinstance(parts, (list, tuple)):
        return Unknown("PathJoinSubstitution of an unknown list")
    return e.PathJoin(tuple(to_text(p) for p in parts),
                      "launch.substitutions.path_join_substitution.PathJoinSubstitution")


def path_substitution(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``PathSubstitution(path)``: a path join of one part, grown by ``/ part``."""
    return e.PathJoin((to_text(arg(a, k, 0, "path")),),
                      "launch.substitutions.path_substitution.PathSubstitution")


def pure_path(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``pathlib.Path(...)`` of known strings: a pure path (no file is looked at); of
    parts known when launch runs (the share folder of a package not installed here), a
    path join of them, grown by ``/`` as the path would be."""
    if k or not all(isinstance(p, (str, PurePosixPath, Lazy, e.Subst)) for p in a):
        return Unknown("a pathlib path of values not known statically")
    if all(isinstance(p, (str, PurePosixPath)) for p in a):
        return PurePosixPath(*a)
    return e.PathJoin(tuple(to_text(p) for p in a), e.PATHLIB)


def os_path_join(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    a = [str(p) if isinstance(p, PurePosixPath) else p for p in a]
    if all(isinstance(p, str) for p in a):
        if not a:
            return Unknown("os.path.join()")
        joined = os.path.join(*a)
        restart = max((j for j, p in enumerate(a) if j and p.startswith("/")), default=0)
        if any(a[:restart]):  # parts os.path.join drops (LAUNCH_PATH_JOIN_ABSOLUTE)
            found = diag.make("LAUNCH_PATH_JOIN_ABSOLUTE", i.where(n), part=a[restart],
                              path=joined)
            if found not in i.diagnostics:
                i.diagnostics.append(found)
        return joined
    return Lazy((e.PathJoin(tuple(to_text(p) for p in a)),))


def os_path_normalized(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``os.path.abspath`` / ``realpath`` of a known path: normalised, a climb out of a
    workspace package's folder starting from its install share folder, as launch finds
    the package there (``share.climbed``)."""
    if a and isinstance(a[0], (str, PurePosixPath)):
        text = str(a[0])
        return climbed(i.workspace, text) if os.path.isabs(text) else os.path.normpath(text)
    return Unknown("abspath of a value not known statically")


def os_path(function: Callable[[str], Any]) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if a and isinstance(a[0], (str, PurePosixPath)):
            return function(str(a[0]))
        if function is os.path.dirname and a and isinstance(a[0], Lazy):
            return Unknown("dirname of a path not known statically")
        return Unknown(f"{function.__name__} of a value not known statically")
    return build


def temporary_name(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``tempfile.mktemp(suffix, prefix, dir)``: a path of a file not made yet, in
    ``dir`` (the system's, ``/tmp``, by default) named ``prefix`` + a part chosen when
    the launch file runs + ``suffix`` (navigation2's simulation launch files have xacro
    write the world there); nothing is made here."""
    suffix = arg(a, k, 0, "suffix", default="")
    prefix = arg(a, k, 1, "prefix", default="tmp")
    folder = arg(a, k, 2, "dir", default=None)
    chosen = e.Opaque("the name tempfile.mktemp chooses when the launch file runs",
                      report=False)
    return Lazy(e.text(to_text(folder) if folder is not None else ("/tmp",), ("/",),
                       to_text(prefix), (chosen,), to_text(suffix)))


def typing_cast(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``typing.cast(T, value)``: ``value`` itself; the type is for type checkers only
    (rm_engineer's launch files cast ``xacro.process_file(...)`` before ``toxml()``)."""
    return arg(a, k, 1, "val")


def file_removal(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``os.remove(path)`` / ``os.unlink(path)``: the file is removed when the launch
    code runs (navigation2's simulation launch files remove their temporary world on
    shutdown); nothing is removed here, and it returns None as it does."""
    return None


def path_exists(test: Callable[[str], bool]) -> Builder:
    """``os.path.exists`` / ``isfile`` / ``isdir`` of a path in a package folder of the
    workspace (``os.path.join(get_package_share_directory(pkg), 'config', name)``: the
    package's folder stands for its share folder, as everywhere here): true when the
    package holds it (raspimouse_ros2_examples' teleop_joy.launch.py loads its
    joystick's parameter file only if it exists). Any other path (outside the
    workspace's packages, or one the package does not hold: it may be installed from
    elsewhere, or made when building) is not known: an ``if`` on it takes both branches,
    each under its test."""
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        path = arg(a, k, 0, "path")
        if isinstance(path, (str, PurePosixPath)):
            text = os.path.normpath(str(path))
            if any(text.startswith(package.root.rstrip(os.sep) + os.sep)
                   for package in i.workspace.packages.values()) and test(text):
                return True
        i.unknown_value(n, "whether the path exists where the launch file runs is not "
                           "known here")
        return Unknown(f"{test.__name__} of a path not known statically")
    return build


def path_tested(test: Callable[[str], bool]) -> Method:
    """``Path.exists()`` / ``is_file()`` / ``is_dir()`` of a pathlib path, as
    ``os.path``'s tests of its text (``path_exists``): roverrobotics_driver's launch
    files ``assert hardware_config.is_file()`` of a file of the package."""
    tested = path_exists(test)

    def call(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if a or k:
            return i.unsupported(n, "a path test with arguments")
        return tested(i, [owner], {}, n)
    return call


def getenv(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    name = arg(a, k, 0, "key")
    if isinstance(name, str) and name in i.environment_unsure:
        i.unknown_value(n, unsure_variable(name))
        return Lazy((e.Opaque(f"environment variable {name}", report=False),))
    if isinstance(name, str) and name in i.environment_removed:
        return arg(a, k, 1, "default")  # os.getenv of a variable not set: the default
    if isinstance(name, str) and name in i.environment:
        return i.environment[name]
    default = arg(a, k, 1, "default")
    if default is not None or len(a) > 1:
        return default
    i.unknown_value(n, f"environment variable {name} is not set in the configuration")
    return Lazy((e.Opaque(f"environment variable {name}", report=False),))


def expand_user(i: Interpreter, path: Any, n: ast.AST) -> Any:
    """What ``os.path.expanduser(path)`` gives: a path not starting with ``~`` is itself;
    ``~`` / ``~/rest`` is HOME (the configuration's environment, as ``os.getenv`` reads
    it here) without its trailing ``/``, then ``rest``; without HOME, or for ``~user``,
    that folder is not known here (said), the rest kept."""
    if isinstance(path, PurePosixPath):
        path = str(path)
    if not isinstance(path, str):
        return Unknown("expanduser of a value not known statically")
    if not path.startswith("~"):
        return path
    cut = path.find("/", 1)
    cut = len(path) if cut < 0 else cut
    user, rest = path[1:cut], path[cut:]
    if user:
        i.unknown_value(n, f"the home folder of user {user} is not known here")
        return Lazy(e.text((e.Opaque(f"the home folder of user {user}", report=False),),
                           to_text(rest)))
    home = getenv(i, ["HOME"], {}, n)
    if isinstance(home, str):
        return (home.rstrip("/") + rest) or "/"
    return Lazy(e.text(to_text(home), to_text(rest)))


def os_path_expanduser(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return expand_user(i, arg(a, k, 0, "path"), n)


def path_expanduser(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``Path.expanduser()``: the path ``os.path.expanduser`` gives its text."""
    expanded = expand_user(i, owner, n)
    if isinstance(expanded, Lazy):  # a path of parts known when launch runs
        return pure_path(i, [expanded], {}, n)
    return PurePosixPath(expanded) if isinstance(expanded, str) else expanded


def find_executable(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return e.FindExec(to_text(arg(a, k, 0, "name")))


def executable_in_package(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return e.FindExec(to_text(arg(a, k, 0, "executable")), to_text(arg(a, k, 1, "package")))


def python_expression(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return e.Eval(to_text(arg(a, k, 0, "expression", default=[])),
                  modules=len(a) > 1 or "python_modules" in k)


def eval_text(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """Python's ``eval`` reached other than by a call written ``eval(text)`` (which
    ``Expressions.eval_source`` reads with the caller's names), or given globals or
    locals: of a text known here, the value the one expression evaluator gives it, as
    ``PythonExpression``, with no names of the file's own; never run as code. Any other
    (a text not known, globals or locals given) is not known."""
    source = a[0] if a else k.get("source")
    if len(a) > 1 or set(k) - {"source"} or not isinstance(source, str):
        return i.unsupported(n, "eval of a value not known statically")
    result = expression.evaluate(source, None, {**expression.BUILTINS, **expression.MATH})
    if isinstance(result, expression.Unknown):
        return i.unsupported(n, f"eval of {source!r}: {result.reason}")
    return result


def logic(op: str, count: int) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        values = list(a) + list(k.values())
        return e.Logic(op, tuple(to_text(v) for v in values[:count]))
    return build


def opaque(what: str) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        return e.Opaque(f"{what} is not evaluated; its value is unknown")
    return build


def text_substitution(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``TextSubstitution(text=...)``: a substitution object whose value is its text, not
    a ``str`` (``isinstance(_, str)`` is false, ``==`` compares identity, ``str()`` is
    its object text, an empty one is still true), as launch's class is. launch takes the
    text by keyword only, and only a ``str`` (else a TypeError)."""
    if a or set(k) != {"text"}:
        return i.failed(n, "TextSubstitution takes one keyword argument, text=",
                        "TypeError")
    text = k["text"]
    if not isinstance(text, (str, Lazy, Unknown)):  # a str when launch runs, maybe
        return i.failed(n, "TextSubstitution(text=...) takes a str, not "
                        f"{type(text).__name__}", "TypeError")
    return e.Literal(to_text(text))


# -- conditions ---------------------------------------------------------------------------
def if_condition(negate: bool) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        expr = arg(a, k, 0, "predicate_expression")
        source = ast.unparse(n.args[0]) if isinstance(n, ast.Call) and n.args else "?"
        if isinstance(expr, (bool, int, float)) or expr is None:
            # launch normalises the predicate to substitutions: a str, a substitution or
            # an iterable of them; anything else raises when the condition is made
            # (amigo_ros2's IfCondition(mode == 'pose_collection'), ``mode`` a
            # LaunchConfiguration: Python's False)
            kind = "IfCondition" if not negate else "UnlessCondition"
            return i.failed(n, f"{kind}({source}) fails: TypeError: its predicate is "
                            f"{expr!r}, a {type(expr).__name__}, where launch takes text "
                            "or substitutions", "TypeError")
        return e.Cond(to_text(expr), negate, source)
    return build


def config_equals(negate: bool) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        name = arg(a, k, 0, "launch_configuration_name")
        expected = arg(a, k, 1, "expected_value")
        text = ast.unparse(n) if isinstance(n, ast.Call) else "?"
        return e.Cond((e.Var(to_text(name), ("",), tested=True),), negate, text,
                      to_text(expected or ""))
    return build


# -- actions ------------------------------------------------------------------------------
def declare_argument(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    name = arg(a, k, 0, "name")
    if not isinstance(name, str):
        i.unsupported(n, "launch argument with a name not known statically")
        return None
    return finish(i, e.DeclareArg(name, text_or_none(arg(a, k, 1, "default_value"))), k, n)


def set_configuration(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return finish(i, e.SetConfig(to_text(arg(a, k, 0, "name")),
                                 to_text(arg(a, k, 1, "value"))), k, n)


def launch_description(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    initial = arg(a, k, 0, "initial_entities", default=[])
    if isinstance(initial, (list, tuple)):
        given = n.args[0] if isinstance(n, ast.Call) and n.args else None
        literal = given.elts if isinstance(given, (ast.List, ast.Tuple)) and not any(
            isinstance(x, ast.Starred) for x in given.elts) else None
        nested_entities(i, list(initial), n, literal)
        return LaunchDescription(list(initial))
    if initial is not None:  # its actions are not known: said, not taken as none
        i.unsupported(n, "launch description is not known statically")
    return LaunchDescription([])


def parameters(i: Interpreter, value: Any, n: ast.AST) -> list[e.ParamEntry]:
    out: list[e.ParamEntry] = []
    if value is None:
        return out
    if not isinstance(value, (list, tuple)):
        i.unsupported(n, "node parameters not known statically")
        return [e.UnknownParams("node parameters not known statically", i.where(n))]
    written = _keyword_items(n, "parameters", len(value))
    for item, display in zip(value, written, strict=True):
        if isinstance(display, ast.Set) and len(display.elts) > 1:
            # ``{"name", value}``: a set, not the dictionary ``{"name": value}``. launch_ros
            # takes what is no mapping for a parameter file's path (its items joined, in
            # an order Python does not fix) and, finding no such file, warns and passes
            # nothing: the node gets none of them (yolo_ros 7d3292d^'s detect_3d_node).
            # A set of one item is that item's path (neuronbot2's slam_toolbox_launch.py
            # writes ``{share + '/config/slam_toolbox_params.yaml'}``), read as one
            i.diagnostics.append(diag.make("LAUNCH_PARAMS_SET", i.where(display),
                                           text=_source(display)))
            continue
        if isinstance(item, dict):
            for key, val in item.items():
                out.append((to_text(key), param_value(val)))
        elif isinstance(item, e.ParamFile):
            out.append(item)
        elif isinstance(item, (str, Lazy, e.Subst, list, PurePosixPath)):
            # a file's path, also a ``pathlib.Path`` (launch_ros takes one: carla's
            # ``Path(get_package_share_directory(pkg), "settings.yaml")``)
            out.append(e.ParamFile(to_text(item), location=i.where(n)))
        elif isinstance(item, Unknown) and item.kind == "unsupported" and (
                item.where is not None):
            # said where it was made (a call not run, a file not read): not again here
            out.append(e.UnknownParams(item.origin, item.where))
        elif isinstance(item, e.Action) and not isinstance(
                item, (e.Unsupported, e.UnknownAction)):
            # a launch action (edu_robot's ``OpaqueFunction(function=..., args=[...])``
            # meant to pick a parameter file): launch_ros takes what is no mapping for a
            # file's path and refuses an action (``ensure_argument_type``: TypeError)
            # when the Node is made, so the launch file does not load
            written_as = _source(display) if display is not None else "an action"
            i.diagnostics.append(diag.make(
                "LAUNCH_BAD_VALUE", i.where(display if display is not None else n),
                detail=f"a node parameter entry is the launch action {written_as}, "
                       "not a parameter file or dictionary: launch_ros refuses it "
                       "(TypeError) and the launch file does not load"))
            out.append(e.UnknownParams("a launch action given as a node parameter entry",
                                       i.where(n)))
        else:
            i.unsupported(n, "a node parameter entry not known statically")
            out.append(e.UnknownParams("a node parameter entry not known statically",
                                       i.where(n)))
    return out


def param_value(value: Any) -> Any:
    """Python values stay (a string too: launch_ros dumps it as YAML and reads it back,
    so ``'1'`` stays the string); substitutions become Text (read as YAML when
    performed)."""
    if isinstance(value, (Lazy, e.Subst, Unknown)):
        return to_text(value)
    if isinstance(value, (list, tuple)):
        if any(isinstance(v, (Lazy, e.Subst)) for v in value) and all(
                isinstance(v, (str, Lazy, e.Subst)) for v in value):
            return to_text(value)  # launch_ros concatenates a list of substitutions
        return [param_value(v) for v in value]
    if isinstance(value, dict):
        return {str(k): param_value(v) for k, v in value.items()}
    if isinstance(value, str):
        return e.ParamValue(value, as_text=True)
    return value


def remappings(i: Interpreter, value: Any, n: ast.AST) -> list[tuple[e.Text, e.Text]]:
    out: list[tuple[e.Text, e.Text]] = []
    if value is None:
        return out
    if not isinstance(value, (list, tuple)):
        i.unsupported(n, "remappings not known statically")
        return out
    for pair in value:
        if isinstance(pair, (list, tuple)) and len(pair) == 2:
            out.append((to_text(pair[0]), to_text(pair[1])))
        elif isinstance(pair, str):
            # ``remappings=['from', 'to']``: launch_ros' normalize_remap_rule takes each
            # item for a (from, to) tuple and raises TypeError for text, so the launch
            # file does not load (f1tenth_system 7c5bc1b^'s ackermann_mux)
            i.diagnostics.append(diag.make(
                "LAUNCH_BAD_VALUE", i.where(n),
                detail=f"remappings holds the text {pair!r}, not a (from, to) tuple: "
                       "launch_ros refuses it (TypeError) and the launch file does not "
                       "load"))
        else:
            i.unsupported(n, "a remapping not known statically")
    return out


def _keyword_items(n: ast.AST, keyword: str, count: int) -> list[ast.AST | None]:
    """The written items of a call's ``keyword=[...]`` display, one per item of its value
    (None each where the value is not written so, or its items are not as many)."""
    if isinstance(n, ast.Call):
        for word in n.keywords:
            if word.arg == keyword and isinstance(word.value, (ast.List, ast.Tuple)) and (
                    len(word.value.elts) == count) and not any(
                    isinstance(elt, ast.Starred) for elt in word.value.elts):
                return list(word.value.elts)
    return [None] * count


def _source(node: ast.AST) -> str:
    text = ast.unparse(node)
    return text if len(text) <= 120 else text[:117] + "..."


def words(value: Any) -> list[e.Text]:
    if value is None:
        return []
    if isinstance(value, (list, tuple)):
        return [to_text(v) for v in value]
    return [to_text(value)]


# launch_ros' Dashing keywords, each with the one that replaced it: deprecated in Foxy
# (a UserWarning), removed in Galactic (launch_ros PR 140 and 122), where ``Node`` and
# ``ComposableNode`` raise TypeError for them and the launch file does not load
DASHING_KEYWORDS = {"node_executable": "executable", "node_name": "name",
                    "node_namespace": "namespace", "node_plugin": "plugin"}
# the distributions whose launch_ros takes them: Dashing and Eloquent as they are, Foxy
# with a deprecation warning
_DASHING_READ = frozenset({"dashing", "eloquent"})
_DASHING_DEPRECATED = frozenset({"foxy"})


def dashing_keywords(i: Interpreter, k: Kwargs, n: ast.AST, action: str) -> None:
    """Said of a ``Node`` / ``ComposableNode`` given a Dashing keyword (urg_node
    369ee4d's ``node_executable='urg_node'``): read as the newer keyword, as Dashing to
    Foxy read it, and said: an error where the configuration's ROS_DISTRO is one whose
    launch_ros refuses it, a warning where it is Foxy's or not known."""
    given = [word for word in k if word in DASHING_KEYWORDS]  # as the call writes them
    if not given:
        return
    distro = i.environment.get("ROS_DISTRO", "").strip().lower()
    if distro in _DASHING_READ:
        return
    words = ", ".join(f"{word}= (now {DASHING_KEYWORDS[word]}=)" for word in given)
    words += ", a keyword" if len(given) == 1 else ", keywords"
    said = distro.capitalize() or "not known (no ROS_DISTRO)"
    if i.guards:
        # made only under a Python test not known statically: a file that chooses
        # the keywords by the release it runs on (lslidar's drivers test the output of
        # ``echo $ROS_DISTRO``) may never run this call where they are refused
        said += (f", and the call is made only where the Python test "
                 f"{conjunction(i.guards)} holds, not known statically, which may keep "
                 "it from running there")
    if distro in _DASHING_DEPRECATED or not distro or i.guards:
        i.diagnostics.append(diag.make(
            "LAUNCH_DASHING_KEYWORD", i.where(n), action=action, words=words,
            distro=said))
    else:
        i.diagnostics.append(diag.make(
            "LAUNCH_DASHING_KEYWORD_REMOVED", i.where(n), action=action, words=words,
            distro=distro.capitalize()))


def node(container: bool) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        dashing_keywords(i, k, n, "ComposableNodeContainer" if container else "Node")
        if "executable" not in k and "node_executable" not in k and not any(
                kw.arg is None for kw in getattr(n, "keywords", ())):
            # launch_ros' Node takes ``executable`` as a required keyword (Dashing's
            # ``node_executable``), and LifecycleNode and ComposableNodeContainer hand
            # theirs on to it: without it the call raises TypeError and the launch file
            # does not load (sjtu_drone e33e86e set ``node.executable`` after the call);
            # a ``**dict`` not known here may hold it
            callee = getattr(getattr(n, "func", None), "attr", None) or getattr(
                getattr(n, "func", None), "id", "Node")
            reason = "TypeError: missing required keyword-only argument: 'executable'"
            return i.failed(n, f"{callee}(...) fails: {reason}", reason)
        action = e.NodeAction(
            text_or_none(k.get("package", k.get("node_package"))),
            text_or_none(k.get("executable", k.get("node_executable"))),
            text_or_none(k.get("name", k.get("node_name"))),
            text_or_none(k.get("namespace", k.get("node_namespace"))),
            parameters(i, k.get("parameters"), n), remappings(i, k.get("remappings"), n),
            words(k.get("arguments")), words(k.get("ros_arguments")), container=container,
            # shell=True: launch joins the command line with spaces and the shell splits
            # it, so an argument that is empty is no word (controller_manager's
            # launch_utils add '--unload-on-kill' or '' so)
            split=k.get("shell") is True)
        if container:
            action.composable = composables(i, k.get("composable_node_descriptions"), n)
        finished = finish(i, action, k, n)
        action.package_written = package_written(i, n, "package", "node_package")
        return then_on_exit(i, finished, k, n)
    return build


def package_written(i: Interpreter, n: ast.AST, *keywords: str) -> Location | None:
    """Where the ``package`` keyword's value of the call ``n`` was written, when another
    file wrote it: a parameter of a helper function another file's call gave (kalman_robot's
    ``launch_node_or_load_component(package="aruco_opencv", ...)`` of kalman_utils, called
    by kalman_aruco's launch file, which is the package that uses aruco_opencv)."""
    written = next((kw.value for kw in getattr(n, "keywords", ()) if kw.arg in keywords),
                   None)
    if written is None:
        return None
    place = i.written(n, written)
    return place if place.file != i.where(n).file else None


def package_action(row: PackageAction) -> Builder:
    """A launch action of an installed package (``package_actions``: ros_gz's
    ``RosGzBridge(bridge_name=..., config_file=...)``): the node its launch file starts,
    named and given parameters by the action's keywords."""
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        action = node_action(row, lambda argument: text_or_none(k.get(argument)))
        return finish(i, action, k, n)
    return build


def then_on_exit(i: Interpreter, process: e.Action, k: Kwargs, n: ast.AST) -> e.Action:
    """A process (``Node``, ``ExecuteProcess``) and what its ``on_exit`` starts: launch
    registers those actions as an ``OnProcessExit`` handler of that process when the
    process runs, so they are what ``RegisterEventHandler(OnProcessExit(target_action=
    process, on_exit=...))`` gives (``event_handler``), under the process's own
    condition (spot_ros2's ``hardware_spawner`` starts the controllers' ``spawner``
    so)."""
    later = k.get("on_exit")
    if later is None:
        return process
    if not isinstance(later, (e.Action, list, tuple, LaunchDescription)):
        not_actions(i, later, n, "on_exit")
        return process
    handler = e.Delayed(actions(i, later, n), exit_event(process.location), "event",
                        location=process.location)
    condition, process.condition = process.condition, None
    return e.Group([process, handler], scoped=False, condition=condition,
                   location=process.location)


def not_actions(i: Interpreter, value: Any, n: ast.AST, label: str) -> None:
    """Said of what an event handler is given that is neither actions nor a list of
    them (launch's ``OnActionEventBase``): a callable is called when the event comes,
    not interpreted here; text is iterated when the handler is made, each character no
    launch entity (a TypeError); a substitution is kept as the one entity to run and
    refused when the event comes (launch's RuntimeError "expected a
    LaunchDescriptionEntity from event_handler"): go2_ros2_sdk's
    ``on_exit=LaunchConfiguration('on_exit', default='shutdown')``."""
    if isinstance(value, str):
        i.diagnostics.append(diag.make(
            "LAUNCH_BAD_VALUE", i.where(n),
            detail=f"{label} is given the text {value!r}, not actions: launch iterates "
                   "it and stops with a TypeError (a character is no launch entity)"))
    elif isinstance(value, (e.Subst, Lazy)):
        i.diagnostics.append(diag.make(
            "LAUNCH_BAD_VALUE", i.where(n),
            detail=f"{label} is given a substitution, not actions: launch keeps it as "
                   "what to run on the event and stops with a RuntimeError when the "
                   "event comes (a substitution is no launch entity)"))
    elif not isinstance(value, Unknown) or value.kind != "unsupported":
        i.unsupported(n, f"{label} with a callable is not interpreted")


def execute_process(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``ExecuteProcess(cmd=[...])``: the node of ``ros2 run PKG EXE ...`` or ``ros2
    topic pub ...`` (``entities.ros2_command_node``), the launch file ``ros2 launch PKG
    FILE ...`` runs (``entities.LaunchCommand``), each of these a shell line runs
    (``entities.process_actions``); any other process, no node."""
    cmd = arg(a, k, 0, "cmd")
    if k.get("shell") is True and isinstance(cmd, (list, tuple)) and cmd and None not in cmd \
            and isinstance(cmd[0], str) and len(cmd[0].split()) > 1:
        # a command line in one word (cmd=['ros2 launch pkg robot.launch.py'],
        # shell=True): launch joins the words with spaces and the shell splits the line,
        # as <executable cmd="..."> is read when performed
        line: list[e.Text] = []
        for index, word in enumerate(cmd):
            line += [(" ",), to_text(word)] if index else [to_text(word)]
        return then_on_exit(i, finish(i, e.Process(e.text(*line)), k, n), k, n)
    made = e.process_actions([to_text(w) for w in cmd], i.where(n)) if isinstance(
        cmd, (list, tuple)) and None not in cmd else []
    if not made:  # said when performed: a ROS node it may start is not in the graph
        words = list(cmd) if isinstance(cmd, (list, tuple)) else [cmd]
        process = e.Process((), [to_text(w) for w in words if w is not None])
        return then_on_exit(i, finish(i, process, k, n), k, n)
    # ros2 run / ros2 launch ...: that node, that launch file's nodes; a shell line's
    # commands, each
    action = made[0] if len(made) == 1 else e.Group(made, scoped=False)
    return then_on_exit(i, finish(i, action, k, n), k, n)


def composable_node(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    # node_plugin/node_name/node_namespace: the Dashing spelling, read as node() reads its own
    dashing_keywords(i, k, n, "ComposableNode")
    return e.ComposableNode(
        text_or_none(k.get("package")), text_or_none(k.get("plugin", k.get("node_plugin"))),
        text_or_none(k.get("name", k.get("node_name"))),
        text_or_none(k.get("namespace", k.get("node_namespace"))),
        parameters(i, k.get("parameters"), n), remappings(i, k.get("remappings"), n),
        cond(i, k.get("condition"), n), i.where(n),
        package_written=package_written(i, n, "package"))


def composables(i: Interpreter, value: Any, n: ast.AST) -> list[e.ComposableNode]:
    if value is None:
        return []
    if not isinstance(value, (list, tuple)):
        i.unsupported(n, "composable node list not known statically")
        return []
    # an item may be a list of descriptions: a name an ``if`` not known set to one of
    # two (``Interpreter.either``), each under its branch's test
    return [c for item in value for c in (item if isinstance(item, (list, tuple)) else (item,))
            if isinstance(c, e.ComposableNode)]


def load_composable(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    target = k.get("target_container")
    if isinstance(target, e.NodeAction):
        target = target.name if target.name is not None else Unknown("container without name")
    return finish(i, e.LoadComposable(to_text(target), composables(
        i, k.get("composable_node_descriptions"), n)), k, n)


def include(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    source = arg(a, k, 0, "launch_description_source")
    given = k.get("launch_arguments", [])
    if isinstance(given, dict):
        given = list(given.items())
    pairs: list[tuple[e.Text, e.Text]] = []
    if isinstance(given, (list, tuple)):
        for pair in given:
            if isinstance(pair, (list, tuple)) and len(pair) == 2:
                pairs.append((to_text(pair[0]), to_text(pair[1])))
    else:
        i.unsupported(n, "launch_arguments not known statically")
    if not isinstance(source, _Source):
        source = _Source(to_text(source))
    return finish(i, e.Include(source.path, pairs), k, n)


class _Source:
    def __init__(self, path: e.Text) -> None:
        self.path = path


def include_in_package(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """launch_pal's ``include_launch_py_description(pkg, [folder, ..., file], **kw)``
    (PAL's robots): the include of the Python launch file at that path of the package's
    share folder (``FindPackageShare`` and ``PathJoinSubstitution``), the other keywords
    the include's (``launch_arguments``, ``condition``)."""
    package, parts = arg(a, k, 0, "pkg_name"), arg(a, k, 1, "paths")
    if not isinstance(parts, (list, tuple)):
        return i.unsupported(n, "include_launch_py_description of a path not known "
                                "statically")
    path = e.PathJoin((to_text(e.FindPackage(to_text(package), True)),
                       *(to_text(part) for part in parts)))
    rest = {key: value for key, value in k.items() if key not in ("pkg_name", "paths")}
    return include(i, [_Source(to_text(path))], rest, n)


def description_source(*keywords: str) -> Builder:
    """A launch description source (``PythonLaunchDescriptionSource(path)``): its
    constructor takes the launch file's path and ``keywords`` only (launch's classes;
    the frontend's also ``method=`` and ``parser=``). Another keyword, or a second
    argument, is launch's TypeError when generate_launch_description runs, and the
    launch file does not load: SAUVC-RPI 1413970's ``launch_arguments=`` written in the
    source's call, meant for the include's."""
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        callee = getattr(getattr(n, "func", None), "attr", None) or getattr(
            getattr(n, "func", None), "id", "the launch description source")
        wrong = [word for word in k if word not in ("launch_file_path", *keywords)]
        if wrong:
            reason = f"TypeError: unexpected keyword argument '{wrong[0]}'"
            return i.failed(n, f"{callee}(...) fails: {reason} (it takes the launch "
                               "file's path; launch_arguments= are the include's)", reason)
        if len(a) > 1 or (a and "launch_file_path" in k):
            reason = "TypeError: one launch file path only"
            return i.failed(n, f"{callee}(...) fails: {reason}", reason)
        return _Source(to_text(arg(a, k, 0, "launch_file_path")))
    return build


def group(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    configs = k.get("launch_configurations") or {}
    pairs = [(to_text(key), to_text(val)) for key, val in configs.items()] if isinstance(
        configs, dict) else []
    scoped, forwarding = k.get("scoped", True), k.get("forwarding", True)
    return finish(i, e.Group(actions(i, arg(a, k, 0, "actions"), n),
                             scoped is not False, forwarding is not False, pairs), k, n)


def reset_configurations(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    given = arg(a, k, 0, "launch_configurations")
    keeps = [(to_text(key), to_text(val)) for key, val in given.items()] if isinstance(
        given, dict) else None
    if given is not None and keeps is None:
        i.unsupported(n, "launch configurations to keep not known statically")
    return finish(i, e.ResetConfigs(keeps), k, n)


def push_namespace(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return finish(i, e.PushNamespace(to_text(arg(a, k, 0, "namespace"))), k, n)


def set_remap(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return finish(i, e.SetRemap(to_text(arg(a, k, 0, "src")), to_text(arg(a, k, 1, "dst"))),
                  k, n)


def set_parameter(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return finish(i, e.SetParam(to_text(arg(a, k, 0, "name")),
                                param_value(arg(a, k, 1, "value"))), k, n)


def set_parameters_from_file(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return finish(i, e.SetParamFile(to_text(arg(a, k, 0, "filename"))), k, n)


def set_env(unset: bool) -> Builder:
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        value = None if unset else to_text(arg(a, k, 1, "value", default=""))
        return finish(i, e.SetEnv(to_text(arg(a, k, 0, "name")), value), k, n)
    return build


def timer(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    period = arg(a, k, 0, "period")
    return finish(i, e.Delayed(actions(i, k.get("actions"), n),
                               f"after TimerAction(period={period})"), k, n)


def event_handler(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    found = [v for key, v in k.items() if key.startswith("on_")]
    label = ast.unparse(n.func) if isinstance(n, ast.Call) else "event"
    contents: list[e.Action] = []
    exit_handler = label.rsplit(".", 1)[-1] == "OnProcessExit"
    for value in found:
        if isinstance(value, Func) and not exit_handler:
            # called with the event when it comes: what it returns is run (webots_ros2's
            # ``on_stdout=lambda event: get_webots_driver_node(event, driver)`` starts
            # the driver once the URDF spawner's output says the robot is spawned). Not
            # a callable run when a process ends: there it starts again what the file
            # started (webots_ros2_husarion's reset handler, ``on_exit=get_ros2_nodes``
            # on the supervisor's exit, after a simulation reset), not more of it
            value = i.call_function(value, [Unknown("the event")], {}, n)
            if value is None or isinstance(value, Unknown):
                i.unsupported(n, f"{label}: what its callable returns is not known "
                                 "statically")
                continue
        if isinstance(value, (e.Action, list, tuple, LaunchDescription)):
            contents.extend(actions(i, value, n))
        elif value is not None:
            not_actions(i, value, n, label)
    target = k.get("target_action")
    if label.rsplit(".", 1)[-1] == "OnProcessExit" and isinstance(target, e.Action) \
            and target.location.file:
        # what it starts runs after that process has ended, never beside it
        # (conditions.after_exit reads it back): named by where the process is made
        return e.Delayed(contents, exit_event(target.location), "event", location=i.where(n))
    return e.Delayed(contents, f"on event {label}", "event", location=i.where(n))


def state_handler(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """launch_ros' ``OnStateTransition``: its ``entities`` run when the managed node
    makes the transition, each under that event, as other handlers' actions do."""
    lifecycle(i, a, k, n)
    entities = k.get("entities")
    if entities is not None and not isinstance(entities, (e.Action, list, tuple,
                                                          LaunchDescription)):
        i.unsupported(n, "OnStateTransition with entities that are not actions is not "
                         "interpreted")
        entities = None
    contents = actions(i, entities, n) if entities is not None else []
    return e.Delayed(contents, "on event OnStateTransition", "event", location=i.where(n))


def lifecycle(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """A lifecycle event or matcher (``ChangeState``, ``matches_node_name``): a managed
    node's transitions change no node, topic nor service of the graph, which takes every
    node with its interface as configured; said once per file (``LAUNCH_PY_LIFECYCLE``)."""
    if not any(d.code == "LAUNCH_PY_LIFECYCLE" for d in i.diagnostics):
        i.diagnostics.append(diag.make("LAUNCH_PY_LIFECYCLE", i.where(n)))
    return None


def register_handler(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    handler = arg(a, k, 0, "event_handler")
    return handler if isinstance(handler, e.Action) else None


def opaque_function(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    function = arg(a, k, 0, "function")
    extra = list(k.get("args") or [])
    extra_kwargs = dict(k.get("kwargs") or {})
    if not hasattr(function, "node"):
        return finish(i, e.Unsupported("OpaqueFunction of an unknown function"), k, n)

    def run(perform: Callable[[e.Text], Value],
            configuration: Callable[[str], tuple[str, Any]] | None = None
            ) -> tuple[list[e.Action], list[Diagnostic]]:
        def py(t: e.Text) -> Any:
            value = perform(t)
            if value.literal is not None:
                return value.literal
            # its unknown parts were said when it was performed (an unset argument,
            # a command never run): the uses of the text say no more
            return Lazy(tuple(p if isinstance(p, str) else e.Opaque(p.origin or "?",
                                                                    report=False)
                              for p in value.parts))

        before = len(i.diagnostics)
        # a launch description given to the function that holds it (spot_ros2's
        # ``ld.add_action(OpaqueFunction(function=launch_setup, args=[ld]))``): what the
        # function adds there runs too, after the rest of that description (launch
        # visits the description's own list, which grows while it is visited); taken
        # back out, so that another run starts from the same list
        given = [v for v in (*extra, *extra_kwargs.values()) if isinstance(v, LaunchDescription)]
        sizes = [len(d.actions) for d in given]
        action.later = []
        added: list[Any] = []
        elsewhere: list[Any] = []
        context = Context(py, configuration=configuration)

        def called() -> list[e.Action]:
            try:
                result = i.call(function, [context, *extra], extra_kwargs, n)
            finally:
                for described, size in zip(given, sizes, strict=True):
                    holds = any(x is action for x in described.actions[:size])
                    (added if holds else elsewhere).extend(described.actions[size:])
                    del described.actions[size:]
            made = actions(i, result, n) if result is not None else []
            # the configurations it set, for what it returns and what comes after it
            made[:0] = [e.SetConfig(to_text(key), to_text(value), location=i.where(n))
                        for key, value in context.assigned.items()]
            action.later = actions(i, added, n)
            if elsewhere:
                i.unsupported(n, "actions an OpaqueFunction adds to a launch description "
                                 "that does not hold it are not read")
            return made

        made: list[e.Action] = i.bounded(i.where(n), called, [])
        return made, i.diagnostics[before:]

    action = e.Callback(run)
    return finish(i, action, k, n)


def for_each(length: bool) -> Builder:
    """``ForEach(input_values, function=f)`` / ``ForLoop(length, function=f)``
    (launch 3.8, Kilted): ``f`` called when the loop runs, once per iteration, with the
    iteration's values as keyword arguments (``ForLoop``: ``i``); values not known
    statically: once, each of its named parameters a value not known."""
    what = "ForLoop" if length else "ForEach"

    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        values = arg(a, k, 0, "length" if length else "input_values")
        function = k.get("function")
        if not isinstance(function, (Func, BoundMethod)):
            return finish(i, e.Unsupported(f"{what} of an unknown function"), k, n)
        where = i.where(n)
        code = function.func if isinstance(function, BoundMethod) else function

        def make(item: dict[str, Any] | None) -> tuple[list[e.Action], list[Diagnostic]]:
            before = len(i.diagnostics)
            if item is None:
                spec = code.node.args
                names = [p.arg for p in (*spec.posonlyargs, *spec.args, *spec.kwonlyargs)]
                if isinstance(function, BoundMethod):
                    names = names[1:]  # its instance (or class)
                given: dict[str, Any] = {name: Unknown(f"a {what} value {name}", "unsupported",
                                                       where=where) for name in names}
            else:
                given = dict(item)
            made: list[e.Action] = i.bounded(
                where, lambda: actions(i, i.call(function, [], given, n), n), [])
            return made, i.diagnostics[before:]

        return finish(i, e.ForEach(to_text(values), length=length,
                                   index="i" if length else None, make=make), k, n)
    return build


def loop_var(index: bool) -> Builder:
    """``ForEachVar(name, default_value=None)`` / ``ForLoopIndex(name)``."""
    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        default = None if index else arg(a, k, 1, "default_value")
        return e.LoopVar(to_text(arg(a, k, 0, "name")),
                         None if default is None else to_text(default))
    return build


def ignored(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return None  # no effect on the Computation Graph (LogInfo, ExecuteProcess, ...)


def param_file(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    given = arg(a, k, 0, "param_file", "source_file")
    substs = arg(a, k, 1, "allow_substs", default=False) is True
    if isinstance(given, e.ParamFile):  # ParameterFile(RewrittenYaml(...))
        given.allow_substs = given.allow_substs or substs
        return given
    return e.ParamFile(to_text(given), location=i.where(n), allow_substs=substs)


def parameter_value(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    value_type = k.get("value_type")
    as_text = isinstance(value_type, Unknown) is False and getattr(
        value_type, "qualified", "") == "str"
    # ``ParameterValue(value, *, value_type=None)``: the value by position or keyword (UR's
    # ur_control.launch.py: ``ParameterValue(value=Command([...]), value_type=str)``)
    given = bool(a) or "value" in k
    value = arg(a, k, 0, "value")
    return e.ParamValue(to_text(value) if given and as_text else param_value(value), as_text)


def copy_of(deep: bool) -> Builder:
    """``copy.copy`` / ``copy.deepcopy`` of a list, tuple or dict (nested ones too when
    deep): new containers, the same items (strings, actions and substitutions are
    never changed in place here)."""
    def dup(value: Any, depth: int) -> Any:
        if depth > 0 and isinstance(value, list):
            return [dup(v, depth - 1) for v in value]
        if depth > 0 and isinstance(value, dict):
            return {k: dup(v, depth - 1) for k, v in value.items()}
        if depth > 0 and isinstance(value, tuple):
            return tuple(dup(v, depth - 1) for v in value)
        return value

    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if len(a) != 1 or k or not isinstance(a[0], (list, tuple, dict, *PLAIN)):
            return Unknown("copy of a value not known statically")
        return dup(a[0], MAX_DEPTH if deep else 1)
    return build


def text_of(as_repr: bool) -> Builder:
    """``str(value)`` / ``repr(value)``: Python's, bounded, of plain values (and of a path
    for ``str``); of an object of launch's API, its object text (``object_text``); the
    ``str`` of a ``pathlib`` path known when launch runs is that path, and that of a text
    known when launch runs that holds a path (``Lazy`` of a share folder
    ``get_package_share_directory`` gives or a path ``os.path.join`` joins) is that
    text, as ``str`` of a ``str`` is the same string (tractobots' nav2.launch.py:15
    ``str(get_package_share_directory('nav2_bringup') + '/launch/...')``, nav2_bringup
    not here)."""
    plain = builtin(repr if as_repr else str,
                    known=lambda v: printable(v, path=not as_repr))

    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if len(a) == 1 and not k:
            if not as_repr and isinstance(a[0], e.PathJoin) and a[0].python == e.PATHLIB:
                return Lazy((a[0],))
            if not as_repr and isinstance(a[0], Lazy) and any(
                    isinstance(part, e.FindPackage | e.PathJoin) for part in a[0].text):
                return a[0]  # a path: a string (not ``int(unknown) + 1``'s text)
            text = object_text(a[0])
            if text is not None:
                return text
        return plain(i, a, k, n)
    return build


def number_of(function: type[int] | type[float], *types: type) -> Builder:
    """``int(value)`` / ``float(value)``: Python's, of plain values; of an object of
    launch's API (a substitution, a condition, an action), a TypeError when
    generate_launch_description runs, since none of their classes converts to a number:
    panther_ros 03ada6da's ``float(EnvironmentVariable(name=..., default_value="1.2"))``,
    which never stands for the variable's text (``.perform(context)`` gives that)."""
    plain = builtin(function, *types)
    name = function.__name__

    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if a and launch_object(a[0]):
            text = object_text(a[0])  # "<launch.substitutions...Class object at ", ...
            head = text.text[0] if text is not None else None
            cls = head.removesuffix(" object at ").rsplit(".", 1)[-1] if isinstance(
                head, str) and head != "<" else "a launch object"
            reason = f"TypeError: {name}() argument must be a string or a number, not {cls}"
            return i.failed(n, f"{name}() of a launch object fails: {reason} (a "
                               "substitution's value is known only when it is performed)",
                            reason)
        return plain(i, a, k, n)
    return build


SCALARS = (str, int, float, bool, list, tuple, dict, type(None))
API: dict[str, Builder] = {
    "LaunchDescription": launch_description,
    "LaunchConfiguration": launch_configuration,
    "perform_substitutions": perform_substitutions,
    "coerce_to_type": coerce_to_type,
    "EnvironmentVariable": environment_variable,
    "LaunchContext": launch_context,
    "FindPackageShare": find_package(True), "FindPackagePrefix": find_package(False),
    "FindPackage": find_package(True),
    "get_package_share_directory": package_directory(True),
    "get_package_share_path": package_share_path,
    "has_resource": has_resource,
    "get_packages_with_prefixes": packages_with_prefixes,
    "get_package_prefix": package_directory(False),
    "cast": typing_cast,
    "mktemp": temporary_name, "remove": file_removal, "unlink": file_removal,
    "join": os_path_join, "dirname": os_path(os.path.dirname),
    "basename": os_path(os.path.basename), "abspath": os_path_normalized,
    "realpath": os_path_normalized, "split": os_path(os.path.split),
    "splitext": os_path(os.path.splitext), "isabs": os_path(os.path.isabs),
    "normpath": os_path(os.path.normpath),
    "exists": path_exists(os.path.exists), "isfile": path_exists(os.path.isfile),
    "isdir": path_exists(os.path.isdir),
    "getenv": getenv, "expanduser": os_path_expanduser,
    "PathJoinSubstitution": path_join, "PathSubstitution": path_substitution,
    "Path": pure_path, "PurePath": pure_path, "PurePosixPath": pure_path,
    "TextSubstitution": text_substitution,
    "PythonExpression": python_expression,
    "ThisLaunchFileDir": lambda i, a, k, n: e.ThisFile(True),
    "ThisLaunchFile": lambda i, a, k, n: e.ThisFile(False),
    "AnonName": lambda i, a, k, n: e.Anon(to_text(arg(a, k, 0, "name"))),
    "NotSubstitution": logic("not", 1), "AndSubstitution": logic("and", 2),
    "OrSubstitution": logic("or", 2), "EqualsSubstitution": logic("equals", 2),
    "NotEqualsSubstitution": logic("notequals", 2),
    "IfElseSubstitution": logic("if", 3),
    "FileContent": lambda i, a, k, n: e.FileContent(to_text(arg(a, k, 0, "path"))),
    "Command": lambda i, a, k, n: e.Command(to_text(arg(a, k, 0, "command"))),
    "FindExecutable": find_executable,
    "ExecutableInPackage": executable_in_package,
    "AnySubstitution": logic("any", 64), "AllSubstitution": logic("all", 64),
    "LaunchLogDir": opaque("LaunchLogDir (known at run time)"),
    "IfCondition": if_condition(False), "UnlessCondition": if_condition(True),
    "LaunchConfigurationEquals": config_equals(False),
    "LaunchConfigurationNotEquals": config_equals(True),
    "DeclareLaunchArgument": declare_argument,
    "SetLaunchConfiguration": set_configuration,
    "Node": node(False), "LifecycleNode": node(False),
    "ComposableNodeContainer": node(True), "ComposableNode": composable_node,
    "LoadComposableNodes": load_composable,
    "IncludeLaunchDescription": include, "include_launch_py_description": include_in_package,
    "PythonLaunchDescriptionSource": description_source(),
    "XMLLaunchDescriptionSource": description_source(),
    "YAMLLaunchDescriptionSource": description_source(),
    "AnyLaunchDescriptionSource": description_source(),
    "FrontendLaunchDescriptionSource": description_source("method", "parser"),
    "GroupAction": group, "PushRosNamespace": push_namespace,
    "ResetLaunchConfigurations": reset_configurations,
    "PushROSNamespace": push_namespace, "SetRemap": set_remap,
    "SetParameter": set_parameter, "SetParametersFromFile": set_parameters_from_file,
    "SetEnvironmentVariable": set_env(False),
    "UnsetEnvironmentVariable": set_env(True), "TimerAction": timer, "ROSTimer": timer,
    "RosTimer": timer,
    "RegisterEventHandler": register_handler, "OnProcessExit": event_handler,
    "OnProcessStart": event_handler, "OnExecutionComplete": event_handler,
    "OnShutdown": event_handler, "OnProcessIO": event_handler,
    "OnStateTransition": state_handler, "ChangeState": lifecycle,
    "matches_node_name": lifecycle, "matches_action": lifecycle,
    "OpaqueFunction": opaque_function,
    "ForEach": for_each(False), "ForLoop": for_each(True),
    "ForEachVar": loop_var(False), "ForLoopIndex": loop_var(True),
    "LogInfo": ignored, "ExecuteProcess": execute_process, "Shutdown": ignored,
    "EmitEvent": ignored, "AppendEnvironmentVariable": ignored, "SetROSLogDir": ignored,
    "SetUseSimTime": ignored,
    "ParameterFile": param_file, "ParameterValue": parameter_value, **NAV2_COMMON,
    **{row.cls: package_action(row) for row in PACKAGE_ACTIONS},
    **CONTROLLER_MANAGER, **LAUNCH_PAL, **ROBOTNIK_COMMON, **MOVEIT_CONFIGS_UTILS, **WEBOTS,
    "len": builtin(len, str, list, tuple, dict),
    "str": text_of(False), "repr": text_of(True),
    "int": number_of(int, str, int, float, bool), "float": number_of(float, str, int, float),
    "bool": builtin(bool, *SCALARS), "list": builtin(list, str, list, tuple, dict),
    "tuple": builtin(tuple, str, list, tuple), "dict": dict_of,
    "sorted": builtin(sorted, list, tuple), "min": builtin(min, int, float, list, tuple),
    "max": builtin(max, int, float, list, tuple), "abs": builtin(abs, int, float),
    "enumerate": builtin(lambda x: list(enumerate(x)), list, tuple, str, dict),
    "zip": builtin(lambda *x: list(zip(*x, strict=False)), list, tuple), "range": bounded_range,
    "print": ignored, "isinstance": is_instance, "type": type_of,
    "all": builtin(all, list, tuple), "any": builtin(any, list, tuple), "sum": summed,
    "open": open_file, "safe_load": safe_load, "yaml.load": yaml_load,
    "json.load": json_load, "json.loads": json_load,
    "yaml.full_load": yaml_load, "itertools.chain": chained,
    "collections.defaultdict": default_dict,
    "copy": copy_of(False), "deepcopy": copy_of(True),
    "process_file": xacro_process_file, "process": xacro_process,
    "xacro.parse": xacro_parse, "xacro.process_doc": xacro_process_doc,
    "load_python_launch_file_as_module": module_of_file, "getattr": get_attribute,
    "eval": eval_text,
}
# methods of the values the interpreter knows, by name (``python_methods``), nav2's,
# robotnik_common's and moveit_configs_utils'
METHODS: dict[str, Method] = {**BASE_METHODS, **NAV2_METHODS, **ROBOTNIK_METHODS,
                              **MOVEIT_METHODS, "exists": path_tested(os.path.exists),
                              "is_file": path_tested(os.path.isfile),
                              "is_dir": path_tested(os.path.isdir),
                              "expanduser": path_expanduser}
BUILTINS = frozenset(("len", "str", "repr", "int", "float", "bool", "list", "tuple", "dict",
                      "sorted", "min", "max", "abs", "enumerate", "zip", "range", "print",
                      "isinstance", "all", "any", "sum", "open", "getattr", "type", "eval",
                      "exit", "quit"))


