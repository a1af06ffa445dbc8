"""The whole pipeline in one function: project file to model.

    project ─ workspace.scan ─ cmake.parse_package ─ extract_nodes ─ launch.load ─ graph.build
"""

from __future__ import annotations

import json
import os
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field, fields, replace
from typing import TYPE_CHECKING, Any

from . import diagnostics as diag
from . import runcache
from .distro_guess import guessed_distro, sole_distro
from .extract import AUTO_CACHE, cpp_sources, extract_nodes, one_run
from .facts import KeptFacts
from .files import cache_folder, content_digest, recording
from .manifest import other_builds
from .model.diagnostic import said_once
from .model.location import Location
from .model.model import Model
from .model.serialise import to_data
from .model.source import Node, Package
from .project import ConfigurationSpec, Project
from .workspace import Workspace, scan

if TYPE_CHECKING:
    from .extract.cpp import CppBatch
    from .launch.model import LaunchModel
    from .models.attach import Attacher

# The stages past the cache (build files, launch files, graph, interface models) are
# imported when a run gets to them: a re-run answered from the cache starts without them.


@dataclass(frozen=True)
class Options:
    """How to run: ``cache_dir`` of source results (None: no cache, a cold run),
    ``jobs`` worker processes parsing C++ (None: one per core), and whether nodes
    without source take the shipped interface models (``models``). ``timings``, when
    given, gets the seconds of each stage (``STAGES``), added up over the run."""

    cache_dir: str | None = AUTO_CACHE
    jobs: int | None = None
    models: bool = True
    timings: dict[str, float] | None = field(default=None, compare=False)


# the stages of a run, in order, as ``Options.timings`` names them
STAGES = ("cache", "scan", "launch", "build files", "C++", "Python", "models", "graph")


@contextmanager
def _stage(options: Options, name: str) -> Iterator[None]:
    start = time.perf_counter()
    try:
        yield
    finally:
        if options.timings is not None:
            options.timings[name] = (options.timings.get(name, 0.0)
                                     + time.perf_counter() - start)


def analyse(project: Project, environment: Mapping[str, str] | None = None,
            options: Options | None = None) -> Model:
    """Scan the workspace, read build files and sources, and build every configuration."""
    with one_run():  # a C++ batch of the same units again takes their prepared headers
        return _run(project, environment, options or Options())


def _run(project: Project, environment: Mapping[str, str] | None, options: Options
         ) -> Model:
    env = distro_environment(project, os.environ if environment is None else environment)
    if options.cache_dir is None:
        return _analyse(project, env, options, None)
    with _stage(options, "cache"):  # a run with nothing changed: its model, kept
        folder = cache_folder(os.path.abspath(
            project.workspace[0] if project.workspace else project.folder), options.cache_dir)
        keys = runcache.run_key(project, env, options.models, folder,
                                runcache.compile_commands_of(project, env))
        if keys is None:
            return _analyse(project, env, options, None)
        key, outer = keys
        kept = runcache.load(folder, key, project.name)
        earlier = runcache.load_outer(folder, outer) if kept is None else None
    if kept is not None:
        return kept
    others = built = None
    # the facts the build-file stage read off files in that run (``facts``)
    facts = KeptFacts(earlier[1].get("facts") if earlier is not None else None)
    if earlier is not None:  # only C++ files changed: the same model if they give the same
        model = _again(project, env, options, folder, *earlier, facts)
        if model is not None:
            with _stage(options, "cache"):
                runcache.store_alias(folder, key, earlier[0], outer)
            return model
        # else the other nodes give what they gave: they read no C++ file (``_units_tell``)
        found = earlier[1].get("others")
        others = found if isinstance(found, dict) else None
        built = earlier[1].get("build")
    record: dict[str, Any] = {}
    moved = None
    if earlier is not None:  # the kept run's model, when the edit moved lines only
        had = earlier[1].get("sources")
        now = runcache.sources(key)
        if isinstance(had, dict):
            changed = [path for path in had.keys() | now.keys()
                       if had.get(path) != now.get(path)]
            earlier_key, counts = earlier[0], earlier[1].get("before_graph")

            def moved(model: Model, workspace: Workspace) -> Model | None:
                with _stage(options, "cache"):
                    return runcache.relocated(folder, earlier_key, counts, key, model,
                                              changed, workspace.root, project.name)
    model = _analyse(project, env, options, record, others, built, moved,
                     earlier[1].get("launched") if earlier is not None else None, facts)
    with _stage(options, "cache"):
        if not runcache.kept_as(model, key):
            runcache.store(folder, key, model)
        if record:
            record["sources"] = runcache.sources(key)
            record["facts"] = facts.to_data()
            runcache.store_outer(folder, outer, key, record)
    return model


