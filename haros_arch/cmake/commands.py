"""Handlers of the CMake commands that matter for finding runnable nodes.

``HANDLERS`` maps a lower-case command name to ``handler(interpreter, command, args)``,
where ``args`` are already expanded. Anything not listed is skipped by the interpreter.
"""

from __future__ import annotations

import fnmatch
import glob
import os
import posixpath
import re
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from .. import diagnostics as diag
from ..files import note_read, read_text
from ..model.conditions import Condition
from ..model.location import NOWHERE
from . import listops
from .conditions import FALSE_WORDS, PACKAGE_MARK_START, TRUE_WORDS
from .lexer import Argument, Invocation
from .listops import RegexLimit, run_list, run_math, run_string, split_list
from .targets import CompileDefinition, Configured, Install, Program, Registration, Target

if TYPE_CHECKING:
    from .interpreter import Interpreter

Handler = Callable[["Interpreter", Invocation, list[str]], None]
HANDLERS: dict[str, Handler] = {}
MAX_GLOB = 10_000
C_SUFFIXES = (".c", ".cc", ".cpp", ".cxx", ".c++", ".C", ".cu")


def handles(*names: str) -> Callable[[Handler], Handler]:
    def register(function: Handler) -> Handler:
        for name in names:
            HANDLERS[name] = function
        return function
    return register


