"""Calls into the package's own functions and methods: the frame their body is walked
or evaluated in, with the call's arguments bound to their parameters (positional,
keyword, defaults; ``*args`` makes the rest unknown), a few calls deep.
"""

from __future__ import annotations

import ast

from ...model.values import Unknown
from .modules import FunctionInfo
from .objects import BoundMethod, Frame, Instance
from .scopes import Scopes

# how many calls deep the walk follows the package's own functions (and the evaluator
# their results and constructors): carla's bridge builds its actors, which make the
# publishers, five calls down; ten recovered every call of the Python nodes of carla's
# ros-bridge, rosbridge_suite and navigation2 (bench/README.md, followups10) but made
# camera_info_manager_py's manager pass the evaluator's step bound (naoqi's camera node
# partial); eight finds 38 of carla's 39, and a cut that may lose a ROS call is said
# (``PY_CALL_DEPTH``)
MAX_CALL_DEPTH = 8


class Calls(Scopes):
    def call_frame(self, func: FunctionInfo | BoundMethod, expr: ast.Call,
                   frame: Frame) -> Frame:
        """A frame for the body of ``func`` with the call's arguments bound."""
        info = func.function if isinstance(func, BoundMethod) else func
        instance = func.instance if isinstance(func, BoundMethod) else None
        values = [self.eval(a, frame) for a in expr.args if not isinstance(a, ast.Starred)]
        starred = any(isinstance(a, ast.Starred) for a in expr.args)
        keywords = {k.arg: self.eval(k.value, frame) for k in expr.keywords if k.arg}
        bound = self.bind_arguments(info, values, keywords, starred,
                                    skip_self=instance is not None)
        if instance is None and info.cls is not None and values and isinstance(
                values[0], Instance) and not starred:
            # ``Base.method(self, ...)`` through the class (stretch's HelloNode.main(self,
            # 'funmap', 'funmap')): a method of the instance passed first
            instance = values[0]
        return Frame(info.module, bound, instance, frame.depth + 1, owner=info.cls)

    def bind_arguments(self, info: FunctionInfo, values: list[object],
                       keywords: dict[str, object], starred: bool,
                       skip_self: bool) -> dict[str, object]:
        args = info.node.args
        params = [*args.posonlyargs, *args.args]
        if skip_self and params:
            params = params[1:]
        bound: dict[str, object] = dict(info.closure or {})
        defaults = args.defaults
        first_default = len(params) - len(defaults)
        home = Frame(info.module)
        for i, param in enumerate(params):
            if i < len(values) and not starred:
                bound[param.arg] = values[i]
            elif param.arg in keywords:
                bound[param.arg] = keywords[param.arg]
            elif i >= first_default and not starred:
                bound[param.arg] = self.eval(defaults[i - first_default], home)
            else:
                bound[param.arg] = Unknown(f"argument {param.arg}")
        for param, default in zip(args.kwonlyargs, args.kw_defaults, strict=False):
            if param.arg in keywords:
                bound[param.arg] = keywords[param.arg]
            elif default is not None:
                bound[param.arg] = self.eval(default, home)
            else:
                bound[param.arg] = Unknown(f"argument {param.arg}")
        return bound


def argument(call: ast.Call, arg: object) -> ast.expr | None:
    """The expression given for ``arg`` (an ``api.Arg``) in ``call``, if any."""
    index, keyword = getattr(arg, "index", None), getattr(arg, "keyword", None)
    if keyword is not None:
        for k in call.keywords:
            if k.arg == keyword:
                return k.value
    if index is not None:
        for i, a in enumerate(call.args):
            if isinstance(a, ast.Starred):
                return None
            if i == index:
                return a
    return None

def unknown_params(info: FunctionInfo) -> dict[str, object]:
    args = info.node.args
    names = [a.arg for a in (*args.posonlyargs, *args.args, *args.kwonlyargs)]
    if info.cls is not None and names:
        names = names[1:]
    return {**(info.closure or {}), **{n: Unknown(f"argument {n}") for n in names}}