def _again(project: Project, env: Mapping[str, str], options: Options, folder: str,
           key: str, extraction: dict[str, Any], facts: KeptFacts | None = None
           ) -> Model | None:
    """The model of the run ``key`` when the C++ translation units of its nodes (in
    ``extraction``, batch by batch) give what they gave, and each batch the diagnostics
    it gave: its C++ nodes are then what they were. None otherwise. The other nodes
    read no C++ file (``_units_tell``): their results stand. ``facts``: those the
    build files gave that run (the include folders the units are parsed with)."""
    from .extract.cpp import CppBatch, unit_digests

    with _stage(options, "scan"):
        workspace = scan(project.workspace, env)
        workspace.source_distro = source_distro(project, env)
        workspace.kept_facts = facts
    parts = extraction.get("parts")
    if not isinstance(parts, list) or not all(
            isinstance(part, list) and all(isinstance(p, str) for p in part)
            for part in parts):
        return None
    batch = None
    if extraction.get("cpp"):
        batch = CppBatch()
        with _stage(options, "C++"):
            for part in parts:  # as the run read them: deferred plugins after the rest
                batch.extend(unit_digests(part, workspace, cache_dir=options.cache_dir,
                                          jobs=options.jobs, **cpp_arguments(project, env)))
    if _json(_gave(batch)) != _json(extraction.get("gave")):
        return None
    with _stage(options, "cache"):
        return runcache.load(folder, key, project.name)


def _units_tell(nodes: list[Node]) -> bool:
    """Whether the C++ translation units alone tell what a change to C++ files changes:
    ``runcache``'s outer key covers every other file by content, and only a node of
    another language with a source named as a C++ file would read one of them."""
    return not any(n.language != "cpp" and any(s.endswith(runcache.CPP_FILES)
                                               for s in n.sources) for n in nodes)


def cpp_arguments(project: Project, env: Mapping[str, str]) -> dict[str, Any]:
    """How a run parses its C++ translation units, beside which (``extract_nodes``'s
    keyword arguments): the compile_commands.json the project file names (None: those
    in the workspace) and the ROS distribution (``source_distro``). ``env``: the run's
    environment (``distro_environment``); bench/cpp_real.py parses with these too."""
    return {"compile_commands": [project.compile_commands] if project.compile_commands
            else None, "distro": source_distro(project, env)}


def _extract(nodes: list[Node], workspace: Workspace, project: Project,
             options: Options, env: Mapping[str, str], cpp_batch: CppBatch | None = None,
             kept: dict[str, Any] | None = None, keep: dict[str, Any] | None = None
             ) -> list[diag.Diagnostic]:
    return extract_nodes(  # every C++ source once, in parallel, cached
        nodes, workspace, cache_dir=options.cache_dir, jobs=options.jobs,
        timings=options.timings, cpp_batch=cpp_batch, kept=kept, keep=keep,
        **cpp_arguments(project, env))


def distro_environment(project: Project, environment: Mapping[str, str]) -> dict[str, str]:
    """The run's environment with the project file's: a ``distro:`` is the ROS_DISTRO the
    launch files run under (as the distribution's setup script sets it, with its
    ROS_VERSION and ROS_PYTHON_VERSION: ``distro_variables``), over the shell's own,
    unless the project's ``environment:`` (or a configuration's) names one:
    OrbbecSDK_ROS2's camera launch files choose a plain node or a component on
    ``os.environ["ROS_DISTRO"] == "foxy"``, and left unset both were started."""
    env = dict(environment)
    if project.distro:
        env["ROS_DISTRO"] = project.distro
        env.update(distro_variables(project.distro))
    env.update(project.environment)
    return env


