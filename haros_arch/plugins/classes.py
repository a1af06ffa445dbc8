"""Plugin classes: pluginlib exports of a package, read down to the library that builds them.

package.xml ``<export><nodelet plugin="${prefix}/nodelets.xml"/>`` (any export tag, and
ROS 2's ``pluginlib_export_plugin_description_file``) names a plugin description; its
``<library path="lib/libfoo">`` elements (one, several in ``<class_libraries>``, or several
at the top of a file, which pluginlib reads too) hold
``<class name="pkg/Name" type="ns::Class" base_class_type="..."/>`` entries. Each class
becomes a ``Node`` of kind ``nodelet`` or ``plugin`` whose executable is the name launch
files and hosts use (``pkg/Name``, else the type) and whose sources are those of the
library target ``foo``. When no target builds that library, the class is looked
for in ``PLUGINLIB_EXPORT_CLASS`` / ``PLUGINLIB_DECLARE_CLASS`` of the package's
libraries.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Collection, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol, TypeVar

from lxml import etree

from .. import diagnostics as diag
from ..ctext import code_only
from ..diagnostics import Diagnostic
from ..facts import remember
from ..files import kept_in, read_bytes, read_text
from ..manifest import xml_parser
from ..model.conditions import Condition
from ..model.location import Location
from ..model.source import Node, NodeKind, Package, Plugin
from .hosts import hosted_class, hosted_tag, node_name_patterns

NODE_PLUGIN_KINDS = ("nodelet",)
_EXPORT = re.compile(
    r"(PLUGINLIB_EXPORT_CLASS|PLUGINLIB_DECLARE_CLASS|RCLCPP_COMPONENTS_REGISTER_NODE"
    r"|MAVROS_PLUGIN_REGISTER|CLASS_LOADER_REGISTER_CLASS)\s*\(([^)]*)\)")
_EXPORT_MARKS = ("PLUGINLIB_", "RCLCPP_COMPONENTS_", "MAVROS_PLUGIN_REGISTER",
                 "CLASS_LOADER_REGISTER_CLASS")
MAX_NAME_SCAN = 200_000  # characters of a source searched for a plugin node's name


T = TypeVar("T")


class Files(Protocol):
    """What the build-file stage needs of a workspace (``Workspace`` is one)."""

    root: str

    def location(self, path: str, line: int = 0, column: int = 0) -> Location: ...

    def relpath(self, path: str) -> str: ...

    def holds(self, path: str) -> bool: ...

    def submodule_of(self, path: str) -> tuple[str, str] | None: ...


def _nothing() -> list[list[str]]:
    return []


@dataclass(frozen=True)
class Library:
    """A library target as far as plugins care: its sources (with those of the package
    libraries it links, for nodelets) and conditions; ``own``: the target's own sources
    (a host plugin links its host's framework library, whose code is the host's);
    ``elsewhere``: the sources of the other workspace packages it links, and of those
    these link, a list per package (``SourceMap.reached``; asked only for a class's
    base classes)."""

    sources: list[str]  # workspace-relative
    conditions: tuple[Condition, ...] = ()
    own: list[str] | None = None
    elsewhere: Callable[[], list[list[str]]] = _nothing
    # a nodelet's files with those of other workspace packages' libraries the target
    # links that they name (``cmake.nodes``' ``with_elsewhere``, as a component's)
    with_elsewhere: Callable[[list[str]], list[str]] | None = field(default=None,
                                                                    compare=False)


def library_name(path: str) -> str:
    """``lib/libfoo`` / ``libfoo.so`` / ``foo`` → ``foo``."""
    name = os.path.basename(path)
    name = re.sub(r"\.(so|dylib|dll)(\.\d+)*$", "", name)
    return name[3:] if name.startswith("lib") and len(name) > 3 else name


# a pluginlib ClassLoader of a base class (``pluginlib::ClassLoader<karto::ScanSolver>``)
_CLASS_LOADER = re.compile(r"\bClassLoader\s*<\s*([A-Za-z_][\w:]*)\s*>")


# a ClassLoader's creation of a class named by a literal (``createSharedInstance("pkg::C")``)
_NAMED_LOAD = re.compile(
    r"\bcreate(?:Shared|Unique|Unmanaged|Class)?Instance\s*\(\s*\"([A-Za-z_][\w/:]*)\"\s*\)")


def named_loads(roots: Iterable[str], workspace: Files) -> frozenset[str]:
    """The plugin classes (lookup names or C++ types) that the C++ files of these package
    folders (their tests left out) create by a name written in the code: given the
    packages that depend on a plugin's package, where the code that loads it usually is
    (cyberdog's sensor_manager creates ``cyberdog::sensor::GpsCarpo``, exported by
    cyberdog_gps), so that class is a plugin node (``plugin_classes``)."""
    found: set[str] = set()
    for root in roots:
        found.update(remembered("named class loads", root, workspace,
                                lambda r=root: _named(r, workspace)))  # type: ignore[misc]
    return frozenset(found)


def _named(root: str, workspace: Files) -> frozenset[str]:
    found: set[str] = set()
    for _path, text in _loader_texts(root, workspace, literals=True):
        found.update(m.group(1).lstrip(":") for m in _NAMED_LOAD.finditer(text))
    return frozenset(found)


def loaded_bases(roots: Iterable[str], workspace: Files) -> frozenset[str]:
    """The base classes (the last part of their names) that pluginlib ClassLoaders in the
    C++ files of these package folders load (their tests left out): the packages' code
    may create a class of them by a parameter's value (``api.PLUGINLIB``), so a
    package's exported classes of those bases are plugin nodes (``plugin_classes``).
    Given the package's own folder and those of the workspace packages it depends on
    (dwb_plugins' trajectory generator, of the base dwb_core's planner loads)."""
    found: set[str] = set()
    for root in roots:
        found.update(remembered("class loaders", root, workspace,
                                lambda r=root: _loaders(r, workspace)))  # type: ignore[misc]
    return frozenset(found)


_CPP_FILES = (".cpp", ".cc", ".cxx", ".hpp", ".h", ".hh", ".hxx")


# a ClassLoader of whatever class a template of the workspace is given: ros_canopen's
# ``template<typename T> class GuardedClassLoader { ... pluginlib::ClassLoader<T> ... }``,
# whose constructions (``GuardedClassLoader<can::DriverInterface>``) no ClassLoader names
ANY_BASE = "*"
_TEMPLATE_PARAMETERS = re.compile(r"\btemplate\s*<([^<>]*)>")
_TYPE_PARAMETER = re.compile(r"\b(?:typename|class)\s+([A-Za-z_]\w*)")


def _generic_loader(text: str) -> bool:
    """Whether ``text`` declares a ClassLoader of a type parameter of a template it
    declares (the class it loads is the one each use of the template gives)."""
    bases = {match.group(1) for match in _CLASS_LOADER.finditer(text)}
    if not bases:
        return False
    parameters = {name for match in _TEMPLATE_PARAMETERS.finditer(text)
                  for name in _TYPE_PARAMETER.findall(match.group(1))}
    return bool(bases & parameters)


def _loaders(root: str, workspace: Files) -> frozenset[str]:
    found: set[str] = set()
    for _path, text in _loader_texts(root, workspace):
        found.update(loader_bases(text))
        if _generic_loader(text):
            found.add(ANY_BASE)
    return frozenset(found)


def _loader_texts(root: str, workspace: Files, literals: bool = False
                  ) -> Iterator[tuple[str, str]]:
    """The C++ files of a package folder (tests and build trees left out) that name a
    ClassLoader, as code without comments (and, unless ``literals``, without the insides
    of string literals)."""
    for folder, dirs, names in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in (
            "test", "tests", "build", "install"))
        for name in sorted(names):
            if not name.endswith(_CPP_FILES):
                continue
            path = os.path.join(folder, name)
            data, _ = read_bytes(path, workspace.location(path))
            if data is None or b"ClassLoader" not in data:
                continue
            yield path, code_only(data.decode("utf-8", "replace"), literals)


def loader_bases(text: str) -> set[str]:
    """The base classes (the last part of their names) of the pluginlib ClassLoaders
    ``text`` declares (``ClassLoader<karto::ScanSolver>``: ``ScanSolver``)."""
    return {base_name(match.group(1)) for match in _CLASS_LOADER.finditer(text)}


def base_name(base: str) -> str:
    """The last part of a base class's name, without template arguments."""
    return base.split("<", 1)[0].strip().rsplit("::", 1)[-1]


