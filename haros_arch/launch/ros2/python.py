"""Python launch files, interpreted statically over ``ast``: never imported nor run.

``parse_python`` reads the module's imports, constants and functions, then interprets
``generate_launch_description()`` with a small interpreter: assignments, calls to the
launch / launch_ros API (``python_api.API``), list / dict literals, comprehensions and
``for`` loops over known values, ``if`` (both branches, conditional, when the test is
unknown), helper functions of the same file, f-strings, ``%``, ``format`` and ``+``,
``os.path`` helpers. Module-level code runs as importing the file would run it; a
module of the workspace the file imports from a folder it put on ``sys.path`` is read
the same way (``Module``). Anything else gives an unknown value and a
``LAUNCH_PY_UNSUPPORTED`` diagnostic; nothing outside the workspace is read or called. Work is
bounded: source size, AST size and depth, evaluation steps, call depth, value sizes.

Strings that hold substitutions or unknown parts are ``Lazy`` (a ``Text``); the runner
computes them where the action runs. ``OpaqueFunction`` bodies run when the runner
reaches them, with ``context`` standing for the launch context of that moment.
"""

from __future__ import annotations

import ast
import builtins
import functools
import os
from collections.abc import Callable, Iterator, Mapping
from pathlib import PurePosixPath
from typing import Any, TypeVar

from ... import diagnostics as diag
from ...diagnostics import Diagnostic
from ...evaluate import budget, syntax
from ...evaluate import operations as ops
from ...extract.python.modules import module_file, submodule, workspace_module
from ...model.launch_tree import PackageUse, installed_check
from ...model.location import Location
from ...model.values import Unknown
from ...share import share_source
from ...workspace import Workspace
from . import entities as e
from .python_expressions import (
    UNBOUND,
    UNFOUND_STARS,
    Expressions,
    _Bound,
    _Environ,
    math_constant,
    os_value,
)
from .python_values import (
    LIMITS,
    MAX_CALL_DEPTH,
    MAX_DEPTH,
    MAX_NODES,
    MAX_READ,
    MAX_SIZE,
    MAX_SOURCE,
    OUTER,
    UNSET,
    ActionClass,
    Budget,
    Constructing,
    Context,
    EnumMember,
    FieldFactory,
    Func,
    Guard,
    InstalledPackages,
    Instance,
    LaunchDescription,
    Lazy,
    Method,
    Module,
    PlainClass,
    Raised,
    ReadOnlyFile,
    Record,
    Ref,
    SubstitutionClass,
    SuperOf,
    _Break,
    _Continue,
    _Flow,
    _known_module,
    _load,
    _Return,
    _source,
    _Stop,
    conjunction,
    derived_unknown,
    env_unset,
    launch_object,
    open_keys,
    said_unknown,
    to_text,
    write_outer,
)

T = TypeVar("T")
FILE_UNKNOWN = "LAUNCH_PY_FILE_UNKNOWN"  # a file read whose content is not known


class _Overlay(Mapping[str, str]):
    """The configuration's environment under what the launch file sets in it."""

    def __init__(self, base: Mapping[str, str]) -> None:
        self.base = base
        self.own: dict[str, str] = {}

    def __getitem__(self, key: str) -> str:
        return self.own[key] if key in self.own else self.base[key]

    def __iter__(self) -> Iterator[str]:
        yield from self.own
        yield from (key for key in self.base if key not in self.own)

    def __len__(self) -> int:
        return len(self.own) + sum(1 for key in self.base if key not in self.own)