def distro_variables(distro: str) -> dict[str, str]:
    """What a distribution's setup script (ros_environment) sets beside ROS_DISTRO:
    ROS_VERSION and ROS_PYTHON_VERSION, which package.xml conditions (REP 149:
    ``<build_type condition="$ROS_VERSION == 2">``), CMake (``$ENV{ROS_VERSION}``) and
    launch files read; none for a distribution we do not know."""
    from .extract.cpp.versions import RCLCPP, ROSCPP

    name = distro.strip().lower()
    if ROSCPP.version(name) is not None:
        return {"ROS_VERSION": "1", "ROS_PYTHON_VERSION": "3" if name == "noetic" else "2"}
    if RCLCPP.version(name) is not None:
        return {"ROS_VERSION": "2", "ROS_PYTHON_VERSION": "3"}
    return {}


def source_distro(project: Project, env: Mapping[str, str]) -> str | None:
    """The ROS distribution the sources are read for (the rclcpp version the C++
    stand-ins announce): the project file's ``distro:``, else ``ROS_DISTRO`` of the
    configurations' environments when they agree (the sources are read once for all of
    them), else of the run's, else the one ROS 2 release the workspace's files name
    (``distro_guess.sole_distro``); None when none is said or they differ."""
    if project.distro:
        return project.distro
    said = {spec.environment.get("ROS_DISTRO", env.get("ROS_DISTRO", ""))
            for spec in project.configurations} or {env.get("ROS_DISTRO", "")}
    if len(said) == 1 and "" in said:
        return sole_distro(project, env)
    return (said.pop() or None) if len(said) == 1 else None


def _gave(batch: CppBatch | None) -> dict[str, Any]:
    """What the C++ translation units of a batch (None: no C++ node) gave, in short: the
    same units and diagnostics make the same C++ nodes (``extract.cpp.unit_digests``)."""
    if batch is None:
        return {"units": {}, "diagnostics": []}
    return {"units": batch.units, "diagnostics": to_data(batch.diagnostics)}


def _json(data: Any) -> str:
    return json.dumps(data, sort_keys=True)


