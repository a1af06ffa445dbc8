"""The shipped table of metapackages: what a binary install of one brings.

A package that depends on a metapackage (``gazebo_ros_pkgs``, ``navigation``,
``image_pipeline``) gets its members installed with it, though it does not name them;
``launch-undeclared-dependency`` must not say a launch file's use of ``gazebo_ros`` is
undeclared when its package depends on ``gazebo_ros_pkgs``. A metapackage of the
workspace is read from the workspace; those that come installed are this table.

``haros-arch models metapackages --sources DIR -o FILE`` reads the package.xml of every
package of the pinned trees of the models' lists (``sources.yaml``, ``interfaces.yaml``
and ``metapackages.yaml``, their ``with`` trees too) whose ``<export>`` says ``<metapackage/>``
(ROS 1), or whose folder holds nothing but its manifest, build file, papers and launch
files (ROS 2 has no such export), and writes each one's run dependencies per
distribution, with the
repositories and commits read. ``members`` answers from the shipped file.
"""

from __future__ import annotations

import functools
import json
import os
from collections.abc import Iterable
from typing import TYPE_CHECKING

from lxml import etree

from ..manifest import RUN_DEPEND_TAGS, xml_parser

if TYPE_CHECKING:
    from .generate import Entry

HERE = os.path.dirname(os.path.abspath(__file__))
TABLE = os.path.join(HERE, "metapackages.json")
LISTS = (os.path.join(HERE, "sources.yaml"), os.path.join(HERE, "interfaces.yaml"),
         os.path.join(HERE, "metapackages.yaml"))
FORMAT = 1
DISTROS = {1: "noetic", 2: "jazzy"}  # the distribution of each ROS generation's table


_PAPERS = (".md", ".rst", ".txt", ".xml")  # CMakeLists.txt, CHANGELOG.rst, README.md
# what else a metapackage's folder holds for its documentation: rosdoc2's configuration,
# a vcstool list of its repositories, a folder of documentation pages (ros2_control's
# and ros2_controllers' metapackages have all three)
_DOC_FILES = ("rosdoc2.yaml",)
_DOC_SUFFIXES = (".repos",)
_DOC_FOLDERS = ("doc", "docs")
# a package that only installs launch files builds nothing either: what a binary install
# of it brings is its run dependencies (jazzy's velodyne, which exec_depends
# velodyne_driver and velodyne_pointcloud; noetic's hector_geotiff_launch)
_LAUNCH_FOLDERS = ("launch",)


def _only_manifest(folder: str) -> bool:
    """A package folder that holds nothing but its manifest, build file, papers,
    documentation and a folder of launch files: a ROS 2 metapackage (navigation2,
    gazebo_ros_pkgs, image_pipeline, ros2_control), which has no ``<metapackage/>``
    export, or a package that builds nothing and brings its run dependencies (velodyne)."""
    try:
        entries = os.listdir(folder)
    except OSError:
        return False

    def paper(entry: str) -> bool:
        if entry.startswith("."):
            return True
        if os.path.isdir(os.path.join(folder, entry)):
            return entry in _DOC_FOLDERS + _LAUNCH_FOLDERS
        return entry.endswith(_PAPERS + _DOC_SUFFIXES) or entry in _DOC_FILES

    return all(paper(e) for e in entries)


# the CMake commands of a ROS 2 package that builds and installs nothing but its manifest
# (moveit2's ``moveit``: ``find_package(ament_cmake)`` and ``ament_package()``, beside a
# scripts/ folder of maintainer tools that nothing installs)
_NOTHING_BUILT = frozenset({"cmake_minimum_required", "project", "find_package",
                            "ament_package"})


def _builds_nothing(folder: str) -> bool:
    """A package folder whose CMakeLists.txt calls nothing but ``_NOTHING_BUILT`` (and no
    setup.py beside it): whatever else the folder holds is not installed, so a binary
    install of it brings its run dependencies, as a metapackage's."""
    from ..cmake.lexer import CMakeSyntaxError, tokenize

    if os.path.exists(os.path.join(folder, "setup.py")):
        return False
    try:
        with open(os.path.join(folder, "CMakeLists.txt"), encoding="utf-8") as handle:
            commands = tokenize(handle.read())
    except (OSError, UnicodeDecodeError, CMakeSyntaxError):
        return False
    names = {command.name for command in commands}
    return "ament_package" in names and names <= _NOTHING_BUILT


def _metapackage(path: str) -> tuple[str, list[str]] | None:
    """(name, run dependencies) of a metapackage's package.xml; None for a package."""
    try:
        root = etree.parse(path, xml_parser()).getroot()
    except (OSError, etree.XMLSyntaxError):
        return None
    export = root.find("export")
    if root.tag != "package":
        return None
    folder = os.path.dirname(path)
    if (export is None or export.find("metapackage") is None) and not _only_manifest(
        folder
    ) and not _builds_nothing(folder):
        return None
    name = (root.findtext("name") or "").strip()
    members = sorted({(e.text or "").strip() for tag in RUN_DEPEND_TAGS
                      for e in root.iter(tag)} - {""})
    return (name, members) if name else None


def collect(entries: Iterable[Entry], sources: str) -> dict[str, object]:
    """The table: per distribution, each metapackage of the trees and its members."""
    from .definitions import package_folders
    from .generate import folder_of

    table: dict[str, dict[str, list[str]]] = {}
    read: list[dict[str, str]] = []
    seen: set[tuple[str, str]] = set()
    for entry in entries:
        for repository, commit in [(entry.repository, entry.commit), *entry.context]:
            if (repository, commit) in seen:
                continue
            seen.add((repository, commit))
            tree = os.path.join(sources, folder_of(repository, commit))
            if not os.path.isdir(tree):
                continue
            found = False
            for folder in package_folders(tree).values():
                meta = _metapackage(os.path.join(folder, "package.xml"))
                if meta is not None:
                    table.setdefault(entry.distro, {})[meta[0]] = meta[1]
                    found = True
            if found:
                read.append({"repository": repository, "commit": commit,
                             "distro": entry.distro})
    return {"format": FORMAT, "sources": read,
            "metapackages": {d: dict(sorted(m.items())) for d, m in sorted(table.items())}}


def write(table: dict[str, object], path: str) -> None:
    with open(path, "w", encoding="utf-8") as handle:
        json.dump(table, handle, indent=1)
        handle.write("\n")


@functools.lru_cache(maxsize=1)
def _shipped() -> dict[str, dict[str, list[str]]]:
    try:
        with open(TABLE, encoding="utf-8") as handle:
            found = json.load(handle).get("metapackages")
    except (OSError, ValueError, AttributeError):
        return {}
    return found if isinstance(found, dict) else {}


def members(name: str, ros_version: int | None) -> list[str]:
    """The packages the installed metapackage ``name`` brings in the table of its ROS
    generation (both tables when the generation is not known); empty for another name."""
    tables = _shipped()
    distros = [DISTROS[ros_version]] if ros_version in DISTROS else list(DISTROS.values())
    found: list[str] = []
    for distro in distros:
        found += tables.get(distro, {}).get(name, [])
    return found
