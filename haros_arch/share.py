"""A package's share folder as ROS 2 sees it after ``colcon build``, without building.

ROS 2 launch files find a package's files under ``install/<pkg>/share/<pkg>/``
(``$(find-pkg-share pkg)``, ``FindPackageShare``, ``get_package_share_directory``), and
what lies there is what the package's build rules install: CMake
``install(DIRECTORY|FILES|PROGRAMS ... DESTINATION share/${PROJECT_NAME}[/sub])`` (with
``FILES_MATCHING``, ``PATTERN`` / ``REGEX`` and ``EXCLUDE``, a trailing ``/`` installing
a folder's contents), ``ament_auto_package(INSTALL_TO_SHARE ...)``, and ament_python's
``setup(data_files=[(destination, [files])])`` (read with ``ast``; ``glob``,
``os.path.join``, concatenation, formatting and simple comprehensions are evaluated
over the package folder, nothing is run).

Entry point: ``share_map(package, workspace)`` maps each share-relative path
(``config/rover.yaml``) to the absolute source file installed there, cached per package
on the workspace. ``share_source(workspace, path)`` turns a path under a workspace
package's folder, as ``Workspace.find`` gives it, into the source file it stands for in
the install space; a path the build rules do not install stays as it is (the installed
layout usually mirrors the source). ROS 1 (devel space = source) does not use this.

The install prefix of a workspace package (``$(find-pkg-prefix)``, ``FindPackagePrefix``,
``get_package_prefix``) is where colcon's default isolated install puts it,
``<install>/<pkg>`` with ``<install>`` beside the workspace's ``src`` folder
(``install_prefix``); ``share_source`` reads ``<install>/<pkg>/share/<pkg>/...`` through
the share map too. ``lib_executables`` names what colcon installs in ``lib/<pkg>``: the
executables and scripts of the package's CMakeLists.txt or setup.py entry points.
``configured`` gives the ``configure_file`` that writes a file into a package's own
folder (a file the build makes there, which a checkout does not hold).
"""

from __future__ import annotations

import os
import posixpath
import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field

from . import pysetup
from .cmake import interpret
from .cmake import parse_package as cmake_nodes
from .cmake.interpreter import BINARY_ROOT
from .cmake.targets import Configured, Install
from .evaluate import syntax
from .facts import remember
from .files import read_text
from .manifest import other_builds
from .model.source import Package
from .workspace import Workspace

MAX_FILES = 20_000  # files in one package's share map
MAX_DEPTH = 16  # folder depth walked under an installed folder
MAX_VISITED = 100_000  # files looked at under one installed folder
_KEYWORDS = frozenset((
    "DESTINATION", "TYPE", "RENAME", "FILE_PERMISSIONS", "DIRECTORY_PERMISSIONS",
    "PERMISSIONS", "USE_SOURCE_PERMISSIONS", "OPTIONAL", "MESSAGE_NEVER", "CONFIGURATIONS",
    "COMPONENT", "EXCLUDE_FROM_ALL", "FILES_MATCHING", "PATTERN", "REGEX", "EXCLUDE"))


def share_map(package: Package, workspace: Workspace) -> dict[str, str]:
    """Share-relative path → absolute source file, for one workspace package."""
    cached = workspace.share_maps.get(package.name)
    if cached is not None:
        return cached
    found: dict[str, str] = {}
    generated: dict[str, tuple[str, int]] = {}
    workspace.generated_shares[package.name] = generated
    setup_py = os.path.join(package.root, "setup.py")
    # a share folder is ROS 2's: with no ROS version given, a package whose manifest
    # builds it with setup.py under ROS 2 shares what that setup.py installs
    ros2 = [environment for version, environment
            in other_builds(package, workspace.environment) if version == "2"]
    if os.path.isfile(os.path.join(package.root, "CMakeLists.txt")) and not (
            (package.build_type == "ament_python" or ros2) and os.path.isfile(setup_py)):
        _from_cmake(package, workspace, found, generated)
        # ament_package() / catkin_package() install the manifest
        found.setdefault("package.xml", os.path.join(package.root, "package.xml"))
    elif os.path.isfile(setup_py):
        # an ament_python package (its manifest's build type, for this ROS version:
        # ros-bridge's packages keep a catkin CMakeLists.txt beside their setup.py)
        _from_setup_py(package, workspace, setup_py, found,
                       ros2[0] if ros2 else workspace.environment)
    workspace.share_maps[package.name] = found
    return found


