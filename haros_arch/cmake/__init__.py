"""CMake front end: which runnable nodes a CMake-built package has, and their sources.

Entry point: ``parse_package(package, workspace)``. It interprets the package's
CMakeLists.txt (with its includes and subdirectories), then turns what was recorded
into nodes: executables, ROS 2 components, nodelets and host plugins (through
``haros_arch.plugins``)
and Python scripts.
"""

from __future__ import annotations

import dataclasses
import functools
import os
import re
import stat
from collections.abc import Callable

from .. import diagnostics as diag
from .. import plugins, pysetup
from ..diagnostics import Diagnostic
from ..files import kept_in, read_text
from ..manifest import build_ros_version, version_environment
from ..model.location import Location
from ..model.source import Node, Package, Plugin
from ..plugins.classes import remembered
from ..workspace import Workspace
from .commands import C_SUFFIXES, effective_standard, handed_extras, newest, on_every_path
from .interpreter import Interpreter
from .lexer import CMakeSyntaxError, Invocation, tokenize
from .nodes import (
    MODELLED_PACKAGES,
    PackageFiles,
    SourceMap,
    components,
    executables,
    gazebo_launchers,
    gazebo_plugins,
    is_python,
    scripts,
    with_elsewhere,
)
from .targets import CompileDefinition, Target

__all__ = ["CMAKE_BUILD_TYPES", "Target", "interpret", "package_libraries", "parse_package",
           "read_commands", "source_definitions", "source_include_dirs", "targets_of"]


def read_commands(path: str, workspace: Workspace | PackageFiles,
                  ) -> tuple[list[Invocation], list[Diagnostic]]:
    """Tokenise a CMake file; a syntax error keeps the commands read before it."""
    text, found = read_text(path, workspace.location(path))
    if text is None:
        return [], found
    try:
        return tokenize(text, path), found
    except CMakeSyntaxError as err:
        # keep what precedes the error: tokenise the text up to the failing line
        head = "\n".join(text.splitlines()[: max(err.line - 1, 0)])
        try:
            commands = tokenize(head, path)
        except CMakeSyntaxError:
            commands = []
        where = workspace.location(path, err.line, err.column)
        return commands, [*found, diag.make("CMAKE_SYNTAX", where, detail=err.message)]


def interpret(package: Package, workspace: Workspace) -> tuple[Interpreter, list[Diagnostic]]:
    """Run the package's top-level CMakeLists.txt (and what it includes)."""
    return _interpret(package, workspace, PackageFiles(package, workspace))


def _interpret(package: Package, workspace: Workspace, files: PackageFiles,
               version: str = "") -> tuple[Interpreter, list[Diagnostic]]:
    """The package's interpreter, run once per run (``Workspace.interpreted``: a package
    whose libraries others link is read for them too); with ``version``, its reading
    as a distribution of that ROS version builds it (``version_nodes``)."""
    key = (package.name, package.root + (f"\0{version}" if version else ""))
    return kept_in(workspace.interpreted, key,
                   lambda: _run(package, workspace, files, version))


_BUILD_DEPENDS = ("depend", "build_depend")
# the build types whose packages this front end reads
CMAKE_BUILD_TYPES = ("catkin", "ament_cmake", "cmake")


def build_depends(package: Package) -> list[str]:
    """The package's build dependencies, as ament_cmake_auto finds and links them."""
    return list(dict.fromkeys(d.name for d in package.dependencies
                              if d.kind in _BUILD_DEPENDS))


def package_libraries(name: str, workspace: Workspace) -> list[str] | None:
    """The workspace-relative sources of the libraries the workspace package ``name``
    builds, for the targets of other packages that link it; None when it is not a
    CMake package of the workspace. catkin's generated config of the package adds the
    libraries of its CATKIN_DEPENDS to its own, transitively: OpenMower's
    mower_comms_v1 links xesc_driver, whose XescDriver builds xesc_2040_driver's
    Xesc2040Driver, a library xesc_driver's own target links nowhere. Not those of the
    client library and its parts (``MODELLED_PACKAGES``: roscpp, xmlrpcpp, ...), whose
    API the stand-ins model."""
    return remembered("libraries", name, workspace,
                      lambda: _package_libraries(name, workspace))


