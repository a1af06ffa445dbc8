"""A project without a project file: what ``haros-arch check src/`` or ``check x.launch``
analyses.

Given a workspace (or package) folder, the configurations are the ones a user would
start by hand: one per launch file of the workspace's packages that no other launch file
of the workspace includes, with every argument at its default. Given one launch file,
that file is the one configuration, and the workspace is found from its package (up to
the catkin / colcon workspace root). ``--launch`` and ``--arg`` choose instead.
``init`` writes the same choice as a project file to edit.

Which files include which is read with the launch loaders themselves (never by text
search), so a file reached through ``$(find pkg)``, ``FindPackageShare`` or
``get_package_share_directory`` counts as included.
"""

from __future__ import annotations

import os
import re
import stat
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field

import yaml

from .project import ConfigurationSpec, Project, ProjectError
from .workspace import IGNORE_MARKERS, SKIP_FOLDERS, Workspace, manifest_variants, scan

# file names that are launch files wherever they are
LAUNCH_SUFFIXES = (".launch", ".launch.xml", ".launch.py", ".launch.yaml", ".launch.yml",
                   "_launch.py", "_launch.xml", "_launch.yaml")
# in a folder named launch/, these are launch files when their content says so
LAUNCH_FOLDER_SUFFIXES = (".py", ".xml", ".yaml", ".yml")
MAX_LAUNCH_FILES = 400  # per workspace: more are left out, with a note
MAX_SEARCH_DEPTH = 6    # folders below a package searched for launch files
MAX_PY_HEAD = 1 << 20   # the bytes of a Python file read for its launch function's name
# a Python file of a launch/ folder is a launch file when it defines the function
# ros2 launch calls (a launch-file writer that only mentions it in a string is none:
# clearpath_generator_common's launch/writer.py)
_PY_LAUNCH = re.compile(
    rb"^[ \t]*(?:async[ \t]+)?def[ \t]+generate_launch_description[ \t]*\(|"
    rb"^generate_launch_description[ \t]*=", re.MULTILINE)
_XML_LAUNCH = re.compile(rb"<launch[\s>]")
_YAML_LAUNCH = re.compile(rb"^launch\s*:", re.MULTILINE)


@dataclass
class Choice:
    """What was chosen for a path without a project file, to tell the user."""

    project: Project
    notes: list[str] = field(default_factory=list)


def is_launch_file(path: str) -> bool:
    """A launch file by name, or a file in a ``launch/`` folder whose content is one."""
    name = os.path.basename(path).lower()
    if name.endswith(LAUNCH_SUFFIXES):
        return True
    if not name.endswith(LAUNCH_FOLDER_SUFFIXES) or os.path.basename(
            os.path.dirname(path)) != "launch":
        return False
    try:
        if not os.path.isfile(path) or not stat.S_ISREG(os.stat(path).st_mode):
            return False
        with open(path, "rb") as handle:
            head = handle.read(64 * 1024)
    except OSError:
        return False
    if name.endswith(".py"):
        return _PY_LAUNCH.search(head) is not None
    if name.endswith(".xml"):
        return _XML_LAUNCH.search(head) is not None
    return _YAML_LAUNCH.search(head) is not None


def _runnable(path: str) -> bool:
    """False for a Python file named like a launch file that never names the function
    ``ros2 launch`` calls (interbotix_xs_modules' ``xs_launch/xs_launch.py``, a module
    of helpers the launch files import), or a YAML file so named without the key
    ``launch``: no configuration of its own."""
    name = os.path.basename(path).lower()
    if not name.endswith(LAUNCH_SUFFIXES):
        return True  # (a launch/ folder's file is a launch file by its content already)
    if name.endswith(".py"):
        marker = re.compile(rb"generate_launch_description")
    elif name.endswith((".yaml", ".yml")):
        # launch's YAML frontend reads one mapping with the key ``launch``: a file named
        # like a launch file without it is data (perseus-v2's config/realsense_launch.yaml,
        # the arguments its launch file gives realsense2_camera's)
        marker = _YAML_LAUNCH
    else:
        return True
    try:
        with open(path, "rb") as handle:
            return marker.search(handle.read(MAX_PY_HEAD)) is not None
    except OSError:
        return False