def _analyse(project: Project, env: Mapping[str, str], options: Options,
             record: dict[str, Any] | None, kept: dict[str, Any] | None = None,
             built: Any = None,
             moved: Callable[[Model, Workspace], Model | None] | None = None,
             launched_before: Any = None, facts: KeptFacts | None = None) -> Model:
    """The run; ``record`` (when given) gets the C++ translation units of its nodes and
    what they gave, for ``_again``, and what the nodes of other languages gave (left
    empty when a node of another language reads a file named as C++: ``_units_tell``),
    and what the build files gave (``_build_files``); ``kept``: what the nodes of other
    languages gave in an earlier run whose files but C++ ones were these
    (``extract_nodes``), ``built`` what its build files gave; ``moved``, given the model
    with its nodes (no configuration built yet), answers with an earlier run's model
    when that run had the same nodes but for lines moved in C++ files (``relocate``);
    ``launched_before``, what the launch files gave the nodes' stage in that run (the
    packages they want, the scripts rosrun finds for them: ``record["launched"]``),
    which the same files give again: the launch files are loaded only when that run's
    model is not the answer (``_Launches``); ``facts``, what the build-file stage reads
    off files, from that run where they are unchanged, and kept for the next."""
    from . import graph, launch
    from .model.runtime import Configuration
    from .models.attach import Attacher
    from .models.library import DATA, Library

    with _stage(options, "scan"):  # folders and package manifests
        workspace = scan(project.workspace, env)
        workspace.source_distro = source_distro(project, env)
        workspace.kept_facts = facts
    model = Model(project.name, diagnostics=list(workspace.diagnostics))

    project_file = Location(file=os.path.relpath(project.path))
    models = Attacher(Library(project.models, DATA if options.models else None),
                      project.distro, model.packages, guessed_distro(project, env))
    def load_launches() -> dict[str, LaunchModel]:
        launches: dict[str, LaunchModel] = {}
        for spec in project.configurations:
            with _stage(options, "launch"):
                launched = _load_launch(spec, project, workspace, env, models)
            # roslaunch starts no <test> node; rostest does (a configuration says so)
            rostest = spec.rostest if spec.rostest is not None else any(
                entry.endswith(".test") for entry in spec.launch)
            launches[spec.name] = launched if rostest else launch.without_tests(launched)
        return launches

    before = _Launches.of(launched_before) if moved is not None else None
    launches = load_launches() if before is None else {}
    gave = before if before is not None else _Launches.from_launches(launches.values())
    wanted = list(project.packages) or sorted(workspace.packages)
    for name in project.packages:
        if name not in workspace.packages:
            model.diagnostics.append(diag.make(
                "PACKAGE_NOT_FOUND", Location(file=os.path.relpath(project.path)), name=name,
                why=workspace.absence(name)))
    model.packages.extend(workspace.packages[name] for name in dict.fromkeys(
        [*wanted, *gave.wanted]) if name in workspace.packages)
    with _stage(options, "build files"):
        model.diagnostics.extend(_build_files(model.packages, workspace, record, built))
    nodes: dict[str, Node] = {node.name: node for package in model.packages
                              for node in package.nodes}
    if before is None:
        gave.scripts = [key for launched in launches.values()
                        for key in _rosrun_scripts(launched, workspace, nodes)]
    else:
        before.replay(workspace, nodes)
    every = [n for p in model.packages for n in p.nodes]
    every += [n for p in model.packages for made in p.version_nodes.values()
              for n in made.values()]
    batch = None
    if cpp_sources(every, workspace):  # libclang loads only when there is C++ to parse
        from .extract.cpp import CppBatch

        batch = CppBatch()
    tells = _units_tell(every)
    others: dict[str, Any] = {}
    model.diagnostics.extend(_extract(every, workspace, project, options, env, batch,
                                      kept if tells else None, others))
    every = without_deferred(model.packages, nodes)
    if record is not None and tells:
        record.update(cpp=batch is not None, parts=batch.parts if batch is not None else [],
                      gave=_gave(batch), others=others, launched=gave.to_data())

    if project.nodes:
        model.diagnostics.extend(graph.apply_node_hints(nodes, project.nodes, project_file))
    if record is not None:  # what the configurations may add to (``moved``)
        record["before_graph"] = {"packages": len(model.packages),
                                  "diagnostics": len(model.diagnostics)}
    if moved is not None:
        earlier = moved(model, workspace)
        if earlier is not None:
            return earlier
    if before is not None:  # the configurations are built: their launch files loaded now
        launches = load_launches()
        if not before.agrees(launches.values(), workspace, nodes):
            # not what they gave before (not expected: the same files): the run made whole
            if record is not None:
                record.clear()
            return _analyse(project, env, options, record, kept, built)

    for spec in project.configurations:
        config = Configuration(spec.name, list(spec.launch), dict(spec.args),
                               {**env, **spec.environment})
        with _stage(options, "models"):  # interface models (no source here)
            known = models.nodes_for(launches[spec.name], workspace,
                                     built_for(launches[spec.name], model.packages, nodes),
                                     config.environment, config.diagnostics)
        with _stage(options, "graph"):
            graph.build(config, launches[spec.name], workspace, known,
                        models.plugin_models(launches[spec.name], config.environment))
            config.launch_tree = launches[spec.name].tree
            graph.external_containers(config, launches[spec.name])
            if spec.hints:
                where = Location(file=project_file.file, line=spec.line, column=1)
                config.diagnostics.extend(graph.apply_hints(config, spec.hints, nodes, where))
                graph.prune_orphans(config)
            graph.find_candidates(config)
        model.configurations.append(config)
    return model


def built_for(launched: LaunchModel, packages: Sequence[Package],
              nodes: dict[str, Node]) -> dict[str, Node]:
    """``nodes`` as the launch files' ROS version builds them: a package CMake builds
    under both versions from other sources (``Package.version_nodes``) gives that
    version's program to the launch files of that version (a ROS 2 launch file of
    depthai_examples starts the ament build's stereo_inertial_node, not the catkin
    one's). Launch files of both versions, or none, take ``nodes`` as they are."""
    versions = {str(decl.ros_version) for decl in launched.nodes}
    if len(versions) != 1:
        return nodes
    version = versions.pop()
    chosen = {node.name: node for package in packages
              for node in package.version_nodes.get(version, {}).values()
              if node.name in nodes}
    return {**nodes, **chosen} if chosen else nodes