def _package_libraries(name: str, workspace: Workspace) -> list[str] | None:
    own = _own_libraries(name, workspace)
    if own is None:
        return None
    found = list(own[0])
    seen = {name}

    def gather(depends: list[str]) -> None:  # depth first, as the configs append them
        for depend in depends:
            if depend in seen or depend in MODELLED_PACKAGES:
                continue  # a CATKIN_DEPENDS cycle ends there; the client library's
                # (roscpp, xmlrpcpp, ...) API is the stand-ins', even when its source is
                # here (ros_comm's tree: topic_tools exports roscpp)
            seen.add(depend)
            more = _own_libraries(depend, workspace)
            if more is not None:
                found.extend(s for s in more[0] if s not in found)
                gather(more[1])

    gather(own[1])
    return found


def _own_libraries(name: str, workspace: Workspace) -> tuple[list[str], list[str]] | None:
    """The sources of the libraries the package ``name`` exports itself, and its
    CATKIN_DEPENDS; None when it is not a CMake package of the workspace."""
    return remembered("own libraries", name, workspace,
                      lambda: _own_libraries_of(name, workspace))


def _own_libraries_of(name: str, workspace: Workspace
                      ) -> tuple[list[str], list[str]] | None:
    package = workspace.packages.get(name)
    if package is None or package.build_type not in CMAKE_BUILD_TYPES:
        return None
    files = PackageFiles(package, workspace)
    interpreter, _ = _interpret(package, workspace, files)
    sources = SourceMap(interpreter, files)
    return (list(dict.fromkeys(source for target in _exported(interpreter, sources)
                               for source in sources.own(target))),
            [d for d in interpreter.catkin_depends if d != name])


def catkin_components(package: Package, workspace: Workspace) -> list[str]:
    """The packages the catkin package's CMake files find as catkin's components
    (``find_package(catkin REQUIRED COMPONENTS roscpp moveit_ros_planning_interface)``),
    in order: the ROS packages its build uses, declared in its package.xml or not."""
    if package.build_type != "catkin" or not package.root:
        return []
    return remembered("catkin components", package.root, workspace, lambda: list(
        _interpret(package, workspace, PackageFiles(package, workspace))[0].catkin_components))


def libraries_handed(name: str, workspace: Workspace) -> list[tuple[str, list[str]]]:
    """What a target that links the workspace package ``name`` gets of the workspace's
    libraries, a (package, sources) pair per package: its own libraries
    (``package_libraries``); where it builds none, a header-only umbrella
    (autoware_utils, whose CMake is ``ament_auto_package()`` alone), those of each
    package it exports (``package_exports``; ament's ``ament_export_dependencies`` and
    ament_cmake_auto, and catkin's ``CATKIN_DEPENDS``, put theirs in its
    ``_LIBRARIES``), an empty list for one that builds none either. A package that
    builds libraries of its own hands on no more: a package's dependencies are its own
    business."""
    own = package_libraries(name, workspace)
    if own is None:
        return []
    if own:
        return [(name, own)]
    return [(other, package_libraries(other, workspace) or [])
            for other in package_exports(name, workspace) if other not in MODELLED_PACKAGES]


def _exported(interpreter: Interpreter, sources: SourceMap) -> list[Target]:
    """The libraries of a package that another package's targets link: a catkin
    package's are those its ``catkin_package(LIBRARIES ...)`` names, with the package
    libraries they link (catkin puts only those in ``catkin_LIBRARIES``: stdr_robot
    exports stdr_handle_robot, not the motion controllers only its nodelet links); where
    that call is not known for certain (none read, or under an ``if()`` not decided),
    every library of the package."""
    libraries = [t for t in interpreter.targets.values() if t.kind == "library"]
    if interpreter.catkin_exports is None or interpreter.catkin_exports_unsure:
        return libraries
    named = set(interpreter.catkin_exports)
    return list({linked.name: linked for target in libraries
                 if target.name in named or target.output_name in named
                 for linked in sources.closure(target) if linked.kind == "library"}.values())


def library_target(package: str, target: str, workspace: Workspace) -> list[str] | None:
    """The workspace-relative sources of the library target ``target`` (by its name or
    output name) of the workspace package ``package``, with the package libraries it
    links; None when the package is not a CMake package of the workspace or builds no
    such library."""
    return remembered("library target", f"{package}\0{target}", workspace,
                      lambda: _library_target(package, target, workspace))