def is_project_file(path: str) -> bool:
    """A YAML file that is not a launch file (``load`` then reads it, or says why not)."""
    return os.path.exists(path) and not os.path.isdir(path) and path.lower().endswith(
        (".yaml", ".yml")) and not is_launch_file(path)


def workspace_of(path: str) -> str:
    """The workspace folder to scan for a launch file or a package folder: the
    ``src`` folder of the catkin / colcon workspace holding its package, else the
    repository (a folder with ``.git``) holding it, else the package's parent."""
    here = os.path.abspath(path if os.path.isdir(path) else os.path.dirname(path))
    package = None
    probe = here
    while True:
        if os.path.isfile(os.path.join(probe, "package.xml")) or os.path.isfile(
                os.path.join(probe, "manifest.xml")):
            package = probe
            break
        parent = os.path.dirname(probe)
        if parent == probe:
            break
        probe = parent
    start = package or here
    probe = start
    for _ in range(8):  # a src/ folder above the package: the workspace's sources
        parent = os.path.dirname(probe)
        if parent == probe:
            break
        if os.path.basename(probe) == "src" and os.path.isdir(probe):
            return probe
        probe = parent
    probe = start
    for _ in range(8):
        if os.path.isdir(os.path.join(probe, ".git")):
            return probe
        parent = os.path.dirname(probe)
        if parent == probe:
            break
        probe = parent
    return os.path.dirname(start) if package else start


def find_launch_files(workspace: Workspace) -> list[str]:
    """Every launch file inside the workspace's packages, in a stable order: not in the
    folder of another package, nor one an ignore marker leaves out; in a folder with a
    package.xml of its own that is no package (packages do not nest: catkin and the
    workspace scan stop at the outer one, and roslaunch finds a package's launch file
    anywhere below it: ros_control_boilerplate's ``rrbot_control/launch``) too."""
    found: list[str] = []
    roots = {os.path.abspath(p.root) for p in workspace.packages.values() if p.root}
    for name in sorted(workspace.packages):
        root = workspace.packages[name].root
        if not root:
            continue
        stack = [(root, 0)]
        while stack and len(found) < MAX_LAUNCH_FILES:
            folder, depth = stack.pop()
            try:
                entries = sorted(os.listdir(folder))
            except OSError:
                continue
            if folder != root and (os.path.abspath(folder) in roots or any(
                    m in entries for m in IGNORE_MARKERS)):
                continue
            for entry in reversed(entries):
                path = os.path.join(folder, entry)
                if entry.startswith(".") or entry in SKIP_FOLDERS:
                    continue
                if os.path.isdir(path) and not os.path.islink(path):
                    if depth < MAX_SEARCH_DEPTH and entry not in ("test", "tests"):
                        stack.append((path, depth + 1))
                elif os.path.isfile(path) and is_launch_file(path) and _runnable(path):
                    found.append(path)
    return sorted(found)


def _config_name(path: str, workspace: Workspace, taken: set[str]) -> str:
    package = workspace.package_of(path) if hasattr(workspace, "package_of") else None
    stem = os.path.basename(path)
    for suffix in sorted(LAUNCH_SUFFIXES + LAUNCH_FOLDER_SUFFIXES, key=len, reverse=True):
        if stem.lower().endswith(suffix):
            stem = stem[: -len(suffix)]
            break
    base = f"{package.name}/{stem}" if package is not None else stem
    name, n = base, 2
    while name in taken:
        name, n = f"{base}#{n}", n + 1
    taken.add(name)
    return name


def _entry(path: str, workspace: Workspace) -> str:
    """A launch entry as a project file writes it: ``pkg/relative/path``."""
    package = workspace.package_of(path) if hasattr(workspace, "package_of") else None
    if package is not None and package.root:
        return f"{package.name}/{os.path.relpath(path, package.root)}"
    return os.path.abspath(path)


