"""Whether a function the walk does not follow (past ``MAX_CALL_DEPTH``) may make a ROS
call: a call in its body, or in a function or class of the modules read that a call of
it names (by name alone, any module, transitively), of a name of the API tables
(``create_publisher``, ``Subscriber``, ``get_param``, ...). Read from the syntax, so it
errs towards yes: a helper of the same name as an API function counts. A cut of a
function that cannot reach one loses nothing and is not said."""

from __future__ import annotations

import ast
from collections.abc import Iterable

from . import rclpy, rospy
from .modules import ClassInfo, FunctionInfo, Module, last_name

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
