"""Launch models: what an installed package's ROS 1 launch files do, kept in its model.

A workspace's launch file often includes one of a package installed from the
distribution (``$(find gazebo_ros)/launch/empty_world.launch``), which is not on this
machine. ``haros-arch models build`` records, from the package's source at its pinned
commit, each ROS 1 XML launch file of the package (``launch_files``: the path below the
package's folder to its ``<launch>`` element) as the launch elements roslaunch
interprets (``arg``, ``node``, ``test``, ``include``, ``group``, ``remap``, ``param``,
``rosparam``, ``env``, ``machine``, ``master``), each with the attributes the loader
reads (a ``doc`` description, comments and whitespace dropped) and the line of the
element upstream; and the YAML files those launch files name in their own package
(``$(find PKG)/config/x.yaml``: ``param_files``, each its parsed value and the line of
each key). Written by our own reader, never a copy of the file::

    "launch_files": {"launch/empty_world.launch": {
        "tag": "launch", "line": 1, "children": [
            {"tag": "arg", "line": 3, "attrs": {"name": "paused", "default": "false"}},
            {"tag": "node", "line": 40, "attrs": {...}, "children": [...]}]}},
    "param_files": {"launch/px4_config.yaml": {"value": {...}, "lines": {...}}}

The ROS 1 launch loader (``ModelledFiles``) gives ``$(find PKG)`` of a package found
neither in the workspace nor installed here, whose model has launch files, the folder a
release installs it in (``/opt/ros/<distro>/share/PKG``), and reads a file of that folder
the model holds as it reads the real one; its elements are placed at the model's
upstream file and line (``github:owner/name@commit/path:line``). A file the model does
not hold stays unknown, as before.
"""

from __future__ import annotations

import copy
import json
import os
import re
from collections.abc import Callable
from typing import Any

import yaml
from lxml import etree

from ..files import read_bytes
from ..launch.ros1.loader import ATTRIBUTES
from ..manifest import as_expat_reads, start_lines, xml_parser
from ..model.location import Location
from .format import InterfaceModel

# the tags roslaunch interprets and the attributes of each the loader reads, but those
# that only describe (``doc``, ``deprecated``); if / unless on all
TAGS: dict[str, tuple[str, ...]] = {
    tag: tuple(a for a in attributes if a not in ("doc", "deprecated"))
    for tag, attributes in ATTRIBUTES.items()}
CONDITIONS = ("if", "unless")
LAUNCH_SUFFIXES = (".launch", ".launch.xml")
PARAM_SUFFIXES = (".yaml", ".yml")
MAX_FILE = 2 * 1024 * 1024
SKIP_FOLDERS = frozenset({".git", "build", "devel", "install", "node_modules"})
# a package's own file named in its launch files: ``$(find PKG)/REL``
_FIND = re.compile(r"\$\(\s*find\s+([A-Za-z0-9_]+)\s*\)/([^\s\"'$()]+)")
INSTALL_ROOT = "/opt/ros/{distro}/share/{package}"


# -- build: from the package's source ---------------------------------------------------
def package_launch_data(package: str, root: str) -> tuple[dict[str, Any], dict[str, Any]]:
    """The launch files of the package in folder ``root`` (each ``*.launch`` /
    ``*.launch.xml`` whose root element is ``<launch>``), and the YAML files of the
    package they name (``$(find package)/...``), as ``launch_files`` / ``param_files``."""
    launch: dict[str, Any] = {}
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_FOLDERS and not d.startswith("."))
        for name in sorted(files):
            if name.endswith(LAUNCH_SUFFIXES):
                path = os.path.join(folder, name)
                element = _launch_element(path)
                if element is not None:
                    launch[os.path.relpath(path, root).replace(os.sep, "/")] = element
    params: dict[str, Any] = {}
    for element in launch.values():
        for text in _attribute_texts(element):
            for match in _FIND.finditer(text):
                rel = os.path.normpath(match.group(2)).replace(os.sep, "/")
                if match.group(1) != package or not rel.endswith(PARAM_SUFFIXES) or \
                        rel.startswith("..") or rel in params:
                    continue
                data = _param_file(os.path.join(root, rel))
                if data is not None:
                    params[rel] = data
    return launch, dict(sorted(params.items()))


def _launch_element(path: str) -> dict[str, Any] | None:
    data, _ = read_bytes(path, Location(file=path), MAX_FILE)
    if data is None:
        return None
    try:
        root = etree.fromstring(as_expat_reads(data), xml_parser())
    except etree.XMLSyntaxError:
        return None
    if root.tag != "launch":
        return None
    start_lines(root, data)
    return _element(root)


def _element(element: Any) -> dict[str, Any]:
    tag = str(element.tag)
    allowed = (*TAGS.get(tag.lower(), ()), *CONDITIONS)
    out: dict[str, Any] = {"tag": tag, "line": element.sourceline or 0}
    attrs = {k: v for k, v in element.attrib.items() if k in allowed}
    if attrs:
        out["attrs"] = attrs
    if tag.lower() == "rosparam":  # its YAML text, as the loader reads it
        text = (element.text or "") + "".join(c.tail or "" for c in element)
        if text.strip():
            out["text"] = text
        return out
    children = [_element(c) for c in element
                if isinstance(c.tag, str) and c.tag.lower() in TAGS]
    if children:
        out["children"] = children
    return out


