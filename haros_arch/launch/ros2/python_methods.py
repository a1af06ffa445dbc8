"""Builtins and methods of known values for the static Python interpreter.

``builtin`` wraps a safe Python builtin for known arguments; ``open`` gives a read-only
handle on a workspace file and ``yaml.safe_load`` reads it with the safe loader;
``METHODS`` maps a method name (``str.format``, ``list.append``,
``LaunchDescription.add_action`` / ``add_entity``, ``LaunchConfiguration.perform``,
``IfCondition.evaluate``...) to its handler. Calls not listed are never made.
"""

from __future__ import annotations

import ast
import json
import os
from collections.abc import Callable
from pathlib import PurePosixPath
from typing import TYPE_CHECKING, Any

import yaml

from ... import diagnostics as diag
from ... import safe_yaml
from ...evaluate import operations as ops
from ...evaluate import partial
from ...model.launch_tree import PackageUse, installed_check
from ...model.values import Unknown
from . import entities as e
from .python_expressions import _Environ
from .python_values import (
    LIMITS,
    Budget,
    Context,
    DefaultDict,
    Instance,
    LaunchDescription,
    Lazy,
    Module,
    ReadOnlyFile,
    Ref,
    XacroDocument,
    _hashable,
    _source,
    concat,
    derived_unknown,
    launch_object,
    open_keys,
    said_unknown,
    to_text,
)

if TYPE_CHECKING:
    from .python import Interpreter

Args = list[Any]
Kwargs = dict[str, Any]
Builder = Callable[["Interpreter", Args, Kwargs, ast.AST], Any]


def arg(args: Args, kwargs: Kwargs, index: int, *names: str, default: Any = None) -> Any:
    if index < len(args):
        return args[index]
    for name in names:
        if name in kwargs:
            return kwargs[name]
    return default


def text_or_none(value: Any) -> e.Text | None:
    return None if value is None else to_text(value)


def cond(interp: Interpreter, value: Any, node: ast.AST) -> e.Cond | None:
    if value is None:
        return None
    if isinstance(value, e.Cond):
        return value
    interp.unsupported(node, "condition is not known statically")
    return e.Cond((e.Opaque("condition"),), source="?")