class Interpreter(Expressions):
    """Statements, calls and the module; expressions come from ``Expressions``."""

    def __init__(self, path: str, workspace: Workspace, environment: Mapping[str, str]) -> None:
        self.path = path
        self.launch_file = path
        self.workspace = workspace
        self.environment = environment
        self.environment_unsure: set[str] = set()
        # variables the file removes (``del os.environ[key]``, ``os.environ.pop(key)``)
        # under no test: read after, they are not set
        self.environment_removed: set[str] = set()
        # ``delete_name``'s, each scope kept with its names (so no other takes its id)
        self.deleted: dict[int, tuple[dict[str, Any], set[str]]] = {}
        self.diagnostics: list[Diagnostic] = []
        # packages whose folders the file asks for now (get_package_share_directory)
        self.uses: list[PackageUse] = []
        # launch imports the file from its path: __file__ is that path, as given
        # (and its module's name, the one launch's loader gives every launch file)
        self.globals: dict[str, Any] = {"__file__": path, "__name__": "python_launch_file"}
        self.steps = 0
        self.limits = LIMITS
        self.depth = 0
        self.running: list[ast.AST] = []  # the functions being run, outermost first
        # where each of them was called: the call, the function, the caller's file and
        # how many values were given before the call's own arguments (a method's self)
        self.call_sites: list[tuple[ast.AST, Func, str, int]] = []
        self.guards: list[Guard] = []  # the unknown Python `if` tests we are under
        # the absolute paths of the files the file opens for writing (not run): made
        # on the machine that runs the launch, so not hard-coded paths of the author's
        self.made_paths: list[str] = []
        self.guard_runs = 0
        self.decided: dict[int, ast.AST] = {}
        # the ``if`` tests not known statically that nothing said why of, by id: said
        # once at the test when an action is first made under one (``guarding``)
        self.tests_unsaid: dict[int, Diagnostic] = {}
        # the enclosing ``try`` statements: the exception classes their handlers name
        # (None: one not known) and how many guards there were when each began
        self.catching: list[tuple[list[tuple[str, ...] | None], int]] = []
        # per enclosing ``try``: whether a handler of it catches ament_index_python's
        # PackageNotFoundError (``catches_missing_package``)
        self.missing_caught: list[bool] = []
        # per function being run: the values it returned under a test not known
        self.returns: list[list[Any]] = []
        # per file read, the names its code binds anywhere (``names_bound``; None: any)
        self.bindings: dict[str, frozenset[str] | None] = {}
        # folders the file put on sys.path (sys.path.append), where `import name` looks
        self.search: list[str] = []
        # modules imported from them, by source path (None: being read, or unreadable)
        self.modules: dict[str, Module | None] = {}
        # what a known library keeps in its module or classes while the file runs
        # (launch_param_builder's ParameterBuilder._parameters, one dict for every builder)
        self.library_state: dict[str, Any] = {}
        # the launch's command-line arguments (``parse_python``)
        self.command_line: Mapping[str, str] = {}
        # ``sys.argv``: the ``ros2 launch`` command line that starts the configuration
        # (``parse_python``), None when not known
        self.argv: list[Any] | None = None
        from .python_api import API, BUILTINS, METHODS

        self.api = API
        self.builtins = BUILTINS
        self.methods = METHODS

    # -- diagnostics -------------------------------------------------------------------
    def written(self, node: ast.AST, expression: ast.AST | None) -> Location:
        """Where the value of ``expression`` (an argument of the call ``node``) was
        written: ``node``'s place, unless ``expression`` is a parameter of the function
        being run, which another file's call gave: then that call's place, and so on up
        (aerostack2's launch files call as2_core's ``get_available_plugins(package)``,
        whose ``get_package_share_directory(package_name)`` asks for the caller's
        package, not for one as2_core names)."""
        here = self.where(node)
        place, path = here, self.path
        depth = len(self.call_sites)
        while isinstance(expression, ast.Name) and depth > 0:
            site, func, caller, given = self.call_sites[depth - 1]
            expression = _argument_written(site, func, expression.id, given)
            if expression is None:
                break
            depth -= 1
            if caller != path:
                line = getattr(site, "lineno", 0) or 0
                place = self.workspace.location(caller, line, getattr(site, "col_offset", -1) + 1)
                path = caller
        return here if place.file == here.file else place

    def where(self, node: ast.AST | None) -> Location:
        line = getattr(node, "lineno", 0) or 0
        col = getattr(node, "col_offset", -1) + 1
        return self.workspace.location(self.path, line, col)

    def bounded(self, where: Location, run: Callable[[], T], failed: T) -> T:
        """``run()``, or ``failed`` when it passes the interpreter's budget or nests too
        deeply (said at ``where``, LAUNCH_PY_BUDGET): a file's module, a function launch
        calls when it runs (``OpaqueFunction``, ``ForEach``)."""
        try:
            return run()
        except Budget as stop:
            self.diagnostics.append(diag.make("LAUNCH_PY_BUDGET", where, detail=str(stop)))
        except _Stop as stop:
            self.diagnostics.append(diag.make("LAUNCH_PY_EXIT", stop.where,
                                              detail=stop.what))
        except (RecursionError, _Flow):
            self.diagnostics.append(diag.make("LAUNCH_PY_BUDGET", where,
                                              detail="interpretation nested too deeply"))
        return failed

    def package_folder(self, path: PurePosixPath) -> tuple[str, str] | None:
        if not path.is_absolute():
            return None
        package = self.workspace.package_of(str(path))
        if package is None or not package.root or package.name not in self.workspace.packages:
            return None
        return package.name, os.path.normpath(package.root)

    def unsupported(self, node: ast.AST | None, detail: str,
                    code: str = "LAUNCH_PY_UNSUPPORTED") -> Unknown:
        """Said here, once: the value is unknown, of kind ``unsupported`` and made at
        this place, so that what uses it later says no more (``python_values.to_text``)
        and an action list it lands in names the place (``actions_of``). ``code``:
        LAUNCH_PY_FILE_UNKNOWN for a file's content not known (``read``), which hides
        no launch configuration as a construct not run does."""
        where = self.where(node)
        found = diag.make(code, where, detail=detail)
        if found not in self.diagnostics:
            self.diagnostics.append(found)
        return Unknown(detail, "unsupported", where=where)

    def compare_values(self, op: ast.cmpop, left: object, right: object,
                       node: ast.Compare) -> Any:
        """One comparison of a chain; ``name in get_packages_with_prefixes()`` asks
        whether that package is installed, as ``has_resource`` does."""
        if isinstance(right, InstalledPackages) and isinstance(op, ast.In | ast.NotIn) and (
                isinstance(left, str)):
            from .python_api import package_installed

            found = package_installed(self, left, node, f"{left!r} in {right.origin}")
            return found if isinstance(found, Unknown) else isinstance(op, ast.In)
        return super().compare_values(op, left, right, node)

    def misspelt_package(self, name: str, where: Location) -> bool:
        """Whether ``name``, a package the file looks up when the call runs
        (``get_package_share_directory``, ``FindPackageShare(...).find()``), is neither
        here nor installed but a letter or two from a package that is, or no name a
        package can have (``Workspace.surely_absent``): then ament_index_python raises
        PackageNotFoundError at that call, whatever the conditions of the actions its
        value goes to, and it is said there, once (``PACKAGE_NOT_FOUND``, as a
        ``FindPackageShare`` of it is where performed). Not in a ``try`` whose handler
        catches the absence, nor under an ``if`` that checks a package is installed: the
        file runs without it."""
        if any(self.missing_caught) or installed_check(self.guards) is not None or (
                not self.workspace.surely_absent(name)):
            return False
        found = diag.make("PACKAGE_NOT_FOUND", where, name=name,
                          why=self.workspace.absence(name))
        if found not in self.diagnostics:
            self.diagnostics.append(found)
        return True

    def unknown_value(self, node: ast.AST, detail: str) -> None:
        self.diagnostics.append(diag.make("LAUNCH_UNKNOWN_VALUE", self.where(node),
                                          detail=detail))

    def sized(self, value: Any) -> Any:
        """``value``, within the one evaluator's size bounds (``LIMITS``) or the file stops."""
        try:
            return ops.checked(value, LIMITS)
        except ops.Refused as err:
            raise Budget(err.reason) from None

    # -- module ------------------------------------------------------------------------
    def module(self, tree: ast.Module) -> list[e.Action] | None:
        self.module_body(tree, self.globals)
        entry = self.globals.get("generate_launch_description")
        if not isinstance(entry, Func):
            self.diagnostics.append(diag.make(
                "LAUNCH_PY_UNSUPPORTED", self.where(None),
                detail="no generate_launch_description() function"))
            return None
        result = self.call(entry, [], {}, entry.node)
        return self.actions_of(result, entry.node)

    def module_body(self, tree: ast.Module, env: dict[str, Any]) -> None:
        """What importing the module does: its names, and its module-level code."""
        self.bindings[self.path] = names_bound(tree)
        for stmt in tree.body:
            if isinstance(stmt, (ast.Import, ast.ImportFrom)):
                self.import_(stmt, env)
            elif isinstance(stmt, ast.FunctionDef):
                env[stmt.name] = Func(stmt, env)
            elif isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant):
                continue  # docstring
            elif isinstance(stmt, ast.If) and "__name__" in ast.dump(stmt.test):
                continue  # if __name__ == '__main__': never run
            elif isinstance(stmt, ast.ClassDef):
                env[stmt.name] = self.class_(stmt, env)
            else:
                # a call, loop or test at module level runs when launch imports the file
                # (``CAMERAS.append(...)`` fills a list generate_launch_description
                # reads): interpreted as in a function, what is not known says so
                self.statement(stmt, env)

    def actions_of(self, value: Any, node: ast.AST) -> list[e.Action]:
        """The actions in a LaunchDescription, a list of actions, or one action."""
        if isinstance(value, LaunchDescription):
            value = value.actions
        if isinstance(value, e.Action):
            return [value]
        if not isinstance(value, (list, tuple)):
            self.unsupported(node, "launch description is not known statically")
            return []
        if budget.item_count(value, MAX_SIZE) > MAX_SIZE:
            self.unsupported(node, f"launch description of more than {MAX_SIZE} items")
            return []
        out: list[e.Action] = []
        for item in value:
            if isinstance(item, (LaunchDescription, list, tuple)):
                out.extend(self.actions_of(item, node))
            elif isinstance(item, e.Action):
                out.append(item)
            elif isinstance(item, Unknown):
                # the interpreter said why it is not known where it was made; as an
                # action it may start, set or declare anything (query.absence,
                # runner.Scope.unseen), said at that place when it is known
                out.append(e.UnknownAction(item.origin or "?",
                                           location=item.where or self.where(node)))
            elif item is not None:
                self.unsupported(node, f"{type(item).__name__} is not a launch action")
        return out

    def class_(self, stmt: ast.ClassDef, env: dict[str, Any]) -> Any:
        """A class of the interpreted code: an ``ActionClass`` when it derives from one
        launch action the API builds (or from another such class) and only adds a
        constructor (launch's ``expose_action`` decorator aside, which names it for XML
        and YAML files); otherwise never run, and a use of it is reported. A method other
        than the constructor may be one launch calls (``execute``, ``visit``), so the
        action would not be the base's."""
        unknown = Unknown(f"class {stmt.name} (not interpreted)")
        if len(stmt.bases) > 1 or stmt.keywords:
            return unknown
        base = self._quiet(stmt.bases[0], env) if stmt.bases else None
        if stmt.bases and base is None:  # a base not known here (``TypedDict``, ``list``)
            return unknown
        if isinstance(base, ActionClass) or (isinstance(base, Ref) and self._builds(base)):
            if not all(self._naming_decorator(d, env) for d in stmt.decorator_list):
                return unknown
            init: Func | None = None
            for item in stmt.body:
                if isinstance(item, ast.FunctionDef) and item.name == "__init__" \
                        and not item.decorator_list and item.args.args:
                    init = Func(item, env)
                elif not _no_op(item):
                    return unknown
            return ActionClass(stmt.name, base, init)
        if isinstance(base, Ref) and base.qualified in _SUBSTITUTION_BASES \
                and not stmt.decorator_list and any(
                    isinstance(item, ast.FunctionDef) and item.name == "perform"
                    for item in stmt.body):
            return SubstitutionClass(stmt.name)
        plain = self.plain_class(stmt, base, env)
        return plain if plain is not None else unknown

    def plain_class(self, stmt: ast.ClassDef, base: Any, env: dict[str, Any]
                    ) -> PlainClass | None:
        """A class of no launch action whose body only defines functions (plain, static,
        class methods, properties) and names, of no base, ``object``, an ``Enum`` or
        another such class, plain or ``@dataclass``; None for any other (not run)."""
        dataclass_ = False
        for decorator in stmt.decorator_list:
            ref = self._quiet(decorator.func if isinstance(decorator, ast.Call)
                              else decorator, env)
            if not (isinstance(ref, Ref) and ref.qualified == "dataclasses.dataclass"):
                return None
            dataclass_ = True
        enum = isinstance(base, Ref) and base.qualified in _ENUM_BASES
        if base is not None and not enum and not isinstance(base, PlainClass) and not (
                isinstance(base, Ref) and base.qualified == "object"):
            return None
        cls = PlainClass(stmt.name, enum=enum or (isinstance(base, PlainClass) and base.enum))
        if isinstance(base, PlainClass):
            cls.methods.update(base.methods)
            cls.attributes.update(base.attributes)
            cls.fields = list(base.fields) if base.fields is not None else None
        if dataclass_ and cls.fields is None:
            cls.fields = []
        scope: dict[str, Any] = {"__closure__": env}  # the class body's own names
        for item in stmt.body:
            if isinstance(item, ast.FunctionDef):
                kind = self._method_kind(item, env)
                if kind is None:
                    return None
                cls.methods[item.name] = (kind, Func(item, env))
            elif isinstance(item, ast.Assign) and all(isinstance(t, ast.Name)
                                                      for t in item.targets):
                value = self.eval(item.value, scope)
                for target in item.targets:
                    assert isinstance(target, ast.Name)
                    scope[target.id] = cls.attributes[target.id] = EnumMember(
                        cls.name, target.id, value) if cls.enum else value
            elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                name = item.target.id
                value = self._field_default(item.value, scope) if dataclass_ else (
                    self.eval(item.value, scope) if item.value is not None else UNSET)
                if cls.fields is not None and dataclass_:
                    cls.fields = [f for f in cls.fields if f[0] != name] + [(name, value)]
                if value is not UNSET and not isinstance(value, FieldFactory):
                    scope[name] = cls.attributes[name] = value
            elif not _no_op(item):
                return None
        return cls

    def _field_default(self, node: ast.expr | None, scope: dict[str, Any]) -> Any:
        """A dataclass field's default: ``UNSET`` for none, ``field(default=v)`` v,
        ``field(default_factory=f)`` a ``FieldFactory`` (moveit_configs_utils'
        ``MoveItConfigs``: ``field(default_factory=dict)``), else the value."""
        if node is None:
            return UNSET
        if isinstance(node, ast.Call) and not node.args and (
                (ref := self._quiet(node.func, scope)) is not None) and isinstance(
                ref, Ref) and ref.qualified == "dataclasses.field":
            keywords = {k.arg: k.value for k in node.keywords}
            if "default_factory" in keywords:
                return FieldFactory(self.eval(keywords["default_factory"], scope))
            if "default" in keywords:
                return self.eval(keywords["default"], scope)
            return UNSET
        return self.eval(node, scope)

    def _method_kind(self, func: ast.FunctionDef, env: dict[str, Any]) -> str | None:
        """How a class's function binds: a plain method, or what its one decorator
        (staticmethod, classmethod, property) makes it; None for another decorator."""
        if not func.decorator_list:
            return "method"
        if len(func.decorator_list) == 1 and isinstance(func.decorator_list[0], ast.Name):
            return {"staticmethod": "static", "classmethod": "class",
                    "property": "property"}.get(func.decorator_list[0].id)
        return None

    def enum_member(self, cls: PlainClass, args: list[Any], kwargs: dict[str, Any],
                    node: ast.AST) -> Any:
        """``Mode(value)`` of an ``Enum``: its member of that value (a member of its own,
        itself), as Python looks it up; a value known that none has fails with Python's
        ``ValueError`` (spot_ros2's ``DepthRegisteredMode(text.lower())``)."""
        value = args[0] if len(args) == 1 and not kwargs else None
        members = _enum_members(cls)
        if isinstance(value, EnumMember) and value in members:
            return value
        if not isinstance(value, (str, int, float)):
            return self.unsupported(node, f"call to the enum {cls.name} is not interpreted")
        found = next((m for m in members if m.value == value), None)
        if found is None:
            return self.failed(node, f"{cls.name}({value!r}) fails",
                               f"ValueError: {value!r} is not a valid {cls.name}")
        return found

    def instantiate(self, cls: PlainClass, args: list[Any], kwargs: dict[str, Any],
                    node: ast.AST) -> Any:
        """``Cls(...)``: an instance, its ``__init__`` run on it, or a dataclass's fields
        set from the arguments and defaults (then its ``__post_init__``)."""
        if cls.enum:
            return self.enum_member(cls, args, kwargs, node)
        instance = Instance(cls)
        init = cls.methods.get("__init__")
        if init is not None:
            if init[0] != "method":
                return self.unsupported(node, f"{cls.name}.__init__ is not a plain method")
            self.call_function(init[1], [instance, *args], kwargs, node)
            return instance
        if cls.fields is None:
            if args or kwargs:
                return self.unsupported(node, f"{cls.name}() takes no arguments")
            return instance
        names = [name for name, _ in cls.fields]
        if len(args) > len(names) or set(kwargs) - set(names):
            return self.unsupported(node, f"arguments of {cls.name}() that are not its "
                                          "fields")
        for index, (name, default) in enumerate(cls.fields):
            if index < len(args):
                instance.attributes[name] = args[index]
            elif name in kwargs:
                instance.attributes[name] = kwargs[name]
            elif isinstance(default, FieldFactory):
                instance.attributes[name] = self.call(default.func, [], {}, node)
            elif default is not UNSET:
                instance.attributes[name] = default
            else:
                instance.attributes[name] = self.unsupported(
                    node, f"field {name} of {cls.name}() is not given")
        post = cls.methods.get("__post_init__")
        if post is not None and post[0] == "method":
            self.call_function(post[1], [instance], {}, node)
        return instance

    def _quiet(self, node: ast.expr, env: dict[str, Any]) -> Any:
        """A name or dotted name's value, saying nothing when it is not defined."""
        if isinstance(node, ast.Name):
            value = self.bound(node.id, env)
            return None if value is UNBOUND else value
        if isinstance(node, ast.Attribute):
            owner = self._quiet(node.value, env)
            if isinstance(owner, Ref):
                return Ref(f"{owner.qualified}.{node.attr}")
            if isinstance(owner, Module):
                return owner.names.get(node.attr)
        return None

    def _builds(self, ref: Ref) -> bool:
        """Whether calling ``ref`` is a launch action (or description) the API builds."""
        short = ref.qualified.rsplit(".", 1)[-1]
        return short in self.api and _known_module(ref.qualified) and short[:1].isupper()

    def _naming_decorator(self, node: ast.expr, env: dict[str, Any]) -> bool:
        """Whether a class decorator is launch's ``expose_action`` / ``expose_substitution``
        (``@expose_action('arm_description')``), which only registers the class."""
        func = node.func if isinstance(node, ast.Call) else node
        ref = self._quiet(func, env)
        return isinstance(ref, Ref) and ref.qualified.startswith("launch.") and \
            ref.qualified.rsplit(".", 1)[-1] in ("expose_action", "expose_substitution")

    def construct(self, cls: ActionClass, args: list[Any], kwargs: dict[str, Any],
                  node: ast.AST) -> Any:
        """``cls(...)``: its constructor run with ``self`` being built; the action is the
        one its ``super().__init__`` (or ``Base.__init__(self, ...)``) built."""
        if cls.init is None:
            return self.construct_base(cls.base, args, kwargs, node)
        instance = Constructing(cls)
        init = Func(cls.init.node, {"__closure__": cls.init.closure,
                                    "super": SuperOf(instance)})
        self.call_function(init, [instance, *args], kwargs, node)
        if instance.built is None:
            return self.unsupported(node, f"class {cls.name}: its constructor does not "
                                          "build the action it derives from")
        return instance.built

    def construct_base(self, base: Any, args: list[Any], kwargs: dict[str, Any],
                       node: ast.AST) -> Any:
        if isinstance(base, ActionClass):
            return self.construct(base, args, kwargs, node)
        return self.call(base, args, kwargs, node)

    def import_(self, stmt: ast.Import | ast.ImportFrom, env: dict[str, Any]) -> None:
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                found = self.find_module(alias.name, stmt)
                if found is not None and not alias.asname and "." in alias.name:
                    env[alias.name.split(".")[0]] = self.dotted_import(alias.name, found,
                                                                       stmt)
                elif found is not None:
                    env[alias.asname or alias.name] = found
                elif alias.asname:
                    env[alias.asname] = Ref(alias.name)
                else:
                    top = alias.name.split(".")[0]
                    env[top] = Ref(top)
            return
        module = ("." * stmt.level) + (stmt.module or "")
        found = self.find_module(module, stmt)
        for alias in stmt.names:
            if found is not None and alias.name == "*":
                # ``from utils_yaml import *`` (OrbbecSDK_ROS2's orbbec_camera.launch.py):
                # the module's public names, or those its ``__all__`` lists, as Python
                listed = found.names.get("__all__")
                public = [n for n in listed if isinstance(n, str)] if isinstance(
                    listed, (list, tuple)) else [n for n in found.names
                                                 if not n.startswith("_")]
                env.update((n, found.names[n]) for n in public if n in found.names)
            elif found is None and module == "math" and math_constant(alias.name):
                env[alias.asname or alias.name] = ops.MATH[alias.name]  # from math import pi
            elif found is None and os_value(module, alias.name) is not None:
                env[alias.asname or alias.name] = os_value(module, alias.name)
            elif found is None and (module, alias.name) == ("sys", "argv") and (
                    self.argv is not None):
                env[alias.asname or alias.name] = list(self.argv)  # from sys import argv
            elif found is None and alias.name == "*":
                # a module not found: the names it binds are not known here (said where
                # one is used: ``lookup``)
                env[UNFOUND_STARS] = [*env.get(UNFOUND_STARS, []), module]
            elif found is None:
                env[alias.asname or alias.name] = Ref(f"{module}.{alias.name}")
            elif alias.name in found.names:
                env[alias.asname or alias.name] = found.names[alias.name]
            elif (inner := submodule(found.path, alias.name)) is not None \
                    and self.workspace.readable(os.path.realpath(inner), self.environment):
                # ``from vrx_gz import bridges``: a submodule the package's __init__ does
                # not bind, which the import loads, as Python does
                loaded = self.module_file(f"{found.name}.{alias.name}",
                                          os.path.realpath(inner), stmt)
                env[alias.asname or alias.name] = loaded if loaded is not None else \
                    self.unsupported(stmt, f"module {found.name}.{alias.name} could not "
                                           "be read")
                if loaded is not None:
                    found.names[alias.name] = loaded
            else:
                env[alias.asname or alias.name] = self.unsupported(
                    stmt, f"{alias.name} is not defined in {found.name} as read here")

    def dotted_import(self, name: str, found: Module, node: ast.AST) -> Module:
        """``import vrx_gz.launch``: Python binds the top package, each module of the path
        an attribute of the one above it (``vrx_gz.launch.spawn(...)`` then reads). A
        package folder without ``__init__.py`` (a namespace package) is a module of no
        names of its own."""
        parts = name.split(".")
        chain = [self.find_module(".".join(parts[:i]), node) for i in range(1, len(parts))]
        modules = [m if m is not None else Module(".".join(parts[:i + 1]), "", {})
                   for i, m in enumerate(chain)] + [found]
        for outer, inner, attr in zip(modules, modules[1:], parts[1:], strict=False):
            outer.names[attr] = inner
        return modules[0]

    # -- modules of the workspace imported from sys.path ---------------------------------
    def add_search(self, func: Ref, args: list[Any], node: ast.AST) -> Any:
        """``sys.path.append(folder)`` / ``sys.path.insert(i, folder)``: ``import name``
        then finds ``name.py`` there, as Python would (launch itself puts nothing on
        sys.path: a launch file that imports its helpers adds their folder)."""
        folder = args[-1] if args else None
        if isinstance(folder, PurePosixPath):
            folder = str(folder)
        if not isinstance(folder, str) or not os.path.isabs(folder):
            return self.unsupported(node, f"{func.qualified} of a folder not known "
                                          "statically; imports from it are not read")
        if func.qualified.endswith(".insert"):
            self.search.insert(0, folder)
        else:
            self.search.append(folder)
        return None

    def find_module(self, name: str, node: ast.AST) -> Module | None:
        """The module ``name`` of a folder on the file's ``sys.path``, of a Python package
        a package of the workspace holds (``from interbotix_xs_modules.xs_launch import
        declare_interbotix_xsarm_robot_description_launch_arguments``: an ament_python
        package installs it where launch imports it), or relative to the module being
        read (``from .xs_launch import *``), interpreted once; None when it is not there
        (a library: a Ref, as before)."""
        if not name or _known_module(name.lstrip(".")):
            return None
        level = len(name) - len(name.lstrip("."))
        parts = [p for p in name.lstrip(".").split(".") if p]
        for source in self._module_files(level, parts):
            source = os.path.realpath(source)
            if os.path.isfile(source) and self.workspace.readable(source, self.environment):
                return self.module_file(name, source, node)
        return None

    def module_file(self, name: str, source: str, node: ast.AST) -> Module | None:
        """The module of the Python file ``source`` (a real path we may read),
        interpreted once however often it is imported. A module imported again while it
        is still being read is the module as read so far, as Python hands out the partly
        initialised module it keeps in ``sys.modules``: a package's ``__init__.py`` that
        says ``from . import mock`` while its submodules say ``from . import behaviours``
        (py_trees_ros_tutorials) is no cycle. A name not bound yet then is not defined
        there, as at run time. A file that could not be read is no module (it was said
        once)."""
        if source in self.modules:
            return self.modules[source]
        module = Module(name, source, {"__file__": source, "__name__": name})
        self.modules[source] = module
        if not self.load_module(module, node):
            self.modules[source] = None
            return None
        return module

    def _module_files(self, level: int, parts: list[str]) -> list[str]:
        """Where module ``parts`` may be, in the order Python looks (``level``: the dots
        of a relative import)."""
        if level:
            base = os.path.dirname(self.path or "")
            if self.path == self.launch_file or not os.path.isfile(
                    os.path.join(base, "__init__.py")):
                return []  # a module of no package (launch loads its file as one)
            for _ in range(level - 1):
                base = os.path.dirname(base)
            found = module_file(base, parts)
            return [found] if found is not None else []
        out = [share_source(self.workspace, os.path.join(folder, parts[0] + ".py"))
               for folder in self.search] if len(parts) == 1 else []
        found = workspace_module(self.workspace, parts)
        return [*out, found] if found is not None else out

    def load_module(self, module: Module, node: ast.AST) -> bool:
        """Interprets the file of ``module`` into its names; False when it cannot be
        read."""
        from ...files import read_text

        source = module.path
        text, found = read_text(source, self.workspace.location(source), MAX_SOURCE)
        self.diagnostics.extend(found)
        if text is None:
            return False
        tree, problem = checked_tree(text, source, self.workspace)
        if tree is None:
            if problem is not None:
                self.diagnostics.append(problem)
            self.unsupported(node, f"module {module.name} could not be read")
            return False
        outer = self.path
        self.path = source
        try:
            self.module_body(tree, module.names)
        finally:
            self.path = outer
        return True

    # -- statements --------------------------------------------------------------------
    def block(self, body: list[ast.stmt], env: dict[str, Any]) -> None:
        for stmt in body:
            self.statement(stmt, env)

    def statement(self, stmt: ast.stmt, env: dict[str, Any]) -> None:
        self.step()
        if isinstance(stmt, ast.Assign):
            value = self.eval(stmt.value, env)
            for target in stmt.targets:
                self.assign(target, value, env)
        elif isinstance(stmt, ast.AnnAssign):
            if stmt.value is not None:
                self.assign(stmt.target, self.eval(stmt.value, env), env)
        elif isinstance(stmt, ast.AugAssign):
            current = self.eval(_load(stmt.target), env)
            value = self.binop(stmt.op, current, self.eval(stmt.value, env), stmt)
            if isinstance(current, list) and isinstance(stmt.op, ast.Add) and isinstance(
                    value, list):
                current[:] = value  # += on a list extends it in place
            self.assign(stmt.target, value, env)
        elif isinstance(stmt, ast.Expr):
            self.eval(stmt.value, env)
        elif isinstance(stmt, ast.Return):
            raise _Return(None if stmt.value is None else self.eval(stmt.value, env))
        elif isinstance(stmt, ast.If):
            self.if_(stmt, env)
        elif isinstance(stmt, ast.For):
            self.for_(stmt, env)
        elif isinstance(stmt, ast.FunctionDef):
            env[stmt.name] = Func(stmt, env)
        elif isinstance(stmt, ast.ClassDef):
            env[stmt.name] = self.class_(stmt, env)
        elif isinstance(stmt, (ast.Import, ast.ImportFrom)):
            self.import_(stmt, env)
        elif isinstance(stmt, ast.Try):
            self.try_(stmt, env)
        elif isinstance(stmt, ast.Pass):
            pass
        elif isinstance(stmt, ast.Break):
            raise _Break()
        elif isinstance(stmt, ast.Continue):
            raise _Continue()
        elif isinstance(stmt, ast.With):
            self.with_(stmt, env)
        elif isinstance(stmt, ast.While):
            self.while_(stmt, env)
        elif isinstance(stmt, (ast.Global, ast.Nonlocal)):
            self.outer_names(stmt, env)
        elif isinstance(stmt, ast.Assert):
            self.assertion(stmt, env)
        elif isinstance(stmt, ast.Raise):
            self.stop(stmt, _raised_name(stmt.exc))
        elif isinstance(stmt, ast.Match) and (chain := _match_as_if(stmt)) is not None:
            self.block(chain, env)
        elif isinstance(stmt, ast.Delete):
            for target in stmt.targets:
                self.delete(target, env)
        else:
            self.unsupported(stmt, f"{type(stmt).__name__} statements are not interpreted")

    def assertion(self, stmt: ast.Assert, env: dict[str, Any]) -> None:
        """``assert TEST, message``: the launch goes on only where TEST holds, so what
        follows is read as it is; a TEST known false is the AssertionError that ends the
        launch, said (or given to a ``try`` that catches it). Autoware's launch files
        check their arguments so (``assert detection_type in [...]``)."""
        _, test = self.test_of(stmt.test, env)
        if test is False:
            self.failed(stmt, f"assert {_source(stmt.test)} fails: the launch stops here",
                        "AssertionError: assertion failed")

    def stop(self, node: ast.AST, exception: str | None) -> Unknown:
        """``raise`` (``exception``: the class raised, by name, None when not known) or
        ``sys.exit()`` (``SystemExit``): the launch file stops here (``_Stop``: the
        branch of a test not known that runs it ends there, as with a ``return``), unless
        a ``try`` around it may catch it. A builtin exception a handler catches goes to
        it, as ``failed`` does; one a handler of a class not known, or under a test not
        known in between, may catch stays not interpreted, said."""
        what = _source(node).split("\n", 1)[0]
        what = what if len(what) <= 80 else what[:77] + "..."
        known = exception in _EXCEPTIONS
        for handlers, guards in reversed(self.catching):
            if known and any(_catches(c, str(exception)) for c in handlers) and (
                    guards == len(self.guards)):
                raise Raised(str(exception))
            if not known or any(c is None for c in handlers) or any(
                    _catches(c, str(exception)) for c in handlers):
                return self.unsupported(node, f"{what} in a try: whether a handler "
                                              "catches it is not known here")
        raise _Stop(what, self.where(node))

    def outer_names(self, stmt: ast.Global | ast.Nonlocal, env: dict[str, Any]) -> None:
        """``global n`` / ``nonlocal n`` in a function: ``n`` is the module's (the
        enclosing function's), not a local. The function works on its value as a local
        would (so an ``if`` whose test is not known joins it with the value before, as
        for any name: neo_simulation2's ``if int(N) > 5: N = '5'`` leaves N unknown),
        and gives the scope its value when it returns and before each function it
        calls (``write_outer``), which may read it: control_quadrupeds_soft_contacts'
        ``generate_launch_description`` sets ``global terrain`` and then calls the
        helpers that read it."""
        if "__closure__" not in env:
            return  # at module level: the names are the module's already
        outer: dict[str, dict[str, Any]] = env.setdefault(OUTER, {})
        for name in stmt.names:
            scope = _scope_of(name, env["__closure__"], isinstance(stmt, ast.Global))
            if scope is None:
                self.unsupported(stmt, f"nonlocal {name}: no enclosing function binds it")
                continue
            outer[name] = scope
            if name in scope:
                env[name] = scope[name]

    def assign(self, target: ast.expr, value: Any, env: dict[str, Any]) -> None:
        if isinstance(target, ast.Name):
            env[target.id] = value
        elif isinstance(target, (ast.Tuple, ast.List)):
            items = list(value) if isinstance(value, (list, tuple)) else None
            if items is None or len(items) != len(target.elts):
                # each name of the target takes what is not known of the value, said
                # where it is used as what it is (autoware's vehicle_info.launch.py:
                # ``for (k, v) in vehicle_param.items()`` of a file not read)
                unknown = value if isinstance(value, Unknown) else Unknown(
                    f"unpacking {_source(target)} from a value not known statically")
                items = [unknown] * len(target.elts)
            for sub, item in zip(target.elts, items, strict=False):
                self.assign(sub, item, env)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, env)
            key = self.eval(target.slice, env)
            if isinstance(container, dict) and not isinstance(key, (list, dict)):
                if isinstance(key, Unknown):
                    # kept under its unknown key (unknown is not empty): a loop over the
                    # dict runs for it, a lookup of a key not among the known ones is not
                    # known (``open_keys``); vrx_gz's ``payload[sensor.name()] = ...``
                    self.unsupported(target, f"{_source(target)} = ...: an item under a "
                                             f"key not known statically; "
                                             f"{_source(target.value)} holds more than "
                                             "its known items")
                container[key] = value
                self.sized(container)
            elif isinstance(container, list) and isinstance(key, int) and (
                    -len(container) <= key < len(container)):
                container[key] = value
            elif isinstance(container, _Environ):
                self.set_environment(target, key, value)
            elif isinstance(container, Context) and isinstance(target.value, ast.Attribute):
                # ``context.launch_configurations[key] = value`` in an OpaqueFunction (UR's
                # ur_control.launch.py: the update rate read from a file, for the
                # ``$(var update_rate)`` of a parameter file)
                if isinstance(key, str):
                    container.assigned[key] = value
                else:
                    self.unsupported(target, f"{_source(target)} = ...: a launch "
                                             "configuration whose name is not known "
                                             "statically")
        elif isinstance(target, ast.Attribute) and isinstance(
                owner := self.eval(target.value, env), (Constructing, Instance)):
            owner.attributes[target.attr] = value  # self.name = ... in a constructor
        elif isinstance(target, ast.Attribute) and isinstance(owner, PlainClass):
            owner.attributes[target.attr] = value  # Cls.count = ... (a class's name)
        elif isinstance(target, ast.Attribute) and isinstance(owner, Record) and (
                target.attr in owner.attributes):
            # moveit_config.robot_description = {...}: a field of its (slotted) dataclass
            owner.attributes[target.attr] = value
        elif isinstance(target, ast.Attribute) and isinstance(owner, Unknown) and (
                owner.kind == "unsupported"):
            # a field of an object made by a construct said not interpreted where it was
            # made: it stays unknown, said there once (crane_x7's launch files set five
            # fields of a RobotDescriptionLoader of a package not in the workspace, each
            # said again)
            pass
        else:
            self.unsupported(target, "assignment to this target is not interpreted")

    def delete(self, target: ast.expr, env: dict[str, Any]) -> None:
        """``del TARGET`` as Python runs it: a name is unbound in its scope (a
        function's local, or the module's or enclosing function's one it declared
        ``global`` / ``nonlocal``); an attribute set on an object or a class of the
        file is removed; ``del os.environ[key]`` removes the variable from the launch
        process's environment (``unset_environment``); ``del d[key]`` the item of a dict
        whose keys are known, ``del items[i]`` (``items[i:j]``) the item (the slice) of
        a list; a tuple or list of targets each in turn. Where Python raises (a name
        bound nowhere in the file, a missing key, an index out of range), the error
        goes to the ``try`` that catches it (``failed``). Anything else is said not
        interpreted."""
        if isinstance(target, (ast.Tuple, ast.List)):
            for each in target.elts:
                self.delete(each, env)
            return
        if isinstance(target, ast.Name):
            self.delete_name(target, env)
            return
        if isinstance(target, ast.Attribute):
            owner = self.eval(target.value, env)
            place = owner.attributes if isinstance(
                owner, (Instance, PlainClass, Constructing)) else None
            if place is not None and target.attr in place:
                del place[target.attr]
                return
            if isinstance(owner, PlainClass) and target.attr in owner.methods:
                del owner.methods[target.attr]
                return
            self.unsupported(target, f"del {_source(target)} is not interpreted")
            return
        if isinstance(target, ast.Subscript):
            container = self.eval(target.value, env)
            key = self.eval(target.slice, env)
            if isinstance(container, _Environ):
                self.unset_environment(target, key)
                return
            if isinstance(container, dict) and isinstance(key, (str, int, float, bool)):
                if key in container:
                    del container[key]
                    return
                if not open_keys(container):  # Python raises here: launch stops
                    self.failed(target, f"del {_source(target)} fails: no such key",
                                "KeyError")
                    return
            if isinstance(container, list) and (isinstance(key, slice) or (
                    isinstance(key, int) and not isinstance(key, bool))):
                try:
                    del container[key]
                except (IndexError, ValueError) as err:  # Python's own, as here
                    self.failed(target, f"del {_source(target)} fails: {err}",
                                f"{type(err).__name__}: {err}")
                return
        self.unsupported(target, f"del {_source(target)} is not interpreted")

    def delete_name(self, target: ast.Name, env: dict[str, Any]) -> None:
        """``del name``: unbound in the scope Python takes it from, the function's own
        (a local: ``del`` makes it one for the whole function) or, declared ``global`` /
        ``nonlocal``, the scope it names (``outer_names``); at module level the
        module's; a read of it after, where no scope binds it again, is Python's
        NameError (``unbound_by_del``). A name bound nowhere in the file (but by
        ``del``), or unbound by a ``del`` before, is Python's NameError
        (UnboundLocalError for a function's local); one bound elsewhere that this
        reading has not bound here is said not known."""
        name = target.id
        scopes = [env]
        outer = env.get(OUTER, {}).get(name) if "__closure__" in env else None
        if outer is not None:
            scopes.append(outer)
        found = [scope for scope in scopes if name in scope]
        if found:
            for scope in found:
                del scope[name]
                self.deleted.setdefault(id(scope), (scope, set()))[1].add(name)
            return
        bindings = self.bindings.get(self.path)
        if (bindings is not None and name not in bindings) or any(
                name in self.deleted_in(scope) for scope in scopes):
            local = "__closure__" in env and outer is None
            error = "UnboundLocalError" if local else "NameError"
            self.failed(target, f"del {name} fails: {name} is not bound here: Python "
                                f"raises {error} here", error)
            return
        self.unsupported(target, f"del {name}: name {name} is not defined here")

    def unset_environment(self, target: ast.AST, key: Any) -> None:
        """``del os.environ[key]`` / ``os.environ.pop(key)``: the variable is not set in
        the launch process's environment from here on (reads of it find it absent); under
        a test not known statically, reads of it after are not known (as for
        ``set_environment``). What launch substitutes later (``EnvironmentVariable``)
        takes it as not known, not as the configuration's value. A name not known is said
        and not applied."""
        if not isinstance(key, str):
            self.unsupported(target, f"{_source(target)}: removes an environment variable "
                                     "whose name is not known statically")
            return
        if isinstance(self.environment, _Overlay):
            self.environment.own.pop(key, None)
        if self.guards:
            self.environment_removed.discard(key)
            self.environment_unsure.add(key)
            return
        self.environment_removed.add(key)
        self.environment_unsure.discard(key)

    def set_environment(self, target: ast.expr, key: Any, value: Any) -> None:
        """``os.environ[key] = value``: the launch process's environment from here on, as
        ``os.environ.get`` / ``os.getenv`` read it after (rslidar_sdk's
        humble_start.py sets RMW_IMPLEMENTATION, then prints it); the configuration's
        own environment is left as it is. Under a test not known statically, reads of it
        after are not known. So are they after a value not known statically
        (ardupilot_ros's ``os.environ["SDF_PATH"] = sdf_path + ":" + gz_sim_resource_path``,
        from variables the configuration does not set): the variable is then set, to a
        value not known. A name not known is said and not applied."""
        if not isinstance(key, str) or not isinstance(value, (str, Unknown, Lazy)):
            self.unsupported(target, f"{_source(target)} = ...: an environment variable "
                                     "whose name or value is not known statically")
            return
        self.environment_removed.discard(key)
        if self.guards or not isinstance(value, str):
            if isinstance(self.environment, _Overlay):
                self.environment.own.pop(key, None)
            self.environment_unsure.add(key)
            return
        if not isinstance(self.environment, _Overlay):
            self.environment = _Overlay(self.environment)
        self.environment.own[key] = value
        self.environment_unsure.discard(key)

    def try_(self, stmt: ast.Try, env: dict[str, Any]) -> None:
        """``try``: its body, then ``else`` and ``finally``. A builtin exception the body
        raises (``failed``) that one of its handlers names goes to that handler, as in
        Python (``try: return int(value) except ValueError: pass``, OrbbecSDK_ROS2's
        convert_value); a handler of a class not known (``json.JSONDecodeError``) is
        not taken, and the failure is said as before."""
        self.catching.append(([_handler_classes(h) for h in stmt.handlers], len(self.guards)))
        self.missing_caught.append(any(catches_missing_package(h) for h in stmt.handlers))
        try:
            try:
                self.block(stmt.body, env)
            finally:
                self.catching.pop()
                self.missing_caught.pop()
        except Raised as raised:
            handler = next((h for h in stmt.handlers
                            if _catches(_handler_classes(h), raised.name)), None)
            if handler is None:
                self.block(stmt.finalbody, env)
                raise
            if handler.name:
                env[handler.name] = Unknown(f"the {raised.name} caught")
            self.block(handler.body, env)
        else:
            self.block(stmt.orelse, env)
        self.block(stmt.finalbody, env)

    def failed(self, node: ast.AST | None, detail: str, reason: str) -> Unknown:
        """A Python error of the interpreted code (``reason``: "ValueError: ..."): raised
        to the ``try`` around it whose handler catches it (no test not known in
        between), else said and unknown (``unsupported``). Under a test not known, the
        values that fail may be those the test rules out (zed_multi_camera's
        ``serials_arr[cam_idx]`` of an empty list, run only where the list has one item
        per camera): said so, not as an error the code makes."""
        name = reason.partition(":")[0].strip()
        if name in _EXCEPTIONS and any(
                guards == len(self.guards) and any(_catches(c, name) for c in handlers)
                for handlers, guards in self.catching):
            raise Raised(name)
        if self.guards:
            detail = (f"{detail}, with the values known here; it runs under "
                      f"{self.guards[-1]}, a test not known statically, which may rule "
                      "them out")
        return self.unsupported(node, detail)

    def if_(self, stmt: ast.If, env: dict[str, Any]) -> None:
        self.decided.pop(id(stmt.test), None)  # said for this run of it only
        said = len(self.diagnostics)
        value, test = self.test_of(stmt.test, env)
        # a test not known only through a value said not known where it was made (an
        # environment variable not set, a call not run): what its branches set, where
        # they differ, is unknown for that cause, said no more
        said_test = test is None and derived_unknown("test", [value], None) is not None
        if test is None and len(self.diagnostics) == said and not said_test:
            # a test not known whose value said nothing of why where it was made (an
            # environment variable not set, a call not run: said there) is said once,
            # at the test, if it guards an action (``guarding``); one unknown only
            # through environment variables not set was said where they were read, and
            # one computed from a value said not known, where that was made
            self.tests_unsaid.setdefault(id(stmt.test), diag.make(
                "LAUNCH_UNSUPPORTED", self.where(stmt.test),
                detail=f"Python test {_source(stmt.test)}"))
        if launch_object(value) or id(stmt.test) in self.decided:
            # ``if LaunchConfigurationEquals(...):`` never tests it, nor does
            # ``if LaunchConfiguration('sim') == 'true':`` (always false) or ``not`` of one
            code = "LAUNCH_PY_ALWAYS_TRUE" if test else "LAUNCH_PY_ALWAYS_FALSE"
            self.diagnostics.append(diag.make(code, self.where(stmt.test),
                                              test=_source(stmt.test)))
        if test is True:
            self.block(stmt.body, env)
        elif test is False:
            self.block(stmt.orelse, env)
        else:
            text = _source(stmt.test)
            # each branch from the names as they are before the ``if``, and the items of
            # the dicts they hold; after it, a name (an item) is what the branch that
            # goes on set (the other returns), else either's
            before = dict(env)
            held = [(d, dict(d)) for d in self.dicts_held(env)]
            taken, body_only = self.branch(stmt.body, env, text, id(stmt.test))
            after_body = dict(env)
            body_items = [dict(d) for d, _ in held]
            for d, items in held:
                _refill(d, items)
            env.clear()
            env.update(before)
            left, else_only = self.branch(stmt.orelse, env, f"not ({text})", id(stmt.test))
            if taken is not None and left is not None:  # both end: so does the if
                ends = [r for r in (taken, left) if isinstance(r, _Return)]
                if len(ends) == 2:
                    raise _Return(self.either([end.value for end in ends],
                                              said=said_test))
                raise ends[0] if ends else taken
            if left is not None:
                env.clear()
                env.update(after_body)
                for (d, _), items in zip(held, body_items, strict=True):
                    _refill(d, items)
            elif taken is None:
                self.join(env, after_body, said_test)
                for (d, _), items in zip(held, body_items, strict=True):
                    self.join_items(d, items, text, said_test)
            returned = taken or left
            if returned is not None:
                # one branch returns (or stops): that value is one the function may
                # give, and the rest of the function runs only under the other branch's
                # test, and the tests that branch goes on under (a return in it)
                if isinstance(returned, _Return):
                    if not self.returns:
                        raise returned
                    self.returns[-1].append(returned.value)
                self.guards.append(self.guard(text if taken is None else f"not ({text})",
                                              id(stmt.test)))
                self.guards.extend(body_only if taken is None else else_only)
            elif body_only or else_only:
                # both go on, one (both) only under tests of its own (a return in it):
                # the rest runs where that branch's test and those hold, or the other's
                self.guards.append(self.guard(_either_goes_on(text, body_only, else_only)))

    def guarding(self) -> None:
        for guard in self.guards:
            found = self.tests_unsaid.pop(guard.test, None) if guard.test is not None \
                else None
            if found is not None and found not in self.diagnostics:
                self.diagnostics.append(found)

    def test_of(self, node: ast.expr, env: dict[str, Any]) -> tuple[Any, bool | None]:
        """The value of an ``if``'s test and its truth (None: not known). An ``and``
        (``or``) with an operand not known still goes on to the operands after it, each
        under that operand's test, as Python runs them only when it holds: one of them
        false (true) makes the whole false (true) whatever the unknown was (spot_ros2's
        ``if not username and _USERNAME in ros_params:`` with ``ros_params`` empty and
        the environment variable not known ran its body, a lookup that fails)."""
        if not isinstance(node, ast.BoolOp):
            value = self.eval(node, env)
            return value, self.truth(value)
        is_and = isinstance(node.op, ast.And)
        unknown: Any = None
        depth = len(self.guards)
        try:
            for operand in node.values:
                value, truth = self.test_of(operand, env)
                if truth is None:
                    unknown = value if unknown is None else unknown
                    text = _source(operand)
                    self.guards.append(self.guard(text if is_and else f"not ({text})"))
                elif truth != is_and:  # short-circuits: decided whatever came before
                    return value, truth
        finally:
            del self.guards[depth:]
        if unknown is None:
            return value, truth
        return (unknown if isinstance(unknown, Unknown)
                else Unknown(f"boolean {_source(node)}")), None

    def join(self, env: dict[str, Any], other: dict[str, Any], said: bool = False) -> None:
        """The names after an ``if`` whose test is not known, both branches having run
        on: ``env`` as the else branch left it, ``other`` as the body left it. A name one
        branch alone binds is that branch's (the other would fail on it); one both bind
        is ``either`` of the two values: the same value, the actions of both (each made
        under its branch's test), else a value not known (``said``: for a cause said
        where the test's value was made, as Eurobot-2026-Main's ``if ros_domain_id ==
        '11':`` over ``os.getenv('ROS_DOMAIN_ID')`` not set)."""
        for name, value in other.items():
            if name not in env:
                env[name] = value
            elif env[name] is value:
                continue
            elif isinstance(value, (Func, Module)) or isinstance(env[name], (Func, Module)):
                env[name] = Unknown(f"{name}, defined in both branches of a test not known "
                                    "statically")
            else:
                env[name] = self.either([value, env[name]], f"{name}, set in both branches",
                                        said)

    def dicts_held(self, env: dict[str, Any]) -> list[dict[Any, Any]]:
        """The dicts the names of ``env`` and of the module hold, and those inside them
        (lists, tuples, objects' attributes, and the attributes themselves), each once:
        what a branch of an ``if`` may change in place (``d[key] = ...``,
        ``d.update(...)``, ``obj.name = ...``), bounded."""
        found: dict[int, dict[Any, Any]] = {}
        stack = [v for scope in (env, self.globals) for name, v in scope.items()
                 if not name.startswith("__")]
        seen: set[int] = set()
        while stack and len(seen) < _MAX_HELD:
            value = stack.pop()
            if id(value) in seen:
                continue
            seen.add(id(value))
            if isinstance(value, dict):
                found[id(value)] = value
                stack.extend(value.values())
            elif isinstance(value, (list, tuple)):
                stack.extend(value)
            elif isinstance(value, (Instance, Constructing, Record)):
                stack.append(value.attributes)  # ``obj.name = ...`` changes it in place
        return list(found.values())

    def join_items(self, held: dict[Any, Any], body: dict[Any, Any], test: str,
                   said: bool = False) -> None:
        """The items of a dict after ``if test:`` whose test is not known, both branches
        having run on: ``held`` as the else branch left it, ``body`` as the body left it.
        An item both hold is ``either`` of the two values (``join``); one that a branch
        alone set may be missing: its value is not known, unless it is an action (or a
        composable node's description), which carries that branch's test already
        (spot_ros2's ``if controllable: params.update({'leasing_mode': 'proxied'})``
        set the parameter whatever ``controllable`` was)."""
        items: dict[Any, Any] = {}
        for key in [*body, *(k for k in held if k not in body)]:
            if key in body and key in held:
                value = body[key] if body[key] is held[key] else self.either(
                    [body[key], held[key]], f"the item {key!r}, set in both branches of "
                                            f"`if {test}`", said)
            else:
                value = body[key] if key in body else held[key]
                if not isinstance(value, (e.Action, e.ComposableNode)):
                    value = Unknown(f"the item {key!r}, set in one branch of `if {test}`"
                                    " (a test not known statically)")
            items[key] = value
        _refill(held, items)

    def branch(self, body: list[ast.stmt], env: dict[str, Any], guard: str,
               test: int | None = None) -> tuple[_Return | _Stop | None, list[Guard]]:
        """One branch of an ``if`` whose test is not known, under that test (``test``:
        its node, by id): its ``return`` (or stop), if it ends so, else the tests of
        its own its end runs under (an ``if`` in it of which a branch returns), which
        do not hold beyond it."""
        depth = len(self.guards)
        self.guards.append(self.guard(guard, test))
        try:
            self.block(body, env)
        except (_Return, _Stop) as ended:
            return ended, []
        finally:
            goes_on = self.guards[depth + 1:]
            del self.guards[depth:]
        return None, goes_on

    def either(self, values: list[Any], what: str = "one of several return values",
               said: bool = False) -> Any:
        """What a function gives that returns one of ``values``, or a name an ``if``
        set to one of them (a test not known statically decides): the actions (or
        composable nodes' descriptions) of all when they are such (each made under its
        branch's test), the value when they agree, a value not known when one is not,
        dicts of the same keys and lists of the same length item by item, texts known
        where they agree (``_common_text``), else an unknown (``what``); ``said``: the
        test that chose is not known for a cause said where it was made, and so is the
        value (kind ``unsupported``), said no more."""
        if all(v is None or isinstance(v, (e.Action, e.ComposableNode, list, tuple,
                                           LaunchDescription))
               for v in values) and any(v is not None for v in values):
            actions: list[Any] = []
            seen: set[int] = set()  # an action in several outcomes (one ld returned
            stack = list(reversed(values))  # from two places, shared lists) runs once
            while stack:
                value = stack.pop()
                if isinstance(value, (LaunchDescription, list, tuple)):
                    items = value.actions if isinstance(value, LaunchDescription) else value
                    stack.extend(reversed(items))
                elif value is not None and id(value) not in seen:
                    seen.add(id(value))
                    actions.append(value)
            if all(isinstance(a, (e.Action, Unknown)) for a in actions):
                if all(v is None or isinstance(v, (list, tuple)) for v in values):
                    return actions  # lists of actions stay a list (``helper() + [...]``)
                return LaunchDescription(actions)
            if actions and all(isinstance(a, e.ComposableNode) for a in actions):
                return actions  # descriptions, each under its test: a list of them
            # lists of plain values (names, arguments): one of them, not all at once
        first = values[0]
        if all(type(v) is type(first) and v == first for v in values):
            return first
        unknown = next((v for v in values if isinstance(v, Unknown)), None)
        if unknown is not None:
            return unknown  # not known either way: why one of them is not
        if all(isinstance(v, dict) and v.keys() == first.keys() for v in values):
            # the same keys (parameters): each value on its own, the rest stays known
            return {key: self.either([v[key] for v in values], f"{what}[{key!r}]", said)
                    for key in first}
        if all(isinstance(v, list) and len(v) == len(first) for v in values):
            return [self.either([v[n] for v in values], f"{what}[{n}]", said)
                    for n in range(len(first))]
        made_said = [said_unknown(what, [v]) for v in values]
        if all(made is not None for made in made_said):
            # each not known for a cause said where it was made: said no more
            return made_said[0]
        reason = f"{what} (a test not known statically)"
        if said:
            return _common_text(values, reason, report=False) or Unknown(reason,
                                                                         "unsupported")
        return _common_text(values, reason) or Unknown(reason)

    def with_(self, stmt: ast.With, env: dict[str, Any]) -> None:
        """``with open(path) as f:``: a read-only handle on a file we may read."""
        for item in stmt.items:
            value = self.eval(item.context_expr, env)
            if not isinstance(value, ReadOnlyFile):
                # said once: the call that made the value (an open() of a file not
                # read: nav2's tb3_simulation_launch.py) or else the statement; what the
                # body sets is unknown, made here, and said no more where it is used
                made = value if isinstance(value, Unknown) and value.kind == "unsupported" \
                    else self.unsupported(stmt, "with statements other than open() are "
                                                "not interpreted")
                for name in _assigned(stmt.body):
                    env[name] = Unknown(f"{name} set in a with statement not interpreted",
                                        "unsupported", where=made.where)
                self.with_returns(stmt.body, made)
                return
            if item.optional_vars is not None:
                self.assign(item.optional_vars, value, env)
        self.block(stmt.body, env)

    def with_returns(self, body: list[ast.stmt], made: Unknown) -> None:
        """A ``with`` body not run that returns: the function returns a value not known
        there (a ``return`` of the body itself), or may (one under a test or a loop of
        it), not ``None`` by running past it (spot_ros2's ``with NamedTemporaryFile(...)
        as out: ...; return out.name``: the rviz config file was ``None``)."""
        unknown = Unknown("the value a with statement not interpreted returns",
                          "unsupported", where=made.where)
        if any(isinstance(stmt, ast.Return) for stmt in body):
            raise _Return(unknown)
        if self.returns and _returns(body):
            self.returns[-1].append(unknown)

    def read(self, path: Any, node: ast.AST) -> str | None:
        """The text of a file of the workspace or an installed package (bounded). One
        not known (not there, outside the workspace, its path not known) is said here,
        LAUNCH_PY_FILE_UNKNOWN: a file's content is data and reads no launch
        configuration by itself (what the code then does with it, a configuration named
        by it or an include of a path in it, says so where it happens), so the arguments
        an include passes are judged on the rest (husky's accessories launch passes
        ``baud`` to microstrain's launch file, whose default parameters file sits in a
        submodule not checked out)."""
        from ...files import read_text
        from ...share import share_source

        if not isinstance(path, str):
            self.unsupported(node, "a file whose path is not known statically", FILE_UNKNOWN)
            return None
        full = os.path.realpath(share_source(self.workspace, path))
        if not self.workspace.readable(full, self.environment):
            self.unsupported(node, f"{path} is outside the workspace; not read", FILE_UNKNOWN)
            return None
        if not os.path.lexists(full):
            # said where it is read, not at a file that is not there: a build step or
            # the launch code itself may make it (vrx_gz's spawn reads the model.urdf its
            # Model.generate wrote), so its content is unknown, as a parameter file's
            self.unsupported(node, f"{self.workspace.relpath(full)} does not exist in the "
                                   "workspace (a build or launch step may make it); its "
                                   "content is not known", FILE_UNKNOWN)
            return None
        text, found = read_text(full, self.workspace.location(full), MAX_READ)
        self.diagnostics.extend(found)
        return text

    def for_(self, stmt: ast.For, env: dict[str, Any]) -> None:
        items = self.iterable(self.eval(stmt.iter, env), stmt.iter)
        if items is None:
            # the loop may run any number of times: its body once, on an item not
            # known, under that loop (what it makes may run, named '?' where it is
            # named after the item), rather than never
            # (said where the value was made, or by ``iterable``: its uses say no more)
            self.assign(stmt.target, Unknown(f"an item of {_source(stmt.iter)}",
                                             "unsupported", where=self.where(stmt.iter)),
                        env)
            try:
                returned, _ = self.branch(stmt.body, env, f"for {_source(stmt.target)} in "
                                                          f"{_source(stmt.iter)}")
            except (_Break, _Continue):
                returned = None
            if isinstance(returned, _Return):  # it may return there, or run on
                if not self.returns:
                    raise returned
                self.returns[-1].append(returned.value)
            return
        for item in items:
            self.step()
            self.assign(stmt.target, item, env)
            if not self._turn(stmt.body, env):
                return
        self.block(stmt.orelse, env)

    def _turn(self, body: list[ast.stmt], env: dict[str, Any]) -> bool:
        """One turn of a loop's body: False when a ``break`` left the loop (its
        ``else`` does not run), True when the turn ended or a ``continue`` ended it."""
        try:
            self.block(body, env)
        except _Break:
            return False
        except _Continue:
            pass
        return True

    def while_(self, stmt: ast.While, env: dict[str, Any]) -> None:
        """``while TEST:``, its test known each time it is checked: the body runs while
        it holds (each turn a step of the evaluation's budget, as every loop), then the
        ``else`` unless a ``break`` left it (lexus_bringup's ``while len(pose) < 6:
        pose.append('0.0')``; tmr_ros2's copy of ``sys.argv[4:]``). A test not known
        (at the first check or a later one) is said, and the loop is left there; so is
        a loop still running after ``MAX_WHILE_TURNS`` turns (``while True:`` waiting
        for what only the running system gives), the rest of the file read on."""
        for turn in range(MAX_WHILE_TURNS + 1):
            if turn == MAX_WHILE_TURNS:
                self.unsupported(stmt, f"while loops that run more than {MAX_WHILE_TURNS} "
                                       "turns are not interpreted")
                return
            self.step()
            _, test = self.test_of(stmt.test, env)
            if test is None:
                self.unsupported(stmt, "a while loop whose test is not known statically is "
                                       "not interpreted")
                return
            if not test:
                break
            if not self._turn(stmt.body, env):
                return
        self.block(stmt.orelse, env)

    def iterable(self, value: Any, node: ast.AST) -> list[Any] | None:
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, (list, tuple, str)):
            return list(value)
        if isinstance(value, PlainClass) and value.enum:
            return _enum_members(value)  # for mode in Mode: (spot_ros2's choices)
        unset = env_unset((value,))
        if unset:
            # unknown only through environment variables the configuration does not set
            # (said, an info, where they were read): what that does to the loop is said
            # as an info too, not as a construct not interpreted (a swarm's
            # ``range(int(os.environ['NUM_DRONES']))``); the configuration can set them
            found = diag.make("LAUNCH_UNKNOWN_VALUE", self.where(node), detail=(
                f"loop over {_source(node)}, not known statically ({', '.join(unset)} "
                "not set): its body is read once, for an item not known"))
            if found not in self.diagnostics:
                self.diagnostics.append(found)
        elif not (isinstance(value, Unknown) and value.kind == "unsupported"):
            # one that a construct not interpreted made was said where it was made
            self.unsupported(node, "loop over a value that is not known statically")
        return None

    # -- functions -----------------------------------------------------------------------
    def call(self, func: Any, args: list[Any], kwargs: dict[str, Any], node: ast.AST) -> Any:
        if isinstance(func, Func):
            return self.call_function(func, args, kwargs, node)
        if isinstance(func, ActionClass):
            return self.construct(func, args, kwargs, node)
        if isinstance(func, PlainClass):
            return self.instantiate(func, args, kwargs, node)
        if isinstance(func, SubstitutionClass):
            return self.user_substitution(func, args, kwargs, node)
        if isinstance(func, Method):
            return self.call_function(func.func, [func.owner, *args], kwargs, node)
        if isinstance(func, SuperOf):  # super(), or super(Class, self)
            return func
        if isinstance(func, _Bound) and isinstance(func.owner, SuperOf) \
                and func.attr == "__init__":
            func.owner.instance.built = self.construct_base(
                func.owner.instance.cls.base, args, kwargs, node)
            return None
        if args and isinstance(args[0], Constructing) and (  # Base.__init__(self, ...)
                (isinstance(func, Ref) and func.qualified.endswith(".__init__"))
                or (isinstance(func, _Bound) and isinstance(func.owner, ActionClass)
                    and func.attr == "__init__")):
            base = func.owner if isinstance(func, _Bound) else Ref(
                func.qualified.removesuffix(".__init__"))
            args[0].built = self.construct_base(base, args[1:], kwargs, node)
            return None
        if isinstance(func, Ref):
            if func.qualified in ("sys.path.append", "sys.path.insert"):
                return self.add_search(func, args, node)
            if func.qualified in _EXITS:
                return self.stop(node, "SystemExit")
            name = func.qualified
            short = name.rsplit(".", 1)[-1]
            if name == f"math.{short}" and callable(ops.MATH.get(short)) and not kwargs \
                    and all(isinstance(a, int | float) and not isinstance(a, bool)
                            for a in args):  # math.sin(x) of numbers known statically
                return self.operation(
                    lambda: ops.call_builtin(ops.MATH[short], args, None, LIMITS), node)
            if name.split(".", 1)[0] == "logging":
                # Python's logging writes messages, nothing launch reads: a logger, a
                # configuration, a message (OrbbecSDK_ROS2's ``logger =
                # logging.getLogger(__name__)``, then ``logger.info(...)``)
                return Ref("logging.Logger") if short == "getLogger" else None
            handler = self.api.get(name) or self.api.get(short)  # xacro.parse: by module
            if handler is not None and (_known_module(name) or short in self.builtins):
                self.charge_arguments([*args, *kwargs.values()])
                # ``os.path.expanduser`` of a path read from a file outside the workspace
                return _said_through(handler(self, args, kwargs, node), f"{short}()",
                                     [*args, *kwargs.values()])
            at = _WRITERS.get(name)
            if at is not None and len(args) > at and isinstance(args[at], str) \
                    and args[at].startswith("/"):
                # a file the launch makes as it runs (``open(path, 'w')`` alike): the
                # processed URDF QUTMS_Driverless's launch file hands a node
                self.made_paths.append(args[at])
            return self.unsupported(node, f"call to {name} is not interpreted (never run)")
        if isinstance(func, _Bound):
            self.charge_arguments([func.owner, *args, *kwargs.values()])
            # ``os.popen(cmd).read().split()``: a method of a value said not known
            return _said_through(func.call(self, args, kwargs, node), f".{func.attr}()",
                                 [func.owner, *args, *kwargs.values()])
        if isinstance(func, Unknown) and func.origin.startswith("class "):
            return self.unsupported(node, f"call to {func.origin}")
        callee = _source(node.func) if isinstance(node, ast.Call) else "?"
        if func is None or isinstance(func, (str, bytes, int, float, tuple, list, dict)):
            # a value known statically that Python does not call: ``('a', 'b') ('c',
            # 'd')``, a comma missing between two remappings, is a TypeError when
            # generate_launch_description runs, not a value unknown
            reason = f"TypeError: '{type(func).__name__}' object is not callable"
            return self.failed(node, f"call to {callee} fails: {reason}", reason)
        if isinstance(func, Unknown) and func.kind == "unsupported":
            # what it calls was said where it was made (``eval`` not defined, a call
            # not interpreted); its result is as unknown, and said no more
            return Unknown(f"call to {callee}", "unsupported", where=func.where)
        return self.unsupported(node, f"call to {callee}, a value not known statically, "
                                      "is not interpreted")

    def user_substitution(self, cls: SubstitutionClass, args: list[Any],
                          kwargs: dict[str, Any], node: ast.AST) -> Any:
        """An object of a substitution class the file defines: its ``perform`` is not
        interpreted (said here), so its value is unknown, but the substitutions given to
        its constructor are performed where it is (``e.Performed``): a launch
        configuration among them that is not set there is said, as launch raises."""
        said = self.unsupported(node, f"call to class {cls.name} (not interpreted)")
        reads: list[e.Text] = []
        for value in [*args, *kwargs.values()]:
            if isinstance(value, (Lazy, e.Subst, list, tuple)):
                text = to_text(value)
                if any(isinstance(part, e.Subst) for part in text):
                    reads.append(text)
        return Lazy((e.Performed(said.origin, tuple(reads)),))

    def charge_arguments(self, values: list[Any]) -> None:
        """What a builder, builtin or method will walk: containers by their nested size,
        shared parts each time (``[[[1] * 300] * 300] * 300`` is 27 million items)."""
        for value in values:
            if isinstance(value, (list, tuple, dict)):
                self.step(ops.walk_cost(value, LIMITS))

    def call_function(self, func: Func, args: list[Any], kwargs: dict[str, Any],
                      node: ast.AST) -> Any:
        given = [*args, *kwargs.values()]
        unknown = [isinstance(v, Unknown) for v in given]
        if func.node in self.running and given and (all(unknown) or (
                any(unknown) and self.running.count(func.node) >= _RECURSION_UNKNOWN)):
            # a function that runs calls itself on values none of which is known (a
            # walk of a YAML file not read, zed_wrapper's), or some of which are not,
            # nested a few times (OrbbecSDK_ROS2's parse_yaml(value, prefix, params) of
            # a YAML file not read, with params a dict): interpreted, each call would
            # recurse on another unknown until the depth bound stops the file; its
            # value is unknown instead
            name = getattr(func.node, "name", "lambda")
            return self.unsupported(node, f"recursive call of {name} on values not known "
                                          "statically")
        wrong = _unexpected_keywords(func.node.args, kwargs)
        if wrong:
            # Python binds no keyword the function does not name unless it takes
            # ``**kwargs``: the call raises TypeError and its body does not run
            # (interbotix 47c468e's xsarm_dual.launch.py gave the helper of
            # interbotix_xs_modules robot_description_launch_configuration_name=, which
            # it names robot_description_launch_config_name)
            name = getattr(func.node, "name", "<lambda>")
            reason = (f"TypeError: {name}() got an unexpected keyword argument "
                      f"'{wrong[0]}'")
            return self.failed(node, f"call to {name} fails: {reason}", reason)
        self.depth += 1
        if self.depth > MAX_CALL_DEPTH:
            self.depth = 0
            raise Budget(f"calls nested deeper than {MAX_CALL_DEPTH}")
        self.running.append(func.node)
        outer = self.path
        written = len(node.args) if isinstance(node, ast.Call) else len(args)
        self.call_sites.append((node, func, outer, len(args) - written))
        self.path = _file_of(func.closure, outer)  # a function of an imported module
        env: dict[str, Any] = {}
        try:
            env = dict(func.closure) if isinstance(func.node, ast.Lambda) else {}
            env["__closure__"] = func.closure
            params = func.node.args
            positional = [a.arg for a in params.posonlyargs + params.args]
            defaults = params.defaults
            for index, name in enumerate(positional):
                if index < len(args):
                    env[name] = args[index]
                elif name in kwargs:
                    env[name] = kwargs[name]
                else:
                    back = index - (len(positional) - len(defaults))
                    env[name] = (self.eval(defaults[back], func.closure) if back >= 0
                                 else Unknown(f"argument {name}"))
            for arg, default in zip(params.kwonlyargs, params.kw_defaults, strict=False):
                env[arg.arg] = kwargs.get(arg.arg, Unknown(arg.arg) if default is None
                                          else self.eval(default, func.closure))
            if params.vararg:
                env[params.vararg.arg] = list(args[len(positional):])
            if params.kwarg:
                env[params.kwarg.arg] = {k: v for k, v in kwargs.items()
                                         if k not in positional}
            if isinstance(func.node, ast.Lambda):
                return self.eval(func.node.body, env)
            self.returns.append([])
            guards = len(self.guards)
            result: Any = None
            stopped = False
            try:
                self.block(func.node.body, env)
            except _Return as ret:
                result = ret.value
            except _Stop:
                # a raise (an exit) reached only where the function did not return
                # earlier, in a branch or a loop over items not known: that path ends
                # there, the function gives what it may return (perseus-v2's host
                # address read from ``ip addr`` line by line, then ``raise``)
                if not self.returns[-1]:
                    raise
                stopped = True
            finally:
                maybe = self.returns.pop()
                del self.guards[guards:]
            if stopped:
                return self.either(maybe)
            return self.either([*maybe, result]) if maybe else result
        finally:
            write_outer(env)
            self.depth = max(self.depth - 1, 0)
            self.running.pop()
            self.call_sites.pop()
            self.path = outer