# -- variables ------------------------------------------------------------------
@handles("set")
def _set(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if not args:
        return
    name, values = args[0], args[1:]
    if "CACHE" in values:
        at = values.index("CACHE")
        if name not in it.cache or "FORCE" in values[at:]:
            joined = ";".join(values[:at])
            it._bounded(name, joined)
            it.cache[name] = joined
        return
    if values[-1:] == ["PARENT_SCOPE"]:
        it.set_parent(name, ";".join(values[:-1]) if values[:-1] else None)
    elif values:
        it.set(name, ";".join(values))
    else:
        it.clear(name)


@handles("unset")
def _unset(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if not args:
        return
    if "CACHE" in args[1:]:
        it.cache.pop(args[0], None)
    elif "PARENT_SCOPE" in args[1:]:
        it.set_parent(args[0], None)
    else:
        it.clear(args[0])


@handles("option")
def _option(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if args and args[0] not in it.cache:
        it.cache[args[0]] = args[2] if len(args) > 2 else "OFF"
        it.options[args[0]] = (it.cache[args[0]], it.where(command))


@handles("list")
def _list(it: Interpreter, command: Invocation, args: list[str]) -> None:
    try:
        run_list(args, it)
    except RegexLimit as slow:
        _slow_regex(it, command, slow)
        # list(FILTER l ...) / list(TRANSFORM l REPLACE ... [OUTPUT_VARIABLE out])
        names = args[1:2] + [args[i + 1] for i, a in enumerate(args[:-1])
                             if a == "OUTPUT_VARIABLE"]
        for name in names:
            it.unset(name)


@handles("string")
def _string(it: Interpreter, command: Invocation, args: list[str]) -> None:
    try:
        run_string(args, it)
    except RegexLimit as slow:
        _slow_regex(it, command, slow)
        # string(REGEX MATCH|MATCHALL re out ...) / string(REGEX REPLACE re with out ...)
        out = 4 if args[1:2] == ["REPLACE"] else 3
        if len(args) > out:
            it.unset(args[out])


def _slow_regex(it: Interpreter, command: Invocation, slow: RegexLimit) -> None:
    it.limit(command, f"regular expression {str(slow)[:80]!r} ran past "
                      f"{listops.REGEX_SECONDS} s; what it sets stays unknown")


@handles("math")
def _math(it: Interpreter, command: Invocation, args: list[str]) -> None:
    run_math(args, it)


@handles("cmake_parse_arguments")
def _cmake_parse_arguments(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if args[:1] == ["PARSE_ARGV"] and len(args) >= 6:
        start = int(args[1]) if args[1].isdigit() else 0
        count = int(it.get("ARGC") or 0)
        values = [it.get(f"ARGV{i}") or "" for i in range(start, count)]
        prefix, specs = args[2], args[3:6]
    elif len(args) >= 4:
        prefix, specs, values = args[0], args[1:4], args[4:]
    else:
        return
    options, singles, multis = (split_list(spec) for spec in specs)
    keywords = set(options) | set(singles) | set(multis)
    parsed: dict[str, list[str]] = {}
    unparsed: list[str] = []
    current: str | None = None
    for value in values:
        if value in keywords:
            current = value
            parsed.setdefault(value, [])
            if value in options:
                current = None
        elif current is not None:
            parsed[current].append(value)
            if current in singles:
                current = None
        else:
            unparsed.append(value)
    for key in options:
        it.set(f"{prefix}_{key}", "TRUE" if key in parsed else "FALSE")
    for key in (*singles, *multis):
        if parsed.get(key):
            it.set(f"{prefix}_{key}", ";".join(parsed[key]))
        else:
            it.unset(f"{prefix}_{key}")
    if unparsed:
        it.set(f"{prefix}_UNPARSED_ARGUMENTS", ";".join(unparsed))
    else:
        it.unset(f"{prefix}_UNPARSED_ARGUMENTS")


@handles("project")
def _project(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if not args:
        return
    name = args[0]
    for key, value in (("PROJECT_NAME", name), ("PROJECT_SOURCE_DIR", it.source_dir),
                       (f"{name}_SOURCE_DIR", it.source_dir),
                       ("PROJECT_BINARY_DIR", it.get("CMAKE_CURRENT_BINARY_DIR") or "")):
        it.set(key, value)
    if it.get("CMAKE_PROJECT_NAME") is None:
        it.set("CMAKE_PROJECT_NAME", name)
    if "VERSION" in args[1:-1]:
        version = args[args.index("VERSION") + 1]
        it.set("PROJECT_VERSION", version)
        it.set(f"{name}_VERSION", version)
    # what catkin's and ament's find_package would define for the package
    it.set("CATKIN_PACKAGE_BIN_DESTINATION", f"lib/{name}")
    it.set("CATKIN_PACKAGE_SHARE_DESTINATION", f"share/{name}")
    it.set("CATKIN_GLOBAL_BIN_DESTINATION", "bin")
    it.set("CATKIN_GLOBAL_INCLUDE_DESTINATION", "include")
    it.set("CATKIN_PACKAGE_INCLUDE_DESTINATION", f"include/{name}")
    # catkin's devel space, in the build folder (its all.cmake's default,
    # ``${CMAKE_BINARY_DIR}/devel``): what a custom command writes there is generated
    # (cpr_multimaster_tools' message_relay builds its processors from sources it
    # writes to ``${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION}``)
    if it.get("CATKIN_DEVEL_PREFIX") is None:
        it.set("CATKIN_DEVEL_PREFIX", (it.get("CMAKE_BINARY_DIR") or "") + "/devel")


@handles("get_filename_component")
def _get_filename_component(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if len(args) < 3:
        return
    var, path, mode = args[0], args[1], args[2]
    base = os.path.basename(path)
    parts = {
        "NAME": base,
        "NAME_WE": base.split(".", 1)[0],
        "NAME_WLE": base.rsplit(".", 1)[0],
        "EXT": "." + base.split(".", 1)[1] if "." in base else "",
        "LAST_EXT": "." + base.rsplit(".", 1)[1] if "." in base else "",
        "DIRECTORY": os.path.dirname(path),
        "PATH": os.path.dirname(path),
        "ABSOLUTE": it.path(path),
    }
    if mode in parts:
        it.set(var, parts[mode])
    else:
        it.unset(var)


@handles("file")
def _file(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if len(args) < 2:
        return
    sub = args[0]
    if sub in ("GLOB", "GLOB_RECURSE"):
        it.set(args[1], ";".join(_glob(it, args[2:], recurse=sub == "GLOB_RECURSE")))
    elif sub == "TO_CMAKE_PATH" and len(args) >= 3:
        it.set(args[2], args[1].replace("\\", "/"))
    elif sub == "RELATIVE_PATH" and len(args) >= 4:
        it.set(args[1], os.path.relpath(args[3], args[2]))
    elif sub in ("READ", "STRINGS", "REAL_PATH", "SIZE", "TIMESTAMP", "MD5", "SHA256"):
        it.unset(args[2] if sub in ("REAL_PATH",) and len(args) > 2 else args[-1])


# the keywords of find_path / find_file that end a list of names or folders
_FIND_KEYWORDS = frozenset({
    "NAMES", "HINTS", "PATHS", "PATH_SUFFIXES", "DOC", "NO_CACHE", "REQUIRED",
    "OPTIONAL", "REGISTRY_VIEW", "VALIDATOR", "NAMES_PER_DIR", "NO_DEFAULT_PATH",
    "NO_PACKAGE_ROOT_PATH", "NO_CMAKE_PATH", "NO_CMAKE_ENVIRONMENT_PATH",
    "NO_SYSTEM_ENVIRONMENT_PATH", "NO_CMAKE_SYSTEM_PATH", "NO_CMAKE_INSTALL_PREFIX",
    "CMAKE_FIND_ROOT_PATH_BOTH", "ONLY_CMAKE_FIND_ROOT_PATH", "NO_CMAKE_FIND_ROOT_PATH"})


@handles("find_path", "find_file")
def _find_path(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``find_path(VAR NAMES n... HINTS dir... PATHS dir... PATH_SUFFIXES s...)`` (and
    the short form ``find_path(VAR n dir...)``): the first folder given, with each
    suffix, that lies in the workspace and holds one of the names; ``find_file`` the file
    itself. A folder of a git submodule not checked out here is the value the build
    finds once it is (darknet_ros' ``find_path(DARKNET_PATH NAMES README.md HINTS
    ${CMAKE_CURRENT_SOURCE_DIR}/../darknet/)``, whose sources lie there); anything
    else (CMake's default search of the build machine's system folders) is not known
    here: the variable is left so. A value in the cache already is kept, as CMake
    searches no more."""
    if len(args) < 2 or it.workspace_holds is None:
        return
    var, rest = args[0], args[1:]
    cached = it.cache.get(var)
    if cached and not cached.upper().endswith("NOTFOUND"):
        return
    lists: dict[str, list[str]] = {"NAMES": [], "HINTS": [], "PATHS": [],
                                   "PATH_SUFFIXES": []}
    if rest[0] not in _FIND_KEYWORDS:  # the short form: a name, then folders
        lists["NAMES"].append(rest[0])
        rest = ["PATHS", *rest[1:]]
    current: list[str] | None = None
    skip = False
    for word in rest:
        if skip:
            skip = False
        elif word in _FIND_KEYWORDS:
            current = lists.get(word)
        elif word == "ENV" and current is not None and current is not lists["NAMES"]:
            skip = True  # a folder from the environment of the build machine
        elif current is not None:
            current.append(word)
    names = [n for n in lists["NAMES"] if n]
    suffixes = ["", *lists["PATH_SUFFIXES"]]
    folders = [os.path.normpath(os.path.join(it.path(folder), suffix))
               for folder in [*lists["HINTS"], *lists["PATHS"]] if folder
               for suffix in suffixes]
    folders = [f for f in dict.fromkeys(folders) if it.workspace_holds(f)]
    value = next((folder if command.name.lower() == "find_path"
                  else os.path.join(folder, name)
                  for folder in folders for name in names
                  if os.path.exists(os.path.join(folder, name))), None)
    if value is None and names and it.submodule_of is not None:
        value = next((folder if command.name.lower() == "find_path"
                      else os.path.join(folder, names[0])
                      for folder in folders if it.submodule_of(folder) is not None), None)
    if value is None:
        return
    if "NO_CACHE" in rest:
        it.set(var, value)
    else:
        it.cache[var] = value
        it.assigned.add(var)


def _glob(it: Interpreter, args: list[str], recurse: bool) -> list[str]:
    relative: str | None = None
    patterns: list[str] = []
    skip = False
    for index, arg in enumerate(args):
        if skip:
            skip = False
        elif arg in ("LIST_DIRECTORIES", "RELATIVE"):
            skip = True
            if arg == "RELATIVE" and index + 1 < len(args):
                relative = args[index + 1]
        elif arg not in ("CONFIGURE_DEPENDS", "FOLLOW_SYMLINKS"):
            patterns.append(it.path(arg))
    found: list[str] = []
    for pattern in patterns:
        if not it.inside_package(_static_prefix(pattern)):
            continue  # only files of the package itself
        found.extend(_glob_recurse(pattern) if recurse
                     else sorted(p for p in glob.glob(pattern) if os.path.isfile(p)))
        if len(found) > MAX_GLOB:
            break
    found = list(dict.fromkeys(found))[:MAX_GLOB]
    return [os.path.relpath(p, relative) for p in found] if relative else found


def _static_prefix(pattern: str) -> str:
    parts = pattern.split(os.sep)
    for index, part in enumerate(parts):
        if any(char in part for char in "*?["):
            return os.sep.join(parts[:index]) or os.sep
    return os.path.dirname(pattern)


def _glob_recurse(pattern: str) -> list[str]:
    base = _static_prefix(pattern)
    rest = os.path.relpath(pattern, base)
    found: list[str] = []
    for folder, dirs, files in os.walk(base):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, base)
            if fnmatch.fnmatchcase(rel, rest) or (
                os.sep not in rest and fnmatch.fnmatchcase(name, rest)
            ):
                found.append(path)
        if len(found) > MAX_GLOB:
            break
    return found


@handles("aux_source_directory")
def _aux_source_directory(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if len(args) < 2:
        return
    folder = it.path(args[0])
    if not it.inside_package(folder) or not os.path.isdir(folder):
        return
    it.set(args[1], ";".join(sorted(
        os.path.join(folder, name) for name in os.listdir(folder)
        if name.endswith(C_SUFFIXES))))


@handles("include")
def _include(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if not args:
        return
    name = args[0]
    if "RESULT_VARIABLE" in args[1:-1]:
        it.set(args[args.index("RESULT_VARIABLE") + 1], "NOTFOUND")
    candidates = [it.path(name)]
    if "/" not in name and not name.endswith(".cmake"):
        # a module first (``<name>.cmake`` on CMAKE_MODULE_PATH), else, as CMake does, a
        # file of that name in the current source folder (naoqi_driver's
        # ``include(CMakeLists_catkin.txt)``, which defines its executable)
        folders = split_list(it.get("CMAKE_MODULE_PATH"))
        candidates = [*(os.path.join(it.path(folder), name + ".cmake") for folder in folders),
                      it.path(name)]
    for path in candidates:
        if it.include(command, path):
            if "RESULT_VARIABLE" in args[1:-1]:
                it.set(args[args.index("RESULT_VARIABLE") + 1], path)
            return


@handles("add_subdirectory")
def _add_subdirectory(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if args:
        it.add_subdirectory(command, it.path(args[0]))


_BUILDS_EXECUTABLE = re.compile(rb"^\s*add_executable\s*\(", re.IGNORECASE | re.MULTILINE)


@handles("externalproject_add")
def _external_project(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``ExternalProject_Add(name SOURCE_DIR folder ...)``: CMake configures and builds
    ``folder`` as a project of its own at build time, so its targets are not this
    package's and are not read here. When the folder is inside the package and its
    CMakeLists.txt builds executables (micro-ROS-demos' rclc package builds each demo so
    and installs the results), the package has nodes the model does not hold: said by
    ``CMAKE_EXTERNAL_PROJECT``, not left silent."""
    if "SOURCE_DIR" not in args[1:-1]:
        return
    folder = it.path(args[args.index("SOURCE_DIR", 1) + 1])
    if os.path.realpath(folder) == it.package_root:
        # a superbuild: the package builds its own folder once more with other cache
        # values (panther_ros' ``ExternalProject_Add(ep SOURCE_DIR ${PROJECT_SOURCE_DIR}
        # CMAKE_ARGS -DUSE_SUPERBUILD=OFF)`` after it builds a dependency): that second
        # configuration's targets are the package's, read by a second run
        values = _cache_arguments(args)
        if values and it.superbuild is None:
            it.superbuild = (it.where(command), args[0], values)
            return
    listing = os.path.join(folder, "CMakeLists.txt")
    if not it.inside_package(folder) or not os.path.isfile(listing):
        return
    note_read(listing)
    try:
        with open(listing, "rb") as handle:
            text = handle.read(MAX_MAIN_READ)
    except OSError:
        return
    if _BUILDS_EXECUTABLE.search(text):
        it.diagnostics.append(diag.make(
            "CMAKE_EXTERNAL_PROJECT", it.where(command), name=args[0],
            folder=os.path.relpath(folder, it.package_root)))


_CACHE_KEYWORDS = ("CMAKE_ARGS", "CMAKE_CACHE_ARGS", "CMAKE_CACHE_DEFAULT_ARGS")
_CACHE_DEFINITION = re.compile(r"-D([A-Za-z_][A-Za-z0-9_.+-]*)(?::[A-Za-z]+)?=(.*)", re.DOTALL)


def _cache_arguments(args: list[str]) -> dict[str, str]:
    """The ``-DNAME[:TYPE]=VALUE`` cache entries an external project's configuration is
    given (its ``CMAKE_ARGS`` / ``CMAKE_CACHE_ARGS`` options, each a run of arguments
    starting with ``-``)."""
    values: dict[str, str] = {}
    index = 1
    while index < len(args):
        if args[index] in _CACHE_KEYWORDS:
            index += 1
            while index < len(args) and args[index].startswith("-"):
                match = _CACHE_DEFINITION.fullmatch(args[index])
                if match:
                    values[match.group(1)] = match.group(2)
                index += 1
        else:
            index += 1
    return values


# -- targets --------------------------------------------------------------------
EXECUTABLE_FLAGS = ("WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL", "NO_TARGET_LINK_LIBRARIES")
LIBRARY_FLAGS = ("STATIC", "SHARED", "MODULE", "OBJECT", "EXCLUDE_FROM_ALL",
                 "NO_TARGET_LINK_LIBRARIES")


@handles("add_executable", "cuda_add_executable", "ament_auto_add_executable",
         "rosbuild_add_executable")
def _add_executable(it: Interpreter, command: Invocation, args: list[str]) -> None:
    _add_target(it, command, args, "executable", EXECUTABLE_FLAGS)


@handles("add_library", "cuda_add_library", "ament_auto_add_library",
         "rosbuild_add_library")
def _add_library(it: Interpreter, command: Invocation, args: list[str]) -> None:
    _add_target(it, command, args, "library", LIBRARY_FLAGS)


# -- catkin_simple (catkin/catkin_simple, and ethz-asl's fork, which maplab builds with)
# the options of its cs_add_executable / cs_add_library
_SIMPLE_FLAGS = ("NO_AUTO_LINK", "NO_AUTO_DEP", "NO_AUTO_EXPORT")


@handles("catkin_simple")
def _catkin_simple(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """catkin_simple's ``catkin_simple()``: parses package.xml (``catkin_package_xml``)
    and finds the build dependencies that are catkin packages as catkin's components
    (``find_package(catkin REQUIRED COMPONENTS ...)``), whose libraries its
    ``cs_add_executable`` / ``cs_add_library`` then link. A dependency is left out only
    where the workspace builds it without catkin (catkin_simple keeps those
    ``find_package`` finds as catkin projects; one outside the workspace is taken as
    one)."""
    package_xml_read(it)
    project = it.get("PROJECT_NAME") or ""
    for variable in ("TARGETS", "LIBRARIES"):
        it.set(f"{project}_{variable}", "")
    depends = [name for name in it.build_depends
               if name != project and it.catkin_project(name)]
    it.set(f"{project}_CATKIN_BUILD_DEPENDS", ";".join(depends))
    _find_package(it, command, ["catkin", "REQUIRED", "COMPONENTS", *depends])


@handles("cs_add_executable", "cs_add_library")
def _cs_add_target(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """catkin_simple's ``cs_add_executable(t ...)`` / ``cs_add_library(t ...)``: the
    target, which links ``${catkin_LIBRARIES}`` (the components ``catkin_simple()``
    found) unless ``NO_AUTO_LINK``; a library is in ``<project>_LIBRARIES`` (what
    ``cs_export()`` exports) unless ``NO_AUTO_EXPORT``."""
    if not args:
        return
    library = command.name.lower() == "cs_add_library"
    given = [a for a in args if a not in _SIMPLE_FLAGS]
    _add_target(it, command, given, "library" if library else "executable",
                LIBRARY_FLAGS if library else EXECUTABLE_FLAGS)
    project = it.get("PROJECT_NAME") or ""
    it.set(f"{project}_TARGETS",
           ";".join([*split_list(it.get(f"{project}_TARGETS") or ""), args[0]]))
    if library and "NO_AUTO_EXPORT" not in args:
        it.set(f"{project}_LIBRARIES",
               ";".join([*split_list(it.get(f"{project}_LIBRARIES") or ""), args[0]]))
    if "NO_AUTO_LINK" not in args:
        _target_link_libraries(it, command,
                               [args[0], *split_list(it.get("catkin_LIBRARIES") or "")])


def _add_target(it: Interpreter, command: Invocation, args: list[str], kind: str,
                flags: tuple[str, ...]) -> None:
    if len(args) == 3 and args[1] == "ALIAS":  # another name of a target
        it.aliases[args[0]] = it.aliases.get(args[2], args[2])
        return
    if not args or "IMPORTED" in args or "ALIAS" in args:
        return
    every = it.every_way(command.args)  # the sources of every path through tests not decided
    if every[:1] == args[:1]:
        args = every
    if kind == "library" and "INTERFACE" in args[1:2]:
        # a header-only library: no code of its own to build (CMake 3.19 allows sources),
        # but what it gives the targets that link it, its INTERFACE include folders
        # (mrover-ros2's ``add_library(motor INTERFACE)`` with
        # ``target_include_directories(motor INTERFACE esw/motor)``, the folder of the
        # brushless.hpp its bridge nodes include), definitions and links
        args = [args[0], *args[2:]]
    sources: list[str] = []
    # a quoted list is one argument and still a list of sources: PX4-Avoidance's
    # add_library(avoidance "${AVOIDANCE_CPP_FILES}") builds each of its files
    rest = _listed(args[1:])
    if "DIRECTORY" in rest:  # ament_auto_add_*: sources found in a folder
        at = rest.index("DIRECTORY")
        folder = rest[at + 1] if at + 1 < len(rest) else "."
        rest = rest[:at] + rest[at + 2:]
        sources.extend(_glob(it, [os.path.join(folder, "*" + s) for s in C_SUFFIXES],
                             recurse=True))
    sources.extend(it.source_path(a) for a in rest if a not in flags)
    made_under = conditions = it.current_conditions()
    before = it.targets.get(args[0])
    if before is not None:
        conditions = on_every_path(before.conditions, conditions)
    target = it.targets[args[0]] = Target(
        args[0], kind, sources, conditions=conditions, made_under=made_under,
        line=command.line,
        column=command.column, file=command.file,
        directory_definitions=it.compile_definitions[-1],
        definitions=[("PRIVATE", each) for each in it.compile_options[-1]],
        directory_includes=it.include_directories[-1])
    # the newest its directory may ask when it is made (a branch not decided: either's)
    target.standard = newest([cxx_standard(v) for v in it.possible("CMAKE_CXX_STANDARD")])
    target.standard_required = any(v.upper() in TRUE_WORDS
                                   for v in it.possible("CMAKE_CXX_STANDARD_REQUIRED"))
    target.extensions = _switch(it.get("CMAKE_CXX_EXTENSIONS"))
    target.options_standard = it.compile_standards[-1][-1] if it.compile_standards[-1] \
        else None
    it.made_here[-1].append(args[0])
    if command.name.lower().startswith("ament_auto_add_"):
        target.auto = True
        # ament_cmake_auto links the package's earlier ament_auto libraries unless told
        # not to (image_pipeline's image_publisher_node runs the library's ImagePublisher)
        if "NO_TARGET_LINK_LIBRARIES" not in rest:
            target.links.extend(name for name in it.auto_libraries if name != args[0])
        if kind == "library":
            it.auto_libraries.append(args[0])


def on_every_path(before: tuple[Condition, ...],
                   now: tuple[Condition, ...]) -> tuple[Condition, ...]:
    """The conditions of a target made again (CMake allows one name once per path): when
    it was made in a branch of an ``if()`` not decided and now in the ``else`` after it
    (sick_scan_xd's sick_generic_caller in both branches of ``if(ROS_VERSION EQUAL 1)``),
    it is made on both paths, under what they share; else under the later's."""
    if before and len(before) == len(now) and before[:-1] == now[:-1]:
        one, other = before[-1], now[-1]
        if (one.text, one.kind, one.location) == (other.text, other.kind, other.location) \
                and one.statement in ("if", "elseif") and other.statement == "else":
            return now[:-1]
    return now


# -- compile definitions ------------------------------------------------------------
_DEFINE = re.compile(r"([A-Za-z_]\w*)(?:=(.*))?", re.S)
_DEFINITION_KEYWORDS = frozenset({"PRIVATE", "PUBLIC", "INTERFACE"})


@handles("add_definitions")
def _add_definitions(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """Only its ``-D`` flags are definitions (others are compiler flags, not read)."""
    for _, found in _definitions(it, command, command.args, "-D"):
        it.compile_definitions[-1].append(found)


@handles("remove_definitions")
def _remove_definitions(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """Takes the directory's ``-D`` definitions of those names out (for every target of
    the directory, as the directory's property is read once it is all read)."""
    names = {each.name for _, each in _definitions(it, command, command.args, "-D")}
    it.compile_definitions[-1][:] = [d for d in it.compile_definitions[-1]
                                     if d.name not in names]


@handles("add_compile_definitions")
def _add_compile_definitions(it: Interpreter, command: Invocation, args: list[str]) -> None:
    for _, found in _definitions(it, command, command.args, ""):
        it.compile_definitions[-1].append(found)


@handles("add_compile_options")
def _add_compile_options(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """Its ``-D`` words define macros (sick_scan_xd's ``-D__ROS_VERSION=${ROS_VERSION}``)
    for the targets of the directory and its subdirectories made after it, as the
    directory's COMPILE_OPTIONS start a target's own; other options are not read."""
    for _, found in _definitions(it, command, command.args, "-D"):
        it.compile_options[-1].append(found)
    it.compile_standards[-1].extend(year for word in args if (year := std_flag(word)))


def directory_done(it: Interpreter) -> None:
    """At the end of a directory's CMakeLists.txt: its ``CMAKE_CXX_FLAGS`` then, which
    CMake gives every target of the directory (a ``set`` after ``add_executable``
    counts), for the targets it made: the standard its last ``-std=`` word asks (the
    newest of the values the paths through undecided if()s leave)."""
    year = newest(_flag_standards(it))
    for name in it.made_here[-1] if year else ():
        target = it.targets.get(name)
        if target is not None:
            target.flags_standard = year


def _flag_standards(it: Interpreter) -> list[int | None]:
    """For each value ``CMAKE_CXX_FLAGS`` may hold here, the standard its last
    ``-std=`` word asks (the compiler takes the last one)."""
    return [next((y for word in reversed(value.split()) if (y := std_flag(word))), None)
            for value in it.possible("CMAKE_CXX_FLAGS")]


def _switch(value: str | None) -> bool | None:
    """A CMake boolean's value: None when not set (or not a boolean word)."""
    if value is None:
        return None
    upper = value.upper()
    return True if upper in TRUE_WORDS else False if upper in FALSE_WORDS or not upper \
        else None


# the compiler's own C++ standard (g++'s default ``-std=gnu++NN``) and whether CMake
# writes the standard's flag before the compile options (newer than 3.25: Jazzy's 3.28;
# 3.22 and 3.25 write it after them), by the distribution's Ubuntu release
_DISTRO_COMPILERS: dict[str, tuple[int, bool]] = {
    "kinetic": (98, False), "lunar": (98, False), "melodic": (14, False),
    "noetic": (14, False), "foxy": (14, False), "galactic": (14, False),
    "humble": (17, False), "iron": (17, False),
    "jazzy": (17, True), "kilted": (17, True), "rolling": (17, True),
}
NEWEST_COMPILER = (17, True)  # a distribution not in the table


def effective_standard(target: Target, required: int | None, cmp0128: bool,
                       distro: str | None) -> int:
    """The C++ standard the compiler uses for ``target``'s sources, as CMake writes its
    compile line: ``CMAKE_CXX_FLAGS``, then the standard's flag, then the compile
    options (after 3.25; until then, the flag after the options), the last ``-std=``
    winning; the flag is the standard asked (``CXX_STANDARD``, raised to what the
    compile features ``required``), left out only under policy CMP0128 NEW (CMake 3.22)
    when that is the compiler's own, not required and with the compiler's extensions;
    with no ``-std=`` at all, the compiler's own."""
    default, flag_first = _DISTRO_COMPILERS.get((distro or "").strip().lower(),
                                                NEWEST_COMPILER)
    asked = newest([target.standard, required])
    flag = asked
    if asked is not None and cmp0128 and not target.standard_required and \
            asked == default and target.extensions is not False:
        flag = None  # the compiler's default already: no flag
    order = [target.flags_standard, flag, target.options_standard] if flag_first else [
        target.flags_standard, target.options_standard, flag]
    return next((year for year in reversed(order) if year), default)


def newest(years: Sequence[int | None]) -> int | None:
    """The newest standard of ``years`` (98 the oldest), None when there is none."""
    known = [y for y in years if y]
    return max(known, key=lambda y: 0 if y == 98 else y) if known else None


@handles("target_compile_options")
def _target_compile_options(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """Its ``-D`` words, as ``target_compile_definitions`` gives them."""
    target = it.targets.get(args[0]) if args else None
    if target is None or not command.args:
        return
    target.definitions.extend(_definitions(it, command, command.args[1:], "-D"))
    own = [year for word in args[1:] if (year := std_flag(word))]
    if own:  # after the directory's options
        target.options_standard = own[-1]


@handles("target_compile_features")
def _target_compile_features(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``cxx_std_NN``: the target's sources (PRIVATE, PUBLIC) and those of the targets
    that link it (PUBLIC, INTERFACE) are compiled with C++NN at least."""
    target = it.targets.get(it.aliases.get(args[0], args[0])) if args else None
    if target is None:
        return
    keyword = "PRIVATE"
    for word in args[1:]:
        if word in _DEFINITION_KEYWORDS:
            keyword = word
        elif word.startswith("cxx_std_") and (year := cxx_standard(word[8:])):
            target.features.append((keyword, year))


# the C++ standards as CMake and the compilers name them, by year
_YEARS = {"98": 98, "03": 98, "11": 11, "0x": 11, "14": 14, "1y": 14, "17": 17, "1z": 17,
          "20": 20, "2a": 20, "23": 23, "2b": 23, "26": 26, "2c": 26}


def cxx_standard(value: str | None) -> int | None:
    """The year of a ``CXX_STANDARD`` value (``20``), None when not one."""
    return _YEARS.get((value or "").strip())


def std_flag(word: str) -> int | None:
    """The year of a compiler's ``-std=c++20`` / ``-std=gnu++2a`` word, else None."""
    match = re.fullmatch(r"-std=(?:c|gnu)\+\+(\w\w)", word)
    return _YEARS.get(match.group(1)) if match else None


@handles("target_compile_definitions")
def _target_compile_definitions(it: Interpreter, command: Invocation,
                                args: list[str]) -> None:
    target = it.targets.get(args[0]) if args else None
    if target is None or not command.args:
        return  # an imported target, or one this reading did not make
    target.definitions.extend(_definitions(it, command, command.args[1:], ""))


@handles("include_directories")
def _include_directories(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """For every target of the directory, as its definitions (``add_definitions``)."""
    it.include_directories[-1].extend(
        (folder, conditions) for _, folder, conditions in include_folders(it, command.args))


@handles("target_include_directories")
def _target_include_directories(it: Interpreter, command: Invocation,
                                args: list[str]) -> None:
    target = it.targets.get(it.aliases.get(args[0], args[0])) if args else None
    if target is None or not command.args:
        return  # an imported target, or one this reading did not make
    target.includes.extend(include_folders(it, command.args[1:]))


_INCLUDE_KEYWORDS = frozenset({"SYSTEM", "BEFORE", "AFTER"})
_BUILD_INTERFACE = re.compile(r"\$<BUILD_INTERFACE:(.*)>", re.S)


def include_folders(it: Interpreter, raw: tuple[Argument, ...]
                    ) -> list[tuple[str, str, tuple[Condition, ...]]]:
    """The folders an include command's arguments ``raw`` (not expanded) give, absolute,
    each with the keyword before it (PRIVATE when none) and the ``if()``s around the
    command that are not decided: a ``$<BUILD_INTERFACE:...>`` its folder, no other
    generator expression (``$<INSTALL_INTERFACE:include>``), no argument that reads what
    this reading does not know (``${rclcpp_INCLUDE_DIRS}``)."""
    conditions = it.unsure_conditions()
    found: list[tuple[str, str, tuple[Condition, ...]]] = []
    keyword = "PRIVATE"
    for arg in raw:
        if arg.kind != "bracket" and it.unknown_reference(arg.text):
            continue
        for item in it.arguments((arg,)):
            if item in _DEFINITION_KEYWORDS:
                keyword = item
                continue
            inner = _BUILD_INTERFACE.fullmatch(item)
            folder = inner.group(1) if inner is not None else item
            if folder and folder not in _INCLUDE_KEYWORDS and "$<" not in folder:
                found.append((keyword, it.path(folder), conditions))
    return found


# the commands that define macros, and whether only their ``-D`` words do
_DEFINING = {"add_definitions": True, "add_compile_options": True,
             "target_compile_options": True, "add_compile_definitions": False,
             "target_compile_definitions": False}


def defined_names(command: Invocation) -> list[str]:
    """The names of the macros a command would define, as written (not expanded):
    ``add_definitions(-DX)``, ``target_compile_definitions(t PRIVATE Y=1)``, ...; none
    for another command."""
    name = command.name.lower()
    flag_only = _DEFINING.get(name)
    if flag_only is None:
        return []
    args = command.args[1:] if name.startswith("target_") else command.args
    found: list[str] = []
    for arg in args:
        for word in arg.text.split():
            if word in _DEFINITION_KEYWORDS or (flag_only and not word.startswith("-D")):
                continue
            match = _DEFINE.match(word[2:] if word.startswith("-D") else word)
            if match is not None:
                found.append(match.group(1))
    return found


def _definitions(it: Interpreter, command: Invocation, raw: tuple[Argument, ...],
                 flag: str, listed: bool = False) -> list[tuple[str, CompileDefinition]]:
    """The definitions ``raw`` (a command's arguments, not expanded) give, each with the
    keyword before it (PRIVATE when none); ``flag``: only words that start with it
    count, without it (``-D``), else a leading ``-D`` is dropped as CMake does. A word
    whose name is not written in the file (a list variable's items, a generator
    expression) is left out; one whose value reads something not set here is defined
    with that value unknown. ``listed``: each argument is a CMake list of definitions (a
    property's value, ``"A;B=1"``)."""
    found: list[tuple[str, CompileDefinition]] = []
    keyword = "PRIVATE"
    # (a test decided on what is not known may have chosen wrongly: as not decided)
    conditions = it.unsure_conditions()
    for arg in raw:
        unknown = arg.kind != "bracket" and it.unknown_reference(arg.text)
        written = arg.text.strip()
        items = it.arguments((arg,))
        for item in [part for i in items for part in i.split(";")] if listed else items:
            if item in _DEFINITION_KEYWORDS:
                keyword = item
                continue
            if flag and not item.startswith(flag):
                continue
            text = item[2:] if item.startswith("-D") else item
            match = _DEFINE.fullmatch(text)
            if match is None or "$<" in item:
                continue
            name, value = match.group(1), match.group(2)
            if unknown and re.match(rf"(?:-D)?{name}(?:=|$)", written) is None:
                continue  # the name itself comes from what is not known
            found.append((keyword, CompileDefinition(
                name, value, not unknown, conditions, command.file, command.line)))
    return found


# commands of CMake itself and of the ROS build tools that make no runnable program
# (tests, messages): an unknown command is looked at only when it is none of these
IGNORED = frozenset({
    "project", "cmake_minimum_required",
    "link_directories", "add_dependencies",
    "message",
    "add_custom_target", "add_custom_command", "add_test",
    "add_message_files", "add_service_files", "add_action_files", "generate_messages",
    "rosidl_generate_interfaces", "ament_export_dependencies", "ament_export_include_directories",
    "ament_export_libraries", "ament_export_targets", "ament_lint_auto_find_test_dependencies",
})
_TARGET_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_.+-]*")
# the keywords before a target's name in a function of keyword arguments
# (``cmake_parse_arguments(ARG "" "TARGET;..." ...)``)
_NAME_KEYWORDS = frozenset({"TARGET", "NAME", "TARGET_NAME"})
_NOT_NODES = re.compile(r"test|gmock|benchmark", re.IGNORECASE)
_LIBRARY_COMMAND = re.compile(r"librar", re.IGNORECASE)
_MAIN = re.compile(rb"\bint\s+main\s*\(")
MAX_MAIN_READ = 2_000_000  # bytes of a source read to find main()


def _defines_main(path: str) -> bool:
    note_read(path)
    try:
        with open(path, "rb") as handle:
            return _MAIN.search(handle.read(MAX_MAIN_READ)) is not None
    except OSError:
        return False


def unknown_command(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """A command neither CMake nor the workspace defines (a function of a package outside
    the workspace: cartographer's ``google_binary(cartographer_node SRCS node_main.cc)``)
    whose first argument is a new target name and whose other arguments include C/C++
    files of the package, one of which defines ``main()``: an executable, which links the
    package's libraries declared so far (``nodes._run`` keeps of them what its code names,
    as for ament_auto). Tests and benchmarks (``ament_add_gmock``, ``catkin_add_gtest``,
    ``ament_add_google_benchmark``, sources in a ``test`` folder) are no nodes. A
    function of keyword arguments names its target after a keyword (MOLA's
    ``mola_add_executable(TARGET mola-cli SOURCES mola-cli.cpp)``): the word after it."""
    code = [it.path(a) for a in args if a.endswith(C_SUFFIXES)]
    it.foreign_calls.append((list(args), [path for path in code if it.inside_package(path)
                                          and os.path.isfile(path)]))
    if args[:1] and args[0] in _NAME_KEYWORDS:
        args = args[1:]
    if (len(args) < 2 or _NOT_NODES.search(command.name) or args[0] in it.targets
            or not _TARGET_NAME.fullmatch(args[0])):
        return
    sources = [it.path(a) for a in args[1:] if a.endswith(C_SUFFIXES)]
    sources = [s for s in sources if it.inside_package(s) and os.path.isfile(s)]
    if not sources or any(_NOT_NODES.search(part) for s in sources
                          for part in os.path.relpath(s, it.package_root).split(os.sep)[:-1]):
        return
    if not any(_defines_main(s) for s in sources):
        if _LIBRARY_COMMAND.search(command.name):
            # a library the name says (MOLA's mola_add_library(TARGET mola_launcher
            # SOURCES ...), cartographer's google_library): the package's executables
            # made after it link it, as they do an add_library's
            it.targets[args[0]] = Target(
                args[0], "library", sources, conditions=it.current_conditions(),
                line=command.line, column=command.column, file=command.file)
            named = [os.path.basename(s) for s in sources]
            it.diagnostics.append(diag.make(
                "CMAKE_GUESSED_LIBRARY", it.where(command), command=command.name,
                target=args[0], sources=", ".join(named[:4]) + (
                    f" and {len(named) - 4} more" if len(named) > 4 else "")))
        return
    target = it.targets[args[0]] = Target(
        args[0], "executable", sources, conditions=it.current_conditions(),
        line=command.line, column=command.column, file=command.file)
    target.links.extend(name for name, other in it.targets.items() if other.kind == "library")
    it.diagnostics.append(diag.make(
        "CMAKE_GUESSED_EXECUTABLE", it.where(command), command=command.name,
        target=args[0], sources=", ".join(os.path.basename(s) for s in sources)))


@handles("target_sources")
def _target_sources(it: Interpreter, command: Invocation, args: list[str]) -> None:
    target = it.targets.get(args[0]) if args else None
    if target is not None:
        keywords = ("PRIVATE", "PUBLIC", "INTERFACE", "FILE_SET", "TYPE", "BASE_DIRS",
                    "FILES", "HEADERS", "CXX_MODULES")
        every = it.every_way(command.args)
        target.sources.extend(it.source_path(a) for a in _listed((every if every[:1] == args[:1]
                                                           else args)[1:])
                              if a not in keywords)


def _listed(args: list[str]) -> list[str]:
    """The items of arguments a command takes as lists (a target's sources): a quoted
    argument ``"a.cpp;b.cpp"`` is the two files, as CMake's SOURCES property reads it. An
    empty item names no file: Kimera-VIO's ``add_library(${PROJECT_NAME} SHARED "")``,
    whose sources ``target_sources`` gives after, has none of its own."""
    return [item for arg in args for item in (split_list(arg) if ";" in arg else [arg])
            if item]


# what ``find_package(pkg)`` leaves in ``pkg_LIBRARIES`` (and catkin in
# ``catkin_LIBRARIES`` for each of its components): a mark that names the package,
# which a target that links it records (``Target.packages``); a generator expression's
# form, which every other use of a source or target name leaves alone
PACKAGE_MARK = PACKAGE_MARK_START + "{}>"
_PACKAGE_MARK = re.compile(re.escape(PACKAGE_MARK_START) + r"([^>]+)>")
_LINK_KEYWORDS = frozenset({"PUBLIC", "PRIVATE", "INTERFACE", "SYSTEM", "LINK_PUBLIC",
                            "LINK_PRIVATE", "LINK_INTERFACE_LIBRARIES", "debug",
                            "optimized", "general"})
_PACKAGE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_TARGET_NAME = re.compile(r"[A-Za-z0-9_.+-]+")


# the build tool and the C++ client library each ROS version's distributions have
_BUILD_TOOLS = {"catkin": "1", "ament_cmake": "2", "roscpp": "1", "rclcpp": "2"}
# those no distribution of the other ROS version has
_ONE_VERSION_ONLY = frozenset({"catkin", "roscpp", "rclcpp"})


def _tool_found(it: Interpreter, name: str, required: bool) -> str | None:
    """``<tool>_FOUND`` for a ROS build tool or C++ client library, where the run's
    environment says which ROS it builds for (``distro:`` gives ROS_VERSION): a
    distribution's own is found (a dual package's ``find_package(catkin QUIET)`` then
    ``if(catkin_FOUND)``; Hesai's driver, ``find_package(rclcpp QUIET)`` then
    ``if(rclcpp_FOUND) add_definitions(-DROS2_FOUND)``); catkin and roscpp are not in a
    ROS 2 one, rclcpp in no ROS 1 one. A run that names no ROS version takes the one
    whose build system the package.xml names, when it names one only
    (``Interpreter.package_ros_version``: ros_deep_learning's catkin package.xml over its
    ``find_package(catkin QUIET)`` / ``if(catkin_FOUND)``). None where that is not known."""
    version = it.environment.get("ROS_VERSION", "").strip() or it.package_ros_version
    tool = _BUILD_TOOLS.get(name)
    if tool is None or version not in ("1", "2"):
        return None
    if version == tool:
        return "TRUE"
    return "FALSE" if name in _ONE_VERSION_ONLY and not required else None


def _built_before(it: Interpreter, name: str) -> bool:
    """Whether ``find_package(name)`` finds a package of the workspace that this package
    declares a build dependency on: catkin and colcon build it first and put its config
    where the search looks, so ``<name>_FOUND`` holds (humanoid_op_ros'
    nimbro_topic_transport depends on plot_msgs, "not a hard dependency", and defines
    WITH_PLOTTING under ``if(plot_msgs_FOUND)``, which chooses its ``/plot``
    publisher)."""
    if name == it.package_name or name not in it.build_depends or it.extras_of is None:
        return False
    root, _extras = it.extras_of(name)
    return bool(root)


def run_extras(it: Interpreter, command: Invocation, name: str) -> None:
    """Run the CMake files the workspace package ``name`` hands to the packages that find
    it (``Interpreter.extras_of``: its ament CONFIG_EXTRAS, catkin CFG_EXTRAS), once per
    reading, with ``<name>_DIR`` its cmake folder (else theirs), as the installed
    package's config has it:
    the macros they define are the caller's (Autoware's
    ``autoware_agnocast_wrapper_register_node(lib PLUGIN ... EXECUTABLE ...)``, from
    autoware_agnocast_wrapper's extras, registers each node of autoware_core's map
    loaders through ``rclcpp_components_register_node``)."""
    if it.extras_of is None or name in it.extras_read:
        return
    it.extras_read.add(name)
    root, files = it.extras_of(name)
    # the installed package's config folder, share/<name>/cmake, holds its extras and
    # what it installs there, most often its own cmake/ folder (autoware_cmake's extras,
    # at its root, include ``${autoware_cmake_DIR}/autoware_package.cmake``)
    folder = os.path.join(root, "cmake")
    for path in files:
        it.set(f"{name}_DIR", folder if os.path.isdir(folder) else os.path.dirname(path))
        it.foreign_roots.append(root)
        try:
            it.include(command, path)
        finally:
            it.foreign_roots.pop()


@handles("catkin_package_xml", "ament_package_xml")
def _package_xml(it: Interpreter, command: Invocation, args: list[str]) -> None:
    package_xml_read(it, args)


def package_xml_read(it: Interpreter, args: list[str] | None = None) -> None:
    """What catkin's ``catkin_package_xml()`` and ament's ``ament_package_xml()`` set from
    the package's package.xml: ``<project>_VERSION``, its ``<version>`` (Lslidar's
    driver defines ``-D${PROJECT_NAME}_VERSION="${${PROJECT_NAME}_VERSION}"`` after
    ``catkin_package()`` and prints it in its ``main``). Each runs once:
    ``catkin_package()``, ``ament_package()``, ``ament_auto_package()`` and
    ``ament_auto_find_build_dependencies()`` run it when it has not run before. Nothing
    is set for another folder's package.xml (``DIRECTORY``) nor when the project is not
    the package (both stop the build then)."""
    if it.package_xml_read:
        return
    it.package_xml_read = True
    project = it.get("PROJECT_NAME")
    if (project and project == it.package_name and it.package_version
            and "DIRECTORY" not in (args or [])):
        it.set(f"{project}_VERSION", it.package_version)


@handles("ament_auto_find_build_dependencies", "autoware_package")
def _ament_auto_find_build_dependencies(it: Interpreter, command: Invocation,
                                        args: list[str]) -> None:
    """ament_cmake_auto finds every build dependency of package.xml: what their config
    extras define is there after it. So does Autoware's ``autoware_package()`` (the
    macro of autoware_cmake, its compile options apart), when autoware_cmake is not in
    the workspace to define it."""
    package_xml_read(it)
    for name in it.build_depends:
        run_extras(it, command, name)


def handed_extras(it: Interpreter, args: list[str], keyword: str = "CONFIG_EXTRAS") -> None:
    """``ament_package(CONFIG_EXTRAS a.cmake ...)`` / ``ament_auto_package``, and
    ``${PROJECT_NAME}_CONFIG_EXTRAS`` for both and at the end of the reading (a wrapper
    of ament_package that is not known here, Autoware's ``autoware_ament_auto_package``,
    reads it too): the files handed to the packages that find this one
    (``Interpreter.config_extras``)."""
    named: list[str] = []
    if keyword in args:
        for arg in args[args.index(keyword) + 1:]:
            if arg.isupper() and arg.replace("_", "").isalpha():
                break  # the next keyword
            named.append(arg)
    named += split_list(it.get(f"{it.get('PROJECT_NAME') or ''}_CONFIG_EXTRAS") or "")
    for name in named:
        path = it.path(name)
        if path.endswith(".cmake") and path not in it.config_extras:
            it.config_extras.append(path)


@handles("ament_package")
def _ament_package(it: Interpreter, command: Invocation, args: list[str]) -> None:
    package_xml_read(it)
    handed_extras(it, args)


@handles("find_package")
def _find_package(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if not args or not _PACKAGE_NAME.fullmatch(args[0]):
        return
    run_extras(it, command, args[0])
    it.found_packages.add(args[0].lower())
    _client_version(it, args[0])
    _message_files(it, args[0])
    found = _tool_found(it, args[0], "REQUIRED" in args[1:])
    if found is None and _built_before(it, args[0]):
        found = "TRUE"
    if found is not None:
        it.set(f"{args[0]}_FOUND", found)
    if args[0] == "catkin":
        components: list[str] = []
        taking = False
        for arg in args[1:]:
            if arg in ("COMPONENTS", "OPTIONAL_COMPONENTS", "REQUIRED"):
                # (CMake's ``REQUIRED [[COMPONENTS] components...]``: the keyword may be
                # left out, vizzy_demos' ``find_package(catkin REQUIRED roscpp ...)``)
                taking = True
            elif arg.isupper():
                taking = False  # QUIET, CONFIG, ...
            elif taking and _PACKAGE_NAME.fullmatch(arg):
                components.append(arg)
                if arg not in it.catkin_components:
                    it.catkin_components.append(arg)
                run_extras(it, command, arg)
                it.found_packages.add(arg.lower())  # catkin finds each one
                _client_version(it, arg)
                _message_files(it, arg)
        it.set("catkin_LIBRARIES", ";".join(PACKAGE_MARK.format(c) for c in components))
        return
    for variable in (f"{args[0]}_LIBRARIES", f"{args[0]}_TARGETS"):
        if it.get(variable) is None:
            it.set(variable, PACKAGE_MARK.format(args[0]))


def _message_files(it: Interpreter, name: str) -> None:
    """What a ROS 1 message package's config (genmsg's ``<name>-msg-extras.cmake``) sets
    for the packages that find it: ``<name>_MESSAGE_FILES`` and ``<name>_SERVICE_FILES``,
    its definitions as ``msg/Name.msg`` / ``srv/Name.srv``, as installed. mavros 1.x
    defines ``HAVE_SENSOR_MSGS_BATTERYSTATE_MSG`` where ``list(FIND
    sensor_msgs_MESSAGE_FILES "msg/BatteryState.msg" ...)`` finds it, and publishes its
    ``battery`` as sensor_msgs/BatteryState then (mavros_msgs/BatteryStatus else). The
    definitions are those of the workspace's package, else of the shipped catalogue for
    the distribution read; a package neither holds keeps the lists unset."""
    if (it.environment.get("ROS_VERSION", "").strip() or it.package_ros_version) != "1":
        return
    from ..extract.cpp.interfaces import catalogue, definition_files
    root = it.extras_of(name)[0] if it.extras_of is not None else ""
    for kind, variable in (("msg", f"{name}_MESSAGE_FILES"),
                           ("srv", f"{name}_SERVICE_FILES")):
        if it.get(variable) is not None:
            continue
        if root:
            names = [file[:-len(kind) - 1] for file in definition_files(root, kind)]
        else:
            lead = f"{name}/{kind}/"
            names = [key[len(lead):] for key in catalogue(False, it.source_distro)
                     if key.startswith(lead)]
        if names:
            it.set(variable, ";".join(f"{kind}/{n}.{kind}" for n in sorted(names)))


def _client_version(it: Interpreter, name: str) -> None:
    """What ``find_package`` of a ROS client library sets of its version
    (``<name>_VERSION`` and its parts), when the distribution the sources are read for
    is known: that release's, the one the C++ stand-ins announce (mavros builds with
    ``-DUSE_OLD_DECLARE_PARAMETER`` only ``if(rclcpp_VERSION VERSION_LESS 9.0.0)``,
    Foxy's); not known otherwise, as any other package's."""
    from ..extract.cpp.versions import RCLCPP, ROSCPP

    library = {"rclcpp": RCLCPP, "roscpp": ROSCPP}.get(name)
    found = library.version(it.source_distro) if library is not None else None
    if found is None:
        return
    it.set(f"{name}_VERSION", ".".join(map(str, found)))
    for part, number in zip(("MAJOR", "MINOR", "PATCH"), found, strict=True):
        it.set(f"{name}_VERSION_{part}", str(number))


@handles("target_link_libraries", "ament_target_dependencies")
def _target_link_libraries(it: Interpreter, command: Invocation, args: list[str]) -> None:
    target = it.targets.get(args[0]) if args else None
    if target is None:
        return
    project = it.get("PROJECT_NAME")
    for arg in args[1:]:
        arg = it.aliases.get(arg, arg)
        mark = _PACKAGE_MARK.fullmatch(arg)
        if arg in it.targets or (
            command.name.lower() == "target_link_libraries" and mark is None
            and arg not in _LINK_KEYWORDS and _TARGET_NAME.fullmatch(arg)
        ):
            # a library the package adds later is linked too: CMake resolves the names
            # once every file is read (autorally_core adds its executables' folder,
            # src/gps, before src/SerialSensorInterface, the library they link); a name
            # that never becomes a target (pthread) is a system library, and skipped
            target.links.append(arg)
            continue
        package = mark.group(1) if mark else arg.split("::", 1)[0] if "::" in arg else (
            arg if command.name.lower() == "ament_target_dependencies" else None)
        if (package and package != project and package not in _LINK_KEYWORDS
                and _PACKAGE_NAME.fullmatch(package) and package not in target.packages):
            target.packages.append(package)


# catkin_package()'s keywords (catkin's own list)
CATKIN_PACKAGE_KEYWORDS = frozenset({"INCLUDE_DIRS", "LIBRARIES", "CATKIN_DEPENDS", "DEPENDS",
                                      "CFG_EXTRAS", "EXPORTED_TARGETS",
                                      "SKIP_CMAKE_CONFIG_GENERATION",
                                      "SKIP_PKG_CONFIG_GENERATION"})


@handles("catkin_package")
def _catkin_package(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``catkin_package(LIBRARIES a b ...)``: the libraries catkin puts in another
    package's ``${catkin_LIBRARIES}`` when it finds this one (``Interpreter.catkin_exports``;
    no LIBRARIES: none), and ``CATKIN_DEPENDS``, whose libraries it puts there too
    (``Interpreter.catkin_depends``)."""
    package_xml_read(it)
    names: list[str] = []
    depends: list[str] = []
    taking = ""
    for arg in args:
        if arg in CATKIN_PACKAGE_KEYWORDS:
            taking = arg
        elif taking == "LIBRARIES" and arg:
            names.append(arg)
        elif taking == "CATKIN_DEPENDS" and _PACKAGE_NAME.fullmatch(arg):
            depends.append(arg)
        elif taking == "CFG_EXTRAS" and arg.endswith(".cmake"):
            # catkin looks for it in the package's cmake folder (a template, .in or
            # .em, is made at build time: not read)
            path = os.path.join(it.package_root, "cmake", arg)
            if os.path.isfile(path) and path not in it.config_extras:
                it.config_extras.append(path)
    if not it.sure():
        it.catkin_exports_unsure = True
    it.catkin_exports = list(dict.fromkeys([*(it.catkin_exports or []), *names]))
    it.catkin_depends = list(dict.fromkeys([*it.catkin_depends, *depends]))


def _property_definitions(it: Interpreter, command: Invocation, names: list[str],
                          raw: tuple[Argument, ...], append: bool) -> None:
    """A target's ``COMPILE_DEFINITIONS`` property set to ``raw`` (``set_property(TARGET
    t PROPERTY COMPILE_DEFINITIONS X)``, ``set_target_properties(t PROPERTIES
    COMPILE_DEFINITIONS "X;Y=1")``): the macros its own sources are compiled with, as
    ``target_compile_definitions(t PRIVATE ...)`` gives them (those of its directory are
    another property); set anew, unless appended, it replaces the private ones given
    before. ethzasl_sensor_fusion's ssf_updates builds pose_sensor and position_sensor
    from one main.cpp, each with its own ``POSE_MEAS`` / ``POSITION_MEAS``."""
    found = [("PRIVATE", definition)
             for _keyword, definition in _definitions(it, command, raw, "", listed=True)]
    for name in names:
        target = it.targets.get(it.aliases.get(name, name))
        if target is None:
            continue  # an imported target, or one this reading did not make
        if not append:
            target.definitions = [("INTERFACE" if keyword == "PUBLIC" else keyword, d)
                                  for keyword, d in target.definitions if keyword != "PRIVATE"]
        target.definitions.extend(found)


@handles("set_target_properties")
def _set_target_properties(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if "PROPERTIES" not in args:
        return
    split = args.index("PROPERTIES")
    raw = command.args
    written = [arg.text.strip() for arg in raw]
    if "PROPERTIES" in written:
        # the raw arguments: a value is a list, whose items the expansion would split
        at = written.index("PROPERTIES")
        for named, given in zip(raw[at + 1::2], raw[at + 2::2], strict=False):
            if named.text.strip() == "COMPILE_DEFINITIONS":
                _property_definitions(it, command, args[:split], (given,), append=False)
    props = args[split + 1:]
    for key, value in zip(props[::2], props[1::2], strict=False):
        if key in ("OUTPUT_NAME", "RUNTIME_OUTPUT_NAME", "LIBRARY_OUTPUT_NAME") and (
                "$<" not in value):  # a generator expression: unknown, keep the target name
            for name in args[:split]:
                if name in it.targets:
                    it.targets[name].output_name = value
        for name in args[:split] if key in _STANDARD_PROPERTIES else ():
            if name in it.targets:
                _standard_property(it.targets[name], key, value)


@handles("set_property")
def _set_property(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if args[:1] != ["TARGET"] or "PROPERTY" not in args:
        return
    at = args.index("PROPERTY")
    if args[at + 1:at + 2] == ["COMPILE_DEFINITIONS"]:
        written = [arg.text.strip() for arg in command.args]
        if "COMPILE_DEFINITIONS" in written:
            names = [name for name in args[1:at] if name not in ("APPEND", "APPEND_STRING")]
            _property_definitions(
                it, command, names, command.args[written.index("COMPILE_DEFINITIONS") + 1:],
                append="APPEND" in args[1:at] or "APPEND_STRING" in args[1:at])
    if args[at + 1:at + 2] in (["OUTPUT_NAME"], ["RUNTIME_OUTPUT_NAME"]) and len(
            args) > at + 2 and "$<" not in args[at + 2]:
        for name in args[1:at]:
            if name in it.targets:
                it.targets[name].output_name = args[at + 2]
    if args[at + 1:at + 2] and args[at + 1] in _STANDARD_PROPERTIES and len(args) > at + 2:
        for name in args[1:at]:
            if name in it.targets:
                _standard_property(it.targets[name], args[at + 1], args[at + 2])


_STANDARD_PROPERTIES = ("CXX_STANDARD", "CXX_STANDARD_REQUIRED", "CXX_EXTENSIONS")


def _standard_property(target: Target, key: str, value: str) -> None:
    if key == "CXX_STANDARD":
        target.standard = cxx_standard(value)
    elif key == "CXX_STANDARD_REQUIRED":
        target.standard_required = value.upper() in TRUE_WORDS
    else:
        target.extensions = _switch(value)


@handles("cmake_minimum_required")
def _cmake_minimum_required(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``VERSION min[...max]`` sets the policies of the newer of the two."""
    if args[:1] == ["VERSION"] and len(args) > 1:
        _policy_version(it, args[1])


@handles("cmake_policy")
def _cmake_policy(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``VERSION min[...max]``, and ``SET CMP0128 NEW|OLD`` (the one read here)."""
    if args[:1] == ["VERSION"] and len(args) > 1:
        _policy_version(it, args[1])
    elif args[:2] == ["SET", "CMP0128"] and len(args) > 2:
        it.cmp0128 = args[2].upper() == "NEW"


def _policy_version(it: Interpreter, text: str) -> None:
    version = tuple(int(p) for p in re.findall(r"\d+", text.split("...")[-1])[:2])
    it.cmp0128 = version >= (3, 22)  # CMP0128 was introduced by CMake 3.22


# -- installed programs and components ------------------------------------------
@handles("catkin_install_python")
def _catkin_install_python(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if args[:1] == ["PROGRAMS"]:
        _programs(it, command, args[1:], rename=None)


@handles("ament_python_install_package")
def _ament_python_install_package(it: Interpreter, command: Invocation,
                                  args: list[str]) -> None:
    if "SCRIPTS_DESTINATION" in args[1:-1]:
        it.python_scripts = True


# configure_file: the options that take no value, and the references it replaces
_CONFIGURE_FLAGS = frozenset({"COPYONLY", "ESCAPE_QUOTES", "@ONLY", "NO_SOURCE_PERMISSIONS",
                              "USE_SOURCE_PERMISSIONS"})
_AT_REFERENCE = r"@([A-Za-z_0-9/.+-]+)@"
_BRACE_REFERENCE = r"\$(ENV|CACHE)?\{([A-Za-z_0-9/.+-]+)\}"
_CMAKEDEFINE = re.compile(r"^([ \t]*#[ \t]*)cmakedefine(01)?[ \t]+([A-Za-z_0-9]+)(.*)$",
                          re.MULTILINE)
MAX_CONFIGURED = 1_000_000  # bytes of a configure_file input read


@handles("configure_file")
def _configure_file(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """The file the build writes from a template. Its text is made here only where the
    package writes it into its own folder (hector_quadrotor_gazebo's
    ``quadrotor_plugins.gazebo.xacro``, which a description includes from there):
    ``${VAR}`` and ``@VAR@`` (``@VAR@`` alone with ``@ONLY``) replaced by the values
    the reading holds at the command, ``#cmakedefine`` lines made, as CMake does; a
    reference to a value not known, or the command under an if() not decided, leaves
    the text not known."""
    positional = [a for a in args if a not in _CONFIGURE_FLAGS]
    if len(positional) < 2:
        return
    source = it.path(positional[0])
    output = positional[1]
    if not output.startswith("$<"):
        output = os.path.normpath(os.path.join(
            it.get("CMAKE_CURRENT_BINARY_DIR") or it.source_dir, output))
        if os.path.isdir(output):  # an existing folder: the input's name in it
            output = os.path.join(output, os.path.basename(source))
    text: str | None = None
    unknown = ""
    if not it.inside_package(output) or not it.inside_package(source):
        unknown = "it is not written into the package's folder, or not from it"
    elif not it.sure():
        unknown = ("it is made under an if() not decided, or from a value not known "
                   "here")
    else:
        where = it.location(command.file, command.line, command.column) if it.location \
            else NOWHERE
        template, found = read_text(source, where, MAX_CONFIGURED)
        it.diagnostics.extend(found)
        if template is None:
            unknown = f"its template {os.path.basename(source)} is not read"
        else:
            text, unknown = configured_text(it, template, "@ONLY" in args,
                                            "COPYONLY" in args, "ESCAPE_QUOTES" in args)
    it.configured.append(Configured(source, output, text, unknown, command.line,
                                    command.column, command.file))


def configured_text(it: Interpreter, template: str, at_only: bool, copy_only: bool,
                    escape_quotes: bool) -> tuple[str | None, str]:
    """``template`` as configure_file writes it with the values ``it`` holds, and ""; or
    None and which reference is not known."""
    if copy_only:
        return template, ""
    missing: list[str] = []

    def value(reference: str) -> str:
        if it.unknown_reference(reference):
            missing.append(reference)
            return ""
        found = it.expand(reference)
        return found.replace('"', '\\"') if escape_quotes else found

    def define(match: re.Match[str]) -> str:
        head, zero_one, name, rest = match.groups()
        reference = "${" + name + "}"
        if it.unknown_reference(reference):
            missing.append(reference)
            return ""
        found = it.expand(reference)
        off = found.upper() in FALSE_WORDS or found.upper().endswith("-NOTFOUND")
        if zero_one:
            return f"{head}define {name} {0 if off else 1}"
        return f"/* #undef {name} */" if off else f"{head}define {name}{rest}"

    text = _CMAKEDEFINE.sub(define, template)
    pattern = _AT_REFERENCE if at_only else f"{_AT_REFERENCE}|{_BRACE_REFERENCE}"
    text = re.sub(pattern, lambda m: value(
        "${" + m.group(1) + "}" if m.group(1) else "$" + (m.group(2) or "") + "{"
        + m.group(3) + "}"), text)
    if missing:
        return None, "it reads " + ", ".join(dict.fromkeys(missing[:5])) + \
            ", not known here"
    return text, ""


@handles("install")
def _install(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if args[:1] in (["DIRECTORY"], ["FILES"], ["PROGRAMS"]) and "DESTINATION" in args[:-1]:
        it.installs.append(Install(args[0], args[1:], it.source_dir, it.current_conditions(),
                                   command.line, command.column, command.file))
    if args[:1] == ["PROGRAMS"]:
        rename = args[args.index("RENAME") + 1] if "RENAME" in args[:-1] else None
        _programs(it, command, args[1:], rename)
    elif args[:1] == ["DIRECTORY"] and "DESTINATION" in args[:-1]:
        destination = args[args.index("DESTINATION") + 1]
        if not destination.startswith("lib/") or "USE_SOURCE_PERMISSIONS" not in args:
            return
        for folder in args[1:args.index("DESTINATION")]:
            path = it.path(folder)
            if it.inside_package(path):
                it.program_dirs.append(Program(path, "", it.current_conditions(),
                                               command.line, command.column, command.file))


# install(PROGRAMS)'s options after its files: ``TYPE BIN`` (CMake 3.14) is a destination
# too (tucan_ros2's qgroundcontrol/CMakeLists.txt:16-19), not two more programs
_PROGRAM_KEYWORDS = ("DESTINATION", "TYPE", "PERMISSIONS", "CONFIGURATIONS", "COMPONENT",
                     "RENAME", "OPTIONAL", "EXCLUDE_FROM_ALL")


def _programs(it: Interpreter, command: Invocation, args: list[str],
              rename: str | None) -> None:
    files: list[str] = []
    for arg in args:
        if arg in _PROGRAM_KEYWORDS:
            break
        files.append(arg)
    for text in files:
        path = it.path(text)
        name = rename if rename and len(files) == 1 else os.path.basename(path)
        it.programs.append(Program(path, name, it.current_conditions(), command.line,
                                   command.column, command.file))


@handles("ament_auto_package")
def _ament_auto_package(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``INSTALL_TO_SHARE dir...`` installs those folders into ``share/<project>``."""
    package_xml_read(it)
    handed_extras(it, args)
    if "INSTALL_TO_SHARE" not in args:
        return
    folders: list[str] = []
    for arg in args[args.index("INSTALL_TO_SHARE") + 1:]:
        if arg.isupper() and arg.replace("_", "").isalpha():
            break  # the next keyword (INSTALL_TO_PATH, USE_SCOPED_HEADER_INSTALL_DIR...)
        folders.append(arg)
    destination = f"share/{it.get('PROJECT_NAME') or ''}"
    it.installs.append(Install("DIRECTORY", [*folders, "DESTINATION", destination],
                               it.source_dir, it.current_conditions(), command.line,
                               command.column, command.file))


# xacro's CMake functions: the options that take no value, and those that take one
_XACRO_FLAGS = frozenset({"INORDER", "INSTALL", "OPTIONAL"})
_XACRO_VALUED = frozenset({"OUTPUT", "TARGET", "DESTINATION"})


def _xacro_args(args: list[str]) -> tuple[list[str], dict[str, str], set[str]]:
    """The inputs of xacro's ``xacro_add_files`` / ``xacro_add_xacro_file`` (``REMAP``'s
    words dropped), the options with a value, and the flags given."""
    inputs: list[str] = []
    valued: dict[str, str] = {}
    flags: set[str] = set()
    at, remap = 0, False
    while at < len(args):
        word = args[at]
        if word in _XACRO_FLAGS:
            flags.add(word)
            remap = False
        elif word in _XACRO_VALUED and at + 1 < len(args):
            valued[word] = args[at + 1]
            at += 1
            remap = False
        elif word in ("REMAP", "DEPENDS"):
            remap = True
        elif not remap:
            inputs.append(word)
        at += 1
    return inputs, valued, flags


def _xacro_output(it: Interpreter, given: str, output: str | None) -> str | None:
    """Where xacro's CMake functions write the file made of ``given``: ``output`` (else
    ``given`` without ``.xacro``), relative to the build folder."""
    name = output or (given[:-len(".xacro")] if given.endswith(".xacro") else None)
    if not name:
        return None
    return os.path.normpath(os.path.join(it.get("CMAKE_CURRENT_BINARY_DIR") or it.source_dir,
                                         name))


def _xacro_install(it: Interpreter, command: Invocation, outputs: list[str],
                   destination: str) -> None:
    """xacro_install's rule: each made file into ``share/<project>/<destination>``, in
    the devel space as in the install space, where roslaunch's ``$(find pkg)/path``
    looks before the package's own folder (vrx_gazebo's worlds)."""
    share = f"share/{it.get('PROJECT_NAME') or ''}"
    it.installs.append(Install(
        "FILES", [*outputs, "DESTINATION", posixpath.join(share, destination) if destination
                  else share], it.source_dir, it.current_conditions(), command.line,
        command.column, command.file))


@handles("xacro_add_files")
def _xacro_add_files(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """xacro's ``xacro_add_files(file... [INSTALL [DESTINATION path]])``: each file run
    through xacro into the build folder (``worlds/ocean.world.xacro`` makes
    ``worlds/ocean.world`` there); with ``INSTALL``, put in the package's share folder
    (``xacro_install``), so a launch file's ``$(find vrx_gazebo)/worlds/ocean.world``
    is there when it runs though no checkout holds it."""
    inputs, valued, flags = _xacro_args(args)
    outputs = [made for made in (_xacro_output(it, given, valued.get("OUTPUT"))
                                 for given in inputs) if made is not None]
    if "INSTALL" in flags and outputs:
        _xacro_install(it, command, outputs, valued.get("DESTINATION", ""))


@handles("xacro_add_xacro_file")
def _xacro_add_xacro_file(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``xacro_add_xacro_file(input [output] ... [OUTPUT variable])``: the path of the
    file made, in the build folder, set in ``variable`` (``XACRO_OUTPUT_FILE``) for a
    later ``xacro_install``."""
    inputs, valued, _ = _xacro_args(args)
    if not inputs:
        return
    made = _xacro_output(it, inputs[0], inputs[1] if len(inputs) > 1 else None)
    if made is not None:
        it.set(valued.get("OUTPUT", "XACRO_OUTPUT_FILE"), made)


@handles("xacro_install")
def _xacro_install_command(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """``xacro_install(target output... DESTINATION path)``."""
    if "DESTINATION" not in args[:-1] or len(args) < 2:
        return
    at = args.index("DESTINATION")
    outputs = [os.path.normpath(os.path.join(it.get("CMAKE_CURRENT_BINARY_DIR") or
                                             it.source_dir, made)) for made in args[1:at]]
    _xacro_install(it, command, outputs, args[at + 1])


@handles("pluginlib_export_plugin_description_file")
def _export_plugin_description(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """ROS 2 pluginlib: ``(base_package description.xml)`` exports the plugin classes
    the file describes, as ``<base_package plugin="..."/>`` does in a package.xml."""
    if len(args) >= 2:
        path = args[1] if os.path.isabs(args[1]) else os.path.join(it.source_dir, args[1])
        it.plugin_descriptions.append((args[0], os.path.normpath(path)))


@handles("generate_parameter_library")
def _parameter_library(it: Interpreter, command: Invocation, args: list[str]) -> None:
    """PickNik's ``generate_parameter_library(target params.yaml [validate.hpp])``
    generates, at build time, ``<PROJECT_NAME>/<target>.hpp`` from the YAML (relative to
    the current source folder); the C++ extractor synthesises that header from it."""
    if len(args) >= 2:
        path = args[1] if os.path.isabs(args[1]) else os.path.join(it.source_dir, args[1])
        it.parameter_libraries.append((args[0], os.path.normpath(path),
                                       it.get("PROJECT_NAME") or ""))


@handles("rclcpp_components_register_node")
def _register_node(it: Interpreter, command: Invocation, args: list[str]) -> None:
    if not args or "PLUGIN" not in args[:-1]:
        return
    plugin = args[args.index("PLUGIN") + 1]
    executable = args[args.index("EXECUTABLE") + 1] if "EXECUTABLE" in args[:-1] else None
    it.registrations.append(Registration(args[0], plugin, executable, it.current_conditions(),
                                         command.line, command.column, command.file))


@handles("rclcpp_components_register_nodes")
def _register_nodes(it: Interpreter, command: Invocation, args: list[str]) -> None:
    skip = False
    for arg in args[1:]:
        if skip:
            skip = False
        elif arg == "RESOURCE_INDEX":
            skip = True
        else:
            it.registrations.append(Registration(args[0], arg, None, it.current_conditions(),
                                                 command.line, command.column, command.file))