# -- builtins --------------------------------------------------------------------------------
def builtin(function: Callable[..., Any], *types: type,
            known: Callable[[Any], bool] | None = None) -> Builder:
    """A builtin on known arguments of ``types`` (or those ``known`` accepts), through the
    one evaluator's table (its bounded ``str``, ``int``, ... where it has one) and its size
    check."""
    name = getattr(function, "__name__", "builtin")
    function = ops.BUILTINS.get(name, ops.BOUNDED.get(name, function))
    accepts = known or (lambda v: isinstance(v, types))

    def build(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if k or not all(accepts(v) for v in a) or any(
                isinstance(x, Unknown) for v in a if isinstance(v, (list, tuple, dict))
                for x in v):  # an unknown item (a dict's: under an unknown key)
            made = derived_unknown(f"{name}()", a, i.where(n)) if not k else said_unknown(
                f"{name}()", a)
            return made or Unknown(f"{name}() of values not known statically")
        try:
            return ops.call_builtin(function, a, {}, LIMITS)
        except ops.Refused as err:
            if err.kind == "limit":
                raise Budget(err.reason) from None
            return i.failed(n, f"{name}() fails: {err.reason}", err.reason)
    return build


def open_file(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``open(path)`` / ``open(path, 'r')``: read-only; any other mode is refused. The
    path is a text or a ``pathlib`` path known here (``open`` takes any path-like:
    roverrobotics_driver's accessories.launch.py opens ``Path(share, 'config/...')``)."""
    mode = arg(a, k, 1, "mode", default="r")
    if a and isinstance(a[0], PurePosixPath):
        a = [str(a[0]), *a[1:]]
    if isinstance(mode, str) and mode.strip("bt+") in ("w", "a", "x") and a and isinstance(
            a[0], str) and a[0].startswith("/"):
        i.made_paths.append(a[0])  # a file the launch makes as it runs (not run here)
    if mode not in ("r", "rt") or not a or not isinstance(a[0], str):
        made = said_unknown("open()", a[:1]) if mode in ("r", "rt") else None
        if made is not None:  # its path was said where it was made (or its parts were)
            return made
        if mode in ("r", "rt") and a and isinstance(a[0], Lazy):
            # a path launch finds when it runs (a package's share folder not here:
            # navigation2's tb3_simulation_launch.py reads its robot's URDF so): data
            # not known, as a file outside the workspace is, not a construct not read
            return i.unsupported(n, f"{_source(n)}: a file whose path is known only when "
                                    "launch runs; not read", "LAUNCH_PY_FILE_UNKNOWN")
        return i.unsupported(n, f"{_source(n)}: open() other than for reading a known "
                                "path is not run")
    return ReadOnlyFile(a[0])


def _loaded_text(i: Interpreter, a: Args, n: ast.AST, kind: str) -> str | Unknown:
    """The text a loader's first argument gives: a file we may read (``open(...)``) or
    a text known here; else why it is not known (a file ``read`` could not read was
    said there, not again)."""
    source = a[0] if a else None
    text = i.read(source.path, n) if isinstance(source, ReadOnlyFile) else (
        source if isinstance(source, str) else None)
    if text is None and isinstance(source, ReadOnlyFile):
        return Unknown(f"{source.path} not read", "unsupported", where=i.where(n))
    if text is None:
        # the text of a file read already (``open(path).read()``) that could not be:
        # said there, not again
        return said_unknown(kind, [source]) or Unknown(f"{kind} not known statically")
    return text


def safe_load(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``yaml.safe_load(f)`` on a file we may read, with the safe loader (bounded)."""
    text = _loaded_text(i, a, n, "YAML")
    if isinstance(text, Unknown):
        return text
    try:
        return safe_yaml.load(text)
    except yaml.YAMLError as err:
        return i.unsupported(n, f"YAML cannot be read: {err}")


def json_load(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``json.load(f)`` on a file we may read, ``json.loads(text)`` on a text known here:
    Python's own JSON reader, which builds data and runs nothing (DOBOT's bringup launch
    file reads its robot's name and number from ``config/param.json``). Keyword
    arguments (``object_hook``, ``parse_float``: callables) are not run."""
    if k:
        return i.unsupported(n, f"{_source(n)}: json.load with keyword arguments is not "
                                "interpreted")
    text = _loaded_text(i, a, n, "JSON")
    if isinstance(text, Unknown):
        return text
    try:
        return json.loads(text)
    except (ValueError, RecursionError) as err:
        # json.JSONDecodeError is a ValueError: the launch file stops there unless a
        # handler catches it
        return i.failed(n, f"{_source(n)}: JSON cannot be read: {err}",
                        f"ValueError: {err}")


# the loaders of ``yaml.load(stream, Loader=...)`` that read plain YAML as the safe one
# does: the standard tags resolved and built alike; what they add are the Python tags
# (``!!python/...``: objects, calls), which the safe reader refuses, so a document with
# one is not known here and nothing is run. ``Loader`` / ``UnsafeLoader`` too
# (autonomous_f1tenth's ``yaml.load(open(config_path), Loader=yaml.Loader)``), not
# ``BaseLoader``, which keeps every scalar a string
_PLAIN_LOADERS = frozenset(f"yaml.{name}" for name in (
    "SafeLoader", "CSafeLoader", "FullLoader", "CFullLoader", "Loader", "CLoader",
    "UnsafeLoader", "CUnsafeLoader"))


def yaml_load(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``yaml.load(stream, Loader=yaml.FullLoader)`` (or ``SafeLoader``, ``Loader``,
    ``UnsafeLoader``, their C forms) and ``yaml.full_load(stream)``: as
    ``yaml.safe_load`` (Autoware's traffic light launch files read their
    ``camera_namespaces`` argument so), a document with a Python tag not known; another
    loader (``BaseLoader``, one of the launch file's own) is not run."""
    loader = k.get("Loader", a[1] if len(a) > 1 else None)
    full = isinstance(n, ast.Call) and isinstance(n.func, ast.Attribute) and (
        n.func.attr == "full_load")
    if not full and not (isinstance(loader, Ref) and loader.qualified in _PLAIN_LOADERS):
        return i.unsupported(n, f"{_source(n)}: a YAML loader other than the safe or full "
                                "one is not run")
    return safe_load(i, a[:1], {}, n)


def default_dict(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``collections.defaultdict(factory[, mapping])``: the dict that fills a key it
    lacks with ``factory()`` when it is looked up (autoware_component_state_monitor's
    ``defaultdict(lambda: defaultdict(list))``); with no factory, a plain dict's lookup."""
    if k or len(a) > 2 or (len(a) == 2 and not isinstance(a[1], dict)):
        return i.unsupported(n, f"{_source(n)}: defaultdict with these arguments is not "
                                "interpreted")
    made = DefaultDict(a[0] if a else None)
    if len(a) == 2:
        made.update(a[1])
    return made


def chained(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``itertools.chain(*iterables)`` of lists, tuples or texts known here: their items
    in turn, as a list (what the launch file makes of it, ``list(chain(...))``, is the
    same); of anything else, not known."""
    if k or not all(isinstance(v, (list, tuple, str)) for v in a):
        return Unknown("itertools.chain() of values not known statically")
    items: list[Any] = []
    for value in a:
        items.extend(value)
    return items


def summed(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``sum(iterable, start=0)``: ``start + item`` for each item in turn, with the
    interpreter's own ``+`` (numbers added, lists joined: kalman_robot's
    ``sum((launch_node_or_load_component(...) for rgbd_id in rgbd_ids), [])``, a list of
    actions; an unknown item keeps its place as ``+`` keeps it). A text start is
    Python's TypeError; an iterable not known here, not known."""
    items = arg(a, k, 0, "iterable")
    start = arg(a, k, 1, "start", default=0)
    if len(a) > 2 or set(k) - {"start"}:
        return i.failed(n, f"{_source(n)} fails: TypeError: sum() takes at most 2 "
                        "arguments", "TypeError")
    if isinstance(start, str):
        return i.failed(n, f"{_source(n)} fails: TypeError: sum() can't sum strings "
                        "[use ''.join(seq) instead]", "TypeError")
    if not isinstance(items, (list, tuple)):
        made = derived_unknown("sum()", [items], i.where(n))
        return made or Unknown("sum() of values not known statically")
    total = start
    for item in items:
        total = i.binop(ast.Add(), total, item, n)
    return total


def m_read_text(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``Path(p).read_text()`` of a path known here: the file's text, as
    ``open(p).read()``."""
    if isinstance(owner, PurePosixPath):
        return m_read(i, ReadOnlyFile(str(owner)), a, k, n)
    return i.unsupported(n, ".read_text() on a value not known statically")


def module_of_file(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """launch's ``load_python_launch_file_as_module(path)``: the Python file at that
    path (of a package's share folder: its source), read as an imported module
    (xarm_ros2's launch files load their helper libraries so, then take a function
    with ``getattr``)."""
    from ...share import share_source

    path = arg(a, k, 0, "python_launch_file_path")
    if isinstance(path, PurePosixPath):
        path = str(path)
    if not isinstance(path, str):
        return i.unsupported(n, "load_python_launch_file_as_module of a path not known "
                                "statically")
    source = os.path.realpath(share_source(i.workspace, path))
    if not os.path.isfile(source) or not i.workspace.readable(source, i.environment):
        return i.unsupported(n, f"{path} is not a file this tool may read; not loaded")
    name = os.path.splitext(os.path.basename(source))[0]
    return i.module_file(name, source, n) or Unknown(f"module {name} not read",
                                                      "unsupported", where=i.where(n))


def get_attribute(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``getattr(module, name[, default])`` of a module read here: its name's value,
    as ``module.name``; of anything else, not known."""
    if len(a) in (2, 3) and isinstance(a[0], Module) and isinstance(a[1], str):
        if a[1] in a[0].names:
            return a[0].names[a[1]]
        if len(a) == 3:
            return a[2]
        return i.failed(n, f"{_source(n)} fails: {a[0].name} has no {a[1]}",
                        "AttributeError")
    if a and isinstance(a[0], Unknown) and a[0].kind == "unsupported":
        return Unknown(f"{_source(n)} of a value not known", "unsupported",
                       where=a[0].where)  # said where the value was made
    return i.unsupported(n, f"{_source(n)}: getattr() of a value not known statically")


# the builtin types ``isinstance`` decides for, by the name the interpreted code calls them
_PLAIN_TYPES: dict[str, type] = {"str": str, "int": int, "float": float, "bool": bool,
                                 "list": list, "tuple": tuple, "dict": dict}


# launch's substitution classes a value made here is an instance of in Python, by the
# class its call built, with their bases (``Substitution``); one that more than one class
# builds here (a path join is also a ``pathlib.Path``, a package find three classes) is
# left out
_LAUNCH_CLASSES: dict[type, frozenset[str]] = {
    e.Var: frozenset(("LaunchConfiguration", "Substitution")),
    e.Env: frozenset(("EnvironmentVariable", "Substitution")),
    e.Command: frozenset(("Command", "Substitution")),
    e.Eval: frozenset(("PythonExpression", "Substitution")),
    e.Literal: frozenset(("TextSubstitution", "Substitution")),
}


def _instance_of(value: Any, cls: Any) -> bool | None:
    """Whether ``isinstance(value, cls)`` is true, or None when not known here."""
    if not isinstance(cls, Ref):
        return None
    if type(value) in (*_PLAIN_TYPES.values(), type(None)):
        return isinstance(value, _PLAIN_TYPES[cls.qualified]) \
            if cls.qualified in _PLAIN_TYPES else None
    if launch_object(value) or isinstance(value, (e.ParamFile, e.ParamValue)):
        # an object of launch's API is none of Python's builtin types
        if cls.qualified in _PLAIN_TYPES:
            return False
        root, _, name = cls.qualified.rpartition(".")
        if root.split(".")[0] in ("launch", "launch_ros") \
                and name in _LAUNCH_CLASSES.get(type(value), ()):
            return True
    elif isinstance(value, Lazy) and cls.qualified in _PLAIN_TYPES:
        # a text made when launch runs: a ``str`` then (or a ``TextSubstitution`` of one),
        # never a number, a container or None
        return None if cls.qualified == "str" else False
    return None


def is_instance(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``isinstance(value, T)`` (``T`` a class or a tuple of them) where it is known: of a
    plain Python value and a builtin type, so a helper that recurses on lists
    (``flatten``) stops at a string; of an object of launch's API (a substitution, a
    condition, an action) and a builtin type: false, as none of them is one; of a
    substitution and its own launch class (or ``Substitution``): true; of a text made
    when launch runs (a package path found then, an f-string of an unknown value) and a
    builtin type other than ``str``: false. Any other value or class is not read here:
    not known."""
    if k or len(a) != 2:
        return Unknown("isinstance")
    classes = a[1] if isinstance(a[1], tuple) else (a[1],)
    answers = [_instance_of(a[0], c) for c in classes]
    if True in answers:
        return True
    if not answers or None in answers:
        return Unknown("isinstance")
    return False


def type_of(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``type(value)`` where it is known: the builtin type of a plain value (vrx_gz's
    ``if type(models) != list: models = [models]``), the class of an instance of a class
    the launch code defines; not known for any other value."""
    if k or len(a) != 1:
        return Unknown("type")
    if isinstance(a[0], Instance):
        return a[0].cls
    name = next((name for name, cls in _PLAIN_TYPES.items() if type(a[0]) is cls), None)
    return Ref(name) if name is not None else Unknown("type of a value not known statically")


def bounded_range(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    if not all(isinstance(v, int) for v in a) or not a:
        return derived_unknown("range()", a, i.where(n)) or Unknown(
            "range of unknown bounds")
    values = range(*a)
    if len(values) > 10_000:
        return i.unsupported(n, "range() above 10000 items is not expanded")
    return list(values)


# -- methods --------------------------------------------------------------------------------
Method = Callable[["Interpreter", Any, Args, Kwargs, ast.AST], Any]


def m_find(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``FindPackageShare('pkg').find('pkg')``: the share folder, now."""
    if isinstance(owner, e.FindPackage) and a and isinstance(a[0], str):
        i.uses.append(PackageUse(a[0], i.where(n), guard=installed_check(i.guards)))
        found = i.workspace.find(a[0])
        if found is not None and owner.share:
            return found
        return Lazy((e.FindPackage((a[0],), owner.share,
                                   said=found is None and i.misspelt_package(a[0], i.where(n))),))
    return i.unsupported(n, ".find() on a value not known statically")


def m_read(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    if isinstance(owner, ReadOnlyFile):
        text = i.read(owner.path, n)
        if text is None:  # said by read(), here: its uses say no more
            return Unknown(f"{owner.path} not read", "unsupported", where=i.where(n))
        return text
    # a file opened at a path said not known where it was made: as unknown, said no more
    return said_unknown(".read()", [owner]) or i.unsupported(
        n, ".read() on a value not known statically")


def m_evaluate(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``IfCondition(...).evaluate(context)`` inside an OpaqueFunction (the context
    given by keyword too: ``evaluate(context=context)``)."""
    context = arg(a, k, 0, "context")
    if not (isinstance(owner, e.Cond) and isinstance(context, Context)):
        return i.unsupported(n, ".evaluate() outside an OpaqueFunction")
    value = context.perform(owner.expression)
    if not isinstance(value, str):
        return Unknown(f"condition {owner.source}")
    if owner.equals is not None:
        expected = context.perform(owner.equals)
        if not isinstance(expected, str):
            return Unknown(f"condition {owner.source}")
        return (value == expected) != owner.negate
    lowered = value.strip().lower()
    if lowered not in ("true", "1", "false", "0"):
        return i.unsupported(n, f"condition value {value!r} is not a boolean")
    return (lowered in ("true", "1")) != owner.negate


def nested_entities(i: Interpreter, items: list[Any], n: ast.AST,
                    written: list[ast.expr] | None = None) -> None:
    """Said of each list or tuple among a ``LaunchDescription``'s entities (``written``:
    their expressions, when the call lists them). launch keeps the entities as given
    (``list(initial_entities)``, ``add_entity`` appends) and walks each as an entity
    when it collects the launch arguments and when it runs the description, so a list
    or tuple there stops the launch with an AttributeError; a comma after an action
    (``declare = DeclareLaunchArgument(...),``) makes such a tuple (cyberdog_nav2's
    node.laser_mapping.launch.py). Its items are kept as the description's actions, so
    the rest of the file is still read."""
    for at, item in enumerate(items):
        if isinstance(item, (list, tuple)):
            kind = type(item).__name__
            where = written[at] if written is not None and at < len(written) else n
            i.diagnostics.append(diag.make(
                "LAUNCH_BAD_VALUE", i.where(where),
                detail=f"the launch description is given a {kind} as an entity (item "
                       f"{at + 1}), not a launch action: launch stops when it walks the "
                       f"description (AttributeError: '{kind}' object has no attribute "
                       "'describe_sub_entities')"))


def m_add_action(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``LaunchDescription.add_action`` and ``add_entity``, which launch makes one: the
    entity may be a whole ``LaunchDescription``, whose actions run in its place."""
    if isinstance(owner, LaunchDescription) and a:
        nested_entities(i, a[:1], n, n.args[:1] if isinstance(n, ast.Call) else None)
        owner.actions.append(a[0])
        return None
    return i.unsupported(n, "add_action on a value not known statically")


def m_list(name: str) -> Method:
    def call(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if isinstance(owner, LaunchDescription) and name in ("append", "extend"):
            owner = owner.actions
        if isinstance(owner, _Environ) and name == "pop" and 1 <= len(a) <= 2 and not k:
            # ``os.environ.pop(key[, default])``: the value (or the default), and the
            # variable is not set from here on
            value = owner.get(i, list(a), n)
            i.unset_environment(n, a[0])
            return value
        if isinstance(owner, dict) and name == "pop" and 1 <= len(a) <= 2 and not k \
                and isinstance(a[0], _PLAIN):
            if a[0] in owner:
                return owner.pop(a[0])
            if len(a) == 2:
                return a[1]
            return i.failed(n, f"dict.pop({a[0]!r}) fails: no such key", "KeyError")
        if isinstance(owner, list):
            if name == "append" and len(a) == 1:
                owner.append(a[0])
            elif name == "extend" and len(a) == 1 and isinstance(a[0], (list, tuple)):
                owner.extend(a[0])
            elif name == "extend" and len(a) == 1 and isinstance(a[0], Unknown):
                # the items of a value not known statically (a helper not read that
                # returns DeclareLaunchArguments, Interbotix's): one unknown item, said
                # where it was made, never none
                owner.append(i.placed(a[0], n))
            elif name == "insert" and len(a) == 2 and isinstance(a[0], int):
                owner.insert(a[0], a[1])
            elif name == "remove" and len(a) == 1 and isinstance(a[0], _PLAIN):
                if a[0] in owner:
                    owner.remove(a[0])
                elif any(isinstance(x, Unknown) for x in owner):
                    return i.unsupported(n, f"list.remove({a[0]!r}) of a list holding a "
                                            "value not known statically")
                else:  # Python raises ValueError here: launch stops
                    return i.failed(n, f"list.remove({a[0]!r}) fails: not in the list",
                                    "ValueError")
            elif name == "pop" and len(a) <= 1 and all(isinstance(x, int) for x in a) \
                    and not k:
                index = a[0] if a else -1
                if -len(owner) <= index < len(owner):
                    return owner.pop(index)
                return i.failed(n, "list.pop() fails: index out of range", "IndexError")
            else:
                return i.unsupported(n, f"list.{name} with these arguments")
            i.sized(owner)
            return None
        return i.unsupported(n, f".{name}() on a value not known statically")
    return call


def m_str(name: str) -> Method:
    def call(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if name == "perform":
            # ``Substitution.perform(self, context)``, the context given by position or
            # by keyword (reseq_ros2's ``LaunchConfiguration('arm').perform(
            # context=context)``)
            context = arg(a, k, 0, "context")
            if isinstance(owner, (e.Subst, Lazy)) and isinstance(context, Context):
                return context.perform(to_text(owner))
            # said here, naming it, rather than at each use of its text
            return i.unsupported(n, f"{_source(n)}: perform() outside an OpaqueFunction "
                                    "is not interpreted")
        if name == "format" and isinstance(owner, str) and any(
                isinstance(v, (Lazy, e.Subst, Unknown)) for v in [*a, *k.values()]):
            return i.operation(lambda: concat(partial.format_parts(
                owner, a, k, _same, lambda reason: Unknown(reason), LIMITS.length)), n)
        if not isinstance(owner, str) or not all(
                isinstance(v, (str, int, float, list, tuple)) for v in [*a, *k.values()]
        ) or any(isinstance(x, (Unknown, Lazy, e.Subst)) for v in a
                 if isinstance(v, (list, tuple)) for x in v):
            if name == "join" and isinstance(owner, str) and a and isinstance(a[0], list):
                return i.operation(lambda: concat(partial.join_parts(
                    owner, a[0], _same, LIMITS.length)), n)
            if isinstance(owner, Lazy) and name in _TEXT_OF_TEXT and any(
                    isinstance(p, (e.Command, e.Opaque)) for p in owner.text):
                # text made of a command's output (xacro's document, andino's
                # ``toprettyxml().replace(...)``): unknown as that output is, said where
                # the command is performed (LAUNCH_UNKNOWN_VALUE), not once more here
                return Lazy((*owner.text, e.Opaque(
                    f"str.{name}() of a value known only when the launch runs",
                    report=False)))
            return Unknown(f"str.{name}() of a value not known statically")
        try:  # the size of what it would make, before making it
            return ops.call_method(owner, name, a, k, LIMITS)
        except ops.Refused as err:
            if err.kind == "limit":
                raise Budget(err.reason) from None
            if err.kind == "error":
                return i.failed(n, f"str.{name}() fails: {err.reason}", err.reason)
            return i.unsupported(n, f"str.{name}(): {err.reason}")
    return call


_PLAIN = (str, int, float, bool, type(None))
# the str methods whose result is text again
_TEXT_OF_TEXT = frozenset(("replace", "strip", "lstrip", "rstrip", "lower", "upper",
                           "capitalize", "title", "removeprefix", "removesuffix"))


def _same(value: Any) -> Any:
    return value


def m_perform_substitution(i: Interpreter, owner: Any, a: Args, k: Kwargs,
                           n: ast.AST) -> Any:
    """``LaunchContext.perform_substitution(sub)``: ``sub.perform(context)``."""
    value = a[0] if a else k.get("substitution")
    if isinstance(owner, Context) and isinstance(value, (e.Subst, Lazy, str)):
        return owner.perform(to_text(value))
    return i.unsupported(n, ".perform_substitution() of a value not known statically")


def m_dict(name: str) -> Method:
    def call(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if isinstance(owner, Context) and name == "get" and a:
            state, held = owner.held(a[0])
            if state == "value":  # set by the function, or launch_ros' global_params
                return held
            if state == "unset":
                # dict.get of a configuration nothing set: the default as it is, a
                # text or not (Autoware's ``.get("ros_params", {})``)
                return a[1] if len(a) > 1 else None
            if state == "unknown" and len(a) > 1 and not isinstance(a[1], str):
                return Unknown(f"launch configuration {a[0]}: an action not seen may set it")
            return owner.perform((e.Var(to_text(a[0]), to_text(a[1]) if len(a) > 1
                                        else None),))
        if hasattr(owner, "get") and not isinstance(owner, dict) and name == "get":
            return owner.get(i, a, n)
        if not isinstance(owner, dict):
            return i.unsupported(n, f".{name}() on a value not known statically")
        if name == "items":
            return list(owner.items())
        if name == "keys":
            return list(owner)
        if name == "values":
            return list(owner.values())
        if name == "get" and a:
            if _hashable(a[0]) not in owner and open_keys(owner):
                return Unknown(f".get({a[0]!r}) of a dict with a key not known statically")
            return owner.get(a[0], a[1] if len(a) > 1 else None)
        if name == "update" and a and isinstance(a[0], dict):
            owner.update(a[0])
            return None
        if name == "copy":
            return dict(owner)
        if name == "setdefault" and 1 <= len(a) <= 2 and not k:
            # the item when the dict has it, else the default, set (mini_pupper_ros'
            # ``sensors_config.setdefault('lidar', False)`` over a YAML file's dict); a
            # key not among the known ones of a dict with a key not known statically may
            # be that one: its value is not known, nor the default's being set
            key = _hashable(a[0])
            if isinstance(key, Unknown):
                return i.unsupported(n, "dict.setdefault of a key not known statically")
            if key not in owner:
                owner[key] = Unknown(f".setdefault({a[0]!r}) of a dict with a key not "
                                     "known statically") if open_keys(owner) else (
                    a[1] if len(a) > 1 else None)
                i.sized(owner)
            return owner[key]
        return i.unsupported(n, f"dict.{name} with these arguments")
    return call


def m_path(name: str) -> Method:
    """``as_posix``, ``joinpath``, ``with_name``, ``with_suffix`` of a pure path."""
    def call(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
        if not isinstance(owner, PurePosixPath) or k or not all(
                isinstance(v, (str, PurePosixPath)) for v in a):
            return Unknown(f"Path.{name}() of a value not known statically")
        try:
            return getattr(owner, name)(*a)
        except (TypeError, ValueError) as err:
            return i.unsupported(n, f"Path.{name}() fails: {err}")
    return call


def m_absolute(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``Path.absolute()`` / ``resolve()`` of a path that is absolute already (one under
    ``__file__``): itself, normalised; the current folder is not known here."""
    if isinstance(owner, PurePosixPath) and owner.is_absolute() and not a and not k:
        return PurePosixPath(os.path.normpath(str(owner)))
    return Unknown("Path.absolute() of a path not known to be absolute")


XACRO_NOT_RUN = "xacro is never run here; the document it makes is unknown"


def xacro_command(path: Any, mappings: Any) -> e.Text:
    """The ``xacro`` command line that ``xacro.process_file(path, mappings)`` stands for."""
    parts: list[Any] = ["xacro ", path]
    if isinstance(mappings, dict):
        for key, value in list(mappings.items())[:1000]:
            parts += [" ", key, ":=", value]
    return to_text(parts)


def xacro_process_file(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``xacro.process_file(path, mappings=...)``: a document never processed here."""
    return XacroDocument(xacro_command(arg(a, k, 0, "input_file_name"),
                                       k.get("mappings", a[1] if len(a) > 1 else None)))


def xacro_process(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``xacro.process(path, mappings=...)``: the XML text, as a ``xacro`` command's."""
    return Lazy((e.Command(xacro_command(arg(a, k, 0, "input_file_name"),
                                         k.get("mappings", a[1] if len(a) > 1 else None)),
                           XACRO_NOT_RUN),))


def xacro_parse(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``xacro.parse(open(path))`` (or ``parse(None, filename=path)``): the file's
    document, not processed yet (bcr_bot's ``get_xacro_to_doc``)."""
    source = arg(a, k, 0, "inp")
    path = source.path if isinstance(source, ReadOnlyFile) else (
        k.get("filename", a[1] if len(a) > 1 else None) if source is None else None)
    if not isinstance(path, str):
        return Unknown("xacro.parse() of a document not read from a known file")
    return XacroDocument(to_text(["cat ", path]), path)


def xacro_process_doc(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``xacro.process_doc(doc, mappings=...)``: ``doc`` (from ``xacro.parse``) becomes
    what the ``xacro`` command line on its file with those arguments makes."""
    doc = arg(a, k, 0, "doc")
    if isinstance(doc, XacroDocument) and doc.path is not None:
        doc.command = xacro_command(doc.path, k.get("mappings", a[1] if len(a) > 1 else None))
        doc.path = None  # processed: what is left has no xacro to expand again
    return None


def m_xml(i: Interpreter, owner: Any, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``toxml()`` / ``toprettyxml()`` of a xacro document: its command's output."""
    if isinstance(owner, XacroDocument):
        return Lazy((e.Command(owner.command, XACRO_NOT_RUN),))
    return Unknown("toxml() of a value not known statically")


METHODS: dict[str, Method] = {
    "toxml": m_xml, "toprettyxml": m_xml,
    "add_action": m_add_action, "add_entity": m_add_action, "find": m_find,
    "read": m_read, "read_text": m_read_text, "evaluate": m_evaluate,
    "append": m_list("append"), "extend": m_list("extend"),
    "insert": m_list("insert"), "remove": m_list("remove"), "pop": m_list("pop"),
    "items": m_dict("items"), "keys": m_dict("keys"),
    "values": m_dict("values"), "get": m_dict("get"), "update": m_dict("update"),
    "copy": m_dict("copy"), "setdefault": m_dict("setdefault"), "perform": m_str("perform"),
    "perform_substitution": m_perform_substitution,
    **{name: m_path(name) for name in ("as_posix", "joinpath", "with_name", "with_suffix")},
    "absolute": m_absolute, "resolve": m_absolute,
    **{name: m_str(name) for name in (
        "format", "join", "replace", "split", "strip", "lstrip", "rstrip", "lower", "upper",
        "startswith", "endswith", "capitalize", "title", "rsplit", "removeprefix",
        "removesuffix")},
}