def parse_python(text: str, path: str, workspace: Workspace,
                 environment: Mapping[str, str] | None = None,
                 uses: list[PackageUse] | None = None,
                 command_line: Mapping[str, str] | None = None,
                 written: dict[str, str] | None = None,
                 unsure: set[str] | None = None,
                 made: list[str] | None = None,
                 argv: list[Any] | None = None,
                 ) -> tuple[list[e.Action] | None, list[Diagnostic]]:
    """The actions of a Python launch file, and what could not be interpreted; the
    packages whose folders it asks for as it runs are added to ``uses``.
    ``command_line``: the ``name:=value`` arguments the launch was started with.
    ``written``: gets what the file writes in ``os.environ`` as it is loaded; ``unsure``:
    the variables written before under a test not known statically, which gets those
    this file so writes (and loses those it writes for sure). ``made``: gets the paths
    of the files it opens for writing. ``argv``: ``sys.argv``, the command line of
    ``ros2 launch`` (``Runner.argv``), None when not known."""
    where = workspace.location(path)
    tree, problem = checked_tree(text, path, workspace)
    if tree is None:
        return None, [problem] if problem is not None else []
    interp = Interpreter(path, workspace,
                         environment if environment is not None else workspace.environment)
    interp.command_line = command_line or {}
    interp.argv = argv
    if unsure:
        interp.environment_unsure |= unsure
    if uses is not None:
        # the caller's list itself: a function that runs only when launch performs its
        # action (an OpaqueFunction's, an event handler's) asks for packages after the
        # module was read (vrx 747cb183's spawn, whose Model.generate asks for
        # wamv_gazebo's share folder)
        interp.uses = uses
    if made is not None:
        interp.made_paths = made  # so too the files such a function writes
    actions = interp.bounded(where, lambda: interp.module(tree), None)
    if written is not None and isinstance(interp.environment, _Overlay):
        written.update(interp.environment.own)
    if unsure is not None:
        unsure.clear()
        unsure |= interp.environment_unsure | interp.environment_removed
    return actions, interp.diagnostics