def install_base(workspace: Workspace) -> str:
    """The folder colcon would install the workspace into: ``install`` beside ``src``."""
    root = os.path.normpath(workspace.root)
    top = os.path.dirname(root) if os.path.basename(root) == "src" else root
    return os.path.join(top, "install")


def install_prefix(workspace: Workspace, name: str) -> str | None:
    """The install prefix of package ``name`` (``<prefix>/share/<name>`` is its share
    folder): ``<install>/<name>`` for a workspace package, the prefix it was found under
    for an installed one; None when the package is not found."""
    if name in workspace.packages:
        return os.path.join(install_base(workspace), name)
    share = workspace.find(name)
    if share is None:
        return None
    parent = os.path.dirname(os.path.normpath(share))
    if os.path.basename(parent) == "share":
        return os.path.dirname(parent)
    return None  # a ROS_PACKAGE_PATH folder: no prefix layout


def lib_executables(package: Package, workspace: Workspace) -> frozenset[str]:
    """The executables and scripts the package installs in ``lib/<pkg>`` (cached)."""
    cached = workspace.lib_executables.get(package.name)
    if cached is not None:
        return cached
    if package.build_type == "ament_python":
        nodes, _ = pysetup.parse_package(package, workspace)  # the build stage reports
    elif os.path.isfile(os.path.join(package.root, "CMakeLists.txt")):
        nodes, _ = cmake_nodes(package, workspace)
    else:
        nodes = []
    for _, environment in other_builds(package, workspace.environment):
        more, _ = pysetup.parse_package(package, workspace, environment)
        nodes = [*nodes, *more]
    found = frozenset(n.executable for n in nodes if n.kind in ("executable", "script"))
    workspace.lib_executables[package.name] = found
    return found


def configured(workspace: Workspace, path: str) -> Configured | None:
    """The last ``configure_file`` of the CMake package holding ``path`` that writes it
    (into the package's folder; CMake's last write is the file), or None."""
    path = os.path.normpath(os.path.abspath(path))
    package = workspace.package_of(path)
    if package is None or not os.path.isfile(os.path.join(package.root, "CMakeLists.txt")):
        return None
    interpreter, _ = interpret(package, workspace)  # the build stage reports problems
    real = os.path.realpath(path)
    return next((made for made in reversed(interpreter.configured)
                 if os.path.realpath(made.output) == real), None)


def generated_at(workspace: Workspace, path: str) -> tuple[str, int] | None:
    """The CMake file and line of the install rule that puts ``path`` (as
    ``share_source`` takes it) into its package's share folder from the build folder: a
    file the build makes (``configure_file``, ``file(GENERATE)``, a custom command),
    which has no source to read; None when no rule installs it so."""
    path = _from_prefix(workspace, os.path.normpath(os.path.abspath(path)))
    package = workspace.package_of(path)
    if package is None or path == package.root:
        return None
    share_map(package, workspace)
    generated = workspace.generated_shares.get(package.name, {})
    relative = os.path.relpath(path, package.root).replace(os.sep, "/")
    found = generated.get(relative)
    if found is not None:
        return found
    return next((where for folder, where in generated.items()
                 if folder.endswith("/") and relative.startswith(folder)), None)


