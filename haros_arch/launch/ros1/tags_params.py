"""``<param>`` and ``<rosparam>``: parameter values as roslaunch would set them.

Files named by ``textfile``, ``binfile`` and ``<rosparam file=...>`` are read only
inside the workspace or an installed package folder, with a size bound. ``command``
is never run: the parameter exists with an unknown value.
"""

from __future__ import annotations

import os
import shlex
from typing import TYPE_CHECKING, Any

import yaml
from lxml import etree

from ... import diagnostics as diag
from ... import safe_yaml
from ...files import read_bytes
from ...model.conditions import Condition
from ...model.location import Location
from ...model.values import Value
from ..model import ParamDecl, program_not_found
from ..partial_yaml import MARK, marked_text, unknown_parts
from ..paths import missing_argument_paths
from .params import (
    Binary,
    ParamError,
    RosparamLoader,
    convert_value,
    flatten,
    join,
    load_yaml,
    type_name,
)
from .scope import PrivateParam, Scope, canonical

if TYPE_CHECKING:
    from .loader import Ros1Loader

Element = etree._Element
MAX_PARAM_FILE = 2 * 1024 * 1024


_TYPE_NAMES = {"string": "str", "boolean": "bool"}


def tag_param(loader: Ros1Loader, element: Element, scope: Scope,
              local: bool = False) -> None:
    kind = (element.get("type") or "auto").lower().strip()
    sources = {key: loader.value(element, key, scope, command=key == "command")
               for key in ("value", "textfile", "binfile", "command")}
    given = [key for key, found in sources.items() if found is not None]
    if len(given) != 1:
        loader.fail(scope, element, "<param> tag must have one and only one of "
                                  "value/textfile/binfile/command")
        return
    source = given[0]
    raw = sources[source]
    assert raw is not None
    name = loader.resolve((element.get("name") or "").strip(), scope, element).text
    value: Any = None
    if raw.literal is not None:
        try:
            value = param_value(loader, source, raw.literal, kind, scope, element)
        except ParamError as err:
            loader.fail(scope, element, f"invalid <param> {name}: {err}")
            return
    elif source == "value" and kind not in ("auto", "str", "string", "int", "double",
                                            "bool", "boolean", "yaml"):
        loader.fail(scope, element, f"invalid <param> {name}: unknown type '{kind}'")
        return
    elif source == "command" and (line := program_not_found(raw)[0]) is not None:
        # ``$(find xacro)/xacro FILE`` with xacro not here: only its program's folder is
        # not known, which a command never run does not need (the robot description is
        # read from FILE, ``robot.attach``); its value is what is not known
        param_value(loader, source, line, kind, scope, element)
    where = loader.where(scope, element)
    set_twice(loader, element, scope, name)
    if source == "value" and isinstance(value, str) and kind != "yaml":
        # judged as a command line's ``name:=PATH`` word is (an output name skipped); a
        # path to a file name (one with an extension) only: a folder the node may make
        # (``$(dirname)/x``, a data or log folder) is not judged
        key = name.rsplit("/", 1)[-1].lstrip("~")
        for path in missing_argument_paths([f"{key}:={value.strip()}"], loader.workspace):
            if os.path.splitext(os.path.basename(path))[1]:
                loader.report("LAUNCH_PARAM_PATH_MISSING", scope, element, name=name,
                              path=loader.workspace.relpath(path))
    # the command line the value comes from (textfile: the file's content, as cat gives it)
    command = raw.text if source == "command" else (
        f"cat {shlex.quote(raw.text)}" if source == "textfile" else None)
    # a value not known here keeps the type= it is given, in the model's names
    declared = type_name(value) if value is not None else (
        None if kind == "auto" else _TYPE_NAMES.get(kind, kind))
    if name.startswith("~") or local:
        scope.add_private(PrivateParam(name, value, declared, scope.conditions, where,
                                       source, command))
    else:
        add_param(loader, join(scope.ns, name), value, declared, scope.conditions, where,
                  source, command)
        parent = element.getparent()
        if parent is not None and not _own_condition(element):
            loader.shared_param_tags[(id(parent), server_name(join(scope.ns, name)),
                                      tuple(c.text for c in scope.conditions))] = element


def _own_condition(element: Element) -> bool:
    return element.get("if") is not None or element.get("unless") is not None


def loaded_over(loader: Ros1Loader, element: Element, scope: Scope, name: str,
                where: Location) -> None:
    """``LAUNCH_PARAM_LOADED_OVER`` at an earlier ``<param>`` of the element that holds
    this ``<rosparam>`` (outside a node, neither with an if / unless of its own, under
    the same conditions) that set ``name``, which the rosparam loads again: roslaunch
    adds both to its parameters in document order, and the later wins without a word."""
    parent = element.getparent()
    if parent is None or _own_condition(element):
        return
    earlier = loader.shared_param_tags.pop(
        (id(parent), name, tuple(c.text for c in scope.conditions)), None)
    if earlier is not None and earlier.getparent() is parent:
        loader.report("LAUNCH_PARAM_LOADED_OVER", scope, earlier, name=name,
                      other=f"{where.file}:{where.line}")