def root_launch_files(files: Sequence[str], workspace: Workspace,
                      environment: Mapping[str, str]) -> tuple[list[str], list[str]]:
    """The files no other file of ``files`` includes (loaded with arguments at their
    defaults), and the included ones."""
    from .launch import load as load_launch

    real = {os.path.realpath(f): f for f in files}
    included: set[str] = set()
    patterns: list[tuple[re.Pattern[str], str]] = []  # (include pattern, its file)
    fragments: set[str] = set()  # the files that start no node
    required: set[str] = set()  # the files with an argument of no default
    for path in files:
        try:
            loaded = load_launch(path, workspace, {}, dict(environment))
        except RecursionError:
            continue
        for other in loaded.files[1:]:  # relative to the workspace root
            key = os.path.realpath(os.path.join(workspace.root, other))
            if key in real and key != os.path.realpath(path):
                included.add(key)
        patterns += [(re.compile(p), os.path.realpath(path)) for p in loaded.include_patterns]
        unread = loaded.unread_includes or any(
            item.kind == "include" and not item.skipped
            for tree in loaded.tree for item in tree.walk())
        if not loaded.nodes and not unread:
            # a file that starts no node it is seen to start (one with an include not
            # read may start nodes unseen: pb2025_nav_bringup's robot_state_publisher
            # launch file, whose own include names a package not here)
            fragments.add(os.path.realpath(path))
        if any(default is None for default in loaded.args.values()):
            required.add(os.path.realpath(path))
    # a file that starts no node and that an include reaches with another value of its
    # arguments is a fragment of that launch, not a configuration (MoveIt's
    # ``$(arg pipeline)_planning_pipeline.launch.xml``: the chomp pipeline's file sets
    # parameters for move_group; alone, every one of them is "set but never read"); so
    # is one with an argument of no default, which the include gives and which alone
    # has no value (a driver's launch file included only ``if`` the robot is real, its
    # ``robot_ip`` given: alone, every name made of it keeps '?'); one that starts nodes
    # with every argument set stays one (turtlebot3_slam's ``turtlebot3_$(arg
    # slam_methods).launch``: each method's file is what a user checks)
    for pattern, owner in patterns:
        for key in (fragments | required) - included:
            if key != owner and (pattern.fullmatch(os.path.abspath(real[key]))
                                 or pattern.fullmatch(key)):
                included.add(key)
    roots = [f for f in files if os.path.realpath(f) not in included]
    return roots, [real[k] for k in sorted(included)]


def _kept_roots(files: list[str], workspace: Workspace, env: Mapping[str, str],
                folder: str, cache_dir: str | None) -> tuple[list[str], list[str]]:
    """``root_launch_files``, kept in the cache folder: it loads every launch file of the
    workspace, most of a no-change re-run of a folder without a project file."""
    if cache_dir is None:
        return root_launch_files(files, workspace, env)
    from . import runcache
    from .files import cache_folder

    return runcache.kept(
        cache_folder(folder, cache_dir), "launch-roots", [folder], env, files,
        lambda: root_launch_files(files, workspace, env),
        list,
        lambda data: ([str(f) for f in data[0]], [str(f) for f in data[1]]))


