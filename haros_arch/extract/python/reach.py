"""Whether a function the walk does not follow (past ``MAX_CALL_DEPTH``) may make a ROS
call: a call in its body, or in a function or class of the modules read that a call of
it names (by name alone, any module, transitively), of a name of the API tables
(``create_publisher``, ``Subscriber``, ``get_param``, ...). Read from the syntax, so it
errs towards yes: a helper of the same name as an API function counts. A cut of a
function that cannot reach one loses nothing and is not said. Nor is the cut of a whole
program (``imports_ros``) that imports no ROS client: a report script installed as a
program that reads CSV files with pandas (lidar_localization_ros2)."""

from __future__ import annotations

import ast
from collections.abc import Iterable

from . import rclpy, rospy
from .modules import ClassInfo, FunctionInfo, Loader, Module, api_modules, last_name

# the names a call of the API tables ends in: ``rospy.Publisher``, ``node.create_client``
API_NAMES = frozenset(
    {key[1] for key in (*rospy.ROWS, *rclpy.ROWS, *rospy.NODE_NAMES, *rclpy.NODE_NAMES)}
    | set(rclpy.NODE_METHODS))


class Reach:
    """The answer per function, for the modules a loader has read (``modules``)."""

    def __init__(self) -> None:
        self._known: dict[int, bool] = {}
        self._index: dict[str, list[FunctionInfo | ClassInfo]] = {}
        self._indexed = 0

    def _reindex(self, modules: Iterable[Module | None]) -> None:
        read = [m for m in modules if m is not None]
        if len(read) == self._indexed:
            return
        self._indexed = len(read)
        self._index = {}
        for module in read:
            for name, function in module.functions.items():
                self._index.setdefault(name, []).append(function)
            for name, cls in module.classes.items():
                self._index.setdefault(name, []).append(cls)
                for method_name, method in cls.methods.items():
                    if method_name != "__init__":  # reached through its class's name
                        self._index.setdefault(method_name, []).append(method)

    def may_call_ros(self, info: FunctionInfo, modules: Iterable[Module | None]) -> bool:
        self._reindex(modules)
        if id(info.node) in self._known:
            return self._known[id(info.node)]
        seen: set[int] = set()
        todo: list[ast.AST] = [info.node]
        found = False
        while todo and not found:
            node = todo.pop()
            if id(node) in seen:
                continue
            seen.add(id(node))
            if self._known.get(id(node)) is True:
                found = True
                break
            for part in ast.walk(node):
                if not isinstance(part, ast.Call):
                    continue
                name = last_name(part.func)
                if not name:
                    continue
                if name in API_NAMES:
                    found = True
                    break
                for target in self._index.get(name, ()):
                    todo.extend(self._bodies(target))
        self._known[id(info.node)] = found
        return found

    def _bodies(self, target: FunctionInfo | ClassInfo) -> list[ast.AST]:
        """What runs when ``target`` is called: a function's body; a class's
        ``__init__`` and its bases' (named, as ``super().__init__`` reaches them); a base
        of an API name (rclpy's ``Node``) stands for a call of it."""
        if isinstance(target, FunctionInfo):
            return [target.node]
        return self._class_bodies(target, set())

    def _class_bodies(self, cls: ClassInfo, seen: set[int]) -> list[ast.AST]:
        if id(cls) in seen:
            return []
        seen.add(id(cls))
        found: list[ast.AST] = []
        init = cls.methods.get("__init__")
        if init is not None:
            found.append(init.node)
        for base in cls.node.bases:
            name = last_name(base)
            if name in API_NAMES:
                found.append(ast.Call(func=ast.Name(id=name), args=[], keywords=[]))
            for other in self._index.get(name, ()):
                if isinstance(other, ClassInfo):
                    found.extend(self._class_bodies(other, seen))
        return found

    def subclasses_may_call_ros(self, name: str, loader: Loader) -> bool:
        """Whether a program that lists the subclasses of the class ``name``
        (``Thruster.__subclasses__()``) and builds them may make a ROS call through
        them: unless ``name`` is one class of the modules read, every module it imports
        of the workspace was read, and no method of a class derived from it (by name,
        transitively, in any module read), nor of their bases, may reach a ROS call
        (``may_call_ros``); a base that is neither a class read nor a builtin one
        (``object``, ``Exception``, ``ABC``) may make any call. The modules are those
        the program imports, transitively (``program_imports``): a subclass is made
        where its module is imported, whether or not the program names it (one a
        module imports by a name known only at run time is the walk's
        ``PY_DYNAMIC_IMPORT``, which makes the node partial on its own). Errs towards
        yes."""
        read, unread, _, _ = program_imports(loader)
        if unread:
            return True  # a module not read may define a subclass
        listed: list[Module | None] = list(loader.modules.values())
        self._reindex(listed)
        classes = [c for m in read for c in m.classes.values()]
        if len([c for c in classes if c.name == name]) != 1:
            return True  # not a class read (``cls``, a parameter), or two of that name
        family = {name}
        grown = True
        while grown:
            grown = False
            for cls in classes:
                if cls.name not in family and any(
                        last_name(base) in family for base in cls.node.bases):
                    family.add(cls.name)
                    grown = True
        seen: set[int] = set()
        todo = [c for c in classes if c.name in family]
        while todo:
            cls = todo.pop()
            if id(cls) in seen:
                continue
            seen.add(id(cls))
            if any(self.may_call_ros(method, listed) for method in cls.methods.values()):
                return True
            for base in cls.node.bases:
                based = last_name(base)
                found = [c for c in self._index.get(based or "", ())
                         if isinstance(c, ClassInfo)]
                if not found and based not in _PLAIN_BASES:
                    return True  # a base not read (an API class among them)
                todo.extend(found)
        return False