def without_deferred(packages: Sequence[Package], nodes: dict[str, Node] | None = None,
                     ) -> list[Node]:
    """The packages' nodes, the plugin classes extraction left deferred (nothing loads
    them: ``Node.deferred``) taken out of them (and of ``nodes``, by name)."""
    for package in packages:
        for node in package.nodes:
            if node.deferred and nodes is not None and nodes.get(node.name) is node:
                del nodes[node.name]
        package.nodes = [node for node in package.nodes if not node.deferred]
    return [node for package in packages for node in package.nodes]


def _build_files(packages: Sequence[Package], workspace: Workspace,
                 record: dict[str, Any] | None, built: Any) -> list[diag.Diagnostic]:
    """Each package's nodes from its build files (``read_build_files``), and their
    diagnostics. A package's as an earlier run whose files but C++ ones were these read
    them (``built``, which ``record`` of that run got) when the C++ sources and headers
    that reading read (a plugin's export macro, a ``main()``, the words of the sources
    of a library it links) are as they were: navigation2's sixteen packages of its
    bringup took 0.9 s of a run after one changed source (4.5 s). ``record``, when
    given, gets what each gave, unless a node or diagnostic would not read back."""
    from .model.load import diagnostic_from_data, node_from_data

    kept = built if isinstance(built, dict) else {}
    said: list[diag.Diagnostic] = []
    for package in packages:
        entry = kept.get(package.name)
        given = _kept_package(entry, package.name) if entry is not None else None
        if given is not None:
            package.nodes, found, package.version_nodes = given
        else:
            with recording() as read:
                found = read_build_files(package, workspace)
            entry = None
            if record is not None:
                nodes = [to_data(node) for node in package.nodes]
                diagnostics = to_data(found)
                versions = {version: {executable: to_data(node)
                                      for executable, node in made.items()}
                            for version, made in package.version_nodes.items()}
                if all(_same(node_from_data(data, package.name), node)
                       for data, node in zip(nodes, package.nodes, strict=True)) and all(
                           _same(node_from_data(versions[version][executable],
                                                package.name), node)
                           for version, made in package.version_nodes.items()
                           for executable, node in made.items()) and [
                           diagnostic_from_data(d) for d in diagnostics] == found:
                    entry = {"nodes": nodes, "diagnostics": diagnostics, "versions": versions,
                             "cpp": {path: content_digest(path)
                                     for path in sorted(read)
                                     if path.endswith(runcache.CPP_FILES)}}
        if record is not None and entry is not None:
            record.setdefault("build", {})[package.name] = entry
        said.extend(found)
    return said


def _kept_package(entry: Any, name: str
                  ) -> tuple[list[Node], list[diag.Diagnostic],
                             dict[str, dict[str, Node]]] | None:
    """What a package's build files gave in an earlier run (``_build_files``), when the
    C++ files that reading read are as they were; else None."""
    from .model.load import diagnostic_from_data, node_from_data

    try:
        if any(content_digest(path) != digest
               for path, digest in entry["cpp"].items()):
            return None
        return ([node_from_data(n, name) for n in entry["nodes"]],
                [diagnostic_from_data(d) for d in entry["diagnostics"]],
                {version: {executable: node_from_data(data, name)
                           for executable, data in made.items()}
                 for version, made in entry.get("versions", {}).items()})
    except (KeyError, TypeError, ValueError, AttributeError):
        return None


def _same(one: Node, other: Node) -> bool:
    """Whether two nodes hold the same (a node compares by identity)."""
    return all(getattr(one, f.name) == getattr(other, f.name) for f in fields(Node))


def read_build_files(package: Package, workspace: Workspace) -> list[diag.Diagnostic]:
    """The package's nodes and their sources, from its CMakeLists.txt or setup.py; an
    unexpected exception is an INTERNAL diagnostic for the package."""
    found: list[diag.Diagnostic] = []
    return diag.per_file(package.location, package.path, found,
                    lambda: _read_build_files(package, workspace), found)


