"""From what the CMake interpreter recorded to runnable ``Node``s.

Executables, ROS 2 components (registered in CMake or with ``RCLCPP_COMPONENTS_REGISTER_NODE``
in a library's source), installed Python programs, and ROS 1 scripts found by the rosrun
convention (executable Python files in ``scripts/`` and ``nodes/``).
"""

from __future__ import annotations

import os
import re
import stat
from collections.abc import Callable, Iterable, Sequence
from functools import partial

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..files import note_read, read_text
from ..model.conditions import Condition
from ..model.location import Location
from ..model.source import Node, Package
from ..plugins import Files, narrow
from ..plugins.classes import (
    code_only,
    code_words,
    declared_nodes,
    defined_in,
    derives_from,
    exported_classes,
    free_functions,
    header_classes,
    header_uses,
    included_headers,
    linked_headers,
    lookup_types,
    main_words,
    named_closure,
    named_helpers,
    named_words,
    node_classes,
    uses_ros,
    with_headers,
)
from ..plugins.inherit import inherited_sources
from ..workspace import Workspace
from .commands import C_SUFFIXES
from .interpreter import BINARY_ROOT, Interpreter
from .targets import Program, Target

SCRIPT_FOLDERS = ("scripts", "nodes")
_GENEX = re.compile(r"^\$<(TARGET_OBJECTS|BUILD_INTERFACE):([^<>]*)>$")
_COMPONENT_MACRO = re.compile(r"RCLCPP_COMPONENTS_REGISTER_NODE\s*\(\s*([A-Za-z_][\w:]*)\s*\)")


class PackageFiles:
    """Locations and relative paths of one package's files, cached: a package's build
    files name the same paths many times, and the workspace answers for any path."""

    def __init__(self, package: Package, workspace: Workspace) -> None:
        self.root = workspace.root
        self.workspace = workspace
        self.package = package
        self._relative: dict[str, str] = {}
        # the words of each source (``classes.named_words``), kept by the workspace
        self.named_words = workspace.named_words
        self.file_facts = workspace.file_facts  # ``classes.remembered``
        self.kept_facts = workspace.kept_facts
        # the workspace's packages, whose headers a file includes as ``<pkg/...>``
        self.packages = workspace.packages

    def relpath(self, path: str) -> str:
        rel = self._relative.get(path)
        if rel is None:
            rel = self._relative[path] = self.workspace.relpath(path)
        return rel

    def holds(self, path: str) -> bool:
        return self.workspace.holds(path)

    def submodule_of(self, path: str) -> tuple[str, str] | None:
        return self.workspace.submodule_of(path)

    def location(self, path: str, line: int = 0, column: int = 0) -> Location:
        if path.startswith(self.package.root + os.sep):
            return Location(self.package.name, self.relpath(path), line, column)
        return self.workspace.location(path, line, column)


def _with_extension(source: str) -> str | None:
    """A source named without its extension (``add_executable(x src/demo)``) is the
    first existing file with a C/C++ one appended, as CMake looks for it."""
    if os.path.isfile(source):
        return None  # another language's file, or a header
    return next((source + ext for ext in C_SUFFIXES if os.path.isfile(source + ext)), None)


# what another package of the workspace builds as libraries, by its name: the
# workspace-relative sources of its libraries (``cmake.package_libraries``); None when
# the package is not in the workspace
Elsewhere = Callable[[str], "list[str] | None"]
# the other packages the libraries of a package of the workspace link, by its name
# (``cmake.package_links``)
Links = Callable[[str], "list[str]"]
# what a target linking a package of the workspace gets of the workspace's libraries, by
# the package's name: a (package, sources) pair per package (``cmake.libraries_handed``)
Handed = Callable[[str], "list[tuple[str, list[str]]]"]
MAX_REACHED = 64  # packages followed from a target for its classes' base classes


