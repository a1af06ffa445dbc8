"""Evaluate CMake files far enough to know a package's build targets.

The interpreter keeps CMake's scopes (directory and function scopes, ``PARENT_SCOPE``,
the cache), runs control flow (``if``/``elseif``/``else``, ``foreach``, bounded
``while``, ``break``/``continue``/``return``), user ``macro``s and ``function``s,
``include()`` of package-local files and ``add_subdirectory``. Commands are dispatched
by name through ``commands.HANDLERS``; commands it does not know are skipped quietly
(they cannot create runnable nodes). A condition that depends on something unknown
(an environment setting, a ``find_package`` result) does not drop what it guards: the
guarded commands run with that condition attached; its branches start from the same
variables, and a variable they leave differently holds either value after it
(``Interpreter.either``). Work is bounded: a step budget, a
loop bound and a nesting depth, each reported once when exceeded.
"""

from __future__ import annotations

import contextlib
import itertools
import os
import re
from collections import ChainMap
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..model.conditions import Condition
from ..model.location import Location
from .commands import HANDLERS, IGNORED, defined_names, directory_done, unknown_command
from .conditions import (
    BINARY,
    FALSE_WORDS,
    FOUND_BY_PACKAGE,
    TRUE_WORDS,
    UNARY,
    UNKNOWN_MARK,
    Evaluator,
)
from .lexer import Argument, Invocation
from .listops import split_list
from .targets import CompileDefinition, Configured, Install, Program, Registration, Target

_VARIABLE_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
# the words of an if() test that are no variable: operators and constants
_TEST_WORDS = frozenset({"NOT", "AND", "OR", *UNARY, *BINARY, *TRUE_WORDS, *FALSE_WORDS})
_VAR_REF = re.compile(r"\$(ENV|CACHE)?\{([^${}]*)\}")
# what a ROS distribution's setup script sets, which every build of a package has: not
# set in the run's environment (no ``distro:``, no ROS_DISTRO), its value is not known,
# not the empty text CMake gives an unset one (``_reads_found``)
_DISTRO_ENV = re.compile(r"\$ENV\{(ROS_DISTRO|ROS_VERSION|ROS_PYTHON_VERSION)\}")
MAX_STEPS = 50_000  # commands and if / elseif tests; real packages take under 1,000
MAX_LOOP = 10_000
MAX_RANGE_DIGITS = 18  # foreach RANGE bounds: CMake reads them as 64-bit integers
MAX_DEPTH = 64
MAX_BLOCK_DEPTH = 200  # if / foreach / while blocks inside each other
MAX_VALUE = 1_000_000  # characters in one variable's value or one command's arguments
MAX_EXPANDED = 20_000_000  # characters of arguments expanded in one run (a loop of a big command)
# the ways an if() test is evaluated, one per choice of the values its variables may hold
# after tests not decided (``Interpreter.either``): past it, the test is not decided
MAX_CHOICES = 64
ARGUMENT_COST = 64  # characters an argument counts for besides its own
BINARY_ROOT = "/<build>"  # CMAKE_BINARY_DIR: generated files have no source to read

Reader = Callable[[str], list[Invocation]]
# the values (None: not set) each variable may hold where a test holds, or does not
Allowed = dict[str, set[str | None]]
Locator = Callable[[str, int, int], Location]


# CMake's variables of the compiler it finds at configure time: not known here
_TOOLCHAIN = frozenset({
    f"CMAKE_{lang}_COMPILER_{what}" for lang in ("C", "CXX") for what in ("VERSION", "ID")})


@dataclass
class Definition:
    kind: str  # "macro" | "function"
    params: list[str]
    body: list[Invocation]


@dataclass
class _Values:
    """The variables at one point of the reading, to run the next branch of an if() not
    decided from the same start, and to join the paths after it."""

    scopes: list[dict[str, str]]
    cache: dict[str, str]
    uncertain: set[str]
    either: dict[str, tuple[str | None, ...]]


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


class _Return(Exception):
    pass


class _Stop(Exception):
    pass