def climbed(workspace: Workspace, path: str) -> str:
    """The absolute ``path`` normalised as ROS 2 launch resolves it where it climbs
    (``..``) out of a folder of a workspace package: a launch file finds a package in its
    install share folder (``<install>/<pkg>/share/<pkg>``, four folders below the
    workspace, not two as ``src/<pkg>``), so the climb starts there: drone_autonomous_
    landing_on_ugv's ``os.path.join(get_package_share_directory(pkg), '..', '..', '..',
    '..', 'src', pkg, 'parameters', 'params.yaml')`` is the workspace's
    ``src/<pkg>/parameters/params.yaml``; a folder analysed that is one repository stands
    for ``src/<its name>`` there (``_checkout``). Only when a file is there (then the
    source file installed there, when the climb stays in the install space); else
    ``path`` normalised as it is."""
    plain = os.path.normpath(path)
    parts = path.split("/")
    if not os.path.isabs(path) or ".." not in parts:
        return plain
    first = parts.index("..")
    before = os.path.normpath("/".join(parts[:first]) or "/")
    package = workspace.package_of(before)
    if package is None or not package.root or package.name not in workspace.packages:
        return plain
    inside = os.path.relpath(before, os.path.normpath(package.root))
    share = os.path.join(install_base(workspace), package.name, "share", package.name)
    moved = _from_prefix(workspace, os.path.normpath(os.path.join(share, inside,
                                                                  *parts[first:])))
    if os.path.lexists(moved):
        return moved
    checkout = _checkout(workspace, moved)
    return checkout if checkout is not None and os.path.lexists(checkout) else plain


def _checkout(workspace: Workspace, path: str) -> str | None:
    """``path`` under ``<workspace>/src/<name>/`` as a path of the folder analysed, when
    that folder is one repository named ``<name>``, not a workspace or its ``src``: it
    stands for its checkout in the workspace's ``src`` under its own name (vortex-asv's
    blackbox.launch.py climbs four folders out of the share folder into
    ``src/vortex-asv/asv_setup/config/robots/``); else None."""
    root = os.path.normpath(workspace.root)
    name = os.path.basename(root)
    top = os.path.dirname(install_base(workspace))
    if name == "src" or top != root:
        return None
    parts = os.path.relpath(path, top).split(os.sep)
    if len(parts) < 3 or parts[0] != "src" or parts[1] != name:
        return None
    return os.path.join(root, *parts[2:])


def share_source(workspace: Workspace, path: str) -> str:
    """The source file that ``path``, a path in a workspace package's share folder as
    ``Workspace.find`` gives it (the package's source folder) or as its install prefix
    gives it (``<install>/<pkg>/share/<pkg>/...``), stands for; ``path`` itself when the
    package's build rules install nothing there."""
    path = climbed(workspace, path) if os.path.isabs(path) else os.path.abspath(path)
    path = _from_prefix(workspace, path)
    package = workspace.package_of(path)
    if package is None or path == package.root:
        return path
    relative = os.path.relpath(path, package.root).replace(os.sep, "/")
    return share_map(package, workspace).get(relative, path)


def file_setting(workspace: Workspace, path: str) -> str:
    """How a parameter file given to several nodes is named as their setting
    (``Parameter.setting``): the source file read, however the launch file writes the
    path to it (vortex-asv's blackbox.launch.py climbs out of its share folder to the
    freya.yaml that asv_setup's launch files name by asv_setup's share folder); a
    relative path, which no folder here resolves, as it is written."""
    return share_source(workspace, path) if os.path.isabs(path) else path


def _from_prefix(workspace: Workspace, path: str) -> str:
    """``<install>/<pkg>/share/<pkg>/rest`` -> ``<pkg source>/rest``; else ``path``."""
    base = install_base(workspace)
    if not path.startswith(base + os.sep):
        return path
    parts = os.path.relpath(path, base).split(os.sep)
    if len(parts) < 3 or parts[1] != "share" or parts[2] != parts[0] or (
            parts[0] not in workspace.packages):
        return path
    return os.path.join(workspace.packages[parts[0]].root, *parts[3:])


# -- CMake -----------------------------------------------------------------------------
def _from_cmake(package: Package, workspace: Workspace, found: dict[str, str],
                generated: dict[str, tuple[str, int]]) -> None:
    interpreter, _ = interpret(package, workspace)  # the build stage reports problems
    for install in interpreter.installs:
        for relative in generated_files(install, package):
            generated.setdefault(relative, (install.file, install.line))
        for relative, source in installed_files(install, package):
            if len(found) >= MAX_FILES:
                return
            found[relative] = source  # a later rule overwrites, as ``cmake --install``


