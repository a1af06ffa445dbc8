"""What the CMake interpreter records: targets, installed programs, component registrations."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..model.conditions import Condition


@dataclass(frozen=True)
class CompileDefinition:
    """A macro the build defines for a target's sources (``add_definitions(-DNAME=v)``,
    ``add_compile_definitions``, ``target_compile_definitions``)."""

    name: str
    value: str | None  # as the compiler gets it (``"x"`` with its quotes); None: no value
    # False: the value uses a variable, environment setting or cache entry this reading
    # never sets (a find_package result, a file read): defined, but to what is not known
    known: bool = True
    conditions: tuple[Condition, ...] = ()  # the if()s around it that are not decided
    file: str = ""
    line: int = 0


@dataclass
class Target:
    """A build target: ``add_executable`` or ``add_library``."""

    name: str
    kind: str  # "executable" | "library"
    sources: list[str] = field(default_factory=list)  # absolute paths or $<...>
    output_name: str | None = None
    links: list[str] = field(default_factory=list)  # target_link_libraries
    # other packages whose libraries it links (``nodes.package_links``): a package's
    # ``<pkg>_LIBRARIES`` / catkin's ``catkin_LIBRARIES`` from ``find_package``,
    # ``ament_target_dependencies``, ``pkg::target``
    packages: list[str] = field(default_factory=list)
    # made by ``ament_auto_add_*``: it also links every build dependency of package.xml
    auto: bool = False
    conditions: tuple[Condition, ...] = ()
    # the if()s not decided around the command that made it last, whose sources these
    # are: a target made in both branches of ``if(ament_cmake_FOUND)`` has no condition
    # (it is made on every path), but the sources of the ``else`` branch's, and what that
    # branch defines for it, are compiled only where that branch is taken; None: as
    # ``conditions``
    made_under: tuple[Condition, ...] | None = None
    line: int = 0
    column: int = 0
    file: str = ""
    # the definitions of its directory (``add_definitions``, ``add_compile_definitions``:
    # those of the directory's whole file, and of its parents' before it was added), the
    # very list the interpreter adds to; and its own (``target_compile_definitions``),
    # each with its keyword: PRIVATE and PUBLIC ones are its sources', PUBLIC and
    # INTERFACE ones those of the targets that link it
    directory_definitions: list[CompileDefinition] = field(default_factory=list)
    definitions: list[tuple[str, CompileDefinition]] = field(default_factory=list)
    # the include folders of its directory (``include_directories``, as its definitions)
    # and its own (``target_include_directories``) with its keyword, each absolute, with
    # the if()s around it the reading did not decide (``commands.include_folders``)
    directory_includes: list[tuple[str, tuple[Condition, ...]]] = field(default_factory=list)
    includes: list[tuple[str, str, tuple[Condition, ...]]] = field(default_factory=list)
    # the C++ standard its CXX_STANDARD property asks (from ``CMAKE_CXX_STANDARD`` when it
    # is made, ``set_property`` / ``set_target_properties``), as a year (17, 20, 23);
    # and those its ``target_compile_features(cxx_std_NN)`` require, each with its
    # keyword (PUBLIC and INTERFACE ones also the targets that link it)
    standard: int | None = None
    features: list[tuple[str, int]] = field(default_factory=list)
    # its CXX_STANDARD_REQUIRED and CXX_EXTENSIONS (None: not set), from the variables
    # when it is made or its properties; the year of the last ``-std=`` word of its
    # directory's ``CMAKE_CXX_FLAGS`` (its value at the directory's end) and of its
    # compile options (the directory's ``add_compile_options`` before it, then its own
    # ``target_compile_options``): ``commands.effective_standard`` orders them as CMake
    # writes the compile line
    standard_required: bool = False
    extensions: bool | None = None
    flags_standard: int | None = None
    options_standard: int | None = None

    @property
    def sources_under(self) -> tuple[Condition, ...]:
        """The if()s not decided that hold wherever its sources are compiled."""
        return self.conditions if self.made_under is None else self.made_under


@dataclass
class Program:
    """A file installed as a runnable program (``install(PROGRAMS)`` and friends)."""

    path: str  # absolute
    name: str  # the name it is installed (and run) as
    conditions: tuple[Condition, ...]
    line: int
    column: int
    file: str


@dataclass
class Configured:
    """``configure_file(<input> <output> ...)``: the file the build writes at ``output``
    (absolute; under ``interpreter.BINARY_ROOT`` when it is in the build folder) from
    ``input``, and its text as the reading gives it there, only for a file written into
    the package's own folder (where the other readers look for it): None when not known,
    ``unknown`` saying why."""

    input: str
    output: str
    text: str | None
    unknown: str
    line: int
    column: int
    file: str


@dataclass
class Registration:
    """``rclcpp_components_register_node(s)``: a component class in a library target."""

    target: str
    plugin: str
    executable: str | None
    conditions: tuple[Condition, ...]
    line: int
    column: int
    file: str


@dataclass
class Install:
    """``install(DIRECTORY|FILES|PROGRAMS ... DESTINATION ...)`` (and ament_auto_package's
    ``INSTALL_TO_SHARE``): what the package puts in its install space, read by
    ``haros_arch.share``. ``args`` are as given after the form; relative paths are
    relative to ``source_dir``."""

    form: str  # "DIRECTORY" | "FILES" | "PROGRAMS"
    args: list[str]
    source_dir: str
    conditions: tuple[Condition, ...]
    line: int
    column: int
    file: str