def checked_tree(text: str, path: str, workspace: Workspace
                 ) -> tuple[ast.Module | None, Diagnostic | None]:
    """The syntax tree of a Python file within the size bounds, or why not."""
    found = _tree(path, text)
    if isinstance(found, ast.Module):
        return found, None
    code, line, column, detail = found
    where = workspace.location(path) if line is None else workspace.location(
        path, line, column or 0)
    return None, diag.make(code, where, detail=detail)


@functools.lru_cache(maxsize=64)
def _tree(path: str, text: str) -> ast.Module | tuple[str, int | None, int | None, str]:
    """``checked_tree`` of ``text`` without the workspace: the tree, or the diagnostic's
    code, line, column (None: the file's) and detail. Kept by path and text (the
    interpreter never changes a tree): a launch file included by many others is read
    once, not once per include."""
    if len(text) > MAX_SOURCE:
        return "LAUNCH_PY_BUDGET", None, None, f"file larger than {MAX_SOURCE} characters"
    try:
        tree = syntax.parse(text, path)
    except SyntaxError as err:
        return "LAUNCH_PY_SYNTAX", err.lineno or 0, err.offset or 0, err.msg
    except (RecursionError, MemoryError, ValueError) as err:
        return ("LAUNCH_PY_SYNTAX", None, None,
                f"too deeply nested to parse ({type(err).__name__})")
    count = 0
    stack: list[tuple[ast.AST, int]] = [(tree, 0)]
    while stack:
        node, depth = stack.pop()
        count += 1
        if count > MAX_NODES or depth > MAX_DEPTH:
            what = f"more than {MAX_NODES} syntax nodes" if count > MAX_NODES else \
                f"nesting deeper than {MAX_DEPTH}"
            return "LAUNCH_PY_BUDGET", None, None, what
        stack.extend((child, depth + 1) for child in ast.iter_child_nodes(node))
    return tree