def _library_target(package_name: str, name: str, workspace: Workspace) -> list[str] | None:
    package = workspace.packages.get(package_name)
    if package is None or package.build_type not in CMAKE_BUILD_TYPES:
        return None
    files = PackageFiles(package, workspace)
    interpreter, _ = _interpret(package, workspace, files)
    found = next((t for t in interpreter.targets.values() if t.kind == "library" and (
        name in (t.name, t.output_name))), None)
    if found is None:
        return None
    return SourceMap(interpreter, files).linked(found)


def package_links(name: str, workspace: Workspace) -> list[str]:
    """The other packages the libraries of the workspace package ``name`` link (as
    ``SourceMap.packages`` says for each); none when it is not a CMake package of the
    workspace."""
    return remembered("library links", name, workspace,
                      lambda: _package_links(name, workspace))


def _package_links(name: str, workspace: Workspace) -> list[str]:
    package = workspace.packages.get(name)
    if package is None or package.build_type not in CMAKE_BUILD_TYPES:
        return []
    files = PackageFiles(package, workspace)
    interpreter, _ = _interpret(package, workspace, files)
    sources = SourceMap(interpreter, files, build_depends=build_depends(package),
                        package=package.name)
    return list(dict.fromkeys(other for target in _exported(interpreter, sources)
                              for other in sources.packages(target)))


# the package.xml dependencies a package hands its users (format 2 and 3)
_EXPORTED = ("depend", "build_export_depend")


def package_exports(name: str, workspace: Workspace) -> list[str]:
    """The dependencies the workspace package ``name`` exports to the packages that
    build on it (``depend``, ``build_export_depend``); none when it is not one."""
    package = workspace.packages.get(name)
    if package is None:
        return []
    return list(dict.fromkeys(d.name for d in package.dependencies if d.kind in _EXPORTED))


# a macro two targets that compile one source define differently, or that a target and a
# library it links define differently: which one a parse should take is not known
CONFLICT = CompileDefinition("", None, known=False)


def source_definitions(package: Package, workspace: Workspace
                       ) -> dict[str, list[dict[str, CompileDefinition]]]:
    """Each C/C++ source of the package's targets (workspace-relative) -> for each target
    that compiles it, the macros that target's compile line defines, by name: its
    directory's (``add_definitions``, ``add_compile_definitions``), its own PRIVATE and
    PUBLIC ones (``target_compile_definitions``), and the PUBLIC and INTERFACE ones of the
    package's libraries it links. A name given two different definitions is
    ``CONFLICT``. Empty for a package CMake does not build."""
    return remembered("compile definitions", package.root, workspace,
                      lambda: _source_definitions(package, workspace))


def absent_definitions(package: Package, workspace: Workspace) -> frozenset[str]:
    """The macros only branches of ``if()`` that the reading decided not taken, on what
    it knows for certain, define: no target of the package gets them from there."""
    def read() -> frozenset[str]:
        if package.build_type not in CMAKE_BUILD_TYPES or not package.root:
            return frozenset()
        interpreter, _ = _interpret(package, workspace, PackageFiles(package, workspace))
        return frozenset(interpreter.absent_definitions)
    return remembered("absent definitions", package.root, workspace, read)


def option_gated(package: Package, workspace: Workspace
                 ) -> dict[str, tuple[str, str, Location]]:
    """The targets (by the first word of the command that would make them) that the
    package's CMake files make only in a branch not taken because an option has its
    default, each with the option, that default and where the option is declared: a
    launch file starting one names a program the default build does not make, not one
    missing from the workspace."""
    if package.build_type not in CMAKE_BUILD_TYPES or not package.root:
        return {}
    interpreter, _ = _interpret(package, workspace, PackageFiles(package, workspace))
    return dict(interpreter.option_gated)