def include_map(package: Package, workspace: Workspace) -> dict[str, str]:
    """Include-relative path -> absolute source file, for the headers a CMake package
    installs under its prefix's ``include`` folder (``install(DIRECTORY|FILES ...
    DESTINATION include[/sub])``), cached per package: the names other packages include
    them by, which the source folders need not hold (zed_components installs
    ``src/zed_camera/include/`` and ``src/tools/include/`` into
    ``include/zed_components/``, and zed_debug includes
    ``<zed_components/zed_camera_component.hpp>``). Empty for a package CMake does not
    build."""
    def compute() -> dict[str, str]:
        found: dict[str, str] = {}
        if not package.root or not os.path.isfile(
                os.path.join(package.root, "CMakeLists.txt")):
            return found
        interpreter, _ = interpret(package, workspace)  # the build stage reports problems
        for install in interpreter.installs:
            for relative, source in installed_files(install, package, _include_sub):
                if len(found) >= MAX_FILES:
                    return found
                found[relative] = source  # a later rule overwrites, as ``cmake --install``
        return found

    return remember(workspace, "include map", package.root, compute)


def _include_sub(destination: str, _name: str) -> str | None:
    """``include/sub`` -> ``sub`` (``""`` for the include folder itself), else None."""
    text = destination.replace("\\", "/")
    if text.startswith("/include"):  # ${CMAKE_INSTALL_PREFIX}/include, the prefix unknown
        text = text[1:]
    text = posixpath.normpath(text) if text else ""
    if text == "include":
        return ""
    return text[len("include/"):] if text.startswith("include/") else None


def installed_files(install: Install, package: Package,
                    where: Callable[[str, str], str | None] | None = None
                    ) -> Iterator[tuple[str, str]]:
    """(share-relative path, source file) for each file one install rule puts into the
    package's share folder (or, with ``where``, into the folder it maps a destination
    to a path under: ``_include_sub``)."""
    items, options = _split(install.args)
    sub = (where or _share_sub)(options.destination, package.name)
    if sub is None:
        return
    root = os.path.realpath(package.root)
    for item in items:
        if not item or item.startswith("$<") or item.startswith(BINARY_ROOT):
            continue  # generated or unknown: nothing to read
        source = os.path.normpath(os.path.join(install.source_dir, item))
        real = os.path.realpath(source)
        if real != root and not real.startswith(root + os.sep):
            continue  # outside the package: not read
        if install.form == "DIRECTORY":
            base = sub if item.endswith("/") else posixpath.join(sub, os.path.basename(source))
            yield from _directory(source, base, options, root)
        elif os.path.isfile(source):
            rename = options.rename if len(items) == 1 else None
            yield posixpath.normpath(posixpath.join(sub, rename or os.path.basename(source))), \
                source


def generated_files(install: Install, package: Package) -> Iterator[str]:
    """The share-relative paths one install rule fills from the build folder (a folder
    as ``sub/``): what the build makes there is installed, but there is no file to read."""
    items, options = _split(install.args)
    sub = _share_sub(options.destination, package.name)
    if sub is None:
        return
    for item in items:
        if not item.startswith(BINARY_ROOT + "/"):
            continue
        name = posixpath.basename(item.rstrip("/"))
        if install.form == "DIRECTORY":
            folder = sub if item.endswith("/") else posixpath.join(sub, name)
            yield folder.rstrip("/") + "/" if folder else ""
        else:
            rename = options.rename if len(items) == 1 else None
            yield posixpath.normpath(posixpath.join(sub, rename or name))


@dataclass
class _Options:
    destination: str = ""
    rename: str | None = None
    files_matching: bool = False
    rules: list[tuple[re.Pattern[str], bool]] = field(default_factory=list)  # (rule, EXCLUDE)

    def excluded(self, path: str) -> bool:
        return any(exclude and rule.search(path) for rule, exclude in self.rules)

    def matched(self, path: str) -> bool:
        return any(not exclude and rule.search(path) for rule, exclude in self.rules)


