"""The include folders a package's CMake files give inside the package.

The parse searches every workspace package's ``include`` folder and those one level down
(``headers.IncludeSetup``); a package that keeps its headers deeper names them in its
CMakeLists (zed_components: ``target_include_directories(zed_camera_component PUBLIC
${CMAKE_CURRENT_SOURCE_DIR}/src/zed_camera/include ...)``), and without them every class
of the package is unknown to the parse. Read as text, like the macros
(``build_macros``): ``include_directories`` and ``target_include_directories`` words that
are a folder of the package, relative or under the source folder variables (and
``${PROJECT_NAME}``, the package's name), or a folder of another workspace package's
exported ``include`` (``${champ_INCLUDE_DIRS}/champ/``). Not a folder
of a library the package builds with ``add_subdirectory`` (one with a CMakeLists.txt of
its own that calls ``project()``, slam_toolbox's ``lib/karto_sdk/include``), whose
headers the parse synthesises as those of a missing package (see
``headers._library_include_dirs``). A word that is a variable the package's CMake files
``set`` to one value, or to the same value wherever they set it, is that value (in turn,
a few levels): microstrain_mips' ``set(MIPLIBINC MIPSDK/C/Library/Include)`` then
``include_directories(include/${PROJECT_NAME} ${MIPLIBINC} ...)``, where the SDK's headers
are; and the words ``list(APPEND var ...)`` adds to it.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable

from ...cmake.commands import CATKIN_PACKAGE_KEYWORDS
from ...files import read_text
from ...workspace import Workspace
from .build_macros import cmake_files

_COMMAND = re.compile(r"^[ \t]*(include_directories|target_include_directories)\s*\(([^)]*)\)",
                      re.IGNORECASE | re.MULTILINE)
_CATKIN_PACKAGE = re.compile(r"^[ \t]*catkin_package\s*\(([^)]*)\)",
                            re.IGNORECASE | re.MULTILINE)
_COMMENT = re.compile(r"#[^\n]*")
_KEYWORDS = frozenset({"SYSTEM", "BEFORE", "AFTER", "PUBLIC", "PRIVATE", "INTERFACE"})
_BUILD_INTERFACE = re.compile(r"\$<BUILD_INTERFACE:([^>]*)>")
_SOURCE_DIR = "${CMAKE_CURRENT_SOURCE_DIR}"
_LIST_DIR = "${CMAKE_CURRENT_LIST_DIR}"
_ROOT_DIRS = ("${PROJECT_SOURCE_DIR}", "${CMAKE_SOURCE_DIR}")
_PROJECT = re.compile(r"^[ \t]*project\s*\(", re.IGNORECASE | re.MULTILINE)
_SET = re.compile(r"^[ \t]*(set\s*\(|list\s*\(\s*APPEND\s)\s*([A-Za-z_][A-Za-z0-9_]*)([^)]*)\)",
                  re.IGNORECASE | re.MULTILINE)
_VARIABLE = re.compile(r"\$\{([A-Za-z_][A-Za-z0-9_]*)\}")
MAX_EXPANSIONS = 4  # variables within variables
MAX_PROJECT_READ = 256 * 1024


def cmake_include_dirs(root: str, workspace: Workspace) -> list[str]:
    """The folders inside package ``root`` that its CMake files give as include
    folders, in the order first given (not the root itself, nor a folder of a
    sub-project the files do not own)."""
    root = os.path.abspath(root)
    found: list[str] = []
    # ament_package() and catkin_package() insist that the project is named as the
    # package: ``include/${PROJECT_NAME}`` (aerostack2's packages, whose sources include
    # their headers by file name) is the package's own folder
    package = workspace.package_of(root)
    project = package.name if package is not None and package.root == root and (
        package.build_type in ("ament_cmake", "catkin")) else None
    texts, variables = _cmake_texts(root, workspace)
    for path, text in texts:
        here = _source_dir(path, root)
        for match in _COMMAND.finditer(text):
            words = match.group(2).split()
            if match.group(1).lower() == "target_include_directories":
                words = words[1:]  # the target
            for written in words:
                for word in _expanded(written.strip("\"'"), variables):
                    if project is not None:
                        word = word.replace("${PROJECT_NAME}", project)
                    word, owner = _exported(word, workspace, root)
                    named = _folder(word, here, owner, os.path.dirname(path))
                    if named is not None and named not in found and _owned(named, owner):
                        found.append(named)
    return found


def _cmake_texts(root: str, workspace: Workspace
                 ) -> tuple[list[tuple[str, str]], dict[str, list[str]]]:
    """The CMake files of package ``root``, each with its text without comments, and
    the variables they set (``_variables``)."""
    texts: list[tuple[str, str]] = []
    for path in cmake_files(root):
        text, _ = read_text(path, workspace.location(path))
        texts.append((path, _COMMENT.sub("", text or "")))
    return texts, _variables(text for _, text in texts)


def exported_include_dirs(root: str, workspace: Workspace) -> list[str]:
    """The folders of package ``root`` that its ``catkin_package(INCLUDE_DIRS ...)``
    exports: what catkin puts in ``${catkin_INCLUDE_DIRS}`` of a package that finds it,
    whatever the folder is called (open_vins' ov_core exports ``src/``, where
    ``utils/opencv_yaml_parse.h`` is that ov_init and ov_msckf include)."""
    root = os.path.abspath(root)
    found: list[str] = []
    texts, variables = _cmake_texts(root, workspace)
    for path, text in texts:
        here = _source_dir(path, root)
        for match in _CATKIN_PACKAGE.finditer(text):
            taking = False
            for written in match.group(1).split():
                if written in CATKIN_PACKAGE_KEYWORDS:
                    taking = written == "INCLUDE_DIRS"
                    continue
                if not taking:
                    continue
                for word in _expanded(written.strip("\"'"), variables):
                    named = _folder(word, here, root, os.path.dirname(path))
                    if named is not None and named not in found and _owned(named, root):
                        found.append(named)
    return found


_EXPORTED = re.compile(r"^\$\{(\w+)_INCLUDE_DIRS?\}(?=/|$)")


def _exported(word: str, workspace: Workspace, root: str) -> tuple[str, str]:
    """``word`` with a leading ``${<pkg>_INCLUDE_DIRS}`` of a workspace package (what
    its ``find_package`` gives: the package's ``include`` folder, as ament and catkin
    export it) written as that folder, with the root of the package it is in (``root``
    for any other word): champ_base's ``${champ_INCLUDE_DIRS}/champ/``, where
    libchamp's headers include each other (``<geometry/geometry.h>``)."""
    found = _EXPORTED.match(word)
    package = workspace.packages.get(found.group(1)) if found is not None else None
    if found is None or package is None or not package.root:
        return word, root
    owner = os.path.abspath(package.root)
    return os.path.join(owner, "include") + word[found.end():], owner