def installed_program(package: Package, workspace: Workspace, name: str) -> str | None:
    """The file the package's CMake files install as the program ``name``
    (``install(PROGRAMS ...)``, ``catkin_install_python``, or an executable file of a
    folder ``install(DIRECTORY ... DESTINATION lib/... USE_SOURCE_PERMISSIONS)`` copies:
    ateam_bringup's ``scripts/scream_if_wifi_enabled.sh``) when it is there and no
    Python program (``scripts`` makes those nodes): a shell script or a prebuilt binary,
    which ros2 launch finds in the package's lib folder and runs, and which this tool does
    not read; None otherwise."""
    if package.build_type not in CMAKE_BUILD_TYPES or not package.root or not name:
        return None
    interpreter, _ = _interpret(package, workspace, PackageFiles(package, workspace))
    for program in interpreter.programs:
        if program.name == name and os.path.isfile(program.path) and not is_python(
                program.path):
            return program.path
    if os.sep in name or name in (".", ".."):
        return None
    for folder in interpreter.program_dirs:
        path = os.path.join(folder.path, name)
        if os.path.isfile(path) and os.stat(path).st_mode & stat.S_IXUSR and not is_python(
                path):
            return path
    return None


def _source_definitions(package: Package, workspace: Workspace
                        ) -> dict[str, list[dict[str, CompileDefinition]]]:
    if package.build_type not in CMAKE_BUILD_TYPES or not package.root:
        return {}
    files = PackageFiles(package, workspace)
    found: dict[str, list[dict[str, CompileDefinition]]] = {}
    # a source only one ROS version's build compiles (``version_builds``) takes what
    # that reading gives it
    for version, interpreter in zip(["", *version_builds(package)],
                                    _readings(package, workspace, files), strict=True):
        sources = SourceMap(interpreter, files, build_depends=build_depends(package),
                            package=package.name)
        here: dict[str, list[dict[str, CompileDefinition]]] = {}
        for target in interpreter.targets.values():
            given = [*(_given_where_made(each, target)
                       for each in target.directory_definitions),
                     *(_given_where_made(each, target)
                       for keyword, each in target.definitions if keyword != "INTERFACE"),
                     *(_given_where_made(each, linked)
                       for linked in sources.closure(target)[1:]
                       for keyword, each in linked.definitions if keyword != "PRIVATE"),
                     *(each for other in sources.packages(target)
                       for each in exported_definitions(other, workspace, version))]
            defined: dict[str, CompileDefinition] = {}
            for each in given:
                known = defined.get(each.name)
                defined[each.name] = each if known is None or _same(known, each) else CONFLICT
            for source in sources.own(target):
                here.setdefault(source, []).append(defined)
        for source, given_here in here.items():
            found.setdefault(source, given_here)
    return found


def exported_definitions(name: str, workspace: Workspace,
                         version: str = "") -> list[CompileDefinition]:
    """The macros the workspace package ``name``'s libraries that others link define
    for the targets linking them (``target_compile_definitions`` PUBLIC and INTERFACE,
    of each exported library and the package libraries it links), each where its
    library is made; as that package's build for ROS ``version`` makes them, where it
    is read per version (``version_builds``). depthai_bridge's ament branch gives its
    library ``PUBLIC IS_ROS2``, which picks the ROS 2 half of every header it installs
    for depthai_examples' ROS 2 nodes."""
    return remembered("exported definitions", f"{name}\0{version}", workspace,
                      lambda: _exported_definitions(name, workspace, version))


def _exported_definitions(name: str, workspace: Workspace,
                          version: str) -> list[CompileDefinition]:
    package = workspace.packages.get(name)
    if package is None or package.build_type not in CMAKE_BUILD_TYPES or not package.root:
        return []
    files = PackageFiles(package, workspace)
    interpreter, _ = _interpret(package, workspace, files,
                                version if version in version_builds(package) else "")
    sources = SourceMap(interpreter, files)
    return list(dict.fromkeys(
        _given_where_made(each, linked) for target in _exported(interpreter, sources)
        for linked in sources.closure(target)
        for keyword, each in linked.definitions if keyword != "PRIVATE"))


def _given_where_made(each: CompileDefinition, target: Target) -> CompileDefinition:
    """``each`` for ``target``: the if()s not decided around both it and the command
    that makes the target do not guard it there, as a target exists only where they
    hold (autorally's ``if(CUDA_FOUND)`` around ``cuda_add_executable(path_integral_bf
    ...)`` and its ``target_compile_definitions(... USE_BASIS_FUNC_MODEL__)``, which
    chooses the dynamics model and its constants: undefined, every line using them was an
    error). The sources of a target made in both branches of an if() not decided are
    those of its last make, compiled only where its branch is taken (depthai_examples'
    ``target_compile_definitions(stereo_inertial_node PRIVATE BLOB_NAME=...)`` in the
    ``else`` of ``if(ament_cmake_FOUND)``, after the ROS 1 make of the node)."""
    made = target.sources_under
    if not each.conditions or not made:
        return each
    rest = tuple(c for c in each.conditions if c not in made)
    return each if len(rest) == len(each.conditions) else dataclasses.replace(
        each, conditions=rest)