def plugin_classes(package: Package, workspace: Files, libraries: Mapping[str, Library],
                   described: Sequence[Plugin] = (), loaded: frozenset[str] = frozenset(),
                   named: frozenset[str] = frozenset(),
                   ) -> tuple[list[Node], list[Diagnostic]]:
    """Nodes for the classes of the package's plugin descriptions: package.xml exports
    and ``described`` (ROS 2's ``pluginlib_export_plugin_description_file``).

    A nodelet (export tag ``nodelet``) is a ``nodelet`` node; a class some host of
    ``hosts.HOSTS`` loads (its export tag or base class is one the table names) is a
    ``plugin`` node. Each is named by its pluginlib lookup name (``name``, else
    ``type``) and keeps its C++ type in ``plugin_class``; so is a class of a base that
    ``loaded`` names (``loaded_bases`` of the package's code), and a class ``named``
    holds by lookup name or type (``named_loads`` of the code of the packages that
    depend on it). Classes nothing loads (rviz, rqt panels) are not nodes.
    """
    # they read classes with this module's helpers
    from .inherit import built_sources, inherited_sources

    names = node_name_patterns()
    nodes: list[Node] = []
    found: list[Diagnostic] = []
    for plugin in [*package.plugins, *described]:
        # a description of classes some host loads, else read for the loaded bases only
        hosted = plugin.kind in NODE_PLUGIN_KINDS or hosted_tag(plugin.kind)
        if not hosted and not loaded and not named:
            continue
        path = os.path.join(workspace.root, plugin.file)
        if plugin in package.plugins and package.build_type in (
                "ament_cmake", "ament_python") and not os.path.isfile(path):
            # an ament package's package.xml export that names no file: ROS 2's
            # pluginlib reads the descriptions the CMake files export
            # (``pluginlib_export_plugin_description_file``), never this one
            # (moveit2_tutorials keeps ROS 1's ``<moveit_core plugin=...>`` to a file of
            # a folder its CMakeLists.txt no longer adds): nothing to read, no error
            continue
        roots = _read_description(path, workspace, found)
        if not roots:
            continue
        root = roots[0]
        # pluginlib reads the first element (stepping into <class_libraries>) and the
        # <library> elements that follow it at the top (a file of several <library>
        # roots, as pointcloud_to_laserscan's nodelets.xml is, loads every one)
        elements = [r for r in roots if r.tag == "library"] if root.tag == "library" \
            else list(root.iter("library"))
        for element in elements:
            wanted = library_name(element.get("path", ""))
            for cls in element.iter("class"):
                name = cls.get("name") or cls.get("type")
                base = cls.get("base_class_type", "")
                # pluginlib's ClassLoader(tag, base) finds the classes exported under its
                # own tag: a class whose tag no host names is loaded by no host, whatever
                # its base (navigation2's dwb_plugins exports goal checkers of
                # nav2_core::GoalChecker under dwb_core, which the controller server's
                # ClassLoader("nav2_core", ...) never reads); it is a node only as one a
                # ClassLoader of its package or its dependencies' code may load, by base,
                # or one the code of a package depending on it creates by its name
                # (or of any base, where a template of that code is a loader of
                # whatever class it is given: a node only once a load names its base)
                by_code = bool(base) and (base_name(base) in loaded or (
                    ANY_BASE in loaded) or bool(
                    named & {(name or "").lstrip(":"), (cls.get("type") or "").lstrip(":")}))
                if not name or (plugin.kind not in NODE_PLUGIN_KINDS and base and (
                        not hosted_class(plugin.kind, base)) and not by_code):
                    continue
                if not base and not hosted:
                    continue  # a description read only for the loaded bases
                where = workspace.location(path, _line(cls), 0)
                type_name = cls.get("type", "")
                registered = _registered(type_name, libraries.get(wanted), libraries,
                                         workspace)
                library = libraries.get(wanted) or _exporting(registered, libraries,
                                                              workspace)
                kind: NodeKind = "nodelet" if plugin.kind in NODE_PLUGIN_KINDS else "plugin"
                # a class only code's ClassLoaders load: a node once something loads it
                # (``Node.deferred``), nothing said of it before
                deferred = kind == "plugin" and bool(base) and not hosted_class(
                    plugin.kind, base)
                if library is None and not deferred:
                    found.append(diag.make("PLUGIN_LIBRARY_UNKNOWN", where,
                                           library=wanted, plugin=name))
                files = [] if library is None else library.sources if (
                    kind == "nodelet" or library.own is None) else library.own
                sources = narrow(files, registered, workspace)
                if sources and library is not None:
                    # its base classes' code, in whichever library it links builds it,
                    # of its package or of another
                    sources += inherited_sources(registered, sources, library.sources,
                                                 workspace, library.elsewhere)
                    if kind == "plugin":
                        # and the code of the classes it builds of the libraries it
                        # links, of its package (MoveIt's OMPL planner builds
                        # moveit_ompl_interface's OMPLInterface) or of others
                        # (dwa_local_planner's members of base_local_planner's
                        # classes), not of those it is given
                        sources += [s for s in built_sources(
                            sources, workspace, _with_linked(library))
                            if s not in sources]
                    if kind == "plugin" and library.with_elsewhere is not None:
                        # and the free functions of other packages' libraries it links
                        # that its code calls: they take its handle as an argument
                        # (abb_robot_driver's ``utilities::getParameter(controller_nh,
                        # "publish_rate", ...)``); not a class's members, whose object
                        # the host may give it with handles of its own
                        sources += free_function_sources(sources, library.with_elsewhere,
                                                         workspace)
                    if kind == "nodelet" and library.with_elsewhere is not None:
                        # and what it names of other packages' libraries it links:
                        # mrs_uav_managers' nodelets build mrs_lib's ParamLoader, whose
                        # ParamProvider reads their parameters
                        sources = library.with_elsewhere(sources)
                if files and not sources and not deferred:
                    found.append(diag.make("PLUGIN_CLASS_NOT_BUILT", where, plugin=name,
                                           cls=registered, library=wanted or "?"))
                nodes.append(Node(package.name, name, kind, "cpp", sources,
                                  rosname=_node_name(sources, names.get(base), workspace),
                                  conditions=library.conditions if library else (),
                                  location=where, plugin_class=type_name or None,
                                  plugin_base=base or None, deferred=deferred))
    return nodes, found


