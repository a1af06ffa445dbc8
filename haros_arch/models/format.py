"""The interface model file: one package's nodes for one ROS distribution.

A versioned serialisation of the model classes (``Node``, ``PrimitiveCall``) through the
one generic serialiser, under a header that says where it comes from::

    {"schema": "haros-arch-model/2", "package": "amcl", "distro": "noetic",
     "version": "1.17.3",                       # the package's package.xml version
     "source": {"repository": "github:ros-planning/navigation",
                "branch": "noetic-devel", "commit": "<40 hex>", "path": "amcl"},
     "generator": {"name": "haros-arch", "version": "0.1.0"},
     "override": "overrides/noetic/amcl.yaml",  # when one completed it, else absent
     "nodes": [{"package": "amcl", "executable": "amcl", "kind": "executable",
                "language": "cpp", "rosname": "amcl",
                "calls": [{"kind": "subscribe", "name": "scan", ...}],
                "completeness": "partial", "completeness_reasons": [...]}]}

A plugin class is a node of kind ``plugin`` whose ``executable`` is its pluginlib lookup
name, with ``plugin_class`` (its C++ type) and, optionally, ``plugin_base`` (the base class
its plugin description names) and ``rosname`` (the name of the node it makes, for plugins
that are nodes of their own: mavros'); hosts find modelled classes by lookup name or type.
An executable that runs nodelets under its own name lists their lookup names in
``nodelets`` (image_view's ``image_view``: ``["image_view/image"]``); its instances make
their calls, the classes found in the workspace or in the models.
Optional fields are additions within ``haros-arch-model/1``: readers ignore what they do
not know, and a file without them reads as before.

Calls keep the names as the code writes them (``~initial_pose``, ``scan``,
``/map``), their types, queue sizes or QoS, parameter reads with their defaults, and
``name_param`` / ``name_default`` for names taken from parameters. Files and lines
are relative to the repository. Users write their own files in the same format.

Versions: 2 adds names taken from a family of parameters (``name_each: "#"``: one call
per parameter ``<name_param>0``, ``<name_param>1``, ... the configuration sets, as
robot_localization reads ``imu0``, ``imu1``); a version 1 file reads unchanged (it
cannot hold that), a file of a later version is refused with its version named.
``transport`` (optional) marks a call made through image_transport (``*``: a publisher;
a subscriber's transport, ``?`` when its node's ``image_transport`` parameter says; a
trailing ``/`` when its transport's topic is named from the base as written, ``=`` when
from a base its ROS 2 code resolved and remapped itself); for a ``?`` transport,
``transport_param``, ``transport_arg`` and ``transport_default`` say what gives it when
that parameter does not (a parameter, a program argument, a text; ``?``: not known), and
``transport_fixed`` that the code passes the transport itself (no parameter of
image_transport changes it). ``launch_files`` / ``param_files`` (optional): a ROS 1
package's launch files and the parameter files they load, ``launch_files``.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from .. import __version__
from ..model.load import node_from_data
from ..model.rosname import node_name_joined
from ..model.serialise import to_data
from ..model.source import CALL_KINDS, Node

SCHEMA_VERSION = 2
SCHEMA = f"haros-arch-model/{SCHEMA_VERSION}"
SCHEMA_PREFIX = "haros-arch-model/"
_TEXT_FIELDS = ("type", "name_param", "name_default", "name_each", "handle_namespace",
                "node_name", "callback", "transport", "variable", "default_param",
                "host_named", "loads", "transport_param", "transport_default")


class ModelFileError(ValueError):
    """The data is not an interface model this reader understands."""


@dataclass
class InterfaceModel:
    """One package's nodes for one distribution, with where they come from."""

    package: str
    distro: str | None
    nodes: list[Node] = field(default_factory=list)
    version: str = ""
    source: dict[str, str] = field(default_factory=dict)
    generator: dict[str, str] = field(default_factory=dict)
    override: str | None = None
    path: str = ""  # the file it was read from (not written)
    # BehaviorTree.CPP: the BT libraries the package builds (library -> registrations)
    # and a tree host's default trees (share path -> tree), as
    # ``plugins.behavior_trees.package_model_data`` writes them
    bt_libraries: dict[str, list[dict[str, Any]]] = field(default_factory=dict)
    bt_trees: dict[str, dict[str, Any]] = field(default_factory=dict)
    # ROS 1 launch models (``launch_files``): the package's launch files by their path
    # below its folder (None: not recorded, an older model; {}: it has none) and the
    # parameter files they load from it
    launch_files: dict[str, dict[str, Any]] | None = None
    param_files: dict[str, dict[str, Any]] = field(default_factory=dict)

    @property
    def label(self) -> str:
        """How the output names it: ``noetic/amcl 1.17.3 ros-planning/navigation@0123abcd``."""
        where = self.source.get("repository", "").removeprefix("github:")
        commit = self.source.get("commit", "")[:8]
        origin = f" {where}@{commit}" if where and commit else f" {where}" if where else ""
        version = f" {self.version}" if self.version else ""
        return f"{self.distro or 'any'}/{self.package}{version}{origin}"

    def node(self, executable: str) -> Node | None:
        """The node of this executable name, else the one releases also install under
        it (``Node.aliases``)."""
        return next((n for n in self.nodes if n.executable == executable), None) or next(
            (n for n in self.nodes if executable in n.aliases), None)