def _enum_members(cls: PlainClass) -> list[EnumMember]:
    """An ``Enum``'s members in the order its body names them, as iterating it gives
    them: a name whose value an earlier member has is an alias of it, not one more."""
    members: list[EnumMember] = []
    for value in cls.attributes.values():
        if isinstance(value, EnumMember) and value.cls == cls.name and not any(
                m.value == value.value for m in members):
            members.append(value)
    return members


def _refill(held: dict[Any, Any], items: dict[Any, Any]) -> None:
    """``held``, the same dict, holding ``items`` now."""
    held.clear()
    held.update(items)


_MAX_HELD = 5000  # the values ``Interpreter.dicts_held`` looks through, at most


def _scope_of(name: str, closure: dict[str, Any] | None, module: bool
              ) -> dict[str, Any] | None:
    """The scope that binds ``name`` for ``global`` (``module``: the outermost of
    ``closure``'s chain) or ``nonlocal`` (the nearest enclosing function's that binds
    it); None when there is none."""
    scope = closure
    while scope is not None:
        if module and "__closure__" not in scope:
            return scope
        if not module and name in scope and "__closure__" in scope:
            return scope
        scope = scope.get("__closure__")
    return None


def _said_through(result: Any, what: str, values: list[Any]) -> Any:
    """A library function's or a method's result, said no more where it is used when it
    is not known because one of ``values`` (its arguments, the method's owner) was said
    not known where it was made (``said_unknown``)."""
    if isinstance(result, Unknown) and result.kind != "unsupported":
        return said_unknown(what, values) or result
    return result