def _with_linked(library: Library) -> Callable[[], list[list[str]]]:
    """The groups of sources a plugin's code may build classes of: those of the
    package's libraries its library links (beyond its own), then other packages'."""
    def groups() -> list[list[str]]:
        own = set(library.own or ())
        linked = [s for s in library.sources if s not in own] if library.own else []
        return [linked, *library.elsewhere()] if linked else library.elsewhere()
    return groups


_PROLOGUE = re.compile(rb"^(\xef\xbb\xbf)?\s*(<\?xml[^>]*\?>)?")
# a comment, or a tag with its quoted attribute values (which may hold ``<`` and ``>``)
_TAG = re.compile(rb"<!--.*?-->|<(?![!?])(?:\"[^\"]*\"|'[^']*'|[^'\">])*>", re.DOTALL)
_QUOTED = re.compile(rb"\"[^\"]*\"|'[^']*'")


def _escaped_attributes(data: bytes) -> bytes:
    """``data`` with ``<`` and ``>`` inside attribute values escaped: TinyXML, which
    pluginlib reads descriptions with, takes them as written, and filters' plugins
    write their base class so (``base_class_type="filters::FilterBase<T>"``)."""
    def tag(match: re.Match[bytes]) -> bytes:
        text = match.group(0)
        if text.startswith(b"<!--"):
            return text
        return text[:1] + _QUOTED.sub(lambda quoted: quoted.group(0).replace(
            b"<", b"&lt;").replace(b">", b"&gt;"), text[1:])
    return _TAG.sub(tag, data)


def lookup_types(package: Package, workspace: Files) -> dict[str, str]:
    """pluginlib lookup name -> C++ type of the classes the package's plugin
    descriptions export (``<class name="image_proc/debayer" type="image_proc::
    DebayerNodelet">``)."""
    def compute() -> dict[str, str]:
        out: dict[str, str] = {}
        for plugin in package.plugins:
            roots = _read_description(os.path.join(workspace.root, plugin.file), workspace,
                                      [])
            for root in roots or ():
                for cls in root.iter("class"):
                    name, type_ = cls.get("name"), cls.get("type")
                    if name and type_:
                        out.setdefault(name, type_.lstrip(":"))
        return out

    return remembered("lookup types", package.name, workspace, compute)


def _read_description(path: str, workspace: Files,
                      found: list[Diagnostic]) -> list[etree._Element]:
    """The top-level elements of a plugin description: one, or several where the file
    has more than one root (not well-formed XML, but pluginlib's TinyXML reads it, as it
    reads ``<`` in an attribute's value)."""
    data, problems = read_bytes(path, workspace.location(path))
    found.extend(problems)
    if data is None:
        return []
    try:
        return [etree.fromstring(data, xml_parser())]
    except etree.XMLSyntaxError as err:
        error = err
    if "Unescaped '<' not allowed in attributes values" in error.msg:
        data = _escaped_attributes(data)
        try:
            return [etree.fromstring(data, xml_parser())]
        except etree.XMLSyntaxError as err:
            error = err
    if "Extra content at the end of the document" in error.msg:
        # the same bytes inside one wrapper element; the XML declaration, allowed only
        # at the very start, becomes blanks so lines and columns stay as they were
        prologue = _PROLOGUE.match(data)
        head = len(prologue.group(0)) if prologue else 0
        blanked = re.sub(rb"[^\n]", b" ", data[:head]) + data[head:]
        try:
            wrapper = etree.fromstring(b"<roots>" + blanked + b"</roots>", xml_parser())
        except etree.XMLSyntaxError:
            pass
        else:
            return [child for child in wrapper if isinstance(child.tag, str)]
    line, column = error.position if error.position else (0, 0)
    found.append(diag.make("PLUGIN_XML_SYNTAX", workspace.location(path, line, column),
                           detail=error.msg))
    return []


def remembered(kind: str, source: str, workspace: Files, compute: Callable[[], T]) -> T:
    """What ``compute`` says of a file, asked once per run where the workspace keeps
    such facts (``Workspace.file_facts``: every executable linking a library, and every
    package linking another's, asks them again), and taken from an earlier run where the
    files it was read from are unchanged (``facts.remember``)."""
    return remember(workspace, kind, source, compute)


def exported_classes(path: str, workspace: Files) -> list[tuple[str, int]]:
    """Classes a C++ file exports with a pluginlib or rclcpp_components macro, with lines."""
    return remembered("exported", path, workspace, lambda: _exported(path, workspace))