_STANDIN = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                        "extract", "standin")
# packages whose API the extractor knows from its own tables and stand-ins (the client
# libraries, tf2_ros, image_transport, actionlib, dynamic_reconfigure, ...): a node
# that links them runs their code, but its calls are those rows, not the library's
# insides (roscpp's own reads of /use_sim_time, topic_tools' relay linking roscpp)
MODELLED_PACKAGES = frozenset({
    *(name for name in os.listdir(_STANDIN) if os.path.isdir(os.path.join(_STANDIN, name))
      and name not in ("std", "fallback", "ros")),
    "roscpp", "rosconsole", "roscpp_serialization", "roscpp_traits", "xmlrpcpp", "rostime",
    "cpp_common", "rcl", "rcl_action", "rcl_lifecycle", "rcutils", "rcpputils", "rmw",
    "rmw_implementation", "tf2", "tf2_eigen"}) if os.path.isdir(_STANDIN) else frozenset()


class SourceMap:
    """Workspace-relative C/C++ sources of targets, with package-local libraries linked in,
    and the libraries of other workspace packages they link (``elsewhere``)."""

    def __init__(self, it: Interpreter, workspace: Files, elsewhere: Elsewhere | None = None,
                 build_depends: Sequence[str] = (), package: str = "",
                 links: Links | None = None, handed: Handed | None = None,
                 named: Elsewhere | None = None) -> None:
        self.targets = it.targets
        self.workspace = workspace
        self.diagnostics: list[Diagnostic] = []
        self._own: dict[str, list[str]] = {}
        # target -> why its code is not all here (sources in a submodule not checked out)
        self.unread: dict[str, str] = {}
        self._elsewhere = elsewhere
        self._build_depends = list(build_depends)
        self._package = package  # its own libraries are ``linked``'s
        self._links = links
        self._handed = handed
        # a library target of another workspace package linked by its bare name
        # (``cmake._named_library``)
        self._named = named

    def own(self, target: Target, seen: frozenset[str] = frozenset()) -> list[str]:
        if target.name in self._own:
            return self._own[target.name]
        out: list[str] = []
        for source in target.sources:
            match = _GENEX.match(source)
            if match and match.group(1) == "TARGET_OBJECTS":
                other = self.targets.get(match.group(2))
                if other is not None and other.name not in seen:
                    out.extend(self.own(other, seen | {target.name}))
                continue
            if match:
                source = os.path.normpath(os.path.join(os.path.dirname(target.file),
                                                       match.group(2)))
            if source.startswith("$<"):
                continue  # other generator expressions are unknown at this stage
            if not source.endswith(C_SUFFIXES):
                found = _with_extension(source)
                if found is None and (os.path.splitext(source)[1] or os.path.isfile(source)):
                    continue  # a header, or another language's file
                source = found or source
            if source.startswith(BINARY_ROOT):
                continue  # generated at build time
            if not os.path.isfile(source) and (
                    sub := self.workspace.submodule_of(source)) is not None:
                # a git submodule not checked out: said once per target and submodule
                said = diag.make(
                    "CMAKE_SOURCE_IN_SUBMODULE",
                    self.workspace.location(target.file, target.line, target.column),
                    target=target.name, submodule=sub[0], declared=sub[1])
                if said not in self.diagnostics:
                    self.diagnostics.append(said)
                self.unread.setdefault(target.name, (
                    f"{said.location.file}:{said.location.line}: sources in the git "
                    f"submodule {sub[0]}, not checked out, are not read"))
                continue
            if not os.path.isfile(source) and self._outside(source):
                # an SDK installed where the robot builds (autonav's
                # /usr/local/vectornav/cpp/src/*.cpp): not a missing file, a file not
                # here, said once per target; a library outside the workspace, read as
                # an installed one is (no ROS calls of its own), the node stays whole
                said = diag.make(
                    "CMAKE_SOURCE_OUTSIDE",
                    self.workspace.location(target.file, target.line, target.column),
                    target=target.name, folder=os.path.dirname(source))
                if not any(d.code == said.code and d.location == said.location
                           for d in self.diagnostics):
                    self.diagnostics.append(said)
                continue
            if not os.path.isfile(source):
                self.diagnostics.append(diag.make(
                    "CMAKE_SOURCE_MISSING",
                    self.workspace.location(target.file, target.line, target.column),
                    path=self.workspace.relpath(source), target=target.name))
                continue
            out.append(self.workspace.relpath(source))
        self._own[target.name] = out = list(dict.fromkeys(out))
        return out

    def _outside(self, source: str) -> bool:
        """Whether ``source`` lies outside every folder of the workspace (an absolute
        path the build files write, to a library installed where the robot is built)."""
        return not self.workspace.holds(os.path.abspath(source))

    def unread_reason(self, target: Target) -> str | None:
        """Why some code ``target`` runs is not here: sources of it or of a package
        library it links lie in a git submodule not checked out; None when all is."""
        for each in self.closure(target):
            self.own(each)
            if each.name in self.unread:
                return self.unread[each.name]
        return None

    def closure(self, target: Target) -> list[Target]:
        """``target`` and the package libraries it links, transitively, in order."""
        out: list[Target] = []
        seen: set[str] = set()
        stack = [target.name]
        while stack:
            name = stack.pop(0)
            if name in seen or name not in self.targets:
                continue
            seen.add(name)
            out.append(self.targets[name])
            stack.extend(self.targets[name].links)
        return out

    def linked(self, target: Target) -> list[str]:
        """The target's sources, then those of package libraries it links, transitively."""
        return list(dict.fromkeys(source for linked in self.closure(target)
                                  for source in self.own(linked)))

    def packages(self, target: Target) -> list[str]:
        """The other packages ``target`` links, itself or through the package's libraries
        it links (an ament_cmake_auto target links every build dependency)."""
        out: list[str] = []
        for linked in self.closure(target):
            out.extend(linked.packages)
            if linked.auto:
                out.extend(self._build_depends)
        return [name for name in dict.fromkeys(out)
                if name != self._package and name not in MODELLED_PACKAGES]

    def elsewhere(self, target: Target) -> list[list[str]]:
        """The sources of the libraries of each other workspace package ``target``
        links (catkin's ``catkin_LIBRARIES``, ament's dependencies), a list per
        package (``cmake.libraries_handed``: a header-only package's are those of the
        packages it exports): move_base links costmap_2d, whose ``Costmap2DROS`` makes
        the costmaps' calls on move_base's node."""
        return [group for _owner, group in self.handed_groups(target)]

    def handed_groups(self, target: Target) -> list[tuple[str, list[str]]]:
        """``elsewhere``'s lists, each with the package it is of ('' for a library
        target linked by its bare name)."""
        if self._handed is None:
            return []
        out: list[tuple[str, list[str]]] = []
        seen = {self._package}
        for name in self.packages(target):
            seen.add(name)
            for owner, group in self._handed(name):
                if owner != name:  # an exported package of a header-only one: once
                    if owner in seen:
                        continue
                    seen.add(owner)
                if group:
                    out.append((owner, group))
        if self._named is not None:
            # a library of another package linked by its target's name (motoman's
            # ``target_link_libraries(motoman_industrial_robot_client
            # industrial_robot_client)``, a library industrial_core does not export)
            named = (self._named(name) for linked in self.closure(target)
                     for name in dict.fromkeys(linked.links) if name not in self.targets)
            out.extend(("", group) for group in named if group)
        return out

    def handed_by(self, package: str) -> list[tuple[str, list[str]]]:
        """The (package, sources) lists of the libraries that the libraries of the
        workspace package ``package`` link in turn (its ``package_links``, each as
        ``libraries_handed`` gives it): what code of that package may call."""
        if self._handed is None or self._links is None:
            return []
        return [(owner, group) for name in self._links(package)
                if name not in MODELLED_PACKAGES and name != self._package
                for owner, group in self._handed(name) if group]

    def reached(self, target: Target) -> list[list[str]]:
        """``elsewhere``'s groups, then those of the packages their libraries link, and
        so on: where the base classes of a class of ``target`` may be built, and their
        own bases (position_controllers' class derives from forward_command_controller's,
        which derives from controller_interface's)."""
        if self._elsewhere is None:
            return []
        names = self.packages(target)
        seen = {self._package, *names}
        out: list[list[str]] = []
        index = 0
        while index < len(names) and index < MAX_REACHED:
            name = names[index]
            index += 1
            group = self._elsewhere(name)
            if group:
                out.append(group)
            for other in self._links(name) if self._links is not None else ():
                if other not in seen and other not in MODELLED_PACKAGES:
                    seen.add(other)
                    names.append(other)
        return out