def _unexpected_keywords(params: ast.arguments, kwargs: dict[str, Any]) -> list[str]:
    """The keywords of a call that the function's parameters do not take: none when it
    has ``**kwargs``; a positional-only parameter is no keyword (Python's TypeError)."""
    if params.kwarg is not None:
        return []
    names = {a.arg for a in (*params.args, *params.kwonlyargs)}
    return [word for word in kwargs if word not in names]


def _argument_written(site: ast.AST, func: Func, name: str, given: int) -> ast.AST | None:
    """The expression ``site`` (a call of ``func``) wrote for its parameter ``name``;
    None when not written there (a default, ``*args``, ``**kwargs``, a lambda's)."""
    if not isinstance(site, ast.Call) or not isinstance(func.node, ast.FunctionDef):
        return None
    params = func.node.args
    positional = [a.arg for a in params.posonlyargs + params.args]
    for keyword in site.keywords:
        if keyword.arg == name:
            return keyword.value
    if name not in positional or any(isinstance(a, ast.Starred) for a in site.args):
        return None
    index = positional.index(name) - given
    return site.args[index] if 0 <= index < len(site.args) else None


def _file_of(closure: dict[str, Any], default: str) -> str:
    """The file a function was written in: its module's ``__file__``, up its closures."""
    scope: dict[str, Any] | None = closure
    for _ in range(MAX_CALL_DEPTH + 2):
        if scope is None:
            break
        if "__closure__" not in scope:
            found = scope.get("__file__")
            return found if isinstance(found, str) else default
        scope = scope.get("__closure__")
    return default