def _exported(path: str, workspace: Files) -> list[tuple[str, int]]:
    text = _text(path, workspace)
    if not text:
        return []
    wrappers = _wrappers_used(path, text, workspace)
    if not wrappers and not any(mark in text for mark in _EXPORT_MARKS):
        return []
    text = code_only(text, literals=True)
    # a macro's body exports nothing where it is defined, only where it is invoked
    defined = [m.span() for m in _DEFINITION.finditer(text)]
    out = []
    for match in _EXPORT.finditer(text):
        cls = _exported_class(match.group(1), match.group(2))
        if cls and not any(a <= match.start() < b for a, b in defined):
            out.append((cls, text.count("\n", 0, match.start()) + 1))
    for name, (params, macro, arguments) in wrappers.items():
        for use in re.finditer(r"\b" + re.escape(name) + r"\s*\(([^)]*)\)", text):
            values = [v.strip() for v in use.group(1).split(",")]
            if len(values) != len(params) or any(a <= use.start() < b for a, b in defined):
                continue
            given = dict(zip(params, values, strict=True))
            cls = _exported_class(macro, _expanded(arguments, given))
            if cls:
                out.append((cls, text.count("\n", 0, use.start()) + 1))
    return sorted(out, key=lambda found: found[1])


def _exported_class(macro: str, arguments: str) -> str | None:
    """The class an export macro's arguments name: the first word,
    ``PLUGINLIB_DECLARE_CLASS(pkg, Name, ns::Class, Base)``'s third."""
    words = re.findall(r"[A-Za-z_][\w:]*", arguments)
    if not words:
        return None
    return (words[2] if macro == "PLUGINLIB_DECLARE_CLASS" and len(words) > 2
            else words[0]).lstrip(":")


# a function-like macro's definition, its continued lines with it: name, parameters, body
_DEFINITION = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)(?:\(([^)]*)\))?"
                         r"((?:[^\n]*\\\n)*[^\n]*)", re.MULTILINE)
# a macro invoked at the start of a line, as exports are (outside any function)
_INVOKED = re.compile(r"^[ \t]*([A-Z_][A-Z0-9_]*)[ \t]*\(", re.MULTILINE)


def _wrappers_used(path: str, text: str, workspace: Files
                   ) -> dict[str, tuple[list[str], str, str]]:
    """The macros of the workspace that wrap an export macro (``export_wrappers``) which
    ``text`` (the file at ``path``) invokes at the start of a line, defined there or in
    a header of the workspace it includes: swri_nodelet's ``SWRI_NODELET_EXPORT_CLASS(NS,
    CLASS)``, ``PLUGINLIB_EXPORT_CLASS(NS::CLASS, nodelet::Nodelet)`` and a factory."""
    invoked = {m.group(1) for m in _INVOKED.finditer(text)}
    if not invoked:
        return {}
    found: dict[str, tuple[list[str], str, str]] = {}
    for source in (path, *included_headers(path, text, workspace),
                   *_other_packages_headers(text, workspace)):
        for name, wrapper in export_wrappers(source, workspace).items():
            if name in invoked:
                found.setdefault(name, wrapper)
    return found


def _other_packages_headers(text: str, workspace: Files) -> list[str]:
    """The headers ``text`` includes as ``<pkg/...>`` from the ``include`` folder of
    another package ``pkg`` of the workspace (swri_transform_util's nodelets include
    ``<swri_nodelet/class_list_macros.h>``)."""
    return [path for _package, path in _packages_headers(text, workspace)]


def _packages_headers(text: str, workspace: Files) -> list[tuple[str, str]]:
    """``_other_packages_headers``, each with the name of its package."""
    packages = getattr(workspace, "packages", None) or {}
    out = []
    for header in INCLUDE.findall(text)[:MAX_NAMED_HEADERS]:
        name = header.split("/", 1)[0] if "/" in header else ""
        package = packages.get(name) if name else None
        candidate = None if package is None else os.path.normpath(
            os.path.join(package.root, "include", header))
        if candidate is not None and os.path.isfile(candidate) and workspace.holds(candidate):
            out.append((name, candidate))
    return out


def linked_headers(sources: Iterable[str], packages: Collection[str],
                   workspace: Files) -> list[str]:
    """The headers of the workspace packages ``packages`` (those whose libraries a node
    links) that ``sources`` include as ``<pkg/...>``, themselves or through a header of
    their own package they include (``named_words``' depth): their inline code runs in
    the node (mrs_lib's param_loader.h, whose template ``ParamLoader`` holds a
    ``ParamProvider``)."""
    out: dict[str, None] = {}
    for source in sources:
        for package, header in _included_elsewhere(source, workspace):
            if package in packages:
                out.setdefault(header)
    return list(out)


def _included_elsewhere(source: str, workspace: Files) -> list[tuple[str, str]]:
    """(package, path) of each header of another workspace package that ``source``
    includes, itself or through a header of its package it includes."""
    def compute() -> list[tuple[str, str]]:
        path = os.path.join(workspace.root, source)
        found: dict[tuple[str, str], None] = {}
        for each in (path, *included_headers(path, _text(path, workspace) or "", workspace)):
            for pair in _packages_headers(_text(each, workspace) or "", workspace):
                found.setdefault(pair)
        return list(found)

    return remembered("other packages' headers", source, workspace, compute)


def export_wrappers(path: str, workspace: Files) -> dict[str, tuple[list[str], str, str]]:
    """The function-like macros a C++ file defines whose body invokes an export macro:
    name -> (parameters, the export macro, its arguments as written in the body)."""
    def wrappers() -> dict[str, tuple[list[str], str, str]]:
        text = _text(path, workspace)
        if not text or "define" not in text or not any(m in text for m in _EXPORT_MARKS):
            return {}
        found = {}
        for definition in _DEFINITION.finditer(code_only(text, literals=True)):
            export = _EXPORT.search(definition.group(3).replace("\\\n", " "))
            # (mavros defines MAVROS_PLUGIN_REGISTER, which ``_EXPORT`` reads as it is)
            if definition.group(2) is not None and export is not None and not (
                    _EXPORT.match(definition.group(1) + "()")):
                params = [p.strip() for p in definition.group(2).split(",")]
                found[definition.group(1)] = (params, export.group(1), export.group(2))
        return found
    return remembered("export wrappers", path, workspace, wrappers)


def _expanded(body: str, values: Mapping[str, str]) -> str:
    """A macro's ``body`` with its parameters replaced by ``values``, ``##`` pasted."""
    replaced = re.sub(r"\b\w+\b", lambda m: values.get(m.group(0), m.group(0)), body)
    return re.sub(r"\s*##\s*", "", replaced)


def header_exports(source: str, workspace: Files) -> set[str]:
    """The classes the headers of the workspace that ``source`` includes export (a
    pluginlib macro written in a header), without template arguments."""
    path = os.path.join(workspace.root, source)
    return {_untemplated(name) for header in included_headers(path, _text(path, workspace) or "",
                                                       workspace)
            for name, _ in exported_classes(header, workspace)}