def executables(it: Interpreter, package: Package, workspace: Files,
                sources: SourceMap) -> list[Node]:
    nodes = []
    for t in it.targets.values():
        if t.kind != "executable":
            continue
        node = Node(package=package.name, executable=t.output_name or t.name,
                    kind="executable", language="cpp", sources=_run(t, sources, workspace),
                    conditions=t.conditions,
                    location=workspace.location(t.file, t.line, t.column))
        _unread(node, t, sources)
        nodes.append(node)
    return nodes


def _unread(node: Node, target: Target, sources: SourceMap) -> None:
    """``node`` partial when code its target runs is in a submodule not checked out."""
    why = sources.unread_reason(target)
    if why is not None:
        node.mark_partial(why)


# words of code that loads plugins by name: such an executable hosts classes its own
# code never names (a costmap's filters, through the filter base class)
# (pluginlib, class_loader, a nodelet::Loader in a standalone nodelet executable, an
# rclcpp_components ComponentManager)
_LOADS_PLUGINS = frozenset({"ClassLoader", "MultiLibraryClassLoader", "createSharedInstance",
                            "createUniqueInstance", "createUnmanagedInstance",
                            "createInstance", "Loader", "ComponentManager"})


def _run(target: Target, sources: SourceMap, workspace: Files) -> list[str]:
    """The sources an executable runs: its own, and those of the package libraries it
    links that its code needs (``classes.named_helpers``: those defining what it names,
    transitively, or nothing one can tell them by), but never a file that exports node
    or plugin classes none of which its code names. A library often holds several
    nodes' classes that each executable links whole: robot_localization's ekf_node
    links navsat_transform.cpp, Autoware's hdd_reader every monitor's component. An
    executable whose code loads plugins by name runs all it links: the plugins' base
    classes are named by the plugins, not by it (nav2's costmap filters), but not a
    file exporting plugin classes it never names (the plugins themselves)."""
    own = sources.own(target)
    return with_elsewhere(_run_here(target, own, sources, workspace), target, sources,
                           workspace)


