"""The ROS 2 distribution a workspace's own files say it is built for, when nothing else
says (no project ``distro:``, no ROS_DISTRO): the distribution decides which interface
models stand for the installed packages its launch files start (Humble's nav2 exports
``nav2_navfn_planner/NavfnPlanner``, Jazzy's only ``nav2_navfn_planner::NavfnPlanner``;
Humble's joint_trajectory_controller reads ``state_publish_rate``, Jazzy's does not) and
which rclcpp the C++ sources are read against.

Package manifests never name one. What does, strongest first: the git branch a checkout
is on (``humble``, ``ros2-humble``, ``jazzy-devel``); the build and CI files
(Dockerfiles, ``.github`` workflows, ``.repos`` files, devcontainers: ``ROS_DISTRO:
humble``, ``FROM ros:humble``); the README's ``ROS 2 Humble``. The first of these that
names a ROS 2 distribution decides: the default (Jazzy) when it is among those named
(the tree is built for it too), else Humble (the other release whose models ship), else
Iron (which takes Jazzy's); a tree that names only older releases (Dashing to
Galactic) is read with Humble's models, the nearest release after them, and only newer
ones (Kilted, Rolling) keeps the default: a guess should not make every modelled node
partial, as a release without models of its own would. The rclcpp the C++ sources are
read against is the guess's only when the files name that one release.
Only files, never a command: the branch is read from ``.git/HEAD``. Bounded: folders
four levels down, a few thousand entries, files of at most 256 KiB.
"""

from __future__ import annotations

import functools
import os
import re
from collections import Counter
from collections.abc import Mapping
from typing import TYPE_CHECKING

from .files import read_text
from .model.location import NOWHERE

if TYPE_CHECKING:
    from .project import Project

ROS2 = ("dashing", "eloquent", "foxy", "galactic", "humble", "iron", "jazzy", "kilted",
        "rolling")
# the releases a guess may choose, in order: the default, the other release whose
# interface models ship, and one that takes the default's models as its own
MODELLED = ("jazzy", "humble", "iron")
# the releases before the oldest whose models ship, read with Humble's (``_choose``)
OLDER = ("dashing", "eloquent", "foxy", "galactic")
MAX_DEPTH = 4
MAX_ENTRIES = 5_000
MAX_READ = 256 * 1024
_WORD = re.compile(r"(?<![A-Za-z0-9])(" + "|".join(ROS2) + r")(?![A-Za-z])", re.I)
_README = re.compile(r"\bROS\s*2?\s*[-:]?\s*(" + "|".join(ROS2) + r")\b", re.I)
_HIDDEN_KEPT = frozenset({".github", ".devcontainer", ".gitlab", ".circleci", "workflows"})
_SKIPPED = frozenset({"build", "install", "log", "devel", "node_modules", "__pycache__"})


def guessed_distro(project: Project, env: Mapping[str, str]) -> tuple[str, str] | None:
    """The ROS 2 distribution the workspace's own files name, with why, when neither the
    project file's ``distro:`` nor a ROS_DISTRO (the run's, a configuration's) says
    one; read once per set of workspace folders in a process. For interface models."""
    found = _said_for(project, env)
    return None if found is None else (found[0], found[1])


def sole_distro(project: Project, env: Mapping[str, str]) -> str | None:
    """The same, only when the files name that one ROS 2 release and no other: the
    rclcpp the C++ sources are read against. A tree built for several (navigation2's CI
    names Rolling, Kilted, Jazzy and Humble) keeps its version tests undecided
    (``CPP_VERSION_UNKNOWN``) rather than read as the release the models take."""
    found = _said_for(project, env)
    return found[0] if found is not None and found[2] else None


def _said_for(project: Project, env: Mapping[str, str]) -> tuple[str, str, bool] | None:
    if project.distro or env.get("ROS_DISTRO") or any(
            spec.environment.get("ROS_DISTRO") for spec in project.configurations):
        return None
    return _guess(tuple(os.path.abspath(root) for root in project.workspace))


@functools.lru_cache(maxsize=8)
def _guess(roots: tuple[str, ...]) -> tuple[str, str, bool] | None:
    return guess(list(roots))


def guess(roots: list[str]) -> tuple[str, str, bool] | None:
    """(distribution, why, whether it is the one release named) for ROS 2, or None when
    the files name none with models of its own."""
    for level, names in (("its git branch", _branches(roots)), *_files(roots)):
        if names:
            chosen = _choose(names)
            if chosen is None:
                return None  # names only releases without models of their own
            why = f"guessed from {level}, which name {_said(names)}"
            if chosen not in names:
                why += (f"; read with {chosen}'s interface models, the nearest release "
                        "after those whose models ship")
            # the rclcpp of a release the files do not name is no reading of its code
            return (chosen, why, len(names) == 1 and chosen in names)
    return None


def _choose(names: Counter[str]) -> str | None:
    """The release to read the tree as, of those named: only one whose interface models
    ship (or that takes another's as its own: iron), as a guess should not make every
    modelled node partial (an end-of-life or rolling release takes a nearer release's
    models as stand-ins, each node that takes one partial: a ``distro:`` says so). A
    tree that names only releases older than Humble (Dashing to Galactic) is read with
    Humble's models, the nearest after them: Foxy's and Galactic's nav2 export
    ``nav2_navfn_planner/NavfnPlanner`` and their bt_navigator reads
    ``default_bt_xml_filename``, as Humble's do and Jazzy's do not; a tree that names
    only newer ones (Kilted, Rolling) keeps the default, the nearest before them."""
    for name in MODELLED:
        if name in names:
            return name
    if any(name in names for name in OLDER):
        return "humble"
    return None