# the C++ standard the parse uses unless told another (``toolchain.base_arguments``);
# the stand-in headers are written for it, so an older one a package asks is read so too
DEFAULT_STANDARD = 17


def source_standards(package: Package, workspace: Workspace) -> dict[str, str]:
    """Each C/C++ source of the package's targets (workspace-relative) whose targets ask
    a C++ standard newer than ``DEFAULT_STANDARD`` -> its ``-std`` value (``c++20``): the
    one the compiler uses for a target (``commands.effective_standard``: its
    ``CXX_STANDARD``, from ``CMAKE_CXX_STANDARD`` when it is made, raised to the newest
    that its ``target_compile_features(cxx_std_NN)`` and the PUBLIC and INTERFACE ones
    of the package's libraries it links require, and the ``-std=`` words of
    ``CMAKE_CXX_FLAGS`` and of its compile options, in the order CMake writes them on
    the compile line, the last winning); the newest of the targets that compile the
    source."""
    return remembered("compile standards", package.root, workspace,
                      lambda: _source_standards(package, workspace))


def _source_standards(package: Package, workspace: Workspace) -> dict[str, str]:
    if package.build_type not in CMAKE_BUILD_TYPES or not package.root:
        return {}
    files = PackageFiles(package, workspace)
    interpreter, _ = _interpret(package, workspace, files)
    sources = SourceMap(interpreter, files)
    found: dict[str, int] = {}
    distro = workspace.environment.get("ROS_DISTRO")
    for target in interpreter.targets.values():
        required = [*(year for keyword, year in target.features if keyword != "INTERFACE"),
                    *(year for linked in sources.closure(target)[1:]
                      for keyword, year in linked.features if keyword != "PRIVATE")]
        year = effective_standard(target, newest(required), interpreter.cmp0128, distro)
        if year <= DEFAULT_STANDARD or year == 98:
            continue
        for source in sources.own(target):
            found[source] = max(found.get(source, 0), year)
    return {source: f"c++{year}" for source, year in found.items()}


def source_include_dirs(package: Package, workspace: Workspace) -> dict[str, list[str]]:
    """Each C/C++ source of the package's targets (workspace-relative) -> the include
    folders the compile lines of the targets that compile it give, in order: each
    target's directory's (``include_directories``), its own PRIVATE and PUBLIC ones
    (``target_include_directories``), then the PUBLIC and INTERFACE ones of the
    package's libraries it links; as written (not checked on disk). Only those given
    wherever the target (or the library) is made: a folder under an ``if()`` the
    reading did not decide that the target is not under too may not be the build's
    (foxglove_bridge's ROS 2 folders under ``if(DEFINED ENV{AMENT_PREFIX_PATH})``, with
    the targets, are; a folder of one branch of ``if(USE_SDK)`` not decided, beside
    another holding the same headers, is not). Empty for a package CMake does not build."""
    return remembered("include folders", package.root, workspace,
                      lambda: _source_include_dirs(package, workspace))


def _source_include_dirs(package: Package, workspace: Workspace) -> dict[str, list[str]]:
    if package.build_type not in CMAKE_BUILD_TYPES or not package.root:
        return {}
    files = PackageFiles(package, workspace)
    found: dict[str, list[str]] = {}
    for interpreter in _readings(package, workspace, files):  # as _source_definitions
        sources = SourceMap(interpreter, files)
        here: dict[str, list[str]] = {}
        for target in interpreter.targets.values():
            made = set(target.sources_under)
            given = [*(folder for folder, under in target.directory_includes
                       if set(under) <= made),
                     *(folder for keyword, folder, under in target.includes
                       if keyword != "INTERFACE" and set(under) <= made),
                     *(folder for linked in sources.closure(target)[1:]
                       for keyword, folder, under in linked.includes
                       if keyword != "PRIVATE" and set(under) <= set(linked.conditions))]
            for source in sources.own(target):
                here[source] = list(dict.fromkeys([*here.get(source, []), *given]))
        for source, folders in here.items():
            found.setdefault(source, folders)
    return found