def _attribute_texts(element: dict[str, Any]) -> list[str]:
    found = list(element.get("attrs", {}).values())
    for child in element.get("children", ()):
        found += _attribute_texts(child)
    return found


def _param_file(path: str) -> dict[str, Any] | None:
    """A parameter file's parsed value and key lines, as ``<rosparam>`` reads it; None
    for one that is not there, not YAML, holds a substitution (``subst_value`` would
    change it) or a value JSON does not keep as it is."""
    from .. import safe_yaml
    from ..launch.ros1.params import RosparamLoader

    if not os.path.isfile(path):
        return None
    data, _ = read_bytes(path, Location(file=path), MAX_FILE)
    if data is None:
        return None
    text = data.decode("utf-8", errors="replace")
    if "$(" in text:
        return None
    try:
        value, lines = safe_yaml.load_with_lines(text, RosparamLoader)
    except (yaml.YAMLError, ValueError, RecursionError):
        return None
    try:
        if json.loads(json.dumps(value)) != value:
            return None
    except (TypeError, ValueError):
        return None
    return {"value": value, "lines": lines}


# -- read: for the ROS 1 launch loader --------------------------------------------------
class ModelledFiles:
    """The launch and parameter files of packages without source held by their models,
    for one configuration's distribution; ``find(package)`` gives a package's model."""

    def __init__(self, find: Callable[[str], InterfaceModel | None], distro: str) -> None:
        self.find = find
        self.distro = distro
        self._roots: dict[str, InterfaceModel] = {}

    def root(self, package: str) -> str | None:
        """The folder ``$(find package)`` gives for a package whose model holds its
        launch files: where a release of the distribution installs it."""
        model = self.find(package)
        if model is None or model.launch_files is None:
            return None
        path = INSTALL_ROOT.format(distro=self.distro, package=package)
        self._roots[path] = model
        return path

    def owner(self, path: str) -> tuple[InterfaceModel, str] | None:
        """The model whose package folder (``root``) ``path`` lies in, and the path
        below it; None for any other path."""
        full = os.path.normpath(path)
        for root, model in self._roots.items():
            if full.startswith(root + "/"):
                return model, full[len(root) + 1:]
        return None

    def holds(self, path: str) -> bool:
        """Whether ``path`` is a launch or parameter file a model holds."""
        found = self.owner(path)
        return found is not None and (found[1] in (found[0].launch_files or {})
                                      or found[1] in found[0].param_files)

    def launch(self, path: str) -> Any:
        """The ``<launch>`` element of a modelled launch file, rebuilt as lxml elements
        at their upstream lines; None when the model does not hold it."""
        found = self.owner(path)
        data = (found[0].launch_files or {}).get(found[1]) if found else None
        return _rebuilt(data) if isinstance(data, dict) else None

    def params(self, path: str) -> tuple[Any, Any] | None:
        """A modelled parameter file's value and key lines; None when not held."""
        found = self.owner(path)
        data = found[0].param_files.get(found[1]) if found else None
        if not isinstance(data, dict):
            return None
        return copy.deepcopy(data.get("value")), copy.deepcopy(data.get("lines"))

    def location(self, path: str, line: int = 0) -> Location | None:
        """Where a modelled file's line is upstream: the repository at the model's
        commit, the file's path in it (``github:ros-simulation/gazebo_ros_pkgs@2d9b5b5f/
        gazebo_ros/launch/empty_world.launch``); None for a path of no model."""
        found = self.owner(path)
        if found is None:
            return None
        model, rel = found
        return Location(None, upstream(model, rel), line)


def upstream(model: InterfaceModel, rel: str) -> str:
    """``github:owner/name@commit/path``: a file of the model's package upstream."""
    repository = model.source.get("repository") or f"model:{model.package}"
    commit = model.source.get("commit", "")[:8]
    folder = model.source.get("path", "").strip("/")
    inner = f"{folder}/{rel}" if folder and folder != "." else rel
    return f"{repository}@{commit}/{inner}" if commit else f"{repository}/{inner}"


def _rebuilt(data: dict[str, Any], parent: Any = None) -> Any:
    tag = str(data.get("tag") or "launch")
    attrs = {str(k): str(v) for k, v in (data.get("attrs") or {}).items()}
    element = etree.Element(tag, attrs) if parent is None else etree.SubElement(
        parent, tag, attrs)
    line = data.get("line")
    if isinstance(line, int) and line > 0:
        element.sourceline = line  # type: ignore[assignment]
    if isinstance(data.get("text"), str):
        element.text = data["text"]
    for child in data.get("children") or ():
        if isinstance(child, dict):
            _rebuilt(child, element)
    return element