def _split(args: list[str]) -> tuple[list[str], _Options]:
    """The paths before the first keyword, and the options that decide where files go."""
    at = next((i for i, word in enumerate(args) if word in _KEYWORDS), len(args))
    items, options = args[:at], _Options()
    while at < len(args):
        word = args[at]
        following = args[at + 1] if at + 1 < len(args) else None
        if word == "DESTINATION" and following is not None:
            options.destination, at = following, at + 1
        elif word == "RENAME" and following is not None:
            options.rename, at = following, at + 1
        elif word in ("PATTERN", "REGEX") and following is not None:
            try:
                rule = _glob_regex(following) if word == "PATTERN" else re.compile(following)
            except re.error:
                rule = re.compile(r"(?!)")  # a regex Python cannot read matches nothing
            options.rules.append((rule, False))
            at += 1
        elif word == "EXCLUDE" and options.rules:
            options.rules[-1] = (options.rules[-1][0], True)
        elif word == "FILES_MATCHING":
            options.files_matching = True
        at += 1
    return items, options


def _share_sub(destination: str, name: str) -> str | None:
    """``share/<name>/sub`` → ``sub`` (``""`` for the share folder itself), else None."""
    text = destination.replace("\\", "/")
    if text.startswith("/share/"):  # ${CMAKE_INSTALL_PREFIX}/share/..., the prefix unknown
        text = text[1:]
    text = posixpath.normpath(text) if text else ""
    head = f"share/{name}"
    if text == head:
        return ""
    if text.startswith(head + "/"):
        return text[len(head) + 1:]
    return None


def _glob_regex(pattern: str) -> re.Pattern[str]:
    """CMake's ``PATTERN``: a glob matched against the end of the path, whole names only."""
    out = [{"*": "[^/]*", "?": "[^/]"}.get(char, re.escape(char)) for char in pattern]
    return re.compile("/" + "".join(out) + "$")


def _directory(folder: str, base: str, options: _Options,
               root: str) -> Iterator[tuple[str, str]]:
    """The files ``install(DIRECTORY folder ...)`` installs, under ``base``."""
    if not os.path.isdir(folder):
        return
    top = folder.count(os.sep)
    seen = 0
    for current, dirs, names in os.walk(folder):
        if current.count(os.sep) - top >= MAX_DEPTH:
            dirs[:] = []
        dirs[:] = sorted(d for d in dirs if not options.excluded(
            os.path.join(current, d).replace(os.sep, "/")))
        for name in sorted(names):
            seen += 1
            if seen > MAX_VISITED:
                return
            path = os.path.join(current, name)
            posix = path.replace(os.sep, "/")
            if options.excluded(posix) or (options.files_matching and
                                           not options.matched(posix)):
                continue
            real = os.path.realpath(path)
            if not real.startswith(root + os.sep) or not os.path.isfile(real):
                continue  # a link out of the package, or not a file
            relative = os.path.relpath(path, folder).replace(os.sep, "/")
            yield posixpath.normpath(posixpath.join(base, relative)), path


# -- ament_python setup.py ----------------------------------------------------------------
def _from_setup_py(package: Package, workspace: Workspace, path: str,
                   found: dict[str, str], environment: Mapping[str, str]) -> None:
    text, _ = read_text(path, workspace.location(path))
    if text is None:
        return
    try:
        tree = syntax.parse(text, path)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return  # pysetup reports it
    module = pysetup.setup_module(tree, package.root, environment)
    data_files: object = None
    for call in module.calls:
        for keyword in call.keywords:
            if keyword.arg == "data_files":
                data_files = module.value(keyword.value)
    if not isinstance(data_files, (list, tuple)):
        return
    root = os.path.realpath(package.root)
    for entry in data_files:
        if not (isinstance(entry, (list, tuple)) and len(entry) == 2
                and isinstance(entry[0], str) and isinstance(entry[1], (list, tuple))):
            continue  # a destination or a file list not known statically
        sub = _share_sub(entry[0], package.name)
        if sub is None:
            continue
        for item in entry[1]:
            if not isinstance(item, str) or len(found) >= MAX_FILES:
                continue
            source = os.path.normpath(os.path.join(package.root, item))
            real = os.path.realpath(source)
            if real.startswith(root + os.sep) and os.path.isfile(source):
                found[posixpath.normpath(posixpath.join(sub, os.path.basename(source)))] = source