def _said(names: Counter[str]) -> str:
    return ", ".join(f"{name} ({count}x)" if count > 1 else name
                     for name, count in names.most_common(4))


def _branches(roots: list[str]) -> Counter[str]:
    """The distributions the branch names of the checkouts around ``roots`` name: a
    root's own, its parents' up to three levels, and the repositories two levels
    below it (a workspace's ``src/<repo>``)."""
    found: Counter[str] = Counter()
    seen: set[str] = set()
    for root in roots:
        root = os.path.abspath(root)
        places = [root]
        parent = root
        for _ in range(3):
            parent = os.path.dirname(parent)
            places.append(parent)
        for child in _children(root, 2):
            places.append(child)
        for place in places:
            if place in seen:
                continue
            seen.add(place)
            branch = _branch(place)
            if branch is not None:
                found.update(m.group(1).lower() for m in _WORD.finditer(branch))
    return found


def _children(root: str, depth: int) -> list[str]:
    out: list[str] = []
    level = [root]
    for _ in range(depth):
        below: list[str] = []
        for folder in level:
            try:
                entries = sorted(os.scandir(folder), key=lambda e: e.name)
            except OSError:
                continue
            for entry in entries[:200]:
                if entry.is_dir(follow_symlinks=False) and not entry.name.startswith(".") \
                        and entry.name not in _SKIPPED:
                    below.append(entry.path)
        out.extend(below)
        level = below
    return out


def _branch(folder: str) -> str | None:
    """The branch ``folder``'s git checkout is on (``.git/HEAD``, or the HEAD of the
    folder a ``.git`` file points to: a worktree, a submodule), None when it has none or
    is detached."""
    git = os.path.join(folder, ".git")
    head = os.path.join(git, "HEAD")
    if os.path.isfile(git):
        text = _read(git, 4096)
        if text is None or not text.startswith("gitdir:"):
            return None
        target = text[len("gitdir:"):].strip()
        head = os.path.join(folder, target, "HEAD") if not os.path.isabs(target) else (
            os.path.join(target, "HEAD"))
    text = _read(head, 4096)
    if text is None or not text.startswith("ref:"):
        return None
    return text[len("ref:"):].strip().removeprefix("refs/heads/")


def _places(roots: list[str]) -> list[tuple[str, str | None]]:
    """The folders whose files are read, each with the folder below it already read
    (None): the roots, and the workspace above a root that is its ``src/`` folder,
    whose Dockerfile and CI files the repository keeps beside ``src/``
    (control_quadrupeds_soft_contacts' ``FROM osrf/ros:${BASE_TAG}`` of
    ``ARG BASE_TAG=iron-desktop``, the workspace chosen being ``src/``)."""
    places: list[tuple[str, str | None]] = [(os.path.abspath(r), None) for r in roots]
    for root, _ in list(places):
        parent = os.path.dirname(root)
        if os.path.basename(root) == "src" and parent != root and all(
                parent != place for place, _ in places):
            places.append((parent, root))
    return places


def _files(roots: list[str]) -> list[tuple[str, Counter[str]]]:
    """The distributions the build and CI files, then the READMEs, under ``roots``
    (and the workspace folder above a ``src/`` root: ``_places``) name, with the file
    each was first seen in."""
    build: Counter[str] = Counter()
    readme: Counter[str] = Counter()
    first: dict[str, str] = {}
    entries = 0
    for root, done in _places(roots):
        for top, folders, files in os.walk(root):
            depth = os.path.relpath(top, root).count(os.sep)
            folders[:] = sorted(f for f in folders if f not in _SKIPPED and (
                not f.startswith(".") or f in _HIDDEN_KEPT) and depth < MAX_DEPTH
                and os.path.join(top, f) != done)
            entries += len(files) + len(folders)
            if entries > MAX_ENTRIES:
                break
            for name in sorted(files):
                kind = _kind(top, name)
                if kind is None:
                    continue
                text = _read(os.path.join(top, name), MAX_READ)
                if text is None:
                    continue
                pattern, counter = (_WORD, build) if kind == "build" else (_README, readme)
                named = [m.group(1).lower() for m in pattern.finditer(text)]
                if named and kind not in first:
                    first[kind] = os.path.relpath(os.path.join(top, name), root)
                counter.update(named)
    return [(f"its build and CI files ({first.get('build', '')} ...)", build),
            (f"its README ({first.get('readme', '')})", readme)]


# the configuration of Mergify, a bot that copies merged changes to other branches: the
# releases it names (``backport to jazzy``, ``branches: [humble]``) are those the tree's
# changes are copied to, not the one it is built for (pb2025_sentry_nav: a humble
# Dockerfile and CI, a mergify.yml backporting to jazzy and humble)
_BACKPORT_CONFIGS = frozenset({"mergify.yml", "mergify.yaml", ".mergify.yml",
                               ".mergify.yaml"})


def _kind(folder: str, name: str) -> str | None:
    low = name.lower()
    parts = set(folder.replace("\\", "/").split("/"))
    if low in _BACKPORT_CONFIGS:
        return None
    if (low.startswith("dockerfile") or low.endswith((".dockerfile", ".repos"))
            or low in (".gitlab-ci.yml", ".travis.yml", "docker-compose.yml",
                       "docker-compose.yaml")
            or (".github" in parts and low.endswith((".yml", ".yaml")))
            or ".devcontainer" in parts):
        return "build"
    if low.startswith("readme"):
        return "readme"
    return None


def _read(path: str, limit: int) -> str | None:
    """The text of ``path`` as every reader of the project has it (``files.read_text``:
    regular files only, a FIFO or device never opened), None when it cannot be read or
    is over ``limit`` bytes."""
    return read_text(path, NOWHERE, limit)[0]
