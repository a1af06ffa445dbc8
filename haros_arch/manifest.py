"""package.xml (formats 1, 2 and 3) and rosbuild's manifest.xml, read with a hardened XML
parser."""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable, Mapping
from typing import Any

from lxml import etree

from . import diagnostics as diag
from .diagnostics import Diagnostic
from .files import read_bytes
from .model.location import Location
from .model.source import BuildType, Dependency, Package, Plugin

DEPEND_TAGS = (
    "depend", "build_depend", "build_export_depend", "buildtool_depend",
    "buildtool_export_depend", "exec_depend", "run_depend", "test_depend", "doc_depend",
)
# what a binary install of a package installs with it (REP 140: ``depend`` is build,
# export and exec at once; format 1's run_depend); a rosbuild manifest's ``depend`` too
RUN_DEPEND_TAGS = frozenset({"depend", "exec_depend", "run_depend"})
BUILD_TYPES: tuple[BuildType, ...] = ("catkin", "ament_cmake", "ament_python", "cmake")


def xml_parser(recover: bool = False) -> etree.XMLParser:
    """An XML parser that never expands entities, loads DTDs or touches the network
    (``recover``: one that goes on past errors; only for a document whose errors are
    known to be harmless)."""
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                           huge_tree=False, remove_comments=True, remove_pis=True,
                           recover=recover)


# the version an XML declaration names: libxml2 refuses one that does not start with
# "1." ("Unsupported version '0.1'"), expat (xml.dom.minidom, which catkin_pkg and
# roslaunch read with) takes any
_DECLARED_VERSION = re.compile(
    rb"\A(\xef\xbb\xbf)?(\s*<\?xml\s+version\s*=\s*)([\"'])([^\"'<>]*)\3")


def as_expat_reads(data: bytes) -> bytes:
    """``data`` with the version of its XML declaration "1.0" when libxml2 would refuse
    it and expat reads it: pyrobot's ``<?xml version="0.1"?>`` package.xml files build
    with catkin, and were each "not well-formed XML" here, their packages left out."""
    match = _DECLARED_VERSION.match(data)
    if match is None or match.group(4).startswith(b"1."):
        return data
    return data[:match.start(4)] + b"1.0" + data[match.end(4):]