def with_elsewhere(kept: list[str], target: Target, sources: SourceMap,
                    workspace: Files) -> list[str]:
    """``kept`` and the sources of other packages' libraries that ``target`` links and
    that kept code names: those defining a class member or free function it names, and
    those that these name in their own package (``classes.named_closure``), and in the
    packages that package's libraries link (Autoware's trajectory follower links the
    MPC controller's library, which builds autoware_vehicle_info_utils'
    ``VehicleInfoUtils`` with the node), never in a package it links only for its
    tests (the route handler names test utilities its tests link). Never one that
    names nothing we can tell,
    nor one that exports plugin or node classes (a plugin's calls reach its host
    through ``plugins.hosts``, not by linking) other than classes the program's
    ``main()`` builds itself (``_built_or_unexported``), nor a class that is a node of its own,
    which makes its calls on that node (nav2's Costmap2DROS in the planner server: its
    host makes it an instance) unless it is this node's own base class (nav2_util's
    LifecycleNode) or a node the program's ``main()`` builds itself, one of the nodes of
    its process (PlanSys2's plansys2_node: the domain expert, problem expert, planner and
    executor nodes of four other packages)."""
    if not kept:
        return kept
    # a class or function the node's own files define is theirs, whatever another
    # package calls the same (opennav_following's ParameterHandler against
    # opennav_docking's)
    own = defined_in(kept, workspace)
    built = frozenset().union(*(main_words(s, workspace) for s in kept))
    handed = sources.handed_groups(target)
    # and the words of the linked packages' headers that kept code includes: their
    # inline code runs here (mrs_lib's param_loader.h, whose template ParamLoader holds
    # a ParamProvider that param_provider.cpp defines: the nodelets name only ParamLoader),
    # but not those of a header declaring a class that is a node of its own (nav2's
    # costmap_2d_ros.hpp: what that node names is its business)
    # (the classes those use, not the free functions a header declares: rtabmap's
    # MsgConversion.h declares a hundred, and a node calling one names it itself; and
    # only of a header declaring a class the code names: nav2's planner includes
    # costmap_layer.hpp for a cast, and runs no code of CostmapLayer's base Layer)
    linked = {*sources.packages(target), *(owner for owner, _ in handed if owner)}
    words = code_words(kept, workspace)
    used = set().union(*(
        header_uses(header, workspace) for header in linked_headers(kept, linked, workspace)
        if header_classes(header, workspace) & words
        and all(cls in built or derives_from(cls, kept, workspace)
                for cls in declared_nodes(header, workspace))))
    if used - words:
        words |= used - free_functions((s for _, group in handed for s in group), workspace)
    words -= own

    def usable(group: list[str]) -> list[str]:
        return [s for s in group if s not in kept
                and _built_or_unexported(s, built, workspace)
                and all(cls in built or derives_from(cls, kept, workspace)
                        for cls in node_classes(s, workspace))]

    # each package's list, and the words that may name its files: the node's own code
    # for the packages it links; the files found of a package for the packages that
    # package's libraries link (the trajectory follower's MPC controller, of another
    # package, builds VehicleInfoUtils with the node)
    groups: dict[str, list[str]] = {}
    naming: dict[str, set[str]] = {}
    for index, (owner, group) in enumerate(handed):
        key = owner or f"\0{index}"
        groups[key] = usable(group)
        naming[key] = set(words)
    found: dict[str, None] = {}
    waiting = list(groups)
    while waiting:
        key = waiting.pop(0)
        new = [s for s in named_closure(naming[key], groups[key], workspace, anonymous=False)
               if s not in found]
        if not new:
            continue
        found.update(dict.fromkeys(new))
        if key.startswith("\0"):
            continue
        said = set().union(*(named_words(s, workspace) for s in new)) - own
        for owner, group in sources.handed_by(key):
            if owner not in groups:
                groups[owner], naming[owner] = usable(group), set()
            if not said <= naming[owner]:
                naming[owner] |= said
                if owner not in waiting:
                    waiting.append(owner)
    # a file that names no ROS client library makes no call of the node (its parse
    # errors would only make the node look partial): what it names still counts
    return [*kept, *(s for s in found if uses_ros(s, workspace))]


