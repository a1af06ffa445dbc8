"""nav2_common's launch helpers, as the static Python interpreter knows them.

``RewrittenYaml`` (parameter, key and value rewrites under an optional root key),
``ReplaceString`` (text replacements, maybe under a condition), ``LaunchConfigAsBool``
and ``HasNodeParams``: rows of ``python_api.API``, never nav2's own code.
"""

from __future__ import annotations

import ast
from typing import TYPE_CHECKING, Any

from ...model.values import Unknown
from . import entities as e
from .python_methods import Args, Builder, Kwargs, arg, cond, text_or_none
from .python_values import to_text

if TYPE_CHECKING:
    from .python import Interpreter


def launch_config_as_bool(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    return e.Logic("asbool", ((e.Var(to_text(arg(a, k, 0, "name"))),),))


def has_node_params(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    node = arg(a, k, 1, "node_name")
    if not isinstance(node, str):
        return Unknown("HasNodeParams with a node name not known statically")
    return e.NodeParamsIn(to_text(arg(a, k, 0, "source_file")), node)


def rewritten_yaml(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    rewrites = k.get("param_rewrites") or {}
    pairs = [(to_text(key), to_text(val) if not isinstance(val, (bool, int, float))
              else val) for key, val in rewrites.items()] if isinstance(rewrites, dict) else []
    root = k.get("root_key")

    def text_pairs(given: Any) -> list[tuple[e.Text, e.Text]]:
        return [(to_text(key), to_text(val)) for key, val in given.items()] if isinstance(
            given, dict) else []

    return e.ParamFile(to_text(arg(a, k, 0, "source_file")), text_or_none(root), pairs,
                       i.where(n), key_rewrites=text_pairs(k.get("key_rewrites")),
                       value_rewrites=text_pairs(k.get("value_rewrites")))


def replace_string(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """nav2_common's ``ReplaceString``: the file with text replaced (if its condition)."""
    replacements = k.get("replacements") or {}
    pairs = [(to_text(key), to_text(val)) for key, val in replacements.items()] if isinstance(
        replacements, dict) else []
    return e.ParamFile(to_text(arg(a, k, 0, "source_file")), location=i.where(n),
                       replacements=pairs, condition=cond(i, k.get("condition"), n))


NAV2_COMMON: dict[str, Builder] = {
    "RewrittenYaml": rewritten_yaml, "ReplaceString": replace_string,
    "LaunchConfigAsBool": launch_config_as_bool, "HasNodeParams": has_node_params,
}