def narrow(sources: list[str], cls: str, workspace: Files) -> list[str]:
    """A library's sources without the files that export only other classes, nor the
    helper files (they export none) whose code the class's own files never name.

    A library often bundles several nodelets or components, one per file; the node of
    one class should not carry the others' calls. A helper file is dropped only when it
    defines members of classes (``Name::member(``) and no kept file, nor a header of
    the workspace it includes, names one of them (nor its free functions): Autoware's
    pointcloud_preprocessor
    builds 38 components in one library, and only the concatenation component uses
    ``collector_matching_strategy.cpp``, whose calls read ``matching_strategy.*``.
    Empty when the library's files export other classes and not this one.
    """
    cls = _untemplated(cls.lstrip(":"))
    own: list[str] = []
    helpers: list[str] = []
    others = False  # a file exports another class: the library names its classes so
    for source in sources:
        # as written in the export macro, whose words leave out template arguments
        # (nav2's ``DriveOnHeading<>``, described as ``nav2_behaviors::DriveOnHeading<>``)
        exported = {_untemplated(name) for name, _ in exported_classes(
            os.path.join(workspace.root, source), workspace)}
        if not exported:
            # the export macro in a header of the workspace that the source includes
            # (xarm_controller's uf_robot_system_hardware.h): the source is that class's
            exported = header_exports(source, workspace)
        if cls in exported:
            own.append(source)
        elif not exported:
            helpers.append(source)
        else:
            others = True
    if not own:
        if others:
            # the library exports its other classes and not this one: its code is not
            # built there (ouster_ros's OusterPcap, whose source only BUILD_PCAP adds):
            # no source, the class's interface unknown (not the helpers' calls)
            return []
        # (a list of its own: each class's node extends its sources, ``cmake.
        # _standalone_names``; the library's list shared by its nodelets gave every one
        # of jsk_pcl_ros_utils' 49 nodelets each other's code)
        return list(helpers or sources)
    used = set(named_helpers(own, helpers, workspace))
    return [s for s in sources if s in own or s in used]


def named_helpers(own: list[str], helpers: list[str], workspace: Files,
                  anonymous: bool = True) -> list[str]:
    """The ``helpers`` the code of ``own`` needs: those that define a class member or a
    free function that a kept file (or a header of the workspace it includes) names,
    transitively, and (``anonymous``) those that define neither (nothing to tell them
    by)."""
    return named_closure(code_words(own, workspace), helpers, workspace, anonymous)


def code_words(own: list[str], workspace: Files) -> set[str]:
    """The words of ``own`` and of the package headers they include, less the classes
    an own source file defines itself: those are its own, whatever a library calls the
    same (cartographer_ros' occupancy_grid_node_main.cc defines a ``class Node`` of its
    own, and does not run the library's Node, node.cc, the SLAM node's topics)."""
    words: set[str] = set()
    for source in own:
        words |= named_words(source, workspace)
    local = set().union(*(_local_classes(source, workspace) for source in own))
    # but a class whose members it declares and defines nowhere in its own files is
    # defined by a helper (a plugin's ``class Handler { Handler(); }``, its constructor
    # in handler.cpp of its library): that helper is named
    elsewhere = set().union(*(_declared_only(source, workspace) for source in own))
    return words - (local - (elsewhere - defined_in(own, workspace)))


def named_closure(words: set[str], helpers: list[str], workspace: Files,
                  anonymous: bool = True) -> list[str]:
    """The ``helpers`` that define what ``words`` name, and what those name in turn. A
    program's ``main`` names no helper: each program runs its own (PX4-Avoidance's
    safe_landing_planner library holds waypoint_generator_node.cpp with that node's
    ``main``, which safe_landing_planner_node links and never runs)."""
    words = set(words) - {"main"}
    waiting = {source: _defined(source, workspace) for source in helpers}
    used = {source for source, defined in waiting.items() if anonymous and not defined}
    changed = True
    while changed:  # a helper a kept file names may name another
        changed = False
        for source, defined in waiting.items():
            if source not in used and defined & words:
                used.add(source)
                words |= named_words(source, workspace) - {"main"}
                changed = True
    return [s for s in helpers if s in used]


_WORD = re.compile(r"[A-Za-z_]\w*")
_TEMPLATE_ARGUMENTS = re.compile(r"<[^<>]*>")


def _untemplated(name: str) -> str:
    """A class name without its template arguments (``ns::Filter<T>``: ``ns::Filter``)."""
    for _ in range(8):
        shorter = _TEMPLATE_ARGUMENTS.sub("", name)
        if shorter == name:
            break
        name = shorter
    return name.replace(" ", "")


# ``Type Name::member(`` / ``Name<T>::member(`` on a line that starts in the first column
# (a definition; a call in a body is indented): a member defined
# (template arguments nest one level and never hold another declaration's words:
# ``std::vector<bool> RosFilter<T>::load(`` defines a member of RosFilter, not of vector);
# not a constructor's member initialiser written from the first column (slam_toolbox's
# ``: rclcpp_lifecycle::LifecycleNode("slam_toolbox", "", options),``, which names the
# base class, not a member the file defines), though ``::ns::T C::f(`` is a definition
_MEMBER = re.compile(r"^(?![ \t,]|:(?!:))[\w:<>,&* \t]*?\b([A-Za-z_]\w*)\s*"
                     r"(?:<[^;{}()\n<>]*(?:<[^;{}()\n<>]*>[^;{}()\n<>]*)*>)?\s*::"
                     r"\s*(~?\w+)\s*\(", re.MULTILINE)
# an ``#include`` line's header name, either spelling (``robot.attach`` reads them too)
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.MULTILINE)
MAX_NAMED_HEADERS = 64  # per file: the headers of the workspace read for the names used


# ``Type name(`` starting in the first column, its line not ending with ``;``: a free
# function defined (Autoware's behavior_path_planner builds its test_utils.cpp into the
# node's library: its test publishers are no call of the node); not a line of a
# constructor's member initialisers written from the first column (``: costmap_(c),``);
# a name in capitals with a type before it too (Google's style: cartographer_ros'
# offline_node.cc defines ``void RunOfflineNode(...)``, which builds the SLAM ``Node``),
# but not a macro's (``TEST(...)``, ``PLUGINLIB_EXPORT_CLASS(...)``, all in capitals)
_FUNCTION = re.compile(r"^(?![ \t#:,])(?:[\w:<>,&* \t]*?(?<![:\w])([a-z_]\w*)|"
                       r"[\w:<>,&* \t]*?[\w>&*][ \t&*]+(?<![:\w])([A-Z][A-Z0-9_]*[a-z]\w*))"
                       r"\s*\(([^\n]*)$", re.MULTILINE)