def set_twice(loader: Ros1Loader, element: Element, scope: Scope, name: str) -> None:
    """``LAUNCH_PARAM_SET_TWICE`` when an earlier ``<param>`` child of the same element
    set ``name`` in the same namespace under the same conditions (neither tag with an
    ``if`` / ``unless`` of its own): roslaunch silently keeps the later value."""
    parent = element.getparent()
    if parent is None or element.get("if") is not None or element.get("unless") is not None:
        return
    key = (id(parent), scope.ns, name, tuple(c.text for c in scope.conditions))
    first = loader.param_tags.setdefault(key, element)
    if first is not element and first.getparent() is parent:
        loader.report("LAUNCH_PARAM_SET_TWICE", scope, element, name=name,
                      line=first.sourceline)


def param_value(loader: Ros1Loader, source: str, text: str, kind: str, scope: Scope,
                element: Element) -> Any:
    if source == "value":
        return convert_value(text.strip(), kind)
    if source == "command":
        loader.report("LAUNCH_UNKNOWN_VALUE", scope, element,
                    detail=f"command \"{text}\" is not run")
        return None
    data = read_param_file(loader, text, scope, element)
    if data is None:
        return None
    if source == "binfile":
        return Binary.of(data)
    return convert_value(data.decode("utf-8", errors="replace"), kind)

def read_param_file(loader: Ros1Loader, path: str, scope: Scope, element: Element
                    ) -> bytes | None:
    if not os.path.isabs(path):
        # roslaunch opens it from the folder it runs in, which no file says (not the
        # folder this tool runs in)
        loader.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=(
            f"{path!r} is a relative path, opened from the folder roslaunch runs in; it is "
            "not read"))
        return None
    unheld = loader.unheld(path)
    if unheld is not None or (loader.models is not None and loader.models.holds(path)):
        # a file of a package not here that its model has not (or only parsed, for
        # ``<rosparam>``): what it holds is not known
        loader.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=unheld or (
            f"{loader.relpath(path)} is kept as parsed values, not as its text"))
        return None
    path = os.path.realpath(path)
    if not loader.workspace.readable(path, loader.environment):
        loader.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=(
            f"{path} is outside the workspace and installed packages; it is not read"))
        return None
    if not os.path.isfile(path) and (
            note := loader.workspace.submodule_note(path)) is not None:
        loader.report("LAUNCH_UNKNOWN_VALUE", scope, element, detail=note)
        return None
    if not os.path.isfile(path):
        loader.fail(scope, element, f"file does not exist: {loader.workspace.relpath(path)}"
                                    f"{loader.unset_hint(path)}")
        return None
    data, found = read_bytes(path, loader.where(scope, element), MAX_PARAM_FILE)
    loader.model.diagnostics.extend(found)
    return data

def add_param(loader: Ros1Loader, name: str, value: Any, kind: str | None,
              conditions: tuple[Condition, ...], location: Location,
              source: str = "value", command: str | None = None,
              setting: str | None = None) -> None:
    """A parameter the launch file sets (``source``: value, textfile, binfile, command,
    rosparam; ``command``: the command line of ``command=``; ``setting``: the parameter
    file loaded into several nodes that gave it, ``ParamDecl.setting``)."""
    loader.model.params.append(ParamDecl(server_name(name), value, kind, conditions,
                                         location, command=command, setting=setting))


def server_name(name: str) -> str:
    """The parameter server's name for a launch parameter: roslaunch sets a ``~name``
    left at the top (no node took it) as the caller ``/roslaunch``, so the master
    stores it as ``/roslaunch/name``."""
    return canonical("/roslaunch/" + name[1:] if name.startswith("~") else name)

