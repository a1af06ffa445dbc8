"""The shipped catalogue of interface definitions: the messages, services and actions of
the standard interface packages (std_msgs, common_msgs / common_interfaces, tf2_msgs,
rcl_interfaces, control_msgs, ...), for each ROS generation.

Node code uses these types everywhere, and a workspace rarely holds their packages (they
come installed). Without their fields, a parse of ``msg.axes[0]`` or
``cloud.point_step`` fails, and an error inside a ROS call's arguments costs the call.
``haros-arch models interfaces`` reads the ``.msg`` / ``.srv`` / ``.action`` files of
the pinned trees listed in ``interfaces.yaml`` (the same list format and sources folder
as ``models build``) and writes ``interfaces/<distro>.json``: each definition as the
fields it declares (type, array, name, constant; comments dropped), keyed
``package/kind/Name``, with the repositories and commits it was read from. The C++
extraction reads it (``extract.cpp.interfaces.known``): a definition in the workspace
comes first, then this catalogue, then a few hand-written fallbacks.
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Iterable

from ..extract.cpp.interfaces import definition_files, parse_definition
from .generate import Entry

HERE = os.path.dirname(os.path.abspath(__file__))
LIST = os.path.join(HERE, "interfaces.yaml")
FOLDER = os.path.join(HERE, "interfaces")
FORMAT = 1
KINDS = {"msg": ".msg", "srv": ".srv", "action": ".action"}
_NAME = re.compile(r"<name>\s*([A-Za-z0-9_]+)\s*</name>")


class MissingTree(ValueError):
    """A pinned tree is not in the sources folder (``scripts/models-fetch`` puts it)."""


def package_folders(tree: str) -> dict[str, str]:
    """The package folders of a tree by package name (each ``package.xml``'s name)."""
    found: dict[str, str] = {}
    for here, dirs, files in os.walk(tree):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        if "package.xml" in files:
            with open(os.path.join(here, "package.xml"), encoding="utf-8",
                      errors="replace") as handle:
                match = _NAME.search(handle.read())
            if match is not None:
                found.setdefault(match.group(1), here)
            dirs[:] = []  # packages do not nest
    return found


def render(package: str, name: str, text: str) -> str:
    """A definition as the fields our parser reads from it, one per line, its sections
    split by ``---`` (comments and blank lines dropped)."""
    sections = parse_definition(package, name, text).sections
    lines: list[str] = []
    for index, section in enumerate(sections):
        if index:
            lines.append("---")
        for field in section:
            kind = field.type if field.array is None else f"{field.type}[{field.array}]"
            lines.append(f"{kind} {field.name}" if field.constant is None
                         else f"{kind} {field.name}={field.constant}")
    return "\n".join(lines)


def collect(entries: Iterable[Entry], sources: str) -> dict[str, dict[str, object]]:
    """Each distribution's document: its sources and its definitions."""
    documents: dict[str, dict[str, object]] = {}
    for entry in entries:
        tree = os.path.join(sources, entry.folder)
        if not os.path.isdir(tree):
            raise MissingTree(f"{entry.repository} {entry.commit[:12]}: no tree at {tree}")
        document = documents.setdefault(entry.distro, {
            "format": FORMAT, "distro": entry.distro, "sources": [], "definitions": {}})
        packages = package_folders(tree)
        missing = [p for p in entry.packages if p not in packages]
        if missing:
            raise MissingTree(f"{entry.repository} {entry.commit[:12]}: no package "
                              f"{', '.join(missing)} in the tree")
        sources_list = document["sources"]
        assert isinstance(sources_list, list)
        sources_list.append({"repository": entry.repository, "commit": entry.commit,
                             "packages": list(entry.packages)})
        definitions = document["definitions"]
        assert isinstance(definitions, dict)
        for package in entry.packages:
            for kind, extension in KINDS.items():
                for file, path in definition_files(packages[package], kind).items():
                    name = file[: -len(extension)]
                    with open(path, encoding="utf-8", errors="replace") as handle:
                        definitions[f"{package}/{kind}/{name}"] = render(
                            package, name, handle.read())
    for document in documents.values():
        definitions = document["definitions"]
        assert isinstance(definitions, dict)
        document["definitions"] = dict(sorted(definitions.items()))
    return documents


def write(documents: dict[str, dict[str, object]], folder: str) -> list[str]:
    os.makedirs(folder, exist_ok=True)
    written = []
    for distro, document in sorted(documents.items()):
        path = os.path.join(folder, f"{distro}.json")
        with open(path, "w", encoding="utf-8") as handle:
            json.dump(document, handle, indent=0, sort_keys=False)
            handle.write("\n")
        written.append(path)
    return written