_STATIC = re.compile(r"\bstatic\b")
_NOT_FUNCTIONS = frozenset({"if", "for", "while", "switch", "return", "sizeof", "namespace",
                            "using", "typedef", "template", "class", "struct", "enum"})


# ``class Name {`` / ``struct Name : Base {`` at the start of a line: a class defined
_CLASS = re.compile(r"^[ \t]*(?:class|struct)\s+([A-Za-z_]\w*)\s*(?:final\s*)?[:{]",
                    re.MULTILINE)
_C_SOURCES = (".c", ".cc", ".cpp", ".cxx", ".c++", ".C")


def _local_classes(source: str, workspace: Files) -> set[str]:
    """The classes a C/C++ source file (not a header) defines."""
    if not source.endswith(_C_SOURCES):
        return set()
    path = os.path.join(workspace.root, source)
    return remembered("local classes", path, workspace,
                      lambda: set(_CLASS.findall(_text(path, workspace) or "")))


# a member function declared with no body in a class's body: ``Name(args);``,
# ``void f(int) const override;`` (not ``= default;`` / ``= delete;``)
_DECLARED_ONLY = re.compile(r"\)\s*(?:const\s*)?(?:noexcept\s*)?(?:override\s*)?"
                            r"(?:final\s*)?;")


def _declared_only(source: str, workspace: Files) -> set[str]:
    """The classes a C/C++ source file defines whose bodies declare a member function
    they do not define (its code is out of the class: in this file, or another)."""
    if not source.endswith(_C_SOURCES):
        return set()
    path = os.path.join(workspace.root, source)

    def compute() -> set[str]:
        code = code_only(_text(path, workspace) or "")
        found: set[str] = set()
        for match in _CLASS.finditer(code):
            start = code.find("{", match.end() - 1)
            body, depth, index = [], 0, start
            while 0 <= index < len(code):  # the body's own level, nested blocks left out
                char = code[index]
                depth += (char == "{") - (char == "}")
                if depth == 1 and char not in "{}":
                    body.append(char)
                if depth == 0:
                    break
                index += 1
            if _DECLARED_ONLY.search("".join(body)):
                found.add(match.group(1))
        return found

    return remembered("declared only", path, workspace, compute)


def _defined(source: str, workspace: Files) -> set[str]:
    """The classes whose members a source file defines, and its free functions."""
    return remembered("defined", source, workspace, lambda: _read_defined(source, workspace))


def defined_in(sources: Iterable[str], workspace: Files) -> set[str]:
    """The classes whose members ``sources`` define, and their free functions."""
    return set().union(*(_defined(source, workspace) for source in sources))


def _read_defined(source: str, workspace: Files) -> set[str]:
    return _members(source, workspace) | _free_functions(source, workspace)


def _members(source: str, workspace: Files) -> set[str]:
    """The classes whose members a source file defines."""
    def compute() -> set[str]:
        return {match.group(1) for match in _MEMBER.finditer(_scoped(source, workspace))}

    return remembered("members", source, workspace, compute)


def _free_functions(source: str, workspace: Files) -> set[str]:
    """The free functions a source file defines that another file can call: not one
    declared ``static`` there (internal linkage: ros_canopen's ros_chain.cpp defines a
    ``static ... create(nh, name, ...)``, which no node that links its library and
    writes ``create`` elsewhere can call)."""
    def compute() -> set[str]:
        # (in code, not a comment's prose: a licence's ``Software License Agreement (BSD
        # License)`` from the first column)
        code = code_only(_scoped(source, workspace))
        hidden = _anonymous_namespaces(code)
        return {match.group(name) for match in _FUNCTION.finditer(code)
                for name in [1 if match.group(1) else 2]
                if not match.group(3).rstrip().endswith(";")
                and not _STATIC.search(match.group(0), 0, match.start(name) - match.start())
                and not any(start <= match.start() < end for start, end in hidden)
                } - _NOT_FUNCTIONS

    return remembered("free functions", source, workspace, compute)


_ANONYMOUS = re.compile(r"\bnamespace\s*\{")


def _anonymous_namespaces(code: str) -> list[tuple[int, int]]:
    """The spans of ``code``'s unnamed namespaces, whose functions have internal
    linkage as ``static`` ones do (kachaka's static_tf_component.cpp and
    dynamic_tf_bridge.cpp each define their own ``ConvertGrpcTfToRosTf`` in one)."""
    spans: list[tuple[int, int]] = []
    for match in _ANONYMOUS.finditer(code):
        if spans and match.start() < spans[-1][1]:
            continue  # (nested in the one before)
        depth, end = 1, len(code)
        for found in _BRACES.finditer(code, match.end()):
            depth += 1 if found.group() == "{" else -1
            if depth == 0:
                end = found.end()
                break
        spans.append((match.start(), end))
    return spans


_BRACES = re.compile(r"[{}]")


def _scoped(source: str, workspace: Files) -> str:
    return remembered("at namespace scope", source, workspace, lambda: at_namespace_scope(
        _text(os.path.join(workspace.root, source), workspace) or ""))


def free_function_sources(sources: list[str],
                          with_elsewhere: Callable[[list[str]], list[str]],
                          workspace: Files) -> list[str]:
    """The files of other packages' libraries (``with_elsewhere``) that define a free
    function the code of ``sources`` names and no member of a class it names."""
    words = code_words(sources, workspace)
    out: list[str] = []
    for source in with_elsewhere(sources):
        if source in sources:
            continue
        named = _defined(source, workspace) & words
        if named and not named & _members(source, workspace):
            out.append(source)
    return out


_BRACE = re.compile(r"[{};]")
# what opens a namespace's block: ``namespace a::b {``, ``namespace {``, ``extern "C" {``
_NAMESPACE_HEAD = re.compile(r'(?:\bnamespace(?:\s+[\w:]+)?|\bextern\s*"[^"\n]*")\s*$')