def choose(path: str, launch: Iterable[str] = (), args: Mapping[str, str] | None = None,
           environment: Mapping[str, str] | None = None, cache_dir: str | None = None
           ) -> Choice:
    """The project for ``path`` (a workspace or package folder, or a launch file)
    without a project file. Raises ``ProjectError`` when there is nothing to analyse.
    ``cache_dir`` (``files.AUTO_CACHE``: the default folder): where the launch files'
    roots are kept while nothing they may read changes (``runcache.kept``); None: not
    kept."""
    env = dict(os.environ if environment is None else environment)
    given = dict(args or {})
    if not os.path.exists(path):
        raise ProjectError(path, 0, 0, "no such file or folder")
    chosen_files = [os.path.abspath(p) for p in launch]
    if os.path.isfile(path):
        if not is_launch_file(path):
            raise ProjectError(path, 0, 0, "not a project file (.yaml), a launch file or "
                                           "a folder")
        chosen_files = [os.path.abspath(path), *chosen_files]
    folder = workspace_of(path)
    if os.path.isdir(path):
        top = os.path.abspath(path)
        src = os.path.join(top, "src")
        # a workspace keeps its packages in src/; a package's own folder (its
        # package.xml at the top: pointcloud_to_laserscan) keeps its C++ sources there
        folder = src if os.path.isdir(src) and not os.path.isfile(
            os.path.join(top, "package.xml")) else top
    workspace = scan([folder], env)
    if not workspace.packages and folder != os.path.abspath(path) and os.path.isdir(path):
        # a repository whose src/ holds code, not packages, and keeps its packages beside
        # it (pyrobot: its Python library in src/, the ROS packages in robots/ and
        # pyrobot_bridge/): the folder given is the one to read
        whole = scan([os.path.abspath(path)], env)
        if whole.packages:
            folder, workspace = os.path.abspath(path), whole
    if not workspace.packages:
        raise ProjectError(path, 0, 0, f"no ROS package (package.xml) under {folder}"
                           + _ignored(workspace)
                           + _manifest_variants(folder if os.path.isdir(path) else path))
    named = os.path.abspath(path if os.path.isdir(path) else folder)
    if os.path.basename(named) == "src":  # a workspace is known by the folder above src/
        named = os.path.dirname(named)
    name = os.path.basename(named) or "workspace"
    project = Project(name=name, path=os.path.join(folder, ".haros-arch"),
                      workspace=[folder])
    choice = Choice(project)
    if chosen_files:
        missing = [f for f in chosen_files if not os.path.isfile(f)]
        if missing:
            raise ProjectError(missing[0], 0, 0, "launch file not found")
        roots = chosen_files
    else:
        from .launch.dialect import foreign_to_package

        files, skipped = [], []
        for file in find_launch_files(workspace):
            why = foreign_to_package(file, workspace)
            if why is None:
                files.append(file)
            else:  # a leftover of a port: no configuration anyone runs
                skipped.append(f"{_entry(file, workspace)} skipped: {why} (name it with "
                               "--launch to analyse it anyway)")
        if len(files) >= MAX_LAUNCH_FILES:
            choice.notes.append(f"more than {MAX_LAUNCH_FILES} launch files: only the "
                                "first are considered (choose with --launch)")
        roots, included = _kept_roots(files, workspace, env, folder, cache_dir)
        choice.notes.append(f"{len(workspace.packages)} packages in {folder}; "
                            f"{len(files)} launch files, {len(included)} included by "
                            f"others, {len(roots)} configurations (one per launch file "
                            "no other includes, arguments at their defaults)")
        choice.notes.extend(skipped)
    taken: set[str] = set()
    for file in roots:
        spec = ConfigurationSpec(_config_name(file, workspace, taken),
                                 [_entry(file, workspace)], dict(given))
        project.configurations.append(spec)
    if not project.configurations:
        choice.notes.append("no launch file found: only the packages' nodes are analysed")
    from .distro_guess import guessed_distro

    guessed = guessed_distro(project, env)
    if guessed is not None and _builds_for_ros2(workspace):
        # (a tree of catkin packages alone is read as ROS 1: kr_autonomous_flight's
        # README names Jazzy, and no model or rclcpp of it is ever read)
        choice.notes.append(f"ROS 2 release {guessed[0]}, {guessed[1]} (ROS_DISTRO or a "
                            "project file's distro: chooses another)")
    return choice


def _builds_for_ros2(workspace: Workspace) -> bool:
    """Whether a package of the workspace builds for ROS 2 (ament, in any ROS version
    its package.xml chooses), so that a guessed ROS 2 release is worth saying."""
    return any(package.build_type.startswith("ament") or any(
        kind.startswith("ament") for kind in package.builds_by_version.values())
        for package in workspace.packages.values())


MAX_IGNORED_SAID = 5  # markers named when none of a folder's packages is read


