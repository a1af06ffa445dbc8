"""Our generated interface models against ROSDiscover's hand-written ones, entity by entity.

    PYTHONPATH=. .venv/bin/python bench/models_accuracy.py ROSDISCOVER_MODELS_DIR [--show]

ROSDISCOVER_MODELS_DIR is ``src/rosdiscover/models`` of a checkout of
github:cmu-rss-lab/rosdiscover (read, never imported or run: each model function's
``c.pub / sub / provide / use / read / write / action_server / action_client`` calls
are read with ``ast``). For every node both cover (ROS 1, our noetic models), it prints
the entities both list, those only in theirs, those only in ours, and type differences.
A name theirs builds at run time (an f-string over a parameter or a plugin) is counted
apart as "dynamic". Topic and service names are compared as written, with a leading
``/`` and ``~`` kept (they mean different things).
"""

from __future__ import annotations

import argparse
import ast
import os
import re
from collections.abc import Callable

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch.models.library import Library

KINDS = {"pub": "publish", "sub": "subscribe", "provide": "server", "use": "client",
         "read": "read", "write": "write", "action_server": "action-server",
         "action_client": "action-client"}
MODEL = re.compile(r"@model\(\s*([\w_]+|'[^']*'|\"[^\"]*\")\s*,\s*['\"]([^'\"]+)['\"]\s*\)\s*\n"
                   r"\s*def\s+(\w+)")
OUR_KINDS = {"declare": "read"}


def _constants(tree: ast.Module) -> dict[str, str]:
    return {t.id: n.value.value for n in tree.body if isinstance(n, ast.Assign)
            for t in n.targets if isinstance(t, ast.Name)
            and isinstance(n.value, ast.Constant) and isinstance(n.value.value, str)}


def theirs(folder: str) -> dict[tuple[str, str], tuple[set, dict, int]]:
    """(package, executable) -> ({(kind, name)}, {(kind, name): type}, dynamic count)."""
    found: dict[tuple[str, str], tuple[set, dict, int]] = {}
    for file in sorted(os.listdir(folder)):
        if not file.endswith(".py"):
            continue
        with open(os.path.join(folder, file), encoding="utf-8") as handle:
            text = handle.read()
        tree = ast.parse(text)
        names = _constants(tree)
        functions = {n.name: n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)}
        for package, executable, function in MODEL.findall(text):
            package = names.get(package, package.strip("'\""))
            entities: set = set()
            types: dict = {}
            dynamic = 0
            for call in ast.walk(functions[function]):
                if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute)
                        and call.func.attr in KINDS and call.args):
                    continue
                kind = KINDS[call.func.attr]
                first = call.args[0]
                if not (isinstance(first, ast.Constant) and isinstance(first.value, str)):
                    dynamic += 1
                    continue
                entities.add((kind, first.value))
                if kind not in ("read", "write") and len(call.args) > 1:
                    second = call.args[1]
                    if isinstance(second, ast.Constant):
                        types[(kind, first.value)] = second.value
                    elif isinstance(second, ast.Name) and second.id in names:
                        types[(kind, first.value)] = names[second.id]
            found[(package, executable)] = (entities, types, dynamic)
    return found


def ours(package: str, executable: str) -> tuple[set, dict, str] | None:
    model = Library().find(package, "noetic")
    node = None if model is None else model.node(executable)
    if node is None or model is None:
        return None
    entities = set()
    types = {}
    for call in node.calls:
        if call.origin == "action":
            continue
        kind = OUR_KINDS.get(call.kind, call.kind)
        name = call.name
        if call.name_param and call.name_default is not None and "?" in name:
            name = name.replace("?", call.name_default, 1)
        entities.add((kind, name))
        if call.type:
            types[(kind, name)] = call.type
    return entities, types, f"{model.label} [{node.completeness}]"


def compare(source: str, found: dict[tuple[str, str], tuple[set, dict, int]],
            show: bool) -> None:
    """Print, per node both ``found`` (another tool's models) and ours cover, the counts."""
    totals = [0, 0, 0, 0]
    missing = []
    for (package, executable), (their, their_types, dynamic) in found.items():
        mine = ours(package, executable)
        if mine is None:
            missing.append(f"{package}/{executable}")
            continue
        entities, types, label = mine
        both = their & entities
        only_theirs = sorted(their - entities)
        only_ours = sorted(entities - their)
        mismatched = sorted(k for k in both if k in their_types and k in types
                            and their_types[k] != types[k]
                            and their_types[k] not in ("any", "unknown type"))
        totals = [totals[0] + len(both), totals[1] + len(only_theirs),
                  totals[2] + len(only_ours), totals[3] + len(mismatched)]
        print(f"== {package}/{executable}: {label}")
        print(f"  both {len(both)}, only {source} {len(only_theirs)} (+{dynamic} dynamic), "
              f"only ours {len(only_ours)}, type differences {len(mismatched)}")
        if show:
            for kind, name in only_theirs:
                print(f"    only {source}: {kind} {name} {their_types.get((kind, name), '')}")
            for kind, name in only_ours:
                print(f"    only ours: {kind} {name} {types.get((kind, name), '')}")
            for key in mismatched:
                print(f"    type: {key[0]} {key[1]}: {source} {their_types[key]}, "
                      f"ours {types[key]}")
    print(f"total: both {totals[0]}, only {source} {totals[1]}, only ours {totals[2]}, "
          f"type differences {totals[3]}")
    print(f"{source}'s nodes we have no model of ({len(missing)}): {', '.join(missing)}")


def run(source: str, read: Callable[[str], dict], doc: str) -> None:
    """The command line both comparisons share: their models' folder, ``--show``."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--show", action="store_true", help="list every difference")
    args = parser.parse_args()
    compare(source, read(args.folder), args.show)


def main() -> None:
    run("ROSDiscover", theirs, __doc__ or "")


if __name__ == "__main__":
    checkout.announce()
    main()