_HIDDEN = re.compile(r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>|<!DOCTYPE[^\[>]*(\[.*?\])?\s*>",
                     re.S)
_START_TAG = re.compile(r"<([A-Za-z_][\w.\-:]*)")


def start_lines(root: Any, data: bytes) -> None:
    """Number each element of ``root`` (parsed from ``data``) by the line its start tag
    begins on. libxml2 numbers an element by the line its start tag ends on, so a
    ``<node`` whose attributes run over several lines was placed at its ``/>``. The
    n-th element named ``tag`` is the n-th ``<tag`` of the text once comments, CDATA,
    processing instructions and the DOCTYPE are blanked; a name whose counts differ
    (namespaces, entities) keeps libxml2's lines."""
    text = data.decode("utf-8", "replace")
    text = _HIDDEN.sub(lambda m: re.sub(r"[^\n]", " ", m.group()), text)
    found: dict[str, list[int]] = {}
    line, at = 1, 0
    for match in _START_TAG.finditer(text):
        line += text.count("\n", at, match.start())
        at = match.start()
        found.setdefault(match.group(1), []).append(line)
    elements: dict[str, list[Any]] = {}
    for element in root.iter():
        if isinstance(element.tag, str):
            elements.setdefault(element.tag, []).append(element)
    for tag, same in elements.items():
        lines = found.get(tag, [])
        if len(lines) != len(same):
            continue
        for element, begins in zip(same, lines, strict=True):
            if isinstance(element.sourceline, int) and begins <= element.sourceline:
                element.sourceline = begins


_TOKEN = re.compile(r"\s*(\$\w+|\w[\w.\-]*|==|!=|>=|<=|>|<|\(|\)|\"[^\"]*\"|'[^']*')")


def condition_holds(expr: str, env: Mapping[str, str]) -> bool | None:
    """Evaluate a REP 149 condition (``$ROS_VERSION == 2 and ...``); None if malformed."""
    tokens: list[str] = []
    pos = 0
    expr = expr.strip()
    while pos < len(expr):
        match = _TOKEN.match(expr, pos)
        if not match:
            return None
        tokens.append(match.group(1))
        pos = match.end()
    values = [_subst(t, env) for t in tokens]
    try:
        result, rest = _parse_or(values)
    except (IndexError, ValueError):
        return None
    return result if not rest else None


def _subst(token: str, env: Mapping[str, str]) -> str:
    if token.startswith("$"):
        return "\x00" + env.get(token[1:], "")
    if token[:1] in "\"'":
        return "\x00" + token[1:-1]
    return token


def _parse_or(t: list[str]) -> tuple[bool, list[str]]:
    left, t = _parse_and(t)
    while t and t[0] == "or":
        right, t = _parse_and(t[1:])
        left = left or right
    return left, t


def _parse_and(t: list[str]) -> tuple[bool, list[str]]:
    left, t = _parse_cmp(t)
    while t and t[0] == "and":
        right, t = _parse_cmp(t[1:])
        left = left and right
    return left, t


def _parse_cmp(t: list[str]) -> tuple[bool, list[str]]:
    if t[0] == "(":
        value, t = _parse_or(t[1:])
        if not t or t[0] != ")":
            raise ValueError("unbalanced")
        return value, t[1:]
    left, op, right = t[0].lstrip("\x00"), t[1], t[2].lstrip("\x00")
    ops = {"==": left == right, "!=": left != right}
    if op in ops:
        return ops[op], t[3:]
    if op in (">", "<", ">=", "<="):
        # as catkin_pkg (colcon, rosdep, bloom) compares: the texts, not numbers, and a
        # variable not set is empty (tiago_2dnav's ``$PAL_DISTRO > 0``: false)
        a, b = left, right
        return {">": a > b, "<": a < b, ">=": a >= b, "<=": a <= b}[op], t[3:]
    raise ValueError(op)


def _read_root(path: str, location: Location) -> tuple[Any, list[Diagnostic]]:
    """The root element of a manifest (package.xml or rosbuild's manifest.xml), or None
    with the diagnostics that say why (unreadable, not well-formed)."""
    data, found = read_bytes(path, location)
    if data is None:
        return None, found
    try:
        return etree.fromstring(as_expat_reads(data), xml_parser()), found
    except etree.XMLSyntaxError as err:
        line, col = err.position if err.position else (0, 0)
        where = Location(None, location.file, line, col)
        return None, [*found, diag.make("PACKAGE_XML_SYNTAX", where, detail=err.msg)]


def parse_manifest(
    path: str, location: Location, rel_folder: str, env: Mapping[str, str]
) -> tuple[Package | None, list[Diagnostic]]:
    """Read one package.xml, or a rosbuild ``manifest.xml`` (the package is named by its
    folder, depends are ``<depend package=>``; read as a format 1 catkin package: ROS 1,
    built with CMake); ``location`` names the manifest file."""
    if os.path.basename(path) == "manifest.xml":
        return _parse_rosbuild(path, location, rel_folder)
    root, found = _read_root(path, location)
    if root is None:
        return None, found
    if root.tag != "package":
        return None, [*found, diag.make("PACKAGE_XML_INVALID", location,
                                        detail=f"root element is <{root.tag}>")]
    name = (root.findtext("name") or "").strip()
    if not name:
        return None, [*found, diag.make("PACKAGE_XML_INVALID",
                                        Location(None, location.file, _line(root)),
                                        detail="no <name>")]

    def active(element: etree._Element) -> bool:
        return holds(element, env)

    package = Package(
        name=name,
        path=rel_folder,
        version=(root.findtext("version") or "").strip(),
        format=_format(root.get("format", "1")),
        location=Location(name, location.file, _line(root), 0),
    )
    for tag in DEPEND_TAGS:
        for element in root.iter(tag):
            text = (element.text or "").strip()
            if text:
                package.dependencies.append(
                    Dependency(text, tag, element.get("condition"), active(element)))
    export = root.find("export")
    chosen = [e for e in export if e.tag == "build_type"] if export is not None else []
    package.build_type = _build_type(chosen, env)
    versionless = not env.get("ROS_VERSION", "").strip()
    if versionless:
        by_version = {version: _build_type(chosen, version_environment(env, version))
                      for version in ROS_VERSIONS}
        if len(set(by_version.values())) > 1:
            package.builds_by_version = by_version
            package.builds_at = _line(chosen[0])
    package.plugins.extend(_plugins(root, rel_folder, (
        lambda element: exported(element, env)) if versionless else active))
    return package, found


def exported(element: etree._Element, environment: Mapping[str, str]) -> bool:
    """Whether a run that names no ROS version reads a plugin export: one whose REP 149
    ``condition`` holds for either ROS version's setup of the run's ``environment``, as
    that run reads each version's build of a package that builds both (foxglove_bridge
    exports its nodelet with ``condition="$ROS_VERSION == 1"``, which a ROS 1 launch
    file of the same tree loads: read with neither version, it was "not in the
    workspace")."""
    return any(holds(element, version_environment(environment, version))
               for version in ROS_VERSIONS)


# what a distribution's setup script sets that REP 149 conditions test, per ROS version
ROS_VERSIONS: dict[str, dict[str, str]] = {
    "1": {"ROS_VERSION": "1", "ROS_PYTHON_VERSION": "3"},
    "2": {"ROS_VERSION": "2", "ROS_PYTHON_VERSION": "3"}}


def version_environment(environment: Mapping[str, str], version: str) -> dict[str, str]:
    """``environment`` with what the setup of a distribution of ROS ``version`` sets."""
    return {**environment, **ROS_VERSIONS[version]}


def other_builds(package: Package, environment: Mapping[str, str]
                 ) -> list[tuple[str, dict[str, str]]]:
    """What a run that gives no ROS version reads beside the package's own build: each
    ROS version whose build type, as the package.xml chooses it by ``$ROS_VERSION``
    (``builds_by_version``), is setup.py's where the package's own reads CMakeLists.txt,
    with the run's ``environment`` as that version's setup makes it, to read setup.py in
    (ros-bridge's runs its ``setup()`` under ``if ROS_VERSION == 2``)."""
    if package.build_type == "ament_python":
        return []
    return [(version, version_environment(environment, version))
            for version, build_type in sorted(package.builds_by_version.items())
            if build_type == "ament_python"]


def _build_type(elements: list[etree._Element], env: Mapping[str, str]) -> BuildType:
    """The build type the ``<export><build_type>`` elements give in ``env`` (the last
    whose condition holds; catkin when none says)."""
    build_type: BuildType = "catkin"
    for element in elements:
        text = (element.text or "").strip()
        if text in BUILD_TYPES and holds(element, env):
            build_type = text
    return build_type


def holds(element: etree._Element, env: Mapping[str, str]) -> bool:
    """Whether an element's REP 149 ``condition`` holds in ``env`` (one that is
    malformed, or none, does)."""
    condition = element.get("condition")
    return condition is None or condition_holds(condition, env) is not False


def _format(text: str) -> int:
    """REP 127/140/149's format number (1, 2, 3); anything else, however long, reads as 1."""
    text = text.strip()
    return int(text) if text.isdigit() and len(text) <= 3 else 1


_ROS2_DEPENDENCIES = frozenset({"rclcpp", "rclpy", "ament_cmake", "ament_cmake_auto",
                                "ament_cmake_python", "ament_python", "rclcpp_lifecycle",
                                "rclcpp_components", "rosidl_default_generators"})
_ROS1_DEPENDENCIES = frozenset({"roscpp", "rospy", "catkin", "nodelet", "message_generation"})


def ros_version(package: Package) -> int | None:
    """Whether a package is ROS 1 or ROS 2 code, from its package.xml: its build tool
    (catkin, ament_*; both, unconditioned: the build type, which colcon builds it with),
    else the build type (ament_cmake / ament_python), else the ROS client libraries and
    build tools it depends on, else format 1 (ROS 1 only); None when nothing says (a
    plain CMake package). A dependency whose condition does not hold is
    not read (foxglove_bridge: ``<buildtool_depend condition="$ROS_VERSION == 1">catkin``
    first, then ament_cmake for ROS 2)."""
    dependencies = [dep for dep in package.dependencies if dep.active]
    tools = {"catkin" if dep.name == "catkin" else "ament" for dep in dependencies
             if dep.kind in ("buildtool_depend", "buildtool_export_depend")
             and not dep.condition and (dep.name == "catkin" or dep.name.startswith("ament_"))}
    if len(tools) == 2:
        # both named with no condition (a port's leftover: quadruped_ros2_control's
        # magicdog_description, catkin and ament_cmake, ``<build_type>ament_cmake``):
        # colcon builds it with its build type, REP 149's, catkin when none is given
        return 2 if package.build_type in ("ament_cmake", "ament_python") else 1
    for dep in dependencies:  # the build tool says it first
        if dep.kind in ("buildtool_depend", "buildtool_export_depend"):
            if dep.name == "catkin":
                return 1
            if dep.name.startswith("ament_"):
                return 2
    if package.build_type in ("ament_cmake", "ament_python"):
        return 2
    names = {dep.name for dep in dependencies}
    if names & _ROS2_DEPENDENCIES:
        return 2
    if names & _ROS1_DEPENDENCIES or package.format == 1:  # rosbuild ones read as format 1
        return 1
    return None


def build_ros_version(package: Package) -> str:
    """The ROS version ("1", "2") whose build system builds the package, where its
    package.xml says one and only one: its build tools (``buildtool_depend`` catkin or
    ament_*) and an ament ``<build_type>``, those whose REP 149 condition does not fail.
    Empty when it names none, or both (a dual package's conditions over
    ``$ROS_VERSION`` read with no ROS version given, ``builds_by_version``): the run's
    ROS version decides then. colcon builds a catkin package with catkin, in a ROS 1
    environment, and an ament one in a ROS 2 one: a dual package's
    ``find_package(catkin QUIET)`` / ``if(catkin_FOUND)`` (ros_deep_learning's
    CMakeLists.txt, whose package.xml is the ROS 1 one) follows the package.xml."""
    if package.builds_by_version:
        return ""
    versions = {"1" if dep.name == "catkin" else "2" for dep in package.dependencies
                if dep.active and dep.kind in ("buildtool_depend", "buildtool_export_depend")
                and (dep.name == "catkin" or dep.name.startswith("ament_"))}
    if package.build_type in ("ament_cmake", "ament_python"):
        versions.add("2")
    return versions.pop() if len(versions) == 1 else ""


def _plugins(root: etree._Element, rel_folder: str,
             active: Callable[[etree._Element], bool] = lambda _: True) -> list[Plugin]:
    """``<export><host plugin="${prefix}/plugins.xml"/></export>``, in both manifests;
    not one whose REP 149 ``condition`` is false in the environment (``active``):
    foxglove_bridge exports its nodelets with ``condition="$ROS_VERSION == 1"``, and a
    ROS 2 build installs no nodelet library."""
    export = root.find("export")
    if export is None:
        return []
    return [Plugin(element.tag, element.get("plugin", "").replace("${prefix}", rel_folder))
            for element in export
            if isinstance(element.tag, str) and element.tag != "build_type"
            and element.get("plugin") and active(element)]


def _parse_rosbuild(path: str, location: Location,
                    rel_folder: str) -> tuple[Package | None, list[Diagnostic]]:
    root, found = _read_root(path, location)
    if root is None:
        return None, found
    if root.tag != "package":
        return None, found  # some other tool's manifest.xml: no ROS package, nothing wrong
    name = os.path.basename(os.path.dirname(os.path.abspath(path)))
    package = Package(name=name, path=rel_folder, format=1, build_type="catkin",
                      version=(root.findtext("version") or "").strip(),
                      location=Location(name, location.file, _line(root), 0))
    for element in root.iter("depend"):
        if element.get("package"):
            package.dependencies.append(Dependency(element.get("package", ""), "depend"))
    package.plugins.extend(_plugins(root, rel_folder))
    return package, found


def _line(element: etree._Element) -> int:
    line = element.sourceline
    return line if isinstance(line, int) else 0


def installed_with(package: Package, packages: Iterable[Package], test: bool = False
                   ) -> set[str]:
    """The names of the packages a binary install of ``package`` brings: its run
    dependencies (``RUN_DEPEND_TAGS``; ``test_depend`` too when ``test``: rostest and
    launch_testing run with them), and theirs in turn where they are among ``packages``
    (a metapackage of the workspace), and the members of an installed metapackage of
    the shipped table (``models.metapackages``). A dependency with a ``condition`` counts
    as declared. The dependencies of another package not among ``packages`` are not
    known here."""
    from .models.metapackages import members  # the installed metapackages' table

    known = {p.name: p for p in packages}
    tags = (RUN_DEPEND_TAGS | {"test_depend"}) if test else RUN_DEPEND_TAGS
    found = {d.name for d in package.dependencies if d.kind in tags}
    todo = list(found)
    generation = ros_version(package)
    while todo:
        name = todo.pop()
        other = known.get(name)
        if other is None:
            # an installed metapackage brings its members (gazebo_ros_pkgs: gazebo_ros)
            for member in members(name, generation):
                if member not in found:
                    found.add(member)
                    todo.append(member)
            continue
        for dep in other.dependencies:
            if dep.kind in RUN_DEPEND_TAGS and dep.name not in found:
                found.add(dep.name)
                todo.append(dep.name)
    found.discard(package.name)
    return found