def _assigned(body: list[ast.stmt]) -> set[str]:
    """The plain names a block assigns (its nested functions' locals excluded)."""
    names: set[str] = set()
    stack: list[ast.AST] = list(body)
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda,
                             ast.ClassDef)):
            if not isinstance(node, ast.Lambda):
                names.add(node.name)
            continue
        if isinstance(node, ast.comprehension):  # its variable is its own
            stack.extend([node.iter, *node.ifs])
            continue
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
        stack.extend(ast.iter_child_nodes(node))
    return names


def _returns(body: list[ast.stmt]) -> bool:
    """Whether a block has a ``return`` (its nested functions' and classes' excluded)."""
    stack: list[ast.AST] = list(body)
    while stack:
        node = stack.pop()
        if isinstance(node, ast.Return):
            return True
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda,
                                 ast.ClassDef, ast.expr)):
            stack.extend(ast.iter_child_nodes(node))
    return False


# how deep a function may call itself with some argument not known before the call's
# value is taken as unknown (a walk of a structure not known would go on to the bound,
# and one that takes both branches of an isinstance() test not known doubles per level)
_RECURSION_UNKNOWN = 3

# names whose use may bind any other name at run time (``names_bound``)
_DYNAMIC = frozenset(("exec", "eval", "globals", "locals", "vars", "setattr", "__dict__",
                      "__builtins__", "__import__", "importlib", "modules"))