def at_namespace_scope(text: str) -> str:
    """``text`` with each line that starts a declaration at namespace scope (inside
    ``namespace x {`` blocks only, not in a class's or function's body) moved to the
    first column, where ``_MEMBER`` and ``_FUNCTION`` look for definitions: a file may
    indent what it defines in a namespace (xarm_ros2's xarm_driver.cpp defines
    ``XArmDriver::init`` four columns in, inside ``namespace xarm_api {``). A call in a
    body stays indented, and so does a line that goes on with a declaration begun above
    (a constructor's member initialisers, ``  enabled_(false),``, and parameters)."""
    code = code_only(text)
    out: list[str] = []
    stack: list[bool] = []  # the blocks open: whether each is a namespace's
    statement = 0  # where the code since the last ``;``, ``{``, ``}`` or directive starts
    offset = 0
    for line in text.split("\n"):
        end = offset + len(line)
        words = code[offset:end]
        # the line starts code (not a comment's) where nothing is left unfinished above
        fresh = not code[statement:offset].strip() and words.strip() != "" and (
            len(words) - len(words.lstrip()) == len(line) - len(line.lstrip()))
        out.append(line.lstrip(" \t") if fresh and stack and all(stack) else line)
        if code[offset:end].lstrip().startswith("#"):
            statement = end  # a preprocessor line ends what came before
        for match in _BRACE.finditer(code, offset, end):
            if match.group() == "{":
                stack.append(bool(_NAMESPACE_HEAD.search(code, statement, match.start())))
            elif match.group() == "}" and stack:
                stack.pop()
            statement = match.end()
        offset = end + 1
    return "\n".join(out)


# ``class Name : public ns::Node`` / ``LifecycleNode`` (first base): a class that is a
# ROS 2 node of its own
_NODE_CLASS = re.compile(r"^[ \t]*class\s+(?:\w+\s+)?([A-Za-z_]\w*)\s*(?:final\s*)?:"
                         r"\s*(?:public|protected|private)?\s*[\w:]*\b(?:Lifecycle)?Node\b",
                         re.MULTILINE)


def node_classes(source: str, workspace: Files) -> set[str]:
    """The classes a source file defines members of that are ROS 2 nodes themselves (a
    subclass of ``rclcpp::Node``, a lifecycle node, a workspace's node base class), as
    its headers declare them: nav2_costmap_2d's ``Costmap2DROS``, a node of its own
    that the planner and controller servers make."""
    def compute() -> set[str]:
        declared = set().union(*(_NODE_CLASS.findall(text)
                                 for text in with_headers(source, workspace)))
        return declared & _defined(source, workspace) if declared else set()

    return remembered("node classes", source, workspace, compute)


_MAIN = re.compile(r"\bint\s+main\s*\([^)]*\)\s*\{")
MAX_MAIN_BODY = 200_000  # characters of a main() body read for the classes it names


# a class declared or defined: ``class Name;``, ``struct Name : Base {``, a nested one
# defined out of its class (mrs_lib's ``class SubscribeHandler<MessageType>::Impl``)
_CLASS_NAMED = re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)?(?:\w+\s*(?:<[^;{}()]*?>)?\s*::\s*)*"
                          r"([A-Za-z_]\w*)\s*(?:final\s*)?[;:{]")


def header_uses(header: str, workspace: Files) -> frozenset[str]:
    """The words of a header's code (and of the headers of its package it includes, as
    ``named_words``), each text without the classes it declares itself: the classes
    and functions its inline code and members use (param_loader.h's ``ParamProvider``
    member of ``ParamLoader``), not those it is the header of (a node that uses a class
    a header declares names it in its own code)."""
    def compute() -> frozenset[str]:
        words: set[str] = set()
        for text in with_headers(header, workspace):
            # (not the paths of its includes: grid_map_ros.hpp, which only includes
            # the package's headers, uses none of the classes they are named after)
            code = INCLUDE.sub("", code_only(text))
            words |= set(_WORD.findall(code)) - set(_CLASS_NAMED.findall(code))
        return frozenset(words)

    return remembered("header uses", header, workspace, compute)


def header_classes(header: str, workspace: Files) -> frozenset[str]:
    """The classes a header (and the headers of its package it includes) declares."""
    return remembered("header classes", header, workspace, lambda: frozenset().union(
        *(_CLASS_NAMED.findall(code_only(text)) for text in with_headers(header, workspace))))


def free_functions(sources: Iterable[str], workspace: Files) -> set[str]:
    """The free functions ``sources`` define."""
    return set().union(*(_free_functions(source, workspace) for source in sources))


def declared_nodes(source: str, workspace: Files) -> set[str]:
    """The classes a file (or a header of its package it includes) declares that are ROS 2
    nodes themselves, defined where they may be (``node_classes``, as declared)."""
    return remembered("declared nodes", source, workspace, lambda: set().union(
        *(_NODE_CLASS.findall(text) for text in with_headers(source, workspace))))


def main_words(source: str, workspace: Files) -> frozenset[str]:
    """The words of the body of the ``main()`` a source file defines (none without one):
    the classes a program builds itself, as nodes of its process (PlanSys2's plansys2_node
    makes ``DomainExpertNode``, ``ProblemExpertNode``, ... of other packages' libraries)."""
    def compute() -> frozenset[str]:
        text = _text(os.path.join(workspace.root, source), workspace)
        code = code_only(text) if text else ""
        found = _MAIN.search(code)
        if found is None:
            return frozenset()
        depth, end = 1, min(len(code), found.end() + MAX_MAIN_BODY)
        for index in range(found.end(), end):
            depth += {"{": 1, "}": -1}.get(code[index], 0)
            if depth == 0:
                end = index
                break
        return frozenset(_WORD.findall(code[found.end():end]))

    return remembered("main words", source, workspace, compute)


# the ROS client libraries (and the API libraries the extractor knows) named in code
_ROS_CODE = re.compile(r"\b(?:ros|rclcpp|rclcpp_lifecycle|rclcpp_action|nodelet|actionlib|"
                       r"image_transport|tf2_ros|message_filters)::|\bNodeHandle\b")


# how deep ``uses_ros`` follows a file's includes of its package's headers
USES_ROS_DEPTH = 8


def uses_ros(source: str, workspace: Files) -> bool:
    """Whether a source file, or a header of its package it includes (directly or
    through its package's other headers), names the ROS client libraries: a file that
    does not (mavros' libmavconn, a serial link) makes no ROS call. A file may call ROS
    only through its package's headers: iiwa_ros' state/joint_position.cpp calls
    ``State<M>::init``, a template of iiwa_ros.hpp that subscribes, which it includes
    through its own header and generic_state.hpp."""
    return remembered("uses ros", source, workspace, lambda: any(
        _ROS_CODE.search(text) for text in with_headers(source, workspace,
                                                        USES_ROS_DEPTH)))


