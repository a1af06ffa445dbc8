"""Our generated interface models against HAROS's hand-written ones, entity by entity.

    PYTHONPATH=. .venv/bin/python bench/models_accuracy_haros.py HAROS_MODELS_DIR [--show]

HAROS_MODELS_DIR is ``haros/models`` of a checkout of github:git-afsantos/haros (one YAML
file per package: distribution -> node type -> advertise / subscribe / service / client /
readParam / writeParam, a node's ``base`` naming the distribution it extends). The newest
distribution there (melodic) is read, its ``base`` chain resolved as HAROS does (the
base's entities, then the node's own), and compared with our noetic models by
``models_accuracy.compare`` (through its ``run``). A name is its ``namespace``
followed by its ``name`` (``~`` private, empty relative), as written in the code.
"""

from __future__ import annotations

import os
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from models_accuracy import run

KINDS = {"advertise": "publish", "subscribe": "subscribe", "service": "server",
         "client": "client", "readParam": "read", "writeParam": "write"}
DISTRO = "melodic"


def _entities(data: dict, distro: str, node: str, entities: set, types: dict,
              seen: set) -> None:
    node_data = (data.get(distro) or {}).get(node)
    if not isinstance(node_data, dict) or distro in seen:
        return
    seen.add(distro)
    base = node_data.get("base")
    if base:
        _entities(data, base, node, entities, types, seen)
    for key, kind in KINDS.items():
        for datum in node_data.get(key) or ():
            name = f"{datum.get('namespace') or ''}{datum['name']}"
            entities.add((kind, name))
            if datum.get("type") and kind not in ("read", "write"):
                types[(kind, name)] = datum["type"]


def theirs(folder: str) -> dict[tuple[str, str], tuple[set, dict, int]]:
    """(package, executable) -> ({(kind, name)}, {(kind, name): type}, 0)."""
    found: dict[tuple[str, str], tuple[set, dict, int]] = {}
    for file in sorted(os.listdir(folder)):
        if not file.endswith(".yaml") or file == "template.yaml":
            continue
        with open(os.path.join(folder, file), encoding="utf-8") as handle:
            data = yaml.safe_load(handle)
        for node in (data.get(DISTRO) or {}):
            entities: set = set()
            types: dict = {}
            _entities(data, DISTRO, node, entities, types, set())
            found[(file[:-len(".yaml")], node)] = (entities, types, 0)
    return found


def main() -> None:
    run("HAROS", theirs, __doc__ or "")


if __name__ == "__main__":
    main()