def _read_build_files(package: Package, workspace: Workspace) -> list[diag.Diagnostic]:
    from . import cmake, pysetup

    found: list[diag.Diagnostic] = []
    if package.build_type == "ament_python":
        package.nodes, found = pysetup.parse_package(package, workspace)
    elif package.build_type in cmake.CMAKE_BUILD_TYPES:
        package.nodes, found = cmake.parse_package(package, workspace)
        package.version_nodes = cmake.version_nodes(package, workspace, package.nodes)
    others = other_builds(package, workspace.environment)
    if others:  # each ROS version's setup.py, the run giving none
        own = {version for version, build_type in package.builds_by_version.items()
               if build_type == package.build_type}
        if len(own) == 1:
            version = own.pop()
            package.node_versions = {node.executable: version for node in package.nodes}
    for version, environment in others:
        more, said = pysetup.parse_package(package, workspace, environment)
        taken = {node.executable for node in package.nodes}
        added = [node for node in more if node.executable not in taken]
        package.nodes.extend(added)
        package.node_versions.update((node.executable, version) for node in added)
        found.extend(said)
    return found


def _rosrun_scripts(launched: LaunchModel, workspace: Workspace,
                    nodes: dict[str, Node]) -> list[tuple[str, str]]:
    """Scripts that launch files start and only rosrun's search of the package finds:
    added to their package, to be extracted with every other node; their packages and
    names, in order."""
    found: list[tuple[str, str]] = []
    for decl in launched.nodes:
        key = f"{decl.package}/{decl.executable}"
        if key in nodes or decl.ros_version != 1:
            continue
        if _rosrun_script(decl.package, decl.executable, workspace, nodes):
            found.append((decl.package, decl.executable))
    return found


def _rosrun_script(package_name: str, executable: str, workspace: Workspace,
                   nodes: dict[str, Node]) -> bool:
    """Add the script rosrun finds as ``package_name/executable`` to its package and to
    ``nodes``, when there is one."""
    from .rosrun import script_node

    package = workspace.packages.get(package_name)
    node = None if package is None else script_node(package, executable, workspace)
    if package is None or node is None:
        return False
    package.nodes.append(node)
    nodes[f"{package_name}/{executable}"] = node
    return True


@dataclass
class _Launches:
    """What the configurations' launch files give the nodes' stage: the packages they
    start nodes of (``wanted``, in order, once each) and the scripts rosrun's search
    found for them (``scripts``: package and name, in order). A run whose files but C++
    ones are an earlier run's gets the same from them, so one that may end with the
    earlier run's model (``relocate``) takes this from that run's record and loads the
    launch files only when it goes on to build the configurations (``agrees``); 1.8 s
    of a 33-configuration navigation2 re-run after an edit that moved lines."""

    wanted: list[str] = field(default_factory=list)
    scripts: list[tuple[str, str]] = field(default_factory=list)

    @classmethod
    def from_launches(cls, launches: Iterable[LaunchModel]) -> _Launches:
        from .graph.build import nodelet_plugin

        wanted = []
        for launched in launches:
            for decl in launched.nodes:
                plugin = nodelet_plugin(decl)
                wanted.append(plugin.partition("/")[0] if plugin else decl.package)
        return cls(list(dict.fromkeys(wanted)))

    @classmethod
    def of(cls, data: Any) -> _Launches | None:
        """From ``to_data``'s; None when it is not that."""
        if not isinstance(data, dict):
            return None
        wanted, scripts = data.get("wanted"), data.get("scripts")
        if not isinstance(wanted, list) or not all(isinstance(w, str) for w in wanted) \
                or not isinstance(scripts, list) or not all(
                    isinstance(s, list) and len(s) == 2 and all(isinstance(p, str) for p in s)
                    for s in scripts):
            return None
        return cls(wanted, [(p, e) for p, e in scripts])

    def to_data(self) -> dict[str, Any]:
        return {"wanted": self.wanted, "scripts": [list(s) for s in self.scripts]}

    def replay(self, workspace: Workspace, nodes: dict[str, Node]) -> None:
        """Add the scripts as ``_rosrun_scripts`` did."""
        for package, executable in self.scripts:
            _rosrun_script(package, executable, workspace, nodes)

    def agrees(self, launches: Iterable[LaunchModel], workspace: Workspace,
               nodes: dict[str, Node]) -> bool:
        """Whether ``launches``, loaded now, want these packages and no other script."""
        launches = list(launches)
        return self.from_launches(launches).wanted == self.wanted and not any(
            _rosrun_scripts(launched, workspace, dict(nodes)) for launched in launches)