def _built_or_unexported(source: str, built: frozenset[str], workspace: Files) -> bool:
    """Whether linked ``source`` exports no plugin or component class, or only classes
    the program's ``main()`` builds itself: those run in its process by construction,
    not by a loader (zed_debug's ``zed_debug_proc`` makes ``stereolabs::ZedCamera`` of
    zed_components' library, whose constructor is in the file that registers it as a
    component)."""
    exported = exported_classes(os.path.join(workspace.root, source), workspace)
    return all(name.split("<", 1)[0].rsplit("::", 1)[-1] in built for name, _ in exported)


def _run_here(target: Target, own: list[str], sources: SourceMap,
              workspace: Files) -> list[str]:
    linked = [s for s in sources.linked(target) if s not in own]
    if not linked:
        return own
    named = named_helpers(own, linked, workspace)
    exported = {source: {name.rsplit("::", 1)[-1] for name, _ in exported_classes(
        os.path.join(workspace.root, source), workspace)} for source in named}
    # what the executable's code names: its own files and the helpers that export
    # nothing (a file that exports a class names that class itself)
    words = set().union(*(named_words(s, workspace) for s in own),
                        *(named_words(s, workspace) for s in named if not exported[s]))
    if words & _LOADS_PLUGINS:
        # a class its code names by its lookup name, written as text (image_proc's
        # wrapper loads ``"image_proc/debayer"`` and ``"image_proc/rectify"`` in its
        # process): named as its C++ type is
        words |= _looked_up(own, workspace)
        # all it links but the files that export plugin classes its code never names:
        # a plugin's calls reach its host when a parameter chooses it
        # (``plugins.attach``), not by linking (nav2's costmap node published the voxel
        # layer's ``voxel_grid`` with only an obstacle and an inflation layer loaded)
        return [*own, *(s for s in linked if not _exports_other(s, words, workspace))]
    return [*own, *(s for s in named if not exported[s] or exported[s] & words)]


_LOOKUP_NAME = re.compile(r'"([A-Za-z_]\w*/[A-Za-z_]\w*)"')


