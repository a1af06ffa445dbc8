"""The BehaviorTree.CPP nodes of a workspace, as plugins.behavior_trees reads them.

    python bench/bt_real.py WORKSPACE

Prints the BT libraries found (per package), the registered IDs by kind (nav2 action,
cancel and service nodes, nodes with calls of their own, nodes with none), the calls of
the nodes of the last kinds and where their names come from, and, for every tree file
under a ``behavior_trees`` folder, how many node tags it has and which IDs no library
registers (what makes a host running it partial).
"""

from __future__ import annotations

import glob
import os
import sys

from haros_arch.diagnostics import Diagnostic
from haros_arch.plugins import behavior_trees
from haros_arch.workspace import scan


def main(root: str) -> None:
    workspace = scan([root])
    found = behavior_trees.libraries(workspace)
    registered: dict[str, behavior_trees.Registered] = {}
    for ids in found.by_library.values():
        registered.update(ids)
    print(f"{len(found.by_library)} libraries, {len(registered)} IDs:",
          {package: len(names) for package, names in found.by_package.items()})
    kinds: dict[str, list[str]] = {}
    for each in registered.values():
        kinds.setdefault(each.base or ("own calls" if each.calls else "no calls"),
                         []).append(each.id)
    for kind, ids in sorted(kinds.items()):
        print(f"  {kind} ({len(ids)}): {' '.join(sorted(ids))}")
    for each in sorted(registered.values(), key=lambda r: r.id):
        if each.base is not None:
            if each.default is None or each.type is None:
                print(f"  {each.id}: {each.base} {each.type or '?'}, no default name")
            continue
        for kind, type_, source in each.calls:
            print(f"  {each.id}: {kind} {type_ or '?'} named by {source or 'unknown'}"
                  + (f" (default {each.ports.get(source[1])})"
                     if source and source[0] == "port" else ""))
    pattern = os.path.join(root, "**", "behavior_trees", "*.xml")
    for path in sorted(glob.glob(pattern, recursive=True)):
        problems: list[Diagnostic] = []
        read = behavior_trees.read_tree(path, workspace, problems)
        tree = read if read is not None else behavior_trees.Tree()
        unknown = sorted({tag.id for tag in tree.tags if tag.id not in registered})
        undefined = sorted({t.id for t in tree.subtrees if t.id not in tree.defined})
        print(f"{workspace.relpath(path)}: {len(tree.tags)} tags, unregistered "
              f"{unknown or '-'}, subtrees not defined {undefined or '-'}"
              + "".join(f", {d.code} {d.location.line}" for d in problems)
              + "".join(f", {reason}" for reason in tree.reasons))


if __name__ == "__main__":
    main(sys.argv[1])