def _same(one: CompileDefinition, other: CompileDefinition) -> bool:
    return (one.value, one.known, one.conditions) == (other.value, other.known,
                                                      other.conditions)


def _run(package: Package, workspace: Workspace, files: PackageFiles,
         version: str = "") -> tuple[Interpreter, list[Diagnostic]]:
    found: list[Diagnostic] = []

    def reader(path: str) -> list[Invocation]:
        commands, problems = read_commands(path, files)
        found.extend(problems)
        return commands

    interpreter = _interpreter(package, workspace, reader, files, version)
    path = os.path.join(package.root, "CMakeLists.txt")
    if os.path.isfile(path):
        _EXTRAS_READING.add(package.name)
        try:
            interpreter.run_file(reader(path))
        finally:
            _EXTRAS_READING.discard(package.name)
        handed_extras(interpreter, [])
    if interpreter.superbuild is None:
        return interpreter, found + interpreter.diagnostics
    # a superbuild configures the package's own folder again with the cache entries it
    # gives: the targets built are that configuration's (read once more, not again after)
    where, name, values = interpreter.superbuild
    first = found + interpreter.diagnostics
    found = []
    again = _interpreter(package, workspace, reader, files, version)
    again.cache.update(values)
    again.run_file(reader(path))
    said = diag.make("CMAKE_SUPERBUILD", where, name=name,
                     values=" ".join(f"-D{k}={v}" for k, v in values.items()))
    return again, list(dict.fromkeys([*first, said, *found, *again.diagnostics]))


def _interpreter(package: Package, workspace: Workspace,
                 reader: Callable[[str], list[Invocation]], files: PackageFiles,
                 version: str = "") -> Interpreter:
    """An interpreter for the package's CMake files, which finds the config extras of
    the workspace's other packages (``config_extras``); with ``version``, in the
    environment a distribution of that ROS version sets (``ROS_VERSION``)."""
    environment = (version_environment(workspace.environment, version) if version
                   else workspace.environment)
    interpreter = Interpreter(package.root, environment, reader, files.location)
    interpreter.build_depends = build_depends(package)
    interpreter.package_name, interpreter.package_version = package.name, package.version
    interpreter.package_ros_version = version or build_ros_version(package)
    interpreter.source_distro = workspace.source_distro

    def catkin_project(name: str) -> bool:
        other = workspace.packages.get(name)
        return other is None or other.build_type == "catkin"

    interpreter.catkin_project = catkin_project

    def extras_of(name: str) -> tuple[str, list[str]]:
        other = workspace.packages.get(name)
        if name == package.name or other is None or not other.root:
            return "", []
        return other.root, config_extras(name, workspace)

    interpreter.extras_of = extras_of
    interpreter.workspace_holds = lambda path: workspace.holds(path) or path in [
        os.path.abspath(folder).rstrip(os.sep) for folder in workspace.folders]
    interpreter.submodule_of = workspace.submodule_of
    return interpreter


_EXTRAS_READING: set[str] = set()  # the packages being read now (two that find each other)


def config_extras(name: str, workspace: Workspace) -> list[str]:
    """The CMake files the workspace package ``name`` hands to the packages that find it
    (ament's ``CONFIG_EXTRAS`` and ``${PROJECT_NAME}_CONFIG_EXTRAS``, catkin's
    ``CFG_EXTRAS`` of its cmake folder), absolute, from a reading of its CMake files;
    none for a package being read for this very question (two packages that find each
    other)."""
    package = workspace.packages.get(name)
    if package is None or package.build_type not in CMAKE_BUILD_TYPES or not package.root:
        return []
    if name in _EXTRAS_READING:
        return []
    interpreter, _ = _interpret(package, workspace, PackageFiles(package, workspace))
    return [path for path in interpreter.config_extras if os.path.isfile(path)]


def _named_library(name: str, own: str, depends: list[str],
                   workspace: Workspace) -> list[str] | None:
    """The sources of the library target ``name`` that a target links by its bare name
    where its own package builds no such target: a library of the workspace package of
    that name, or of one of its build dependencies (catkin's devel space holds every
    package's libraries, so ``target_link_libraries(x industrial_robot_client)`` links
    industrial_core's library that its ``catkin_package`` does not export)."""
    for package in dict.fromkeys([name, *depends]):
        if package == own or package not in workspace.packages:
            continue
        found = library_target(package, name, workspace)
        if found:
            return found
    return None