def _looked_up(own: list[str], workspace: Files) -> set[str]:
    """The class names of the plugins of the package's descriptions whose lookup names
    ``own``'s code writes as string literals."""
    package = getattr(workspace, "package", None)
    if package is None or not package.plugins:
        return set()
    written = set()
    for source in own:  # read once per run (``named_words`` read them already)
        written.update(_LOOKUP_NAME.findall(with_headers(source, workspace, 0)[0]))
    if not written:
        return set()
    types = lookup_types(package, workspace)
    return {types[name].rsplit("::", 1)[-1] for name in written if name in types}


def _exports_other(source: str, words: set[str], workspace: Files) -> bool:
    """Whether ``source`` exports plugin classes (a pluginlib macro) none of which
    ``words`` names."""
    exported = {name.rsplit("::", 1)[-1] for name, _ in exported_classes(
        os.path.join(workspace.root, source), workspace)}
    return bool(exported) and not exported & words


def _component(target: Target, cls: str, sources: SourceMap, workspace: Files) -> list[str]:
    """The sources a component class runs: the files of its library that are its own
    (``narrow``), what they name of other packages' libraries (``with_elsewhere``), and
    the files defining its base classes, in its package's libraries or in another
    package's (``inherit.inherited_sources``: a file that exports a class of its own is
    no helper, but it is a base's code)."""
    linked = sources.linked(target)
    kept = narrow(linked, cls, workspace)
    files = with_elsewhere(kept, target, sources, workspace)
    if not kept:
        return files
    return [*files, *(s for s in inherited_sources(cls, files, linked, workspace,
                                                   partial(sources.reached, target))
                      if s not in files)]


def components(it: Interpreter, package: Package, workspace: Files,
               sources: SourceMap) -> list[Node]:
    nodes: list[Node] = []
    registered: set[str] = set()
    for reg in it.registrations:
        target = it.targets.get(reg.target)
        files = _component(target, reg.plugin, sources, workspace) if target else []
        conditions = (target.conditions if target else ()) + tuple(
            c for c in reg.conditions if target is None or c not in target.conditions)
        where = workspace.location(reg.file, reg.line, reg.column)
        registered.add(reg.plugin)
        made = [Node(package.name, reg.plugin, "component", "cpp", list(files),
                     conditions=conditions, location=where)]
        if reg.executable:
            made.append(Node(package.name, reg.executable, "executable", "cpp", list(files),
                             conditions=conditions, location=where))
        for node in made:
            if target is not None:
                _unread(node, target, sources)
        nodes.extend(made)
    for target in it.targets.values():
        if target.kind != "library":
            continue
        for path in sources.own(target):
            for plugin, line in _registered_in(os.path.join(workspace.root, path), workspace):
                if plugin in registered:
                    continue
                registered.add(plugin)
                nodes.append(Node(package.name, plugin, "component", "cpp",
                                  _component(target, plugin, sources, workspace),
                                  conditions=target.conditions,
                                  location=workspace.location(
                                      os.path.join(workspace.root, path), line, 1)))
    return nodes


# Gazebo classic's registration macros: the library is a plugin of that kind (the
# macro defines the library's one ``RegisterPlugin``, so one class per library)
_GAZEBO_MACRO = re.compile(
    r"\bGZ_REGISTER_(MODEL|SENSOR|WORLD|SYSTEM|VISUAL|GUI)_PLUGIN\s*\(\s*([A-Za-z_][\w:]*)\s*\)")
GAZEBO_BASES = {"MODEL": "Model", "SENSOR": "Sensor", "WORLD": "World", "SYSTEM": "System",
                "VISUAL": "Visual", "GUI": "GUI"}


def gazebo_plugins(it: Interpreter, package: Package, workspace: Files,
                   sources: SourceMap) -> list[Node]:
    """The Gazebo classic plugins the package's libraries are: a library whose own
    source registers a class with ``GZ_REGISTER_<KIND>_PLUGIN`` is a ``plugin`` node
    named by the library (the ``<plugin filename>`` a robot description loads it by),
    with the class's sources as a component's are found; its ``plugin_base`` is
    ``gazebo::<Kind>Plugin``. ``robot.attach`` gives its calls to the Gazebo node. The
    macro may be written in a header of the workspace the source includes, after the
    class it declares (audibot_gazebo's AudibotInterfacePlugin.hpp): the one source
    that includes it defines the registration."""
    nodes: list[Node] = []
    for target in it.targets.values():
        if target.kind != "library":
            continue
        for path in sources.own(target):
            source = os.path.join(workspace.root, path)
            where, found = source, _gazebo_registered(source, workspace)
            if found is None:
                text, _ = read_text(source, workspace.location(source))
                for header in included_headers(source, text or "", workspace):
                    where, found = header, _gazebo_registered(header, workspace)
                    if found is not None:
                        break
            if found is None:
                continue
            kind, cls, line = found
            nodes.append(Node(package.name, target.output_name or target.name, "plugin",
                              "cpp", _component(target, cls, sources, workspace),
                              conditions=target.conditions,
                              location=workspace.location(where, line, 1),
                              plugin_class=cls,
                              plugin_base=f"gazebo::{GAZEBO_BASES[kind]}Plugin"))
            break
    return nodes