def names_bound(tree: ast.Module) -> frozenset[str] | None:
    """Every name the file's code binds anywhere, in any scope (assignments,
    definitions, parameters, imports, handlers, ``with ... as``, ``global``, patterns),
    whether or not the interpreter runs that code; None when the file can bind names
    it does not write (``from m import *``, ``exec``, ``globals()``, ``setattr``, a
    module's ``__dict__``): a name outside the set is then not known to be unbound."""
    bound: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            if isinstance(node.ctx, ast.Store):  # (``del x`` binds nothing to read)
                bound.add(node.id)
            elif node.id in _DYNAMIC:
                return None
        elif isinstance(node, ast.Attribute) and node.attr in _DYNAMIC:
            return None
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            bound.add(node.name)
        elif isinstance(node, ast.arg):
            bound.add(node.arg)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name == "*":
                    return None
                bound.add(alias.asname or alias.name.split(".", 1)[0])
        elif isinstance(node, ast.ExceptHandler) and node.name:
            bound.add(node.name)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            bound.update(node.names)
        elif isinstance(node, (ast.MatchAs, ast.MatchStar)) and node.name:
            bound.add(node.name)
        elif isinstance(node, ast.MatchMapping) and node.rest:
            bound.add(node.rest)
    return frozenset(bound)


def _match_as_if(stmt: ast.Match) -> list[ast.stmt] | None:
    """A ``match`` whose cases test values only, as the ``if`` / ``elif`` / ``else``
    chain Python runs for it: ``case 'rl' | 'ftg':`` is ``subject == 'rl' or subject ==
    'ftg'`` (``is`` for ``None``, ``True``, ``False``), a guard joins its test with
    ``and``, ``case _:`` (or a bare name, bound to the subject) is the ``else``; the
    subject is evaluated once (autonomous_f1tenth's sim.launch.py chooses its tracking
    so). None for a case of another pattern (a class, sequence or mapping), not read."""
    subject: ast.expr = stmt.subject
    head: list[ast.stmt] = []
    if any(isinstance(n, (ast.Call, ast.NamedExpr, ast.Await, ast.Yield))
           for n in ast.walk(subject)):
        held = ast.Name(id=f"__match_subject_{stmt.lineno}", ctx=ast.Load())
        head.append(ast.copy_location(ast.Assign(
            targets=[ast.Name(id=held.id, ctx=ast.Store())], value=subject), subject))
        subject = held
    chain: list[ast.stmt] = []
    tail = chain
    for case in stmt.cases:
        test, binds = _pattern_test(case.pattern, subject)
        if test is False:
            return None
        body = list(case.body)
        if binds is not None:
            body.insert(0, ast.copy_location(ast.Assign(
                targets=[ast.Name(id=binds, ctx=ast.Store())], value=subject), case.pattern))
        if test is True and case.guard is None:
            tail.extend(body)  # irrefutable: the cases after it never run
            break
        parts = [t for t in (test, case.guard) if isinstance(t, ast.expr)]
        condition = parts[0] if len(parts) == 1 else ast.BoolOp(op=ast.And(), values=parts)
        branch = ast.copy_location(ast.If(test=condition, body=body, orelse=[]),
                                   case.pattern)
        tail.append(branch)
        tail = branch.orelse
    return [ast.fix_missing_locations(node) for node in head + chain]


def _pattern_test(pattern: ast.pattern, subject: ast.expr
                  ) -> tuple[ast.expr | bool, str | None]:
    """The test of a value pattern on ``subject`` and the name it binds: True for a
    wildcard or capture (which always matches), False for a pattern not read here."""
    if isinstance(pattern, ast.MatchValue):
        return ast.Compare(left=subject, ops=[ast.Eq()], comparators=[pattern.value]), None
    if isinstance(pattern, ast.MatchSingleton):
        return ast.Compare(left=subject, ops=[ast.Is()],
                           comparators=[ast.Constant(value=pattern.value)]), None
    if isinstance(pattern, ast.MatchAs) and pattern.pattern is None:
        return True, pattern.name
    if isinstance(pattern, ast.MatchOr):
        tests = [_pattern_test(p, subject) for p in pattern.patterns]
        if any(t is False or b is not None for t, b in tests):
            return False, None
        if any(t is True for t, _ in tests):
            return True, None
        return ast.BoolOp(op=ast.Or(), values=[t for t, _ in tests
                                               if isinstance(t, ast.expr)]), None
    return False, None


# Python's builtin exception classes by name, to tell which handler catches which
_EXCEPTIONS: dict[str, type] = {
    name: value for name, value in vars(builtins).items()
    if isinstance(value, type) and issubclass(value, BaseException)}


# what ends the Python process: SystemExit (os._exit: none a handler may catch)
_EXITS = frozenset(("exit", "quit", "sys.exit", "os._exit"))
# the calls (not run) that write a file, by the position of its path among their
# arguments: xacro's own opener for its output, an empty file, a copy's target
_WRITERS = {"xacro.open_output": 0, "os.mknod": 0, "shutil.copy": 1, "shutil.copy2": 1,
            "shutil.copyfile": 1}
# the turns a ``while`` loop whose test stays true may run before it is left, said
MAX_WHILE_TURNS = 10_000


def _raised_name(exc: ast.expr | None) -> str | None:
    """The class a ``raise`` names (``raise KeyError(key)``, ``raise errors.Bad``), None
    for a bare ``raise`` or one not named."""
    if isinstance(exc, ast.Call):
        exc = exc.func
    if isinstance(exc, ast.Name):
        return exc.id
    if isinstance(exc, ast.Attribute):
        return exc.attr
    return None


def _either_goes_on(test: str, body: list[Guard], orelse: list[Guard]) -> str:
    """The text of where the code after an ``if`` of ``test`` runs, when its branches
    go on only under the tests of their own ``body`` / ``orelse`` (a ``return`` in
    them): where the test holds and the body's do, or it does not and the else's do."""
    if not orelse:
        return f"not ({test}) or ({conjunction(body)})"
    if not body:
        return f"({test}) or ({conjunction(orelse)})"
    return (f"({conjunction([test, *body])}) or "
            f"({conjunction([f'not ({test})', *orelse])})")


# what a handler that catches ament_index_python's PackageNotFoundError (a KeyError)
# names: the class itself, or one of its builtin bases
_MISSING_PACKAGE = frozenset({"PackageNotFoundError", "KeyError", "LookupError",
                              "Exception", "BaseException"})


def catches_missing_package(handler: ast.ExceptHandler) -> bool:
    """Whether an ``except`` catches the error ``get_package_share_directory`` raises for
    a package not installed (a bare ``except``, ``except Exception``,
    ``except PackageNotFoundError``, ...)."""
    if handler.type is None:
        return True
    items = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return any((item.id if isinstance(item, ast.Name) else item.attr if isinstance(
        item, ast.Attribute) else None) in _MISSING_PACKAGE for item in items)


def _handler_classes(handler: ast.ExceptHandler) -> tuple[str, ...] | None:
    """The builtin exception classes an ``except`` names (``()``: a bare ``except``);
    None when one is not a builtin class (its hierarchy is not known here)."""
    if handler.type is None:
        return ()
    items = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    names = tuple(item.id for item in items if isinstance(item, ast.Name)
                  and item.id in _EXCEPTIONS)
    return names if len(names) == len(items) else None


def _catches(classes: tuple[str, ...] | None, name: str) -> bool:
    """Whether a handler's classes (``_handler_classes``) catch the builtin exception
    ``name``."""
    if classes is None:
        return False
    if classes == ():
        return True
    raised = _EXCEPTIONS[name]
    return any(issubclass(raised, _EXCEPTIONS[c]) for c in classes)


def _common_text(values: list[Any], reason: str, report: bool = True) -> Lazy | None:
    """Texts (strings, or strings with substitutions) that differ: the start and the
    end all of them share, known, and an unknown part (``reason``) between
    (``'real_driver'`` or ``'sim_driver'``: ``?_driver``); None when a value is no text
    or they share nothing."""
    tokens: list[list[str | e.Subst]] = []
    for value in values:
        if isinstance(value, str):
            tokens.append(list(value))
        elif isinstance(value, Lazy):
            tokens.append([c for part in value.text
                           for c in (part if isinstance(part, str) else (part,))])
        else:
            return None
    shortest = min(len(t) for t in tokens)
    head = 0
    while head < shortest and all(t[head] == tokens[0][head] for t in tokens):
        head += 1
    tail = 0
    while tail < shortest - head and all(t[-1 - tail] == tokens[0][-1 - tail] for t in tokens):
        tail += 1
    if not head and not tail:
        return None
    first = tokens[0]
    parts: list[str | e.Subst] = []
    for token in [*first[:head], e.Opaque(reason, report=report),
                  *first[len(first) - tail:]]:
        if isinstance(token, str) and parts and isinstance(parts[-1], str):
            parts[-1] += token
        else:
            parts.append(token)
    return Lazy(tuple(parts))


# launch's base class of substitutions, as a launch file imports it
_SUBSTITUTION_BASES = ("launch.Substitution", "launch.substitution.Substitution")
_ENUM_BASES = ("enum.Enum", "enum.IntEnum", "enum.StrEnum", "enum.Flag", "enum.IntFlag")


def _no_op(item: ast.stmt) -> bool:
    """A class body's ``pass`` or docstring."""
    return isinstance(item, ast.Pass) or (
        isinstance(item, ast.Expr) and isinstance(item.value, ast.Constant))