def targets_of(package: Package, workspace: Workspace) -> tuple[list[Target], list[Diagnostic]]:
    """The build targets of a package's CMake files."""
    interpreter, found = interpret(package, workspace)
    return list(interpreter.targets.values()), found


def _standalone_names(classes: list[Node], it: Interpreter, files: PackageFiles) -> None:
    """A command defined outside the workspace that is given one of the package's nodelet
    classes by its lookup name may build a program that runs it alone under its own node
    name (jsk_topic_tools' ``jsk_nodelet(src/logger.cpp "pkg/Logger" logger SRCS EXECS)``
    configures a ``main`` that loads the class, as ``nodelet standalone`` does, and adds
    the source to the list SRCS the package's library builds): the command's other plain
    words are the names such a program may have (``Node.aliases``), which a launch file's
    ``type=`` that names no target of the package takes (``graph.build.node_key``), and
    its C/C++ files of the package are the class's code. Class names and targets are no
    program names."""
    for node in classes:
        if node.kind != "nodelet":
            continue
        for args, code in it.foreign_calls:
            if node.executable not in args:
                # a call that names the class otherwise (a lookup name the plugin
                # description has since changed: jsk_pcl_ros_utils' ``"jsk_pcl/
                # CloudOnPlane"``, described as ``jsk_pcl_utils/CloudOnPlane``) still
                # builds the file that exports it into the library
                node.sources.extend(relative for relative in map(files.relpath, code)
                                    if relative not in node.sources
                                    and _exports(relative, node.plugin_class, files))
                continue
            node.aliases.extend(
                a for a in dict.fromkeys(args) if a != node.executable
                and _PROGRAM_NAME.fullmatch(a) and not a.endswith(_CODE_SUFFIXES)
                and a not in it.targets and a not in node.aliases)
            node.sources.extend(relative for relative in map(files.relpath, code)
                                if relative not in node.sources)


def _exports(source: str, cls: str | None, files: PackageFiles) -> bool:
    """Whether the package's file ``source`` exports the plugin class ``cls``."""
    if not cls:
        return False
    return cls.lstrip(":") in {name for name, _ in plugins.exported_classes(
        os.path.join(files.root, source), files)}


# a word that may name a program: no path, no ``::`` (C/C++ files left out by suffix)
_PROGRAM_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_.+-]*")
_CODE_SUFFIXES = (*C_SUFFIXES, ".h", ".hh", ".hpp", ".hxx")


def version_builds(package: Package) -> list[str]:
    """The ROS versions ("1", "2") under which a dual package's package.xml has CMake
    build it (``builds_by_version``: catkin for ROS 1, ament_cmake for ROS 2, chosen by
    ``$ROS_VERSION``, the run giving none), when there are two: its CMake files are
    then read once more as each version's distribution builds them, where
    ``if(ament_cmake_FOUND)`` or ``if($ENV{ROS_VERSION} EQUAL 2)`` is decided
    (``version_nodes``); empty otherwise."""
    versions = [version for version, build_type in sorted(package.builds_by_version.items())
                if build_type in CMAKE_BUILD_TYPES]
    return versions if len(versions) > 1 else []


def version_nodes(package: Package, workspace: Workspace,
                  nodes: list[Node]) -> dict[str, dict[str, Node]]:
    """For a package CMake builds under both ROS versions (``version_builds``), each
    version -> the executables of ``nodes`` (the reading that decides no version) that
    this version's build makes from other sources, as it makes them. A target made in
    both branches of an ``if()`` on the ROS version (depthai_examples'
    ``if(ament_cmake_FOUND) ... elseif(CATKIN_DEVEL_PREFIX)``, each branch making
    ``stereo_inertial_node`` from its own source) is one node of the last make's
    sources in ``nodes``; the launch files of each ROS version start the program that
    version's build makes (``pipeline.built_for``)."""
    found: dict[str, dict[str, Node]] = {}
    plain = {node.executable: node for node in nodes if node.kind == "executable"}
    for version in version_builds(package):
        made, _ = parse_package(package, workspace, version)
        for node in made:
            known = plain.get(node.executable)
            if node.kind == "executable" and known is not None and node.sources != known.sources:
                found.setdefault(version, {})[node.executable] = node
    return found