def tag_rosparam(loader: Ros1Loader, element: Element, scope: Scope,
                 in_node: bool = False) -> None:
    """``<rosparam>``; ``in_node``: a child of a ``<node>``, in its private namespace.
    A file loaded there is a setting for every node it is loaded into (``setting``:
    its path): a launch file that loads one parameter file into several nodes gives
    each all of it, for each to read what it needs (f1tenth_simulator's params.yaml in
    its five nodes), so a key is unread only when none of them reads it."""
    command = loader.text(element, "command", scope) or "load"
    ns = loader.text(element, "ns", scope)
    named = loader.text(element, "param", scope)
    file = loader.value(element, "file", scope)
    subst = loader.flag(element, "subst_value", scope, False)
    param = join(ns or "", named or "") if (ns or named) else ""
    if command not in ("load", "dump", "delete"):
        loader.fail(scope, element, "command must be 'load', 'dump', or 'delete'")
        return
    if file is not None and command == "delete":
        loader.fail(scope, element, "'file' attribute is invalid with 'delete' command.")
        return
    full = join(scope.ns, param) if param else scope.ns
    if command == "dump":
        return
    if command == "delete":
        loader.model.deleted_params.append(server_name(full))
        return
    where = loader.where(scope, element)
    if file is not None:
        if file.literal is None:
            if named:  # ``param=``: that parameter is set, to what the file holds
                add_param(loader, full, None, None, scope.conditions, where, "rosparam")
            # else (a dictionary, as roslaunch requires) only what is under the namespace
            unseen(loader, full, scope, where)
            return
        modelled = loader.models.params(file.literal) if loader.models is not None else None
        data = None if modelled is not None else read_param_file(loader, file.literal,
                                                                  scope, element)
        if data is None and modelled is None:
            unseen(loader, full, scope, where)
            return
        text = data.decode("utf-8", errors="replace") if data is not None else ""
        lines = _key_lines(text) if modelled is None else modelled[1]
        # (PyYAML replaces a mapping written twice whole: its first keys are gone too)
        for twice, first, later in safe_yaml.keys_twice(text, RosparamLoader, merging=False):
            said = diag.make("LAUNCH_PARAM_FILE_KEY_TWICE", loader.place(
                file.literal, later), key="/".join(twice), line=first,
                reader="roslaunch (PyYAML)")
            if said not in loader.model.diagnostics:
                loader.model.diagnostics.append(said)
    else:
        text = (element.text or "") + "".join(c.tail or "" for c in element)
        lines, modelled = None, None
    if subst is None:
        subst = True  # unknown: substitute, as values do not change otherwise
    if subst and modelled is None:  # (a modelled file holds no substitution)
        value = loader.resolve(text, scope, element)
        text = marked_text(value)
    try:
        data_value = load_yaml(text) if modelled is None else modelled[0]
    except ParamError as err:
        loader.report("LAUNCH_YAML", scope, element, detail=str(err))
        unseen(loader, full, scope, where)
        return
    if data_value is None:
        data_value = {}
    if isinstance(data_value, str) and MARK in data_value and (
            not param or canonical(full) == "/"):
        # text a substitution not known statically makes (``$(arg robot_ips)``): it may
        # well be the dictionary roslaunch wants; what it sets is not known
        unseen(loader, full, scope, where)
        return
    if not param and not isinstance(data_value, dict):
        loader.report("LAUNCH_YAML", scope, element, detail=(
            "'param' attribute must be set for non-dictionary values"))
        return
    if canonical(full) == "/" and not isinstance(data_value, dict):
        loader.report("LAUNCH_YAML", scope, element, detail=(
            "cannot load non-dictionary values into the global namespace '/'"))
        return
    setting = file.literal if in_node and file is not None else None
    # a parameter of a file is where its key is written (a finding about it points
    # there: the file is what a fix changes), the others where the element is
    keys = dict(flatten(full, lines)) if isinstance(lines, dict) and file is not None \
        and file.literal is not None else {}
    for name, leaf in flatten(full, data_value):
        leaf = unknown_parts(leaf)
        line = keys.get(name)
        place = loader.place(file.literal, line) if (
            isinstance(line, int) and file is not None and file.literal is not None) \
            else where
        add_param(loader, name.replace(MARK, "?"), leaf,
                  type_name(leaf) if leaf is not None else None,
                  scope.conditions, place, "rosparam", setting=setting)
        if not in_node and MARK not in name:
            loaded_over(loader, element, scope, server_name(name), place)


def _key_lines(text: str) -> Any:
    """Where each key of a parameter file is written (``safe_yaml.load_with_lines``, with
    the loader the values are read with: rosparam's ``!degrees`` / ``!radians`` tags, which
    pmb2_2dnav's amcl.yaml writes); None when the file cannot be read so (its diagnostic
    is the load's)."""
    try:
        return safe_yaml.load_with_lines(text, RosparamLoader)[1]
    except (yaml.YAMLError, ValueError, RecursionError):
        return None


def unseen(loader: Ros1Loader, namespace: str, scope: Scope, where: Location) -> None:
    """A ``<rosparam>`` whose content is not known (its file not named statically, not
    read, or not YAML): it may set any parameter under its namespace, which the model
    says with a parameter ``<namespace>/?`` set by the launch (unknown is not empty)."""
    add_param(loader, join(namespace, "?"), None, None, scope.conditions, where, "rosparam")


__all__ = ["Value", "add_param", "tag_param", "tag_rosparam"]