def derives_from(cls: str, sources: Iterable[str], workspace: Files) -> bool:
    """Whether a class of ``sources`` (or of the headers they include) names ``cls`` as
    a base: the node's own base class (nav2's servers are ``nav2_util::LifecycleNode``s)."""
    base = re.compile(rf"(?:public|protected|private)\s+(?:virtual\s+)?[\w:]*\b{cls}\b")
    return any(base.search(text) for source in sources
               for text in with_headers(source, workspace))


def named_words(source: str, workspace: Files) -> frozenset[str]:
    """The words of the code of a source file and of the headers of its package it
    includes (its own header declares the members whose types name helper classes),
    not those of comments and string literals (``code_only``: laser_filters'
    scan_to_cloud_filter_chain.cpp names ``ScanShadowsFilter`` only in a comment); a
    ``Workspace``'s read once per run."""
    def words() -> frozenset[str]:
        return frozenset(set().union(
            *(_WORD.findall(code_only(text)) for text in with_headers(source, workspace))))

    memo: dict[str, Any] | None = getattr(workspace, "named_words", None)
    return words() if memo is None else kept_in(memo, source, words)


def with_headers(source: str, workspace: Files, depth: int = 1) -> list[str]:
    """The text of a file (workspace-relative or absolute) and of the headers of the
    workspace it includes, found beside it or in its package's ``include`` folder, and
    theirs down to ``depth`` levels of inclusion (read once per run: every executable
    that links a library asks for its files again)."""
    return list(remembered(f"with headers {depth}", source, workspace,
                           lambda: _with_headers(source, workspace, depth)))


def _text(path: str, workspace: Files) -> str | None:
    """A file's text, read once per run (a header many sources include)."""
    return remembered("text", path, workspace,
                      lambda: read_text(path, workspace.location(path))[0])


def _with_headers(source: str, workspace: Files, depth: int) -> list[str]:
    path = os.path.join(workspace.root, source)
    texts: list[str] = []
    seen: set[str] = set()
    level = [path]
    for step in range(depth + 1):
        below: list[str] = []
        for each in level:
            if each in seen:
                continue
            seen.add(each)
            text = _text(each, workspace)
            texts.append(text or "")
            if step < depth:
                below.extend(included_headers(each, text or "", workspace))
        level = below
    return texts


def included_headers(path: str, text: str, workspace: Files) -> list[str]:
    """The headers of the workspace ``text`` (the file at ``path``) includes by name,
    found beside it, in its package's ``include`` folder or in that folder's
    ``include/<package>``: CMake's ``include_directories(include/${PROJECT_NAME})`` lets
    aerostack2's as2_platform_gazebo.cpp write ``#include "as2_platform_gazebo.hpp"``
    for ``include/as2_platform_gazebo/as2_platform_gazebo.hpp``, the header that says
    its class derives from as2_core's ``AerialPlatform``."""
    out = []
    package = _package_root(os.path.dirname(path), workspace)
    folders = [os.path.dirname(path), *(_include_folders(package, workspace)
                                        if package else [])]
    for header in INCLUDE.findall(text)[:MAX_NAMED_HEADERS]:
        for folder in folders:
            candidate = os.path.normpath(os.path.join(folder, header))
            if os.path.isfile(candidate) and workspace.holds(candidate):
                out.append(candidate)
                break
    return out


_PACKAGE_NAME = re.compile(r"<name>\s*([\w.-]+)\s*</name>")


def _include_folders(package: str, workspace: Files) -> list[str]:
    """A package's ``include`` folder, then ``include/<its name>`` (package.xml's name,
    and its folder's when that differs)."""
    include = os.path.join(package, "include")
    manifest = _text(os.path.join(package, "package.xml"), workspace) or ""
    found = _PACKAGE_NAME.search(manifest)
    names = dict.fromkeys([*([found.group(1)] if found else []), os.path.basename(package)])
    return [include, *(os.path.join(include, name) for name in names)]


def _package_root(folder: str, workspace: Files) -> str | None:
    """The nearest folder at or above ``folder``, in a workspace folder, with a
    package.xml."""
    while workspace.holds(folder + os.sep):
        if os.path.isfile(os.path.join(folder, "package.xml")):
            return folder
        parent = os.path.dirname(folder)
        if parent == folder:
            break
        folder = parent
    return None


def _exporting(type_name: str, libraries: Mapping[str, Library],
               workspace: Files) -> Library | None:
    """The library whose sources export ``type_name`` with a pluginlib macro."""
    for library in libraries.values():
        for source in library.sources:
            path = os.path.join(workspace.root, source)
            if type_name.lstrip(":") in (c for c, _ in exported_classes(path, workspace)):
                return library
    return None


def _registered(type_name: str, library: Library | None,
                libraries: Mapping[str, Library], workspace: Files) -> str:
    """The class a description's ``type`` is exported as, by the described library's
    sources (every library's when the described one is not known): ``registered_class``."""
    return registered_class(type_name, (
        source for each in ([library] if library is not None else list(libraries.values()))
        for source in each.sources), workspace)


def registered_class(type_name: str, sources: Iterable[str], workspace: Files) -> str:
    """The class a description's ``type`` is exported as: a factory template stands for
    its argument (mavros' PluginFactoryTemplate<Imu> is exported by
    MAVROS_PLUGIN_REGISTER(Imu)), unless one of ``sources`` exports the specialisation
    itself (grid_map_cv's
    ``PLUGINLIB_EXPORT_CLASS(grid_map::InpaintFilter<grid_map::GridMap>, ...)``)."""
    argument = _template_argument(type_name)
    if argument is None:
        return type_name
    own = _untemplated(type_name.lstrip(":"))
    for source in sources:
        path = os.path.join(workspace.root, source)
        if own in (_untemplated(c) for c, _ in exported_classes(path, workspace)):
            return type_name
    return argument


def _template_argument(type_name: str) -> str | None:
    """``ns::Factory<ns::Class>`` → ``ns::Class``; None when not a template."""
    match = re.fullmatch(r"[\w:]+\s*<\s*([\w:]+)\s*>", type_name.strip())
    return match.group(1) if match else None


def _node_name(sources: list[str], pattern: str | None, workspace: Files) -> str | None:
    """The name a plugin's code gives the node it makes (mavros' ``Plugin(uas, "imu")``):
    the first match of its host's pattern in the class's sources."""
    if pattern is None:
        return None
    for source in sources:
        path = os.path.join(workspace.root, source)
        text, _ = read_text(path, workspace.location(path))
        match = re.search(pattern, text[:MAX_NAME_SCAN]) if text else None
        if match:
            return match.group(1)
    return None


def _line(element: etree._Element) -> int:
    line = element.sourceline
    return line if isinstance(line, int) else 0