def _variables(texts: Iterable[str]) -> dict[str, list[str]]:
    """The variables the CMake ``texts`` set to one value (its words), or to the same
    value each time, with the words ``list(APPEND name ...)`` adds after (quadruped-robot's
    ``includePath``, built up so and given to ``target_include_directories``: every
    word appended, under whatever ``if``); not those set to several values, nor a cache
    entry's default (``set(X value CACHE ...)``: the command line may give another)."""
    values: dict[str, list[str] | None] = {}
    for text in texts:
        for match in _SET.finditer(text):
            name, words = match.group(2), [w.strip("\"'") for w in match.group(3).split()]
            if match.group(1)[0] in "lL":  # ``list(APPEND name words...)``
                held = values.get(name, [])
                values[name] = None if held is None else [*held, *words]
                continue
            if "CACHE" in words:
                values[name] = None
                continue
            if words[-1:] == ["PARENT_SCOPE"]:
                words = words[:-1]
            if name in values and values[name] != words:
                values[name] = None
            else:
                values[name] = words
    return {name: words for name, words in values.items() if words}


def _expanded(word: str, variables: dict[str, list[str]], depth: int = 0) -> list[str]:
    """``word`` with each variable of ``variables`` it is wholly replaced by that
    variable's words, or with one it holds replaced by its one word; as written else."""
    whole = _VARIABLE.fullmatch(word)
    if depth >= MAX_EXPANSIONS or "$" not in word:
        return [word]
    if whole is not None and whole.group(1) in variables:
        return [w for value in variables[whole.group(1)]
                for w in _expanded(value, variables, depth + 1)]

    def one(found: re.Match[str]) -> str:
        value = variables.get(found.group(1))
        return value[0] if value is not None and len(value) == 1 else found.group(0)
    replaced = _VARIABLE.sub(one, word)
    return [word] if replaced == word else _expanded(replaced, variables, depth + 1)


def _source_dir(path: str, root: str) -> str:
    """The folder relative paths of CMake file ``path`` start from: its own for a
    CMakeLists.txt; for another file (``cmake/ROS1.cmake``, which a CMakeLists.txt
    includes) the nearest folder above it, up to ``root``, with a CMakeLists.txt, as
    CMake's current source folder stays the including file's (open_vins' ov_core
    gives ``include_directories(src)`` and ``catkin_package(INCLUDE_DIRS src/)`` in
    cmake/ROS1.cmake: ov_core/src)."""
    here = os.path.dirname(path)
    if os.path.basename(path) == "CMakeLists.txt":
        return here
    current = here
    while current == root or current.startswith(root + os.sep):
        if os.path.isfile(os.path.join(current, "CMakeLists.txt")):
            return current
        current = os.path.dirname(current)
    return here