# a shell script that runs Gazebo's server (``gzserver`` as a word of its code) with
# system plugins ``-s .../lib<name>.so`` (gazebo_ros' gzserver, gazebo, debug, perf)
_GZSERVER = re.compile(r"(?<![\w.-])gzserver(?![\w.-])")
_SYSTEM_PLUGIN = re.compile(r"(?<![\w-])-s\s[^\n]*?\blib([A-Za-z0-9_]+)\.")


def gazebo_launchers(it: Interpreter, package: Package, workspace: Files,
                     plugins: Sequence[Node]) -> list[Node]:
    """The installed shell scripts that run Gazebo's server with system plugins of
    this package's libraries (gazebo_ros' ``gzserver`` adds ``-s
    libgazebo_ros_api_plugin.so``): each is a node whose sources are those plugins', so
    its interface is theirs (the ROS node the API plugin's ``ros::init`` makes). Scripts
    are read as text for these words, never run."""
    system = {n.executable: n for n in plugins
              if n.kind == "plugin" and n.plugin_base == "gazebo::SystemPlugin"}
    nodes: list[Node] = []
    if not system:
        return nodes
    for program in it.programs:
        if not os.path.isfile(program.path) or is_python(program.path):
            continue
        text, _ = read_text(program.path, workspace.location(program.path))
        code = "\n".join(line.partition("#")[0] for line in (text or "").splitlines())
        if not _GZSERVER.search(code):
            continue
        loaded = [system[name] for name in dict.fromkeys(_SYSTEM_PLUGIN.findall(code))
                  if name in system]
        if not loaded:
            continue
        sources = list(dict.fromkeys(s for n in loaded for s in n.sources))
        nodes.append(Node(package.name, program.name, "executable", "cpp", sources,
                          conditions=program.conditions,
                          location=workspace.location(program.file, program.line,
                                                      program.column)))
    return nodes


def _gazebo_registered(path: str, workspace: Files) -> tuple[str, str, int] | None:
    text, _ = read_text(path, workspace.location(path))
    if not text or "GZ_REGISTER_" not in text:
        return None
    text = code_only(text, literals=True)
    match = _GAZEBO_MACRO.search(text)
    if match is None:
        return None
    return (match.group(1), match.group(2).lstrip(":"),
            text.count("\n", 0, match.start()) + 1)


def _registered_in(path: str, workspace: Files) -> Iterable[tuple[str, int]]:
    text, _ = read_text(path, workspace.location(path))
    if not text or "RCLCPP_COMPONENTS_REGISTER_NODE" not in text:
        return
    text = code_only(text, literals=True)
    for match in _COMPONENT_MACRO.finditer(text):
        yield match.group(1).lstrip(":"), text.count("\n", 0, match.start()) + 1


# a shell line that runs the script itself again under Python: ``python "$0"``,
# ``exec python3 "${BASH_SOURCE[0]}" "$@"``, ``python${ROS_PYTHON_VERSION:-} ...``
_SHELL_RERUN = re.compile(
    rb"^\s*(?:exec\s+)?(?:/usr/bin/(?:env\s+)?)?python[\w.${}:-]*\s+(?:-\w+\s+)*"
    rb"([\"']?)\$(?:0|\{0\}|\{BASH_SOURCE(?:\[0\])?\})\1(?=\s|$)", re.MULTILINE)
_SHELLS = (b"sh", b"bash", b"dash", b"zsh", b"ksh")


