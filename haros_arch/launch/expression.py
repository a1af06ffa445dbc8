"""``$(eval ...)`` of ROS 1 launch files and ROS 2 ``PythonExpression``: a configuration of
the one safe evaluator (``haros_arch.evaluate.python``).

roslaunch and ROS 2 hand the string to Python's ``eval``; we never do. What is particular
to launch files is only this: ``__`` anywhere in the text is refused (roslaunch's rule,
kept for ROS 2 too), and the functions are ``BUILTINS`` unless the caller gives its own
table (``arg``, ``env``, ``find``... in ROS 1; ``MATH`` added in ROS 2). The public call,
which robot descriptions (xacro ``${}``) use too, stays::

    evaluate(text, names, functions) -> object | Unknown
"""

from __future__ import annotations

import builtins
import math
from collections.abc import Callable, Mapping
from typing import Any

from ..evaluate.python import (
    BUILTINS,
    MATH,
    Limits,
    Unknown,
    is_unknown,
    names_from,
    undefined_name,
    unknown_reasons,
)
from ..evaluate.python import evaluate as _evaluate

__all__ = ["BUILTINS", "MATH", "Limits", "Unknown", "eval_knows", "evaluate", "is_unknown",
           "names_from", "undefined_name", "unknown_reasons"]


def evaluate(text: str, names: Callable[[str], object] | None = None,
             functions: Mapping[str, Any] | None = None,
             limits: Limits | None = None) -> object:
    """Evaluate the Python expression ``text`` of a launch file; an ``Unknown`` (with why)
    when it cannot be. Never raises for bad input and never runs code from ``text``."""
    return _evaluate(text, names, functions, limits, dunder=False)


def eval_knows(name: str | None) -> bool:
    """Whether ROS 2 launch's ``eval`` of a ``PythonExpression`` / ``$(eval)`` (no
    ``python_modules``) has ``name``: Python's builtins, the module ``math`` and its names
    (Humble's globals are math's; later ones add the module itself). None: not known."""
    return name is None or name == "math" or hasattr(builtins, name) or hasattr(math, name)
