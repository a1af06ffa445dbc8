"""ros_gz bridges: nodes whose ROS interface is their arguments and their config file.

gz sim's systems talk gz transport; ``ros_gz_bridge parameter_bridge`` makes their topics
ROS topics, one per argument ``/topic@ros_type@gz_type`` (``@`` both ways: it publishes
and subscribes, ``[`` gz to ROS: it publishes, ``]`` ROS to gz: it subscribes; a
``/srv/`` type is a service it serves) and per entry of the YAML file its
``config_file`` parameter names (``ros_topic_name`` / ``gz_topic_name`` /
``topic_name``, ``ros_type_name``, ``direction`` BIDIRECTIONAL, GZ_TO_ROS, ROS_TO_GZ).
``ros_gz_image image_bridge`` publishes each topic its arguments name as an image, through
image_transport (so with its transport plugins' topics).
Facts from ros_gz's ``ros_gz_bridge/src/parameter_bridge.cpp``, ``bridge_config.cpp``,
``ros_gz_bridge.cpp`` and ``ros_gz_image/src/image_bridge.cpp``.

A bridge instance with no source gets these calls: with no interface model, on a node
made here (partial when its config file cannot be read); with one (the model knows the
bridge's parameters, not the topics they name), beside the model's calls. So does one
whose source is in the workspace (ros_gz itself): its code makes the topics from argv and
the config file, in factories generated at build time, so the source gives none; it is
made partial when its config file cannot be read.
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Sequence
from typing import Any, cast

import yaml

from .. import diagnostics as diag
from .. import safe_yaml
from ..files import read_text
from ..launch.model import LaunchModel, NodeDecl, shell_words
from ..model.location import Location
from ..model.runtime import Configuration, NodeInstance
from ..model.source import CallKind, Node, PrimitiveCall
from ..model.values import UNKNOWN_MARK
from ..plugins.attach import own_partial
from ..share import share_source
from ..workspace import Workspace

# (bridge_node: the RosGzBridge component as a program, ros_gz_bridge.cpp, which reads
# the same config_file; what the package's launch file and its <ros_gz_bridge> action run)
PARAMETER_BRIDGES = (("ros_gz_bridge", "parameter_bridge"),
                     ("ros_ign_bridge", "parameter_bridge"),
                     ("ros_gz_bridge", "bridge_node"))
IMAGE_BRIDGES = (("ros_gz_image", "image_bridge"), ("ros_ign_image", "image_bridge"))
MAX_ENTRIES = 1_000
_DIRECTIONS = {"BIDIRECTIONAL": ("publish", "subscribe"), "GZ_TO_ROS": ("publish",),
               "ROS_TO_GZ": ("subscribe",)}


def bridges(config: Configuration, launch: LaunchModel,
            started: Sequence[tuple[NodeDecl, NodeInstance]], workspace: Workspace,
            ) -> list[tuple[NodeInstance, list[PrimitiveCall]]]:
    """The calls of the ros_gz bridge instances whose interface is not otherwise known."""
    out = []
    owned: set[int] = set()
    for decl, instance in started:
        key = (decl.package, decl.executable)
        if key not in (*PARAMETER_BRIDGES, *IMAGE_BRIDGES):
            continue
        # known = from an interface model or from the workspace's own ros_gz sources:
        # either way the code makes its topics from argv and the config file at run
        # time (parameter_bridge's in factories generated at build time), not seen there
        known = instance.node is not None
        # the calls go on a node of their own: a model's node is shared by its instances
        node = Node(decl.package, decl.executable, location=decl.location)
        positional, params = _arguments(decl.args)
        if key in IMAGE_BRIDGES:
            # through image_transport::create_publisher (image_bridge.cpp): with the
            # topics of the transport plugins
            node.calls = [PrimitiveCall("publish", topic, "sensor_msgs/msg/Image",
                                        location=decl.location, origin="description",
                                        transport="*")
                          for topic in positional[:MAX_ENTRIES]]
        else:
            node.calls = list(_from_arguments(positional, decl.location))
            path = _launch_param(launch, decl, "config_file") or params.get("config_file")
            if path:
                node.calls.extend(_from_file(path, decl, node, workspace, config))
        if not known:
            # the program is neither in the workspace nor modelled: its topics are its
            # arguments and config file, but which parameters of its own it reads
            # depends on its release (``config_file``, ``lazy``, ...; galactic's
            # ros_ign_bridge reads none): a read of a private name not known, so a
            # parameter the launch file gives it is neither read nor unread
            node.calls.append(PrimitiveCall("read", f"~{UNKNOWN_MARK}", location=decl.location,
                                            origin="description"))
            instance.node = node
        elif node.completeness == "partial" and instance.node is not None:
            # a config file not read: the bridged topics are not known, whether the
            # program's interface is from its source or from a model (which says
            # complete: its topics come from the file at run time)
            for reason in node.completeness_reasons:
                own_partial(instance, reason, owned)
        out.append((instance, list(node.calls)))
    return out


def _arguments(args: str) -> tuple[list[str], dict[str, str]]:
    """Positional arguments before ``--ros-args``, and the ``-p name:=value`` after it."""
    words = shell_words(args)
    positional: list[str] = []
    params: dict[str, str] = {}
    ros = False
    for index, word in enumerate(words):
        if word == "--ros-args":
            ros = True
        elif word == "--":
            ros = False
        elif ros and word in ("-p", "--param") and index + 1 < len(words):
            name, sep, value = words[index + 1].partition(":=")
            if sep:
                params[name] = value
        elif not ros and not word.startswith("-"):
            positional.append(word)
    return positional, params


def _launch_param(launch: LaunchModel, decl: NodeDecl, key: str) -> str | None:
    """A parameter the launch file gives the declaration (ROS 2: by the declaration it
    was given to, as unnamed nodes share the name ``/?``)."""
    owners = {index for index, other in enumerate(launch.nodes) if other is decl or (
        (other.package, other.executable, other.location)
        == (decl.package, decl.executable, decl.location))}
    found = None
    for param in launch.params:
        mine = param.owner in owners if param.owner is not None else param.node == decl.name
        if param.key == key and mine and isinstance(param.value, str):
            found = param.value
    return found


def _from_arguments(words: list[str], where: Location) -> Iterator[PrimitiveCall]:
    for word in words[:MAX_ENTRIES]:
        topic, sep, rest = word.partition("@")
        if not sep or not topic:
            continue
        for mark, marked in (("@", ("publish", "subscribe")), ("[", ("publish",)),
                            ("]", ("subscribe",))):
            ros_type, found, _ = rest.partition(mark)
            if found and ros_type:
                kinds = marked
                break
        else:  # no direction mark: a service whose gz types are inferred, or nothing
            if "/srv/" not in rest or "@" in rest:
                continue
            ros_type, kinds = rest, ("server",)
        if "/srv/" in ros_type:
            kinds = ("server",)
        for kind in kinds:
            yield PrimitiveCall(cast(CallKind, kind), topic, ros_type, location=where,
                                origin="description")


def _from_file(path: str, decl: NodeDecl, node: Node, workspace: Workspace,
               config: Configuration) -> Iterator[PrimitiveCall]:
    if UNKNOWN_MARK in path or not os.path.isabs(path):
        node.mark_partial(f"config_file {path} is not known ({decl.location.file}:"
                          f"{decl.location.line})")
        return
    if not os.path.isfile(path):
        path = share_source(workspace, path)
    where = workspace.location(path, 1)
    document: Any = None
    if os.path.isfile(path) and workspace.readable(path):
        text, problems = read_text(path, where)
        config.diagnostics.extend(problems)
        try:
            document = safe_yaml.load(text) if text is not None else None
        except yaml.YAMLError:
            document = None
    if not isinstance(document, list):
        config.diagnostics.append(diag.make("BRIDGE_CONFIG_FILE", decl.location,
                                            path=workspace.relpath(path)))
        node.mark_partial(f"config_file {workspace.relpath(path)} is not read "
                          f"({decl.location.file}:{decl.location.line})")
        return
    for entry in document[:MAX_ENTRIES]:
        if not isinstance(entry, dict):
            continue
        topic = entry.get("ros_topic_name") or entry.get("topic_name") or \
            entry.get("gz_topic_name")
        ros_type = entry.get("ros_type_name")
        if not isinstance(topic, str) or not isinstance(ros_type, str):
            continue
        kinds = _DIRECTIONS.get(str(entry.get("direction", "BIDIRECTIONAL")), ())
        for kind in kinds:
            yield PrimitiveCall(cast(CallKind, kind), topic, ros_type, location=where,
                                origin="description")