def _readings(package: Package, workspace: Workspace,
              files: PackageFiles) -> list[Interpreter]:
    """The package's reading that decides no ROS version, then each version's reading
    (``version_builds``)."""
    return [_interpret(package, workspace, files, version)[0]
            for version in ["", *version_builds(package)]]


def parse_package(package: Package, workspace: Workspace,
                  version: str = "") -> tuple[list[Node], list[Diagnostic]]:
    """The runnable nodes a CMake-built package has, with their sources; with
    ``version``, as a distribution of that ROS version builds it."""
    files = PackageFiles(package, workspace)
    interpreter, found = _interpret(package, workspace, files, version)
    found = list(found)
    depends = build_depends(package)
    sources = SourceMap(interpreter, files, lambda name: package_libraries(name, workspace),
                        depends, package.name,
                        lambda name: package_links(name, workspace),
                        lambda name: libraries_handed(name, workspace),
                        lambda name: _named_library(name, package.name, depends, workspace))
    nodes = executables(interpreter, package, files, sources)
    nodes.extend(components(interpreter, package, files, sources))
    nodes.extend(gazebo_plugins(interpreter, package, files, sources))
    nodes.extend(gazebo_launchers(interpreter, package, files, nodes))
    libraries: dict[str, plugins.Library] = {}
    for target in interpreter.targets.values():
        if target.kind == "library":
            library = plugins.Library(
                sources.linked(target), target.conditions, sources.own(target),
                functools.partial(sources.reached, target),
                # a nodelet's files with what they name of other workspace packages'
                # libraries that its library links
                with_elsewhere=functools.partial(with_elsewhere, target=target,
                                                 sources=sources, workspace=files))
            libraries.setdefault(target.name, library)
            libraries.setdefault(target.output_name or target.name, library)
    described = [Plugin(base, files.relpath(path))
                 for base, path in interpreter.plugin_descriptions]
    roots = [package.root, *(workspace.packages[d].root for d in depends
                             if d in workspace.packages and workspace.packages[d].root)]
    # pluginlib's ClassLoader(tag, base) reads the classes every package exports under
    # its tag, and the code that declares it includes the base's header, so its package
    # is the tag's package or depends on it: jsk_aerial_robot's dragon exports
    # controllers under aerial_robot_control, and aerial_robot_base, which depends on
    # aerial_robot_control (not on dragon), loads them by a parameter's value
    tags = {plugin.kind for plugin in [*package.plugins, *described]}
    roots += [other.root for other in workspace.packages.values() if other.root and (
        other.root not in roots) and (other.name in tags or any(
            d.name in tags for d in other.dependencies))]
    named: frozenset[str] = frozenset()
    if package.plugins or described:
        # the code that creates a class by its name is usually in a package that depends
        # on the class's package
        dependents = [other.root for other in workspace.packages.values() if other.root
                      and any(d.name == package.name for d in other.dependencies)]
        named = plugins.named_loads([*roots, *dependents], files)
    classes, problems = plugins.plugin_classes(
        package, files, libraries, described, plugins.loaded_bases(roots, files), named)
    _standalone_names(classes, interpreter, files)
    nodes.extend(classes)
    found.extend(problems)
    found.extend(sources.diagnostics)
    nodes.extend(scripts(interpreter, package, files, found))
    if interpreter.python_scripts:
        entry_points, problems = pysetup.setup_cfg_nodes(package, workspace)
        nodes.extend(entry_points)
        found.extend(problems)
    return _unique(nodes), found


def _unique(nodes: list[Node]) -> list[Node]:
    """One node per name: the first declaration wins (CMake refuses duplicate targets);
    one declared again in the ``else`` of the ``if()`` not decided that declared it is
    made on both paths (Autoware's traffic_light_classifier_node, registered under
    ``if(TRT_AVAIL AND CUDA_AVAIL AND CUDNN_AVAIL)`` and in its ``else()``)."""
    seen: dict[str, Node] = {}
    for node in nodes:
        known = seen.setdefault(node.executable, node)
        if known is not node:
            both = on_every_path(known.conditions, node.conditions)
            if len(both) < len(node.conditions):
                known.conditions = both
    return list(seen.values())