def _ignored(workspace: Workspace) -> str:
    """What to say when the folder's packages are all under folders an ignore marker
    leaves out (interbotix_ros_manipulators' ROS 1 branch: ``CATKIN_IGNORE`` in each
    robot family's folder): the markers, and how many packages each hides."""
    if not workspace.ignored:
        return ""
    hidden: dict[str, list[str]] = {}
    for name, (marker, _) in sorted(workspace.ignored.items()):
        hidden.setdefault(marker, []).append(name)
    said = [f"{workspace.relpath(marker)} ({len(names)}: {', '.join(names[:3])}"
            f"{', ...' if len(names) > 3 else ''})"
            for marker, names in sorted(hidden.items())[:MAX_IGNORED_SAID]]
    more = len(hidden) - len(said)
    return (f"; {len(workspace.ignored)} package(s) there are in folders an ignore marker "
            f"keeps colcon and catkin out of, as this analysis: {'; '.join(said)}"
            f"{f' and {more} more' if more > 0 else ''}")


def _manifest_variants(folder: str) -> str:
    """What to say when ``folder`` (or the folder above a workspace's ``src/``) holds
    package manifests under other names than package.xml: none is read, and which one
    the build copies is the user's choice."""
    found: list[str] = []
    for place in dict.fromkeys((folder, os.path.dirname(folder.rstrip(os.sep)))):
        found += [os.path.join(place, n) for n in manifest_variants(place)]
    if not found:
        return ""
    return (f"; {', '.join(found)} {'is' if len(found) == 1 else 'are'} there, a "
            "manifest the build copies to package.xml: copy the one for your ROS there "
            "to analyse the package")


def project_text(choice: Choice) -> str:
    """The chosen project as a project file (for ``haros-arch init``)."""
    project = choice.project
    data: dict[str, object] = {"project": project.name}
    folder = os.path.dirname(project.path)
    data["workspace"] = os.path.relpath(project.workspace[0], folder) if project.workspace \
        else "."
    configurations: dict[str, object] = {}
    for spec in project.configurations:
        entry: dict[str, object] = {"launch": list(spec.launch)}
        if spec.args:
            entry["args"] = dict(spec.args)
        configurations[spec.name] = entry
    data["configurations"] = configurations
    head = ("# haros-arch project file, written by 'haros-arch init'. One configuration per\n"
            "# launch file that no other launch file includes, arguments at their defaults;\n"
            "# edit freely (see README.md, 'Project file').\n%YAML 1.1\n---\n")
    text = head + yaml.safe_dump(data, sort_keys=False, default_flow_style=False)
    from .distro_guess import guessed_distro

    guessed = guessed_distro(project, {})
    if guessed is not None:  # said, not set: a ROS_DISTRO of the shell still wins
        text += (f"# distro: {guessed[0]}  # {guessed[1]}; set it to fix the interface "
                 "models and rclcpp the analysis reads for\n")
    return text


# what the command line chose for paths that are not project files (--launch, --arg)
_selection: tuple[tuple[str, ...], tuple[tuple[str, str], ...]] = ((), ())
_chosen: dict[tuple[object, ...], Choice] = {}


def select(launch: Iterable[str] = (), args: Mapping[str, str] | None = None) -> None:
    """Set the launch files and arguments that ``open_project`` uses for a path that is
    not a project file (the command line's ``--launch`` and ``--arg``)."""
    global _selection
    _selection = (tuple(launch), tuple(sorted((args or {}).items())))


def open_choice(path: str, cache_dir: str | None = None) -> Choice:
    """The project for ``path``: a project file is loaded; a folder or a launch file is
    chosen as ``choose`` does (with ``cache_dir``), once per process (commands ask more
    than once)."""
    from .project import load

    key: tuple[object, ...]
    if is_project_file(path):
        try:  # read once per command (and again only when the file changed)
            key = (os.path.abspath(path), os.stat(path).st_mtime_ns, *_selection)
        except OSError:
            key = (os.path.abspath(path), None, *_selection)
        if key not in _chosen:
            project = load(path)
            launch, args = _selection
            for spec in project.configurations:
                spec.args.update(dict(args))
            _chosen[key] = Choice(project)
        return _chosen[key]
    key = (os.path.abspath(path), *_selection)
    if key not in _chosen:
        launch, args = _selection
        _chosen[key] = choose(path, launch, dict(args), cache_dir=cache_dir)
    return _chosen[key]


def open_project(path: str) -> Project:
    return open_choice(path).project