def _folder(word: str, here: str, root: str, listed: str | None = None) -> str | None:
    """The folder ``word`` names, written in a CMake file whose current source folder is
    ``here`` (and its own folder ``listed``, ``${CMAKE_CURRENT_LIST_DIR}``), or None (a
    keyword, another variable, a folder outside the package or not there)."""
    inner = _BUILD_INTERFACE.fullmatch(word)
    if inner is not None:
        word = inner.group(1)
    if not word or word.upper() in _KEYWORDS:
        return None
    if word.startswith(_SOURCE_DIR):
        word = here + word[len(_SOURCE_DIR):]
    if word.startswith(_LIST_DIR):
        word = (listed or here) + word[len(_LIST_DIR):]
    for variable in _ROOT_DIRS:
        if word.startswith(variable):
            word = root + word[len(variable):]
    if "$" in word:
        return None
    folder = os.path.normpath(os.path.join(here, word))
    if folder == root or not folder.startswith(root + os.sep) or os.path.islink(folder) \
            or not os.path.isdir(folder):
        return None
    return folder


def own_folder(folder: str, workspace: Workspace) -> bool:
    """Whether ``folder`` is a folder (not a link) of a workspace package's own CMake
    project (``_owned``), the package's root among them: the build's include folders
    may name it (hebi_cpp_api_examples' ``include_directories(. ${catkin_INCLUDE_DIRS})``
    with ``#include "src/util/odom_publisher.hpp"``, the class that publishes a base's
    odometry, in its nodes' sources)."""
    package = workspace.package_of(folder)
    if package is None or not package.root or os.path.islink(folder) \
            or not os.path.isdir(folder):
        return False
    root = os.path.abspath(package.root)
    return folder == root or _owned(folder, root)


def shared_folder(folder: str, workspace: Workspace) -> bool:
    """Whether ``folder`` is a folder (not a link) that no package holds, of the workspace
    or of the workspace folder above its ``src/`` (not the build's ``build``,
    ``install``, ``devel``, ``log``): code several packages of a repository build from one
    tree outside them, which a package's CMake names by a path up from its own folder
    (hexapod-ros2-control's ``set(FW_SRC ${CMAKE_CURRENT_SOURCE_DIR}/../../shared/
    motion_core)``, the firmware's control code the bridge node compiles, with
    ``target_include_directories(firmware_bridge_node PRIVATE ${FW_SRC})``: its headers
    were missing and the node partial). Never a folder elsewhere (an installed library's,
    whose headers the stand-ins are)."""
    folder = os.path.abspath(folder)
    if workspace.package_of(folder) is not None or os.path.islink(folder) \
            or not os.path.isdir(folder):
        return False
    if workspace.holds(folder):
        return True
    for top in workspace.folders:
        top = os.path.abspath(top)
        if os.path.basename(top) != "src":
            continue
        above = os.path.dirname(top)
        inside = os.path.relpath(folder, above).split(os.sep)
        if inside[0] not in (os.pardir, os.curdir) and inside[0] not in _BUILD_FOLDERS:
            return True
    return False


_BUILD_FOLDERS = frozenset({"build", "install", "devel", "log"})


def in_own_project(path: str, root: str) -> bool:
    """Whether the file or folder ``path`` of the package at ``root`` belongs to the
    package's own CMake project (``_owned``), not to a sub-project it vendors (ouster-ros'
    ``ouster-sdk``, a ``project()`` of its own)."""
    path = os.path.abspath(path)
    return _owned(path if os.path.isdir(path) else os.path.dirname(path), os.path.abspath(root))


def _owned(folder: str, root: str) -> bool:
    """Whether ``folder`` belongs to the package's own CMake project: no folder between
    the package root and it (itself included) is another project, one whose
    CMakeLists.txt calls ``project()`` (even when that project's own files give it)."""
    current = folder
    while current.startswith(root + os.sep):
        if _is_project(os.path.join(current, "CMakeLists.txt")):
            return False
        current = os.path.dirname(current)
    return True


def _is_project(path: str) -> bool:
    if not os.path.isfile(path):
        return False
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            text = handle.read(MAX_PROJECT_READ)
    except OSError:
        return False
    return _PROJECT.search(_COMMENT.sub("", text)) is not None