class Interpreter:
    def __init__(self, source_dir: str, environment: Mapping[str, str],
                 reader: Reader | None = None, location: Locator | None = None) -> None:
        self.package_root = os.path.realpath(source_dir)
        self.environment = environment
        # the ROS distribution the sources are read for (``Workspace.source_distro``):
        # ``find_package(rclcpp)`` / ``roscpp`` set that release's version
        self.source_distro: str | None = None
        self.reader = reader or (lambda path: [])
        self.location = location
        self.scopes: list[dict[str, str]] = [{}]
        self.cache: dict[str, str] = {}
        self.assigned: set[str] = set()
        self.targets: dict[str, Target] = {}
        # ament_cmake_auto: the libraries ``ament_auto_add_library`` made so far, which
        # every later ``ament_auto_add_*`` target links (``${PROJECT_NAME}_LIBRARIES``)
        self.auto_libraries: list[str] = []
        # add_library(<name> ALIAS <target>): the names linking <name> reaches <target> by
        # (nav2's ``${PROJECT_NAME}::nav2_costmap_2d_core``)
        self.aliases: dict[str, str] = {}
        self.programs: list[Program] = []
        self.program_dirs: list[Program] = []
        # add_custom_target / add_custom_command: what they make at build time is not
        # known here (a program installed from the source folder may be one)
        self.custom_builds: list[Invocation] = []
        # the arguments of each command neither CMake nor the workspace defines (a
        # function of a package outside it: jsk_topic_tools' ``jsk_nodelet(src.cpp
        # "pkg/Class" exe ...)``), expanded, with the package's C/C++ files among them
        # (absolute paths): what they may build is named there
        self.foreign_calls: list[tuple[list[str], list[str]]] = []
        self.installs: list[Install] = []  # for haros_arch.share
        self.configured: list[Configured] = []  # configure_file, for haros_arch.share
        # ament_python_install_package(... SCRIPTS_DESTINATION ...): setup.cfg's entry
        # points are installed as executables
        self.python_scripts = False
        self.registrations: list[Registration] = []
        # pluginlib_export_plugin_description_file: (base package, absolute path)
        self.plugin_descriptions: list[tuple[str, str]] = []
        # generate_parameter_library: (target, absolute path of its YAML, PROJECT_NAME)
        self.parameter_libraries: list[tuple[str, str, str]] = []
        self.definitions: dict[str, Definition] = {}
        # the CMake files a workspace package hands to the packages that find it (its
        # ament CONFIG_EXTRAS, catkin CFG_EXTRAS), with that package's folder: given by
        # the reading of the workspace (``cmake.config_extras``), None without one
        self.extras_of: Callable[[str], tuple[str, list[str]]] | None = None
        # whether an absolute path lies in the workspace, and the git submodule not
        # checked out that it lies in (``Workspace.holds``, ``Workspace.submodule_of``):
        # given by the reading of the workspace, for ``find_path``; None without one
        self.workspace_holds: Callable[[str], bool] | None = None
        self.submodule_of: Callable[[str], tuple[str, str] | None] | None = None
        # this package's build dependencies (``ament_auto_find_build_dependencies``)
        self.build_depends: list[str] = []
        # this package's name and version in its package.xml, which catkin's and ament's
        # package.xml parse (``catkin_package_xml()``, ``ament_package_xml()``) sets as
        # ``<name>_VERSION``; and whether the parse was read (each runs once)
        self.package_name = ""
        self.package_version = ""
        # the ROS version whose build system builds this package, as its package.xml
        # says (``manifest.build_ros_version``; empty when it does not say one): what a
        # ``<tool>_FOUND`` follows when the run names no ROS version
        self.package_ros_version = ""
        self.package_xml_read = False
        # whether ``find_package(name)`` finds a catkin project (catkin_simple takes
        # only those of the build dependencies as catkin's components): not one the
        # workspace builds otherwise; given by the reading of the workspace
        self.catkin_project: Callable[[str], bool] = lambda name: True
        # what this package hands on so (absolute paths), and the packages whose extras
        # this reading ran; while one runs, its package folder (an include may read there)
        self.config_extras: list[str] = []
        self.extras_read: set[str] = set()
        self.foreign_roots: list[str] = []
        # the compile definitions of each directory being read, innermost last: a
        # subdirectory starts with a copy of its parent's (``Target.directory_definitions``)
        self.compile_definitions: list[list[CompileDefinition]] = [[]]
        # the ``-D`` words of each directory's ``add_compile_options`` so far, innermost
        # last: a target takes those made before it (the directory's COMPILE_OPTIONS
        # start its own), a subdirectory starts with a copy of its parent's
        self.compile_options: list[list[CompileDefinition]] = [[]]
        # the C++ standards the ``-std=`` words of each directory's
        # ``add_compile_options`` ask so far, innermost last, as its ``-D`` words; and the
        # targets each directory being read made, which the directory's CMAKE_CXX_FLAGS
        # at its end compiles too (``commands.directory_done``)
        self.compile_standards: list[list[int]] = [[]]
        # policy CMP0128 NEW (``cmake_minimum_required(VERSION 3.22)`` or later): no
        # standard flag when the compiler's own is the one asked
        self.cmp0128 = False
        self.made_here: list[list[str]] = [[]]
        # the ``include_directories`` folders of each directory being read, innermost
        # last, as its compile definitions (``Target.directory_includes``)
        self.include_directories: list[list[tuple[str, tuple[Condition, ...]]]] = [[]]
        # the macros a branch this reading decided not taken, on what it knows for
        # certain, would define (sick_scan_xd's ``if(ROS_VERSION EQUAL 0)
        # add_compile_options(-DROSSIMU)`` in a ROS 2 build): known absent there
        self.absent_definitions: set[str] = set()
        # the options (``option(NAME doc default)``) this reading gave their default, with
        # where; and the first word of each command of a branch not taken because an
        # option has its default (cartographer_ros' ``if (${BUILD_GRPC})
        # google_binary(cartographer_grpc_node ...)``, off by default): the target it
        # may make is built with the option given otherwise (``-DBUILD_GRPC=ON``), by
        # that word: (option, its default, where the option is declared)
        self.options: dict[str, tuple[str, Location]] = {}
        self.option_gated: dict[str, tuple[str, str, Location]] = {}
        # variables whose value this reading may have wrong: set from something not set
        # here (``set(V ${found_by_find_package})``), or in a branch chosen by a test
        # that read such a thing (``if("${pkg_VERSION}" VERSION_GREATER 1)``, decided on
        # an empty string); ``unknown_reference`` takes them as not known
        self.uncertain: set[str] = set()
        # the packages a find_package of this reading looks for (and catkin's
        # components), lower-cased: what it sets of them (``<pkg>_VERSION``) is not known
        self.found_packages: set[str] = set()
        # variables computed from such a value (``string(REGEX MATCH "^[0-9]+" MAJOR
        # "${rclcpp_VERSION}")``, or from another of them): not known either, so a test
        # that reads one is not decided (``test_arguments``)
        # ... and so are the compiler's version and identity, which CMake finds at
        # configure time (jsk_perception builds DualFisheyeToPanorama only under
        # ``if("${CMAKE_CXX_COMPILER_VERSION}" VERSION_GREATER "7.0" AND ...)``: read as
        # empty, the test was decided false and the nodelet's code left out)
        self.from_found: set[str] = set(_TOOLCHAIN)
        self._deriving = 0  # > 0: what is set now is computed from such a value
        # variables written on some paths through if()s the reading cannot decide and not
        # on others, or to different values: each path's value (None: not set), the
        # variable holding the last path's (or its last set one) meanwhile. A test that
        # reads one is decided only if every choice of values decides it alike
        # (sick_scan_xd's ``if(EXISTS "/opt/ros/${distro}/setup.sh") set(ROS_VERSION 2)``
        # leaves ROS_VERSION 2 or not set); any other reading of one is not known
        self.either: dict[str, tuple[str | None, ...]] = {}
        self._unsure = 0  # > 0: what is set now is uncertain
        # the if() tests around the command being run that were decided on something not
        # known (``uncertain``): what they guard may run when it should not, or not run
        self.unsure_tests: list[Condition] = []
        self.conditions: list[Condition] = []  # enclosing if / while not decided
        self.returns: list[Condition] = []  # return() under a condition not decided
        # ExternalProject_Add of the package's own folder with cache entries (a
        # superbuild): where, the external project's name, the entries
        self.superbuild: tuple[Location, str, dict[str, str]] | None = None
        # catkin_package(LIBRARIES ...): the libraries another package's
        # ``${catkin_LIBRARIES}`` links; None before any catkin_package() is read
        self.catkin_exports: list[str] | None = None
        # a catkin_package() read under an if() not decided, or with a value not known:
        # which libraries it exports is not known
        self.catkin_exports_unsure = False
        # catkin_package(CATKIN_DEPENDS ...): the packages whose exported libraries
        # catkin's generated config adds to this one's (``<pkg>_LIBRARIES``)
        self.catkin_depends: list[str] = []
        # find_package(catkin COMPONENTS ...): the ROS packages the build finds, which
        # its package.xml may not name (vizzy_control builds with moveit's
        # MoveGroupInterface and declares no moveit package)
        self.catkin_components: list[str] = []
        self.diagnostics: list[Diagnostic] = []
        self.steps = 0
        self.expanded = 0  # characters of arguments expanded, against MAX_EXPANDED
        self.depth = 0
        self.block_depth = 0
        # opening command (by identity) -> distances to its middle and closing commands
        # (kept with the command itself, so its id is never reused while cached)
        self._blocks: dict[int, tuple[Invocation, list[int]]] = {}
        self.current: Invocation | None = None  # the command being run, for limits
        self._enter_directory(source_dir)
        scope = self.scopes[-1]
        scope.update({"CMAKE_SOURCE_DIR": source_dir, "PROJECT_SOURCE_DIR": source_dir,
                      "CMAKE_BINARY_DIR": BINARY_ROOT, "PROJECT_BINARY_DIR": BINARY_ROOT,
                      # a Linux build, as ROS's tier-1 platforms
                      "UNIX": "1", "WIN32": "", "APPLE": "", "MSVC": "", "ANDROID": "",
                      "CMAKE_SYSTEM_NAME": "Linux", "CMAKE_HOST_UNIX": "1",
                      # CMake 3, as every ROS distribution's (kinetic's 3.5 on)
                      "CMAKE_MAJOR_VERSION": "3"})

    # -- scopes ---------------------------------------------------------------
    def get(self, name: str) -> str | None:
        value = self.scopes[-1].get(name)
        return self.cache.get(name) if value is None else value

    def possible(self, name: str) -> list[str]:
        """Each value variable ``name`` may hold here: its value, and those the paths
        through the if()s the reading did not decide leave it (``either``)."""
        return [v for v in dict.fromkeys((self.get(name), *self.either.get(name, ())))
                if v is not None]

    def set(self, name: str, value: str) -> None:
        self._bounded(name, value)
        self.scopes[-1][name] = value
        self.assigned.add(name)
        self.either.pop(name, None)
        if self._unsure:
            self.uncertain.add(name)
        else:
            self.uncertain.discard(name)
        self._derived(name)

    def _derived(self, name: str) -> None:
        if self._deriving:
            self.from_found.add(name)
        else:
            self.from_found.discard(name)

    def _bounded(self, name: str, value: str) -> None:
        """A value past ``MAX_VALUE`` (a list or string doubled in a loop or through
        macro arguments) stops the file, with a limit diagnostic at the command."""
        if len(value) > MAX_VALUE and self.current is not None:
            self.limit(self.current, f"the value of {name[:60]} grew past {MAX_VALUE} "
                                     "characters")
            raise _Stop

    def unset(self, name: str) -> None:
        """V's value is not known here (a result this reading does not compute)."""
        self.scopes[-1].pop(name, None)
        self.either.pop(name, None)

    def clear(self, name: str) -> None:
        """``set(V)`` / ``unset(V)``: V is not set here, for certain (read, it is empty;
        ``if(DEFINED V)`` is false), as a variable set in another scope only is."""
        self.unset(name)
        self.assigned.add(name)
        if self._unsure:
            self.uncertain.add(name)
        else:
            self.uncertain.discard(name)
        self._derived(name)

    def set_parent(self, name: str, value: str | None) -> None:
        if len(self.scopes) < 2:
            return
        if value is None:
            self.scopes[-2].pop(name, None)
        else:
            self._bounded(name, value)
            self.scopes[-2][name] = value
            self.assigned.add(name)

    def current_conditions(self) -> tuple[Condition, ...]:
        return (*self.returns, *self.conditions)

    def unsure_conditions(self) -> tuple[Condition, ...]:
        """``current_conditions`` with the tests decided on what is not known
        (``unsure_tests``: they may have chosen wrongly, so as not decided); not one the
        reading left undecided, which is there already as the branch it is in (the
        ``else`` of ``if("$ENV{ROS_VERSION}" STREQUAL "1")`` where ``elseif(... "2")``
        runs: foxglove_bridge's ROS 2 include folders carried the ``if`` too, under which
        their target, made in that branch, is not, so no target was given them)."""
        current = self.current_conditions()
        tracked = {c.location for c in current}
        return (*current, *(t for t in self.unsure_tests if t.location not in tracked))

    def sure(self) -> bool:
        """Whether the command being run runs for certain, with what it reads known: under
        no if() or return() not decided, reading no value not known."""
        return not (self._unsure or self.conditions or self.returns)

    @property
    def variables(self) -> Mapping[str, str]:
        return ChainMap(self.scopes[-1], self.cache)

    @property
    def source_dir(self) -> str:
        return self.get("CMAKE_CURRENT_SOURCE_DIR") or self.package_root

    def _enter_directory(self, folder: str) -> None:
        rel = os.path.relpath(folder, self.package_root)
        binary = os.path.normpath(os.path.join(BINARY_ROOT, rel))
        self.scopes[-1].update({
            "CMAKE_CURRENT_SOURCE_DIR": folder, "CMAKE_CURRENT_LIST_DIR": folder,
            "CMAKE_CURRENT_LIST_FILE": os.path.join(folder, "CMakeLists.txt"),
            "CMAKE_CURRENT_BINARY_DIR": binary})

    def inside_package(self, path: str) -> bool:
        real = os.path.realpath(path)
        return real == self.package_root or real.startswith(self.package_root + os.sep)

    def path(self, text: str) -> str:
        """A path argument, relative to the current source folder."""
        if text.startswith("$<"):
            return text
        return os.path.normpath(os.path.join(self.source_dir, text))

    def source_path(self, text: str) -> str:
        """A target's source: relative to the current source folder, as ``path``; but
        where no file of that name is there and a configure_file before wrote one in the
        current binary folder, that one, as CMake looks a relative source up in the
        source folder and then in the binary folder (jsk_topic_tools' ``jsk_nodelet``
        macro configures ``<name>.cpp`` and builds ``add_executable(<name> <name>.cpp)``)."""
        found = self.path(text)
        if text.startswith("$<") or os.path.isabs(text) or os.path.exists(found):
            return found
        binary = os.path.normpath(os.path.join(
            self.get("CMAKE_CURRENT_BINARY_DIR") or self.source_dir, text))
        if any(made.output == binary for made in self.configured):
            return binary
        return found

    # -- values ---------------------------------------------------------------
    def expand(self, text: str) -> str:
        return self._expanded(text)[0]

    def unknown_reference(self, text: str, either: bool = True) -> bool:
        """Whether expanding ``text`` reads a variable, environment setting or cache entry
        that is not set here (its value is then not known, not empty); with ``either``
        False, a variable of ``self.either`` does not count."""
        return self._expanded(text, stop_at_unknown=True, either=either)[1]

    def _names_read(self, args: tuple[Argument, ...]) -> list[str]:
        """The variables a command's arguments read: through ``${V}`` (also the inner
        ones of ``${${PROJECT_NAME}_SOURCES}``, as expanding it reads them), or named bare
        (``if(V)``)."""
        names: list[str] = []
        for arg in args:
            if arg.kind == "bracket":
                continue
            self._expanded(arg.text, read=names)
            if arg.kind == "unquoted" and _VARIABLE_WORD.fullmatch(arg.text):
                names.append(arg.text)
        return names

    def _expanded(self, text: str, stop_at_unknown: bool = False,
                  either: bool = True, read: list[str] | None = None) -> tuple[str, bool]:
        """``text`` with its references replaced by their values (one not set: empty, as
        CMake gives it), and whether one read is not known here: not set, a variable set
        under a test decided on what is not known (``uncertain``), or (with ``either``)
        one whose value depends on tests not decided (``self.either``). With
        ``stop_at_unknown``, the walk ends at the first such reference. A text that
        keeps growing past 1 MB or 1,000 replacements is not known either."""
        if "$" not in text:
            return text, False
        for _ in range(1000):
            match = _VAR_REF.search(text)
            if not match:
                return text, False
            kind, name = match.group(1), match.group(2)
            if read is not None and not kind:
                read.append(name)
            value = (self.environment.get(name) if kind == "ENV" else
                     self.cache.get(name) if kind == "CACHE" else self.get(name))
            # not set: not known, unless this reading set or unset it (in a scope
            # left, or here: then it is empty, as ``if()`` takes it, ``Evaluator``)
            if stop_at_unknown and ((value is None and (kind or name not in self.assigned))
                                    or (not kind and (name in self.uncertain or (
                                        either and name in self.either)))):
                return text, True
            text = text[:match.start()] + (value or "") + text[match.end():]
            if len(text) > 1_000_000:
                break
        return text, True

    def arguments(self, args: tuple[Argument, ...]) -> list[str]:
        """Expand references; unquoted arguments split on ';' as CMake does."""
        values: list[str] = []
        for arg in args:
            if arg.kind == "bracket":
                values.append(arg.text)
            elif arg.kind == "quoted":
                values.append(self.expand(arg.text))
            elif "$" not in arg.text and ";" not in arg.text:
                values.append(arg.text)
            else:
                values.extend(item.replace("\\;", ";")
                              for item in split_list(self.expand(arg.text)))
            if len(values) > MAX_VALUE // 8 and self.current is not None:
                self.limit(self.current, "a command's arguments expand to more than "
                                         f"{MAX_VALUE // 8} items")
                raise _Stop
        # each argument costs its length, and an argument's own work as 64 characters
        self.expanded += sum(map(len, values)) + ARGUMENT_COST * len(args)
        if self.expanded > MAX_EXPANDED and self.current is not None:
            self.limit(self.current, f"more than {MAX_EXPANDED} characters of arguments "
                                     f"expanded in all ({ARGUMENT_COST} per argument)")
            raise _Stop
        return values

    def where(self, command: Invocation) -> Location:
        if self.location is not None:
            return self.location(command.file, command.line, command.column)
        return Location(file=command.file, line=command.line, column=command.column)

    def limit(self, command: Invocation, detail: str) -> None:
        self.diagnostics.append(diag.make("CMAKE_LIMIT", self.where(command), detail=detail))

    # -- execution ------------------------------------------------------------
    def run_file(self, commands: list[Invocation]) -> None:
        """Run a top-level file; stops quietly after a reported limit."""
        with contextlib.suppress(_Stop, _Return, _Break, _Continue):
            self.run(commands)
        directory_done(self)

    def run(self, commands: list[Invocation], start: int = 0, end: int | None = None) -> None:
        """Run ``commands[start:end]`` (a block's body is a range of the list that holds
        it, never a copy: nested blocks would copy their bodies once per level)."""
        stop = len(commands) if end is None else end
        index = start
        while index < stop:
            index = self.step(commands, index, stop)

    def charge(self, command: Invocation) -> None:
        """One step of work (a command, or an ``elseif`` test) against ``MAX_STEPS``."""
        self.steps += 1
        if self.steps > MAX_STEPS:
            self.limit(command, f"more than {MAX_STEPS} commands evaluated")
            raise _Stop

    def step(self, commands: list[Invocation], index: int, end: int | None = None) -> int:
        command = commands[index]
        self.current = command
        self.charge(command)
        name = command.name
        block = _BLOCKS.get(name)
        if block is not None:
            if self.block_depth >= MAX_BLOCK_DEPTH:
                self.limit(command, f"blocks nested deeper than {MAX_BLOCK_DEPTH}")
                raise _Stop
            self.block_depth += 1
            try:
                return block(self, commands, index, len(commands) if end is None else end)
            finally:
                self.block_depth -= 1
        if name == "break":
            raise _Break
        if name == "continue":
            raise _Continue
        if name == "return":
            raise _Return
        definition = self.definitions.get(name)
        if definition is not None:
            self.call(definition, command)
            return index + 1
        if name in ("add_custom_target", "add_custom_command"):
            self.custom_builds.append(command)
        handler = HANDLERS.get(name[1:] if name.startswith("_") else name)
        if handler is not None:
            # (the variable ``set()`` writes is no value it reads)
            read = command.args[1:] if name == "set" else command.args
            unsure = self._reads_unknown(read)
            deriving = self._reads_found(read)
            self._unsure += unsure
            self._deriving += deriving
            try:
                handler(self, command, self.arguments(command.args))
            finally:
                self._unsure -= unsure
                self._deriving -= deriving
        elif name not in IGNORED:
            unknown_command(self, command, self.arguments(command.args))
        return index + 1

    def block_end(self, commands: list[Invocation], index: int, end: int, opener: str,
                  closer: str, middles: tuple[str, ...] = ()) -> list[int]:
        """Indexes of the middle keywords at depth 0 and of the closing command, looked for
        up to ``end`` (the end of the range that holds the block).

        The distances from the opening command to its marks are the same wherever the
        block is run from: they are found once per opening command (a loop over nested
        blocks would otherwise scan each block again on every pass)."""
        head = commands[index]
        cached = self._blocks.get(id(head))
        if cached is not None and cached[0] is head:  # the same command, still alive
            known = cached[1]
            if index + known[-1] < end:
                return [index + offset for offset in known]
        depth = 0
        marks: list[int] = []
        for position in range(index + 1, end):
            name = commands[position].name
            if name == opener:
                depth += 1
            elif name == closer:
                if depth == 0:
                    marks.append(position)
                    self._blocks[id(head)] = (head, [mark - index for mark in marks])
                    return marks
                depth -= 1
            elif depth == 0 and name in middles:
                marks.append(position)
        marks.append(end)  # not closed: to the end of this range, not kept
        return marks

    def evaluate(self, args: list[str]) -> bool | None:
        evaluator = Evaluator(self.variables, self.targets, self.package_root,
                              lambda name: name.lower() in HANDLERS
                              or name.lower() in self.definitions, self.assigned,
                              self.environment, self._in_absent_submodule)
        return evaluator.evaluate(args)

    def _in_absent_submodule(self, path: str) -> bool:
        return self.submodule_of is not None and self.submodule_of(path) is not None

    def decide(self, head: Invocation) -> tuple[bool | None, Allowed, Allowed]:
        """An if() / elseif() / while() test: True, False or None (not decided). A test
        that reads variables of ``self.either`` is evaluated for every choice of their
        values and decided when all agree; when not, also the values of each such
        variable with which the test may hold, and those with which it may not (a path
        into the branch, or past it, holds only those)."""
        names = [name for name in dict.fromkeys(self._names_read(head.args)) if name in self.either]
        if not names:
            return self.evaluate(self.test_arguments(head.args)), {}, {}
        choices = list(itertools.product(*(self.either[name] for name in names)))
        if len(choices) > MAX_CHOICES:
            return None, {}, {}
        scope = self.scopes[-1]
        kept = {name: scope.get(name) for name in names}
        results: list[bool | None] = []
        try:
            for choice in choices:
                for name, value in zip(names, choice, strict=True):
                    _put(scope, name, value)
                results.append(self.evaluate(self.test_arguments(head.args)))
        finally:
            for name, value in kept.items():
                _put(scope, name, value)
        if len(set(results)) == 1:
            return results[0], {}, {}
        holds: Allowed = {name: set() for name in names}
        fails: Allowed = {name: set() for name in names}
        for choice, result in zip(choices, results, strict=True):
            for name, value in zip(names, choice, strict=True):
                if result is not False:
                    holds[name].add(value)
                if result is not True:
                    fails[name].add(value)
        return None, holds, fails

    def test_arguments(self, args: tuple[Argument, ...]) -> list[str]:
        """An ``if()`` / ``while()`` test's arguments expanded, each one that reads what a
        ``find_package`` of this reading sets (``${mongodb_store_VERSION}`` after
        ``find_package(catkin COMPONENTS mongodb_store)``) which is not set here
        ``UNKNOWN_MARK``: its value is not known, not the empty text CMake would give an
        unset variable (jsk_robot_startup's ``if("${mongodb_store_VERSION}"
        VERSION_GREATER "0.5.1")`` of a package not in the workspace is not decided). A
        package no find_package looks for sets nothing: empty, as CMake has it (MoveIt 2's
        ``if("${catkin_LIBRARIES}" MATCHES ...)`` in an ament package)."""
        values: list[str] = []
        for arg in args:
            if arg.kind == "unquoted" and arg.text in self.from_found:
                values.append(UNKNOWN_MARK)  # ``if(MAJOR GREATER 20)``, named bare
            elif self._reads_found((arg,)):
                values.append(UNKNOWN_MARK)
            else:
                values.extend(self.arguments((arg,)))
        return values

    def _reads_found(self, args: tuple[Argument, ...]) -> bool:
        """Whether the arguments read, through a reference, what a ``find_package`` of
        this reading sets that is not set here, or a variable computed from such a
        value (``from_found``); or a setting of the distribution's setup script the
        run's environment lacks (``_DISTRO_ENV``: aubo_demo builds each executable under
        ``if("$ENV{ROS_DISTRO}" STREQUAL "noetic")``, ``"melodic"``, ...; read as empty,
        no test held and the package had no program)."""
        for arg in args:
            read: list[str] = []
            if arg.kind != "bracket":
                if any(name not in self.environment
                       for name in _DISTRO_ENV.findall(arg.text)):
                    return True
                self._expanded(arg.text, read=read)
            if any(name in self.from_found or (
                    self.get(name) is None and name not in self.assigned
                    and (found := FOUND_BY_PACKAGE.fullmatch(name)) is not None
                    and found.group(1).lower() in self.found_packages) for name in read):
                return True
        return False

    def every_way(self, args: tuple[Argument, ...]) -> list[str]:
        """A command's arguments expanded with every choice of the values its variables
        of ``self.either`` may hold, each item once: as they are now, then those the
        other choices add (a target's sources: those of every path, as
        ``if(CUDA_FOUND) list(APPEND SRCS gpu.cpp) endif()`` leaves ``SRCS`` with or
        without gpu.cpp); past ``MAX_CHOICES`` choices, as they are."""
        names = [name for name in dict.fromkeys(self._names_read(args)) if name in self.either]
        choices = list(itertools.product(*(self.either[name] for name in names)))
        if not names or len(choices) > MAX_CHOICES:
            return self.arguments(args)
        scope = self.scopes[-1]
        kept = {name: scope.get(name) for name in names}
        found = dict.fromkeys(self.arguments(args))
        try:
            for choice in choices:
                for name, value in zip(names, choice, strict=True):
                    _put(scope, name, value)
                found.update(dict.fromkeys(self.arguments(args)))
        finally:
            for name, value in kept.items():
                _put(scope, name, value)
        return list(found)

    def _values(self) -> _Values:
        return _Values([dict(scope) for scope in self.scopes], dict(self.cache),
                       set(self.uncertain), dict(self.either))

    def _restore(self, values: _Values) -> None:
        for scope, saved in zip(self.scopes, values.scopes, strict=True):
            scope.clear()
            scope.update(saved)
        self.cache.clear()
        self.cache.update(values.cache)
        self.uncertain.clear()
        self.uncertain.update(values.uncertain)
        self.either = dict(values.either)

    def _narrow(self, allowed: Allowed) -> None:
        """Keep, of the values each variable of ``self.either`` may hold, those
        ``allowed`` gives it (the path goes where a test holds, or where it does not)."""
        for name, values in allowed.items():
            held = tuple(value for value in self.either.get(name, ()) if value in values)
            if held:
                self._hold(name, held, self.scopes[-1])

    def _hold(self, name: str, held: tuple[str | None, ...], table: dict[str, str]) -> None:
        """``name`` may hold any of ``held``: the last set one is its value meanwhile."""
        _put(table, name, next((value for value in reversed(held) if value is not None),
                               None))
        if len(held) > 1:
            self.either[name] = held
        else:
            self.either.pop(name, None)

    def _join(self, paths: list[_Values]) -> None:
        """The variables after paths the reading could not choose between (the last one
        is the reading's own, as it ran them in turn): a variable all of them leave
        alike keeps that value; one they leave differently may hold each
        (``self.either``); one that is uncertain on a path stays so."""
        self._restore(paths[-1])
        for path in paths[:-1]:
            self.uncertain.update(path.uncertain)
        top = len(self.scopes) - 1
        # the cache, then the scopes outward in: the innermost scope's marks win
        for level in (-1, *range(top + 1)):
            tables = [path.cache if level < 0 else path.scopes[level] for path in paths]
            names = dict.fromkeys(name for table in tables for name in table)
            if level == top:
                names.update(dict.fromkeys(name for path in paths for name in path.either))
            for name in names:
                held: list[str | None] = []
                for path, table in zip(paths, tables, strict=True):
                    if level == top and name in path.either:
                        held.extend(path.either[name])
                    else:
                        held.append(table.get(name))
                values = tuple(dict.fromkeys(held))
                if len(values) > 1:
                    self._hold(name, values, self.cache if level < 0 else self.scopes[level])

    def _reads_unknown(self, args: tuple[Argument, ...], either: bool = True) -> bool:
        """Whether a command's arguments read something not known here (a reference, or
        a variable named bare, as ``if(V)`` reads it, that is uncertain, or with
        ``either``, that holds one of several values)."""
        return any(arg.kind != "bracket" and (self.unknown_reference(arg.text, either) or (
            arg.kind == "unquoted" and (arg.text in self.uncertain or (
                either and arg.text in self.either)))) for arg in args)

    def run_if(self, commands: list[Invocation], index: int, limit: int) -> int:
        marks = self.block_end(commands, index, limit, "if", "endif", ("elseif", "else"))
        branches = [index, *marks[:-1]]
        end = marks[-1]
        pushed = 0
        returned: list[Condition] = []
        undecided: list[tuple[str, Invocation]] = []  # the tests not decided, in order
        unsure = 0  # 1 once a test read something not known: what follows may be wrong
        # after a test not decided: the variables where the next branch starts (as
        # before that test, narrowed to where it did not hold), and those each branch
        # under such a test left; joined after the block (``_join``)
        start_values: _Values | None = None
        paths: list[_Values] = []
        fell_through = True  # no branch is taken for certain (no else, none decided true)
        try:
            for number, start in enumerate(branches):
                stop = marks[number]
                head = commands[start]
                if not unsure and head.name != "else" and self._reads_unknown(
                        head.args, either=False):
                    unsure = 1
                    self._unsure += 1
                    self.unsure_tests.append(Condition(
                        " ".join(a.text for a in head.args), "source", head.name,
                        self.where(head)))
                if head.name == "else":
                    fell_through = False
                    try:
                        self.run(commands, start + 1, stop)
                    except _Return:
                        if not undecided:
                            raise
                        # an ``else`` after a test not decided that returns: what follows
                        # runs only when one of those tests held (rotors_hil_interface's
                        # ``if (Mavlink_DIR) ... else () ... return() endif ()``)
                        text = " OR ".join(f"({t})" for t, _ in undecided) \
                            if len(undecided) > 1 else undecided[0][0]
                        returned.append(Condition(text, "source", "if",
                                                  self.where(undecided[-1][1])))
                    break
                if number:  # an elseif's test is work too (the if's own is its step)
                    self.charge(head)
                decided, holds, fails = self.decide(head)
                if decided is None:
                    text = " ".join(a.text for a in head.args)
                    undecided.append((text, head))
                    self.conditions.append(Condition(text, "source", head.name,
                                                     self.where(head)))
                    pushed += 1
                    if start_values is None:
                        start_values = self._values()
                    self._narrow(holds)
                    try:
                        self.run(commands, start + 1, stop)
                    except _Return:  # what follows runs only when this did not hold
                        returned.append(Condition(f"NOT ({text})", "source", head.name,
                                                  self.where(head)))
                    except (_Break, _Continue):
                        pass  # the loop goes on where this did not hold
                    paths.append(self._values())
                    self._restore(start_values)
                    self._narrow(fails)
                    start_values = self._values()
                    self.conditions[-1] = Condition(text, "source", "else", self.where(head))
                    continue
                if decided:
                    fell_through = False
                    self.run(commands, start + 1, stop)
                    if not unsure and self._certain(head):
                        self._not_taken(commands, branches[number + 1:], marks[number + 1:])
                    self._gated(head, commands, branches[number + 1:], marks[number + 1:])
                    break
                if not unsure and self._certain(head):
                    self._not_taken(commands, [start], [stop])
                self._gated(head, commands, [start], [stop])
            if paths:
                # as the branches ran in turn, the one left (taken, or none) last; when
                # none was taken, the variables as the last branch left them last
                here = self._values()
                self._join([here, *paths] if fell_through else [*paths, here])
        finally:
            del self.conditions[len(self.conditions) - pushed:]
            self._unsure -= unsure
            if unsure:
                self.unsure_tests.pop()
        self.returns.extend(returned)
        return end + 1

    def _certain(self, head: Invocation) -> bool:
        """Whether an ``if()`` / ``elseif()`` test reads only what this reading knows:
        every word of it that may name a variable names one set here (not a cache entry
        the command line may give, ``-DROS_EDITION=ROS2``)."""
        return all(arg.kind != "unquoted" or not _VARIABLE_WORD.fullmatch(arg.text)
                   or arg.text.upper() in _TEST_WORDS or arg.text in self.variables
                   for arg in head.args)

    def _not_taken(self, commands: list[Invocation], starts: list[int],
                   stops: list[int]) -> None:
        """Record the macros the branches [start, stop) would define, which the reading
        decided not taken for certain (under no test that is not decided)."""
        if self._unsure or self.conditions:
            return
        for start, stop in zip(starts, stops, strict=True):
            for command in commands[start + 1:stop]:
                self.absent_definitions.update(defined_names(command))

    def _gated(self, head: Invocation, commands: list[Invocation], starts: list[int],
               stops: list[int]) -> None:
        """Record the first word of each command of the branches [start, stop), not
        taken because of ``head``'s test, when that test reads an option that has its
        default (``option_gated``)."""
        read = [name for name in self._names_read(head.args) if name in self.options
                and name not in self.assigned and self.cache.get(name) == self.options[
                    name][0]]
        if not read:
            return
        option = read[0]
        default, where = self.options[option]
        for start, stop in zip(starts, stops, strict=True):
            for command in commands[start + 1:stop]:
                if command.name.lower() in _NO_TARGET:
                    continue
                word = command.args[0].text if command.args else ""
                if word and "$" not in word:
                    self.option_gated.setdefault(word, (option, default, where))
                elif word.startswith("${PROJECT_NAME}"):  # (the usual one)
                    named = self.get("PROJECT_NAME")
                    if named:
                        self.option_gated.setdefault(named + word[len("${PROJECT_NAME}"):],
                                                     (option, default, where))

    def run_foreach(self, commands: list[Invocation], index: int, limit: int) -> int:
        end = self.block_end(commands, index, limit, "foreach", "endforeach")[-1]
        args = self.arguments(commands[index].args)
        for assignment in self._foreach_items(commands[index], args):
            for name, value in assignment:
                self.set(name, value)
            try:
                self.run(commands, index + 1, end)
            except _Break:
                break
            except _Continue:
                continue
        return end + 1

    def _foreach_items(self, command: Invocation,
                       args: list[str]) -> list[list[tuple[str, str]]]:
        if "IN" in args:
            split = args.index("IN")
            names, rest = args[:split], args[split + 1:]
        else:
            names, rest = args[:1], args[1:]
        if not names:
            return []
        if rest[:1] == ["RANGE"]:
            written = [x for x in rest[1:4] if re.fullmatch(r"-?\d+", x)]
            if any(len(x.lstrip("-")) > MAX_RANGE_DIGITS for x in written):
                self.limit(command, f"foreach RANGE bound of more than {MAX_RANGE_DIGITS} "
                                    "digits (CMake's are 64-bit integers)")
                return []
            numbers = [int(x) for x in written]
            if not numbers:
                return []
            start, stop, step = (0, numbers[0], 1) if len(numbers) == 1 else (
                numbers[0], numbers[1], numbers[2] if len(numbers) > 2 else 1)
            values = range(start, stop + 1, step or 1)
            if len(values) > MAX_LOOP:
                self.limit(command, f"foreach RANGE of more than {MAX_LOOP} items")
                values = values[:MAX_LOOP]
            return [[(names[0], str(n))] for n in values]
        if rest[:1] == ["ZIP_LISTS"]:
            lists = [split_list(self.get(name)) for name in rest[1:]]
            size = max((len(items) for items in lists), default=0)
            if len(names) == 1:
                names = [f"{names[0]}_{i}" for i in range(len(lists))]
            return [[(name, items[i] if i < len(items) else "")
                     for name, items in zip(names, lists, strict=False)]
                    for i in range(size)]
        values_list: list[str] = []
        mode = "ITEMS" if "IN" not in args else ""
        for item in rest:
            if item in ("LISTS", "ITEMS") and "IN" in args:
                mode = item
            elif mode == "LISTS":
                values_list.extend(split_list(self.get(item)))
            elif mode == "ITEMS":
                values_list.append(item)
        return [[(names[0], value)] for value in values_list]

    def run_while(self, commands: list[Invocation], index: int, limit: int) -> int:
        end = self.block_end(commands, index, limit, "while", "endwhile")[-1]
        head = commands[index]
        for _ in range(MAX_LOOP):
            decided, holds, _ = self.decide(head)
            if decided is False:
                return end + 1
            if decided is None:  # run the body once, under the condition
                text = " ".join(a.text for a in head.args)
                self.conditions.append(Condition(text, "source", "while", self.where(head)))
                before = self._values()
                self._narrow(holds)
                try:
                    self.run(commands, index + 1, end)
                except (_Break, _Continue):
                    pass
                finally:
                    self.conditions.pop()
                self._join([before, self._values()])  # run once, or not at all
                return end + 1
            try:
                self.run(commands, index + 1, end)
            except _Break:
                return end + 1
            except _Continue:
                continue
        self.limit(head, f"while loop ran {MAX_LOOP} times")
        return end + 1

    def define(self, commands: list[Invocation], index: int, limit: int) -> int:
        kind = commands[index].name
        end = self.block_end(commands, index, limit, kind, "end" + kind)[-1]
        args = self.arguments(commands[index].args)
        if args:
            self.definitions[args[0].lower()] = Definition(
                kind, args[1:], commands[index + 1:end])
        return end + 1

    def call(self, definition: Definition, command: Invocation) -> None:
        if self.depth >= MAX_DEPTH:
            self.limit(command, f"calls nested deeper than {MAX_DEPTH}")
            return
        args = self.arguments(command.args)
        named = dict(zip(definition.params, args, strict=False))
        extra = args[len(definition.params):]
        values = {**named, "ARGC": str(len(args)), "ARGV": ";".join(args),
                  "ARGN": ";".join(extra)}
        values.update((f"ARGV{i}", arg) for i, arg in enumerate(args))
        self.depth += 1
        frame = len(self.returns)
        try:
            if definition.kind == "macro":
                self.run([_substitute(c, values) for c in definition.body])
            else:
                self.scopes.append(dict(self.scopes[-1]))
                self.scopes[-1].update(values)
                try:
                    self.run(definition.body)
                except _Return:
                    pass
                finally:
                    self.scopes.pop()
        finally:
            self.depth -= 1
            if definition.kind == "function":
                del self.returns[frame:]

    def include(self, command: Invocation, path: str) -> bool:
        """Run a package-local file in the current scope (or one of the folder of the
        package whose config extras run, ``foreign_roots``); False if not read."""
        if not (os.path.isfile(path) and (self.inside_package(path) or any(
                _below(path, root) for root in self.foreign_roots))):
            return False
        if self.depth >= MAX_DEPTH:
            self.limit(command, f"include() nested deeper than {MAX_DEPTH}")
            return True
        saved = {k: self.get(k) for k in ("CMAKE_CURRENT_LIST_DIR", "CMAKE_CURRENT_LIST_FILE")}
        self.set("CMAKE_CURRENT_LIST_DIR", os.path.dirname(path))
        self.set("CMAKE_CURRENT_LIST_FILE", path)
        self.depth += 1
        frame = len(self.returns)
        try:
            self.run(self.reader(path))
        except _Return:
            pass
        finally:
            self.depth -= 1
            del self.returns[frame:]
            for key, value in saved.items():
                self.set(key, value or "")
        return True

    def add_subdirectory(self, command: Invocation, folder: str) -> None:
        listfile = os.path.join(folder, "CMakeLists.txt")
        if not (os.path.isfile(listfile) and self.inside_package(listfile)):
            return
        if self.depth >= MAX_DEPTH:
            self.limit(command, f"add_subdirectory() nested deeper than {MAX_DEPTH}")
            return
        self.scopes.append(dict(self.scopes[-1]))
        self.compile_definitions.append(list(self.compile_definitions[-1]))
        self.compile_options.append(list(self.compile_options[-1]))
        self.compile_standards.append(list(self.compile_standards[-1]))
        self.made_here.append([])
        self.include_directories.append(list(self.include_directories[-1]))
        self._enter_directory(folder)
        self.depth += 1
        frame = len(self.returns)
        try:
            self.run(self.reader(listfile))
        except _Return:
            pass
        finally:
            self.depth -= 1
            del self.returns[frame:]
            directory_done(self)
            self.scopes.pop()
            self.compile_definitions.pop()
            self.compile_options.pop()
            self.compile_standards.pop()
            self.made_here.pop()
            self.include_directories.pop()