def to_document(model: InterfaceModel) -> dict[str, Any]:
    data: dict[str, Any] = {
        "schema": SCHEMA, "package": model.package, "distro": model.distro,
        "version": model.version, "source": dict(model.source),
        "generator": dict(model.generator) or {"name": "haros-arch", "version": __version__},
    }
    if model.override:
        data["override"] = model.override
    data["nodes"] = [to_data(node) for node in model.nodes]
    if model.bt_libraries:
        data["bt_libraries"] = model.bt_libraries
    if model.bt_trees:
        data["bt_trees"] = model.bt_trees
    if model.launch_files is not None:
        data["launch_files"] = model.launch_files
        data["param_files"] = model.param_files
    return data


def dumps(model: InterfaceModel) -> str:
    return json.dumps(to_document(model), indent=1, ensure_ascii=False, sort_keys=False) + "\n"


def from_document(data: Any, path: str = "") -> InterfaceModel:
    """An interface model from its data; raises ``ModelFileError`` saying what is wrong."""
    if not isinstance(data, dict):
        raise ModelFileError("an interface model is a JSON object")
    schema = data.get("schema")
    if not isinstance(schema, str) or not schema.startswith(SCHEMA_PREFIX):
        raise ModelFileError(f"schema is {schema!r}, expected {SCHEMA!r}")
    version = schema.removeprefix(SCHEMA_PREFIX)
    if not (version.isdigit() and len(version) < 4 and 1 <= int(version) <= SCHEMA_VERSION):
        raise ModelFileError(f"schema version {version[:20]!r} is not one this reader "
                             f"knows (1 to {SCHEMA_VERSION})")
    package = data.get("package")
    if not isinstance(package, str) or not package:
        raise ModelFileError("'package' must be the package's name")
    distro = data.get("distro")
    if distro is not None and not isinstance(distro, str):
        raise ModelFileError("'distro' must be a distribution name (noetic, jazzy, ...)")
    nodes = data.get("nodes")
    if not isinstance(nodes, list) or not all(isinstance(n, dict) for n in nodes):
        raise ModelFileError("'nodes' must be a list of node objects")
    calls = [c for n in nodes for c in _list(n.get("calls"))]
    if not all(isinstance(c, dict) and isinstance(c.get("name", ""), str) for c in calls):
        raise ModelFileError("each call must be an object with a string 'name'")
    for call in calls:
        if call.get("kind", "publish") not in CALL_KINDS:
            raise ModelFileError(f"a call's kind is {call.get('kind')!r}, expected one of "
                                 f"{', '.join(CALL_KINDS)}")
        if not all(isinstance(call.get(key), str | None) for key in _TEXT_FIELDS):
            raise ModelFileError(f"a call's {', '.join(_TEXT_FIELDS)} must be strings")
        for key in ("program_arg", "name_arg", "transport_arg"):
            arg = call.get(key)
            if arg is not None and (not isinstance(arg, int) or isinstance(arg, bool)
                                    or arg == 0):
                raise ModelFileError(f"a call's {key} must be a non-zero integer")
    try:
        built = [node_from_data(n, package) for n in nodes]
    except (TypeError, ValueError, AttributeError) as error:
        raise ModelFileError(f"a node entry cannot be read: {error}") from None
    for node in built:  # models written when a namespace passed as "" left "//name"
        node.rosname = node_name_joined(node.rosname) if node.rosname else node.rosname
        node.rosnames = [node_name_joined(n) for n in node.rosnames]
    libraries, trees = data.get("bt_libraries", {}), data.get("bt_trees", {})
    if not isinstance(libraries, dict) or not all(
            isinstance(k, str) and isinstance(v, list) for k, v in libraries.items()):
        raise ModelFileError("'bt_libraries' must map library names to lists")
    if not isinstance(trees, dict) or not all(
            isinstance(k, str) and isinstance(v, dict) for k, v in trees.items()):
        raise ModelFileError("'bt_trees' must map share paths to trees")
    launch, params = data.get("launch_files"), data.get("param_files", {})
    for key, value in (("launch_files", launch), ("param_files", params)):
        if value is not None and not (isinstance(value, dict) and all(
                isinstance(k, str) and isinstance(v, dict) for k, v in value.items())):
            raise ModelFileError(f"'{key}' must map paths in the package to objects")
    return InterfaceModel(package, distro, built, str(data.get("version") or ""),
                          _strings(data.get("source")), _strings(data.get("generator")),
                          data.get("override") if isinstance(data.get("override"), str)
                          else None, path, libraries, trees, launch, params or {})


def _list(value: Any) -> Sequence[Any]:
    return value if isinstance(value, list) else []


def _strings(value: Any) -> dict[str, str]:
    if not isinstance(value, dict):
        return {}
    return {str(k): str(v) for k, v in value.items() if v is not None}
