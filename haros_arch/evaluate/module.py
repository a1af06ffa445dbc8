"""Module-level statements of a file (setup.py) run by the one safe evaluator.

``run_module(tree, functions)`` follows imports (as aliases), assignments to names (``+=``
too) and calls of allowed functions and methods (``files.append(...)``), with one work
budget for the whole file; ``Module.value(node)`` is then the value of any expression of
the file over those names, and ``Module.limited`` the first bound reached, if any.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from ..model.values import Unknown
from .operations import BUILTINS, Limits
from .python import _dotted, _Interpreter, _shape_ok

FILE_LIMITS = Limits(text=1024 * 1024, nodes=200_000, depth=100)


@dataclass
class Module:
    """The module-level names of a file and the calls it makes at module level."""

    names: dict[str, object] = field(default_factory=dict)
    aliases: dict[str, str] = field(default_factory=dict)  # local name -> dotted origin
    calls: list[ast.Call] = field(default_factory=list)
    interpreter: _Interpreter | None = None

    def value(self, node: ast.AST) -> object:
        """The value of an expression of this module (after its statements ran)."""
        if self.interpreter is None:
            return Unknown("no module", "undefined")
        return self.interpreter.run(node)

    def qualified(self, node: ast.expr) -> str | None:
        """The dotted name a callee of this module stands for, its imports applied
        (``generate_distutils_setup`` of ``from catkin_pkg.python_setup import ...``)."""
        return _qualified(node, self.aliases)

    @property
    def limited(self) -> tuple[Unknown, ast.AST] | None:
        """The first work bound reached, and where: the values after it are unknown."""
        return self.interpreter.limited if self.interpreter is not None else None


def run_module(tree: ast.Module, functions: Mapping[str, Any] | None = None,
               limits: Limits = FILE_LIMITS, mutate: bool = True,
               calls: Iterable[str] = ()) -> Module:
    """Run ``tree``'s module-level statements over known values: imports (as aliases),
    assignments to names (``+=`` too), and calls of allowed functions and methods
    (``files.append(...)``); an item of a list or tuple that cannot be known is an
    ``Unknown`` item, the rest stays known. Every other statement is skipped: the names it
    would set stay as they were. ``calls``: dotted names of calls to collect (``setup``)
    from anywhere in the module, never run. One budget for the whole file."""
    module = Module()
    wanted = set(calls)
    refused = _shape_ok(tree, limits)
    module.interpreter = _Interpreter(None, {}, limits)
    if refused is not None:
        module.interpreter.limited = (refused, tree)
        return module
    interp = _Interpreter(module.names.__getitem__, functions or BUILTINS, limits, mutate,
                          module.aliases, lenient=True)
    module.interpreter = interp
    for statement in tree.body:
        for inner in ast.walk(statement):
            if isinstance(inner, ast.Call) and _qualified(inner.func, module.aliases) in wanted:
                module.calls.append(inner)
        _statement(statement, module, interp)
        if interp.steps > limits.steps:
            break
    return module


def _statement(statement: ast.stmt, module: Module, interp: _Interpreter) -> None:
    """One module-level statement run over known values; an ``if`` whose test is known
    runs the branch it takes (setup.py's ``if ROS_VERSION == 2:`` over the distribution's
    environment), one whose test is not known neither."""
    if isinstance(statement, ast.If):
        test = interp.run(statement.test)
        if type(test) in (bool, int, str):
            for inner in statement.body if test else statement.orelse:
                _statement(inner, module, interp)
                if interp.steps > interp.limits.steps:
                    return
    elif isinstance(statement, ast.Import):
        for alias in statement.names:
            local = alias.asname or alias.name.split(".")[0]
            module.aliases[local] = alias.name if alias.asname else local
    elif isinstance(statement, ast.ImportFrom) and statement.module:
        for alias in statement.names:
            module.aliases[alias.asname or alias.name] = f"{statement.module}.{alias.name}"
    elif isinstance(statement, ast.Assign) and len(statement.targets) == 1 \
            and isinstance(statement.targets[0], ast.Name):
        module.names[statement.targets[0].id] = interp.run(statement.value)
    elif isinstance(statement, ast.AugAssign) and isinstance(statement.target, ast.Name):
        combined = ast.BinOp(ast.Name(statement.target.id, ast.Load()), statement.op,
                             statement.value)
        module.names[statement.target.id] = interp.run(combined)
    elif isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Call) \
            and statement.value not in module.calls:
        interp.run(statement.value)


def _qualified(node: ast.expr, aliases: Mapping[str, str]) -> str | None:
    dotted = _dotted(node)
    if dotted is None:
        return None
    head, dot, rest = dotted.partition(".")
    return aliases.get(head, head) + dot + rest