def is_python(path: str) -> bool:
    """A ``.py`` file, or one whose shebang names Python, or a shell script that runs
    itself again under Python: a file both read, the shell's lines hidden from Python
    in a string (``#!/bin/bash``, ``if "true" : '''\\'``, ``then``, ``python
    "${BASH_SOURCE[0]}" $*``, ``exit``, ``fi``, ``'''``), whose program is Python's."""
    if path.endswith(".py"):
        return True
    note_read(path)
    try:
        with open(path, "rb") as handle:
            head = handle.read(2048)
    except OSError:
        return False
    first = head.split(b"\n", 1)[0][:200]
    if not first.startswith(b"#!"):
        return False
    if b"python" in first:
        return True
    words = first[2:].split()
    shell = (words[1] if len(words) > 1 and words[0].endswith(b"/env")
             else words[0] if words else b"")
    return (shell.rsplit(b"/", 1)[-1] in _SHELLS
            and _SHELL_RERUN.search(head) is not None)


def _script_source(path: str, workspace: Files) -> str:
    """A symlinked script's source is the file it points to, when in the workspace."""
    real = os.path.realpath(path)
    if real != os.path.abspath(path) and workspace.relpath(real) != real:
        return workspace.relpath(real)
    return workspace.relpath(path)


def scripts(it: Interpreter, package: Package, workspace: Files,
            found: list[Diagnostic]) -> list[Node]:
    """Installed Python programs, and for catkin packages the rosrun convention."""
    nodes: dict[str, Node] = {}

    def add(path: str, name: str, conditions: tuple[Condition, ...], where: Program | None) -> None:
        if name in nodes:
            return
        location = (workspace.location(where.file, where.line, where.column) if where
                    else workspace.location(path, 1, 1))
        nodes[name] = Node(package.name, name, "script", "python",
                           [_script_source(path, workspace)], conditions=conditions,
                           location=location, entry="")

    for program in it.programs:
        if not os.path.isfile(program.path) and it.custom_builds:
            # webots_ros2_driver installs webots/webots-controller, which the make of
            # its add_custom_target builds: absent from the sources is not missing
            custom = it.custom_builds[0]
            found.append(diag.make(
                "CMAKE_PROGRAM_NOT_IN_SOURCES",
                workspace.location(program.file, program.line, program.column),
                path=workspace.relpath(program.path), command=custom.name,
                where=f"{workspace.relpath(custom.file)}:{custom.line}"))
        elif program.path.startswith(BINARY_ROOT):
            # installed from the build folder (tucan_ros2's QGroundControl.AppImage, which
            # its file(DOWNLOAD) fetches there): made by the build, not missing
            found.append(diag.make(
                "CMAKE_PROGRAM_FROM_BUILD",
                workspace.location(program.file, program.line, program.column),
                path=program.path.replace(BINARY_ROOT, "${CMAKE_BINARY_DIR}", 1)))
        elif not os.path.isfile(program.path):
            found.append(diag.make(
                "CMAKE_SOURCE_MISSING",
                workspace.location(program.file, program.line, program.column),
                path=workspace.relpath(program.path), target=program.name))
        elif is_python(program.path):
            add(program.path, program.name, program.conditions, program)
    for folder in it.program_dirs:
        for path in _executable_files(folder.path):
            add(path, os.path.basename(path), folder.conditions, folder)
    if package.build_type == "catkin":
        for sub in SCRIPT_FOLDERS:
            for path in _executable_files(os.path.join(package.root, sub)):
                add(path, os.path.basename(path), (), None)
    return list(nodes.values())


def _executable_files(folder: str) -> list[str]:
    """Executable Python files directly in ``folder``; symlinks to ``.py`` files too."""
    try:
        names = sorted(os.listdir(folder))
    except OSError:
        return []
    out = []
    for name in names:
        path = os.path.join(folder, name)
        try:
            mode = os.stat(path).st_mode
        except OSError:
            continue
        if not stat.S_ISREG(mode) or name.startswith((".", "__init__")):
            continue
        linked_py = os.path.islink(path) and os.path.realpath(path).endswith(".py")
        if (mode & stat.S_IXUSR or linked_py) and (linked_py or is_python(path)):
            out.append(path)
    return out