# commands whose first word names no target (a variable, a list operation, a file)
_NO_TARGET = frozenset({
    "set", "unset", "list", "string", "file", "math", "option", "message", "install",
    "get_filename_component", "if", "elseif", "else", "endif", "foreach", "endforeach",
    "while", "endwhile", "function", "endfunction", "macro", "endmacro", "return",
    "include", "find_package", "add_subdirectory", "configure_file", "cmake_parse_arguments",
})


def _below(path: str, root: str) -> bool:
    real, top = os.path.realpath(path), os.path.realpath(root)
    return real == top or real.startswith(top + os.sep)


def _put(table: dict[str, str], name: str, value: str | None) -> None:
    if value is None:
        table.pop(name, None)
    else:
        table[name] = value


def _substitute(command: Invocation, values: Mapping[str, str]) -> Invocation:
    """Macro arguments are text replacements of ``${param}`` in the body."""
    def replace(text: str) -> str:
        if "${" not in text:
            return text
        return re.sub(r"\$\{([A-Za-z0-9_]+)\}",
                      lambda m: values.get(m.group(1), m.group(0)), text)

    args = tuple(arg if arg.kind == "bracket" else Argument(replace(arg.text), arg.kind)
                 for arg in command.args)
    return Invocation(command.name, args, command.line, command.column, command.file)


_BLOCKS: dict[str, Callable[[Interpreter, list[Invocation], int, int], int]] = {
    "if": Interpreter.run_if, "foreach": Interpreter.run_foreach,
    "while": Interpreter.run_while, "macro": Interpreter.define,
    "function": Interpreter.define,
}