def launch_path(entry: str, project: Project, workspace: Workspace) -> str | None:
    """A launch file named ``pkg/relative/path`` (as in HAROS) or by a path."""
    from .share import share_source

    candidate = os.path.join(project.folder, entry)
    if os.path.isabs(entry) or os.path.isfile(candidate):
        return candidate
    package, _, rest = entry.partition("/")
    folder = workspace.find(package)
    if folder is None:
        return None
    path = os.path.join(folder, rest)
    # not in the source: maybe a ROS 2 launch file named where its package installs it
    return path if os.path.exists(path) else share_source(workspace, path)


def _guessed_environment(environment: Mapping[str, str], workspace: Workspace,
                         path: str) -> Mapping[str, str]:
    """The environment a ROS 2 launch file runs in: ``environment``, with the
    ROS_DISTRO (and ROS_VERSION, ROS_PYTHON_VERSION) the distribution's setup script
    sets when nothing sets one and the workspace's files name one ROS 2 release alone
    (``source_distro``: the release its C++ is read for too): reseq_ros2's
    ``'servo_node_main' if os.environ.get('ROS_DISTRO') == 'humble' else 'servo_node'``
    of a tree whose CI names Humble alone. A tree naming several keeps it unset (not
    known), and so does a roslaunch file (a ROS 1 distribution's shell runs it)."""
    from .launch.dialect import ros_version
    from .models.attach import ros_of

    distro = workspace.source_distro
    if environment.get("ROS_DISTRO") or not distro or ros_of(distro) != 2 \
            or ros_version(path, workspace) != 2:
        return environment
    return {"ROS_DISTRO": distro, **distro_variables(distro), **environment}


def _load_launch(spec: ConfigurationSpec, project: Project, workspace: Workspace,
                 env: Mapping[str, str], attacher: Attacher | None = None) -> LaunchModel:
    """The configuration's launch files read and merged; ``attacher``: the interface
    models, whose launch files (``models.launch_files``) stand for those of the ROS 1
    packages found neither in the workspace nor installed here."""
    from . import launch
    from .launch.model import LaunchModel
    from .models.launch_files import ModelledFiles

    merged = LaunchModel()
    environment = {**env, **spec.environment}
    finder = attacher.plugin_models(LaunchModel(), environment) if attacher else None
    modelled = ModelledFiles(finder.package, finder.distro) if finder else None
    lines = spec.launch_lines or [spec.line] * len(spec.launch)
    for entry, line in zip(spec.launch, lines, strict=False):
        where = Location(file=os.path.relpath(project.path), line=line, column=1)
        path = launch_path(entry, project, workspace)
        if path is None:
            package = entry.partition("/")[0]
            merged.diagnostics.append(diag.make(
                "PACKAGE_NOT_FOUND", where, name=package, why=workspace.absence(package)))
            continue
        if not os.path.isfile(path):
            merged.diagnostics.append(diag.make("LAUNCH_FILE_MISSING", where, path=entry))
            continue
        running = _guessed_environment(environment, workspace, path)
        loaded = diag.per_file(  # one launch file (and its includes): a bug stays with it
            where, entry, merged.diagnostics,
            lambda: launch.load(path, workspace, spec.args,  # noqa: B023 (called at once)
                                running, modelled), LaunchModel())  # noqa: B023
        merged.files.extend(loaded.files)
        merged.tree.extend(loaded.tree)
        offset = len(merged.nodes)
        merged.nodes.extend(loaded.nodes)
        merged.params.extend(param if param.owner is None else replace(
            param, owner=param.owner + offset) for param in loaded.params)
        merged.args.update(loaded.args)
        merged.diagnostics.extend(loaded.diagnostics)
        merged.package_uses.extend(loaded.package_uses)
        merged.environment_values.extend(loaded.environment_values)
        merged.unread_includes.extend(loaded.unread_includes)
        merged.foreign_sections.extend(loaded.foreign_sections)
    # the values the configuration gives its launch arguments come from outside the
    # launch files, as the environment's do (a map folder given as ``map_path:=``)
    merged.environment_values.extend(v for v in spec.args.values() if isinstance(v, str))
    # an argument left without a value: said once for the configuration, with its uses
    merged.diagnostics = said_once(merged.diagnostics)
    return merged