# bases a class may have that make no call of their own
_PLAIN_BASES = frozenset({"object", "Exception", "ABC", "Generic", "Protocol"})

# builtins and modules that import a module named at run time
_DYNAMIC_NAMES = frozenset({"__import__", "exec", "eval"})
_DYNAMIC_MODULES = frozenset({"importlib", "imp", "runpy", "pkgutil"})
# a ROS package's interface modules, which make no call
_INTERFACES = frozenset({"msg", "srv", "action"})


def imports_ros(loader: Loader, unseen: frozenset[str]) -> bool:
    """Whether the modules read, or one of the package's or workspace's modules they
    import (transitively, each read here), import a module whose code may make a ROS
    call: a client library or a module the API tables read (``api_modules``), one of
    the ROS packages ``unseen`` (not in the workspace; their interface modules,
    ``std_msgs.msg``, aside), or any module by a name known only at run time
    (``importlib``, ``__import__``, ``exec``). A module of none of these (the standard
    library, numpy) is one the walk reads no ROS call in either."""
    clients = api_modules() | unseen
    _, _, outside, dynamic = program_imports(loader)
    return dynamic or any(name.split(".")[0] in clients | _DYNAMIC_MODULES
                          for name in outside)


def program_imports(loader: Loader) -> tuple[list[Module], bool, list[str], bool]:
    """What the modules read import, transitively: the package's and workspace's
    modules (each read here, so the loader holds them too), whether one of those could
    not be read, the other modules' names (not a message module's, ``std_msgs.msg``,
    nor a name in a module of the package), and whether a module is imported by a name
    known only at run time (``__import__``, ``exec``, ``eval``)."""
    todo = [m for m in loader.modules.values() if m is not None]
    unread = any(m is None for m in loader.modules.values())
    read: list[Module] = []
    outside: list[str] = []
    dynamic = False
    seen: set[str] = set()
    while todo:
        module = todo.pop()
        if module.path in seen:
            continue
        seen.add(module.path)
        read.append(module)
        for node in ast.walk(module.tree):
            if isinstance(node, ast.Name) and node.id in _DYNAMIC_NAMES:
                dynamic = True
            if isinstance(node, ast.Import):
                named = [(0, alias.name) for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                named = [(node.level, base), *((node.level, f"{base}.{alias.name}" if base
                                                else alias.name)
                                               for alias in node.names if alias.name != "*")]
            else:
                continue
            for level, dotted in named:
                local = loader.resolve_import(module.path, level, dotted) if dotted else None
                if local is not None:
                    found = loader.load(local)
                    if found is not None:
                        todo.append(found)
                    else:
                        unread = True
                    continue
                parts = dotted.split(".")
                if level or (len(parts) > 1 and parts[1] in _INTERFACES):
                    continue  # a name in a module of the package, or a message module
                outside.append(dotted)
    return read, unread, outside, dynamic
