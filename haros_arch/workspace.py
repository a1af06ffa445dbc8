"""Find the packages of a workspace, and the installed ones that ``$(find)`` can see."""

from __future__ import annotations

import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from lxml import etree

from . import diagnostics as diag
from .diagnostics import Diagnostic
from .facts import KeptFacts
from .files import read_bytes
from .manifest import parse_manifest, xml_parser
from .model.location import Location
from .model.source import Package

IGNORE_MARKERS = ("CATKIN_IGNORE", "COLCON_IGNORE", "AMENT_IGNORE")
SKIP_FOLDERS = frozenset({"build", "devel", "install", "log", "node_modules", "__pycache__"})
MAX_DEPTH = 12
MAX_PATH_FOLDERS = 50_000  # folders listed when indexing ROS_PACKAGE_PATH
MAX_NEAR = 3  # package names a "did you mean" offers at most
MAX_REMEMBERED_PATHS = 200_000  # relpath's answers kept per workspace


@dataclass
class Workspace:
    """The packages found under ``root`` (the first workspace folder) and beyond."""

    root: str
    roots: list[str] = field(default_factory=list)
    packages: dict[str, Package] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    environment: Mapping[str, str] = field(default_factory=dict)
    # the ROS distribution the sources are read for (``pipeline.source_distro``: the
    # rclcpp / roscpp the C++ stand-ins announce), which the CMake reading takes
    # ``rclcpp_VERSION`` / ``roscpp_VERSION`` from; None when not known
    source_distro: str | None = None
    _installed: dict[str, str | None] = field(default_factory=dict)
    _path_index: dict[str, str] | None = field(default=None, repr=False)
    # the names of the packages installed here, for ``misspelt``: filled when first asked
    _known_names: list[str] | None = field(default=None, repr=False)
    # package name -> {share-relative path: source file}, filled by haros_arch.share
    share_maps: dict[str, dict[str, str]] = field(default_factory=dict, repr=False)
    # package name -> {share-relative path (a folder ends in "/"): (CMake file, line) of
    # the rule installing it from the build folder}, filled by haros_arch.share
    generated_shares: dict[str, dict[str, tuple[str, int]]] = field(
        default_factory=dict, repr=False)
    # package name -> executables colcon installs in lib/<pkg>, filled by haros_arch.share
    lib_executables: dict[str, frozenset[str]] = field(default_factory=dict, repr=False)
    # package folder -> package, for package_of; rebuilt when the packages change
    _index: dict[str, Package] = field(default_factory=dict, repr=False)
    _index_key: tuple[int, int] = field(default=(0, -1), repr=False)
    _relpaths: dict[tuple[str, str], str] = field(default_factory=dict, repr=False)
    _prefixes_key: tuple[str, tuple[str, ...]] | None = field(default=None, repr=False)
    _prefixes_of: tuple[str, ...] = field(default=(), repr=False)
    # source file -> the words it and the package headers it includes hold
    # (``plugins.classes.named_words``: each executable linking a library asks them
    # again), read once per run
    # (each of these memos keeps the files read to make an entry: ``files.kept_in``)
    named_words: dict[str, object] = field(default_factory=dict, repr=False)
    # what the build-file stage reads off a file, by kind and path
    # (``plugins.classes.remembered``), once per run
    file_facts: dict[tuple[str, str], object] = field(default_factory=dict, repr=False)
    # those an earlier run read off files unchanged since, and this run's, for the next
    # (``facts.KeptFacts``; None: none kept)
    kept_facts: KeptFacts | None = field(default=None, repr=False)
    # (package name, folder) -> its CMake interpreter and diagnostics
    # (``cmake._interpret``): a package whose libraries others link is read once
    interpreted: dict[tuple[str, str], object] = field(default_factory=dict, repr=False)
    # package name -> (its ignore marker, its folder): a package under a folder with an
    # IGNORE_MARKERS file, left out as colcon and catkin leave it out, kept to say why
    ignored: dict[str, tuple[str, str]] = field(default_factory=dict, repr=False)
    # folder -> the submodules its .gitmodules declares, (absolute path, line), read once
    _gitmodules: dict[str, list[tuple[str, int]]] = field(default_factory=dict, repr=False)

    @property
    def folders(self) -> list[str]:
        """The workspace folders: the project's (``roots``), else ``root``."""
        return self.roots or [self.root]

    def holds(self, path: str) -> bool:
        """Whether absolute ``path`` lies below one of the workspace folders (its path,
        as written: not its target when it is a link). Every folder counts, not the
        first only: a project of several trees (``workspace: [a, b]``) reads b's
        headers and sources as its own, as it reads a's."""
        return path.startswith(self._prefixes())

    def _prefixes(self) -> tuple[str, ...]:
        key = (self.root, tuple(self.roots))
        if self._prefixes_key != key:
            self._prefixes_of = tuple(
                os.path.abspath(folder).rstrip(os.sep) + os.sep for folder in self.folders)
            self._prefixes_key = key
        return self._prefixes_of

    def relpath(self, path: str) -> str:
        """A path relative to the workspace root when inside it, else absolute (asked
        for every include of every unit: remembered per root and path)."""
        known = self._relpaths.get((self.root, path))
        if known is not None:
            return known
        full = os.path.abspath(path)
        top = os.path.abspath(self.root)
        if full == top:
            rel = "."
        elif full.startswith(top.rstrip(os.sep) + os.sep):
            rel = full[len(top.rstrip(os.sep)) + 1:]
        else:
            rel = full
        if path.startswith(os.sep) and len(self._relpaths) < MAX_REMEMBERED_PATHS:
            self._relpaths[(self.root, path)] = rel  # a relative one depends on the cwd
        return rel

    def __getstate__(self) -> dict[str, object]:
        state = dict(self.__dict__)
        state["_relpaths"] = {}  # not sent to worker processes
        state["named_words"] = {}
        state["interpreted"] = {}
        state["file_facts"] = {}
        state["kept_facts"] = None
        return state

    def package_of(self, path: str) -> Package | None:
        """The workspace package whose folder holds ``path`` (the innermost one): the
        path's folders looked up from the deepest, in an index of package folders."""
        index = self._roots_index()
        here = os.path.abspath(path)
        while True:
            found = index.get(here)
            if found is not None:
                return found
            parent = os.path.dirname(here)
            if parent == here:
                return None
            here = parent

    def _roots_index(self) -> dict[str, Package]:
        # packages are added (by the scan, by models), never moved: their number tells
        key = (id(self.packages), len(self.packages))
        if self._index_key != key:
            self._index = {package.root: package for package in self.packages.values()
                           if package.root}
            self._index_key = key
        return self._index

    def location(self, path: str, line: int = 0, column: int = 0) -> Location:
        package = self.package_of(path)
        return Location(package.name if package else None, self.relpath(path), line, column)

    def readable(self, path: str, environment: Mapping[str, str] | None = None) -> bool:
        """Whether the analysis may read ``path``: it lies (after resolving links) in a
        workspace folder, in a workspace package (which may be a link to a checkout kept
        elsewhere) or in an installed package's prefix; never anywhere else on disk."""
        real = os.path.realpath(path)
        env = self.environment if environment is None else environment
        roots = [*self.roots, self.root, *installed_roots(env),
                 *(package.root for package in self.packages.values())]
        for root in roots:
            if not root:
                continue
            top = os.path.realpath(root)
            if real == top or real.startswith(top.rstrip(os.sep) + os.sep):
                return True
        return False

    def find(self, name: str) -> str | None:
        """Absolute folder of package ``name``, in the workspace or installed."""
        if name in self.packages:
            return self.packages[name].root
        if name not in self._installed:
            if self._path_index is None:
                self._path_index = package_path_index(self.environment)
            self._installed[name] = _find_installed(name, self.environment,
                                                    self._path_index)
        return self._installed[name]

    def submodule_of(self, path: str) -> tuple[str, str] | None:
        """The git submodule ``path`` lies in when that submodule is not checked out
        here (its folder missing or empty, as ``git clone`` without ``--recursive``
        leaves it): its folder and the ``.gitmodules`` line declaring it, both relative
        to the workspace; None otherwise. ``.gitmodules`` files are looked for in the
        folders from ``path`` up to the workspace's roots (microstrain_inertial's
        driver launch files read ``microstrain_inertial_driver_common/config/params.yml``
        from such a submodule: not a missing file, a file not here)."""
        real = os.path.abspath(path)
        tops = [os.path.abspath(r) for r in (self.roots or [self.root]) if r]
        folder = os.path.dirname(real)
        while True:
            for sub, line in self._submodules(folder):
                if (real == sub or real.startswith(sub + os.sep)) and not _has_entries(sub):
                    where = os.path.join(folder, ".gitmodules")
                    return self.relpath(sub), f"{self.relpath(where)}:{line}"
            if any(folder == top for top in tops) or not any(
                    folder.startswith(top + os.sep) for top in tops):
                return None
            parent = os.path.dirname(folder)
            if parent == folder:
                return None
            folder = parent

    def submodule_note(self, path: str) -> str | None:
        """What a launch diagnostic says of ``path`` when it lies in a git submodule not
        checked out here (``submodule_of``); None when it does not."""
        sub = self.submodule_of(path)
        if sub is None:
            return None
        folder, declared = sub
        return (f"{self.relpath(path)} lies in the git submodule {folder} (declared at "
                f"{declared}), which is not checked out here (git submodule update "
                "--init); it is not read")

    def _submodules(self, folder: str) -> list[tuple[str, int]]:
        found = self._gitmodules.get(folder)
        if found is None:
            found = []
            listed = os.path.join(folder, ".gitmodules")
            data = read_bytes(listed, self.location(listed), MAX_GITMODULES)[0] if (
                os.path.isfile(listed)) else None
            for number, text in enumerate((data or b"").decode("utf-8", "replace")
                                          .splitlines(), start=1):
                match = _GITMODULE_PATH.match(text)
                if match:
                    found.append((os.path.normpath(os.path.join(folder, match.group(1))),
                                  number))
            self._gitmodules[folder] = found
        return found

    def absence(self, name: str) -> str:
        """Why ``find(name)`` found nothing, the rest of a sentence "package NAME ...":
        a package of the workspace left out by its ignore marker (named, the place to
        look) is not just missing; a name a letter or two from a package's that is here
        says which (``misspelt``)."""
        ignored = self.ignored.get(name)
        if ignored is None and not PACKAGE_NAME.match(name):
            return (f"(written {name!r}) is no name a package can have: catkin_pkg refuses "
                    "it, so no workspace or install holds it")
        if ignored is None:
            near = self.misspelt(name)
            hint = f" (did you mean {' or '.join(near)}?)" if near else ""
            return "is not in the workspace nor installed here" + hint
        marker, folder = ignored
        return (f"is in the workspace ({self.relpath(folder)}) but ignored: "
                f"{self.relpath(marker)} keeps colcon and catkin out of that folder")


    def surely_absent(self, name: str) -> bool:
        """Whether ``name``, a package ``find`` does not find, cannot be installed on the
        robot either: no name a package can have (``PACKAGE_NAME``: empty, blanks, a
        `/`), or most likely a package's here misspelt (``misspelt``)."""
        return self.find(name) is None and (
            not PACKAGE_NAME.match(name) or bool(self.misspelt(name)))

    def misspelt(self, name: str) -> list[str]:
        """The names of the packages here (in the workspace, on ROS_PACKAGE_PATH, in an
        ament index) nearest to ``name``, a package ``find`` does not find, when they are
        close enough that ``name`` is most likely one of them misspelt: at most one edit
        per four letters and never more than two (``query.absence.distance``, the
        similar-name rule's measure); none when nothing is that close."""
        if not name or self.find(name) is not None:
            return []
        from .query.absence import MAX_DISTANCE, distance, masks
        limit = min(MAX_DISTANCE, len(name) // 4)
        if limit < 1:
            return []
        if self._known_names is None:
            if self._path_index is None:
                self._path_index = package_path_index(self.environment)
            self._known_names = [*self._path_index, *ament_index_packages(self.environment)]
        pattern = masks(name)
        scored = [(distance(name, other, pattern), other)
                  for other in sorted({*self.packages, *self._known_names})
                  if abs(len(other) - len(name)) <= limit]
        best = min((score for score, _other in scored), default=limit + 1)
        return [other for score, other in scored if score == best <= limit][:MAX_NEAR]


# a name a package can have: catkin_pkg refuses any other (upper case and dashes only warned
# of), and colcon, catkin and ament build none
PACKAGE_NAME = re.compile(r"[a-zA-Z0-9][a-zA-Z0-9_-]*\Z")

# a submodule's ``path = <folder>`` line of a .gitmodules file (git's config syntax)
_GITMODULE_PATH = re.compile(r"^\s*path\s*=\s*(\S(?:.*\S)?)\s*$")
MAX_GITMODULES = 1 << 20


def _has_entries(folder: str) -> bool:
    try:
        with os.scandir(folder) as entries:
            return any(True for _ in entries)
    except OSError:
        return False


def ament_index_packages(env: Mapping[str, str]) -> list[str]:
    """The packages the ament index of each prefix on AMENT_PREFIX_PATH registers (the
    file names in ``share/ament_index/resource_index/packages``), as ros2 lists them."""
    names: list[str] = []
    for prefix in env.get("AMENT_PREFIX_PATH", "").split(os.pathsep):
        folder = os.path.join(prefix, "share", "ament_index", "resource_index", "packages")
        if prefix and os.path.isdir(folder):
            try:
                names.extend(n for n in os.listdir(folder) if not n.startswith("."))
            except OSError:
                continue
    return names


def scan(roots: Iterable[str], environment: Mapping[str, str] | None = None) -> Workspace:
    """Find every package under ``roots``. Problems become diagnostics, never exceptions."""
    env = dict(os.environ if environment is None else environment)
    roots = [os.path.abspath(r) for r in roots]
    ws = Workspace(root=roots[0] if roots else os.getcwd(), roots=roots, environment=env)
    seen: set[str] = set()
    skipped: list[tuple[str, str]] = []
    variants: list[tuple[str, list[str]]] = []
    for top in roots:
        if not os.path.isdir(top):
            ws.diagnostics.append(diag.make("WORKSPACE_MISSING", Location(file=top), path=top))
            continue
        for folder in _package_folders(top, skipped=skipped, variants=variants):
            real = os.path.realpath(folder)
            if real in seen:
                continue
            seen.add(real)
            manifest = manifest_of(folder)
            where = Location(None, ws.relpath(manifest))
            nothing: tuple[Package | None, list[Diagnostic]] = (None, [])
            package, found = diag.per_file(
                where, ws.relpath(manifest), ws.diagnostics,
                lambda: parse_manifest(manifest, where, ws.relpath(folder), env),  # noqa: B023
                nothing)
            ws.diagnostics.extend(found)
            if package is None:
                continue
            package.root = folder
            if package.name in ws.packages:
                other = ws.packages[package.name]
                ws.diagnostics.append(diag.make(
                    "PACKAGE_DUPLICATE", package.location, name=package.name,
                    other=other.location.file))
                continue
            if package.build_type == "catkin" and not os.path.exists(
                os.path.join(folder, "CMakeLists.txt")
            ) and os.path.exists(os.path.join(folder, "setup.py")):
                package.build_type = "ament_python"
            if package.builds_by_version:
                ws.diagnostics.append(diag.make(
                    "PACKAGE_BUILD_BY_ROS_VERSION",
                    Location(package.name, where.file, package.builds_at),
                    name=package.name, builds=", ".join(
                        f"{kind} for ROS {version}"
                        for version, kind in sorted(package.builds_by_version.items()))))
            ws.packages[package.name] = package
    for folder, names in variants:
        ws.diagnostics.append(diag.make(
            "PACKAGE_MANIFEST_VARIANT", Location(file=ws.relpath(os.path.join(folder, names[0]))),
            folder=ws.relpath(folder) or ".", names=", ".join(names)))
    _note_ignored(ws, skipped)
    return ws


def _note_ignored(ws: Workspace, skipped: list[tuple[str, str]]) -> None:
    """Record the packages under the folders their ``(folder, marker)`` left out (the
    outermost marker names them all), not those the workspace has elsewhere."""
    budget = [MAX_PATH_FOLDERS]
    for top, marker in skipped:
        for folder in _package_folders(top, (), budget=budget):
            name = _package_name(folder)
            if name is not None and name not in ws.packages:
                ws.ignored.setdefault(name, (os.path.join(top, marker), folder))


def _package_folders(top: str, ignore: tuple[str, ...] = IGNORE_MARKERS,
                     skip: frozenset[str] = SKIP_FOLDERS,
                     budget: list[int] | None = None,
                     skipped: list[tuple[str, str]] | None = None,
                     variants: list[tuple[str, list[str]]] | None = None) -> Iterable[str]:
    """Folders holding a package.xml or a rosbuild manifest.xml, honouring the ``ignore``
    markers (each folder one leaves out added to ``skipped`` with its marker) and
    leaving out the ``skip`` folders; packages do not nest. A folder with manifests
    under other names only (livox_ros_driver2's package_ROS1.xml and package_ROS2.xml,
    one of which its build.sh copies to package.xml) is no package: added to
    ``variants`` with their names.

    Symbolic links to folders are followed, as catkin, colcon and rospkg do (a
    workspace's src/ often links checkouts kept elsewhere); each real folder is visited
    once, so a link cycle ends the walk there, and a link to the folder itself or to one
    above it (``/``, ``..``) is not followed. ``budget`` (one count, shared by several
    walks) bounds how many folders are listed.
    """
    stack = [(top, 0)]
    visited: set[str] = set()
    while stack:
        folder, depth = stack.pop()
        real = os.path.realpath(folder)
        if real in visited:
            continue
        visited.add(real)
        if budget is not None:
            if budget[0] <= 0:
                return
            budget[0] -= 1
        try:
            entries = sorted(os.listdir(folder))
        except OSError:
            continue
        marker = next((m for m in ignore if m in entries), None)
        if marker is not None:
            if skipped is not None:
                skipped.append((folder, marker))
            continue
        if "package.xml" in entries or "manifest.xml" in entries:
            yield folder
            continue
        if variants is not None and (found := manifest_variants(folder, entries)):
            variants.append((folder, found))
        if depth >= MAX_DEPTH or "rospack_nosubdirs" in entries:
            continue
        for entry in reversed(entries):
            path = os.path.join(folder, entry)
            if entry.startswith(".") or entry in skip:
                continue
            if os.path.islink(path) and _is_ancestor(os.path.realpath(path), real):
                continue  # a link to "/" or to a folder above would walk it all again
            if os.path.isdir(path):
                stack.append((path, depth + 1))


# a package manifest under another name, one a build chooses from (``package_ROS2.xml``)
_MANIFEST_VARIANT = re.compile(r"package[_.-]\w+\.xml")


def manifest_variants(folder: str, entries: Iterable[str] | None = None) -> list[str]:
    """The names of the package manifests under other names than package.xml that
    ``folder`` holds (``entries``: its listing, when made already), in order; none when
    it cannot be listed."""
    if entries is None:
        try:
            entries = sorted(os.listdir(folder))
        except OSError:
            return []
    return [e for e in entries if _MANIFEST_VARIANT.fullmatch(e)
            and os.path.isfile(os.path.join(folder, e))]


def _is_ancestor(target: str, real: str) -> bool:
    """``target`` is ``real`` or a folder above it (both real paths)."""
    return real == target or real.startswith(target.rstrip(os.sep) + os.sep)


def manifest_of(folder: str) -> str:
    """The manifest that makes ``folder`` a package: package.xml, else manifest.xml."""
    xml = os.path.join(folder, "package.xml")
    return xml if os.path.exists(xml) else os.path.join(folder, "manifest.xml")


def installed_roots(env: Mapping[str, str]) -> list[str]:
    """Folders where installed packages live, as roslaunch and ros2 would look."""
    roots: list[str] = []
    for entry in env.get("ROS_PACKAGE_PATH", "").split(os.pathsep):
        if entry:
            roots.append(entry)
    for var in ("AMENT_PREFIX_PATH", "CMAKE_PREFIX_PATH"):
        for prefix in env.get(var, "").split(os.pathsep):
            if prefix:
                roots.append(os.path.join(prefix, "share"))
    return roots


def package_path_index(env: Mapping[str, str]) -> dict[str, str]:
    """Package name -> folder for every package on ``ROS_PACKAGE_PATH``, as rospkg (and
    so roslaunch's ``$(find)``) finds them: each entry searched recursively, following
    links, not below a folder with a package.xml or manifest.xml (a rosbuild package is
    named by its folder), nor into hidden folders, a ``CATKIN_IGNORE``d one or one with
    ``rospack_nosubdirs``; a metapackage is no package here; an earlier entry wins.
    Bounded: MAX_DEPTH levels, MAX_PATH_FOLDERS folders listed in all."""
    index: dict[str, str] = {}
    budget = [MAX_PATH_FOLDERS]
    entries = [e for e in env.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if e]
    for entry in entries:
        for folder in _package_folders(entry, ("CATKIN_IGNORE",), frozenset(), budget):
            name = _package_name(folder)
            if name is not None:
                index.setdefault(name, folder)
    return index


def _package_name(folder: str) -> str | None:
    """The name rospkg gives the package in ``folder`` (None for a metapackage)."""
    manifest = manifest_of(folder)
    if os.path.basename(manifest) == "manifest.xml":
        return os.path.basename(os.path.abspath(folder))
    data, _found = read_bytes(manifest, Location(None, manifest))
    if data is None:
        return None
    try:
        root = etree.fromstring(data, xml_parser())
    except etree.XMLSyntaxError:
        return None
    name = (root.findtext("name") or "").strip()
    return name if name and root.find("export/metapackage") is None else None


def _find_installed(name: str, env: Mapping[str, str],
                    path_index: dict[str, str]) -> str | None:
    if name in path_index:
        return path_index[name]
    for var in ("AMENT_PREFIX_PATH", "CMAKE_PREFIX_PATH"):
        for prefix in env.get(var, "").split(os.pathsep):
            candidate = os.path.join(prefix, "share", name)
            if prefix and os.path.isfile(os.path.join(candidate, "package.xml")):
                return candidate
    return None
