"""Compare ``haros_arch.launch`` with the real ROS 2 launch code on real launch files.

The real side runs ros2/launch and ros2/launch_ros (jazzy) through the real
``LaunchService`` in a scratch virtual environment, with process start intercepted:
``Node.execute`` performs the node's substitutions and records what launch_ros computed
(package, executable, name, namespace, remappings, parameters after parameter files and
substitutions, via launch_ros's own ``to_parameters_list``), then starts nothing;
``LoadComposableNodes.execute`` records each load request; ``ExecuteLocal.execute``
starts nothing. ``rclpy``, message packages and ``ament_index_python`` are small
stand-ins written by this script (the package index maps each package name to its
source folder, as our workspace scan does). Our side runs ``haros_arch.launch.load``.

Nothing fetched is committed and CI never runs this. To reproduce:

1. Sources (any way of getting them; branch jazzy where there is one), in one folder
   SRC: ``launch`` (github ros2/launch), ``launch_ros`` (ros2/launch_ros), and the launch
   files to compare: ``demos`` (ros2/demos), ``navigation2`` (ros-navigation/navigation2,
   at least nav2_bringup and nav2_common), ``turtlebot3`` (ROBOTIS-GIT/turtlebot3),
   ``ros2_control_demos`` (ros-controls/ros2_control_demos).
2. A scratch venv (not .venv)::

       python3 -m venv /tmp/bench/venv
       /tmp/bench/venv/bin/pip install pyyaml lark osrf-pycommon setuptools
       for p in launch/launch launch/launch_xml launch/launch_yaml launch_ros/launch_ros; do
           /tmp/bench/venv/bin/pip install --no-deps --no-build-isolation SRC/$p; done

3. Run with our venv::

       .venv/bin/python bench/launch_ros2_compare.py SRC --real-python /tmp/bench/venv/bin/python \\
           --targets demos navigation2/nav2_bringup turtlebot3 ros2_control_demos

It prints, per launch file, whether each side could run it, then the agreement per
field over the nodes both sides found. The real side records parameters with launch_ros's
``to_parameters_list``, which matches a parameter file's ``/**`` and exact node names
only; a running node gets rcl's wildcards too (``/**/driver``), as ours does, so such
entries show as differences. Our own fixture packages (fixtures/launch_ros2/src,
fixtures/share_ros2/src) can be copied under SRC and given as targets too.

The real side always runs in the install-like tree. Ours does too, unless
``--ours-from-source``: then ours reads the source folders as they are, finding each
package's share folder through its install rules (``haros_arch.share``), starts each
launch file by its installed name, and writes path values as installed before comparing.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import textwrap
from collections import Counter
from typing import Any

import checkout  # bench/checkout.py: says which haros_arch is measured

COMMAND_OUTPUT = '<robot name="standin"/>'  # what the stand-in xacro prints
STANDIN_FILES = {
    "standin_finder.py": '''
import importlib.abc, importlib.machinery, sys, types
from unittest import mock
PREFIXES = ("rclpy", "composition_interfaces", "lifecycle_msgs", "rcl_interfaces",
            "builtin_interfaces", "std_msgs", "launch_testing_ros", "rosgraph_msgs")
class _Module(types.ModuleType):
    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        value = mock.MagicMock(name=f"{self.__name__}.{name}")
        setattr(self, name, value)
        return value
class Finder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    def find_spec(self, name, path, target=None):
        if name.split(".")[0] in PREFIXES and name != "rclpy.parameter":
            return importlib.machinery.ModuleSpec(name, self, is_package=True)
        return None
    def create_module(self, spec):
        module = _Module(spec.name)
        module.__path__ = []
        return module
    def exec_module(self, module):
        pass
sys.meta_path.insert(0, Finder())
''',
    "rclpy_parameter.py": '''
import enum
class Parameter:
    class Type(enum.Enum):
        BOOL = 1
        INTEGER = 2
        DOUBLE = 3
        STRING = 4
        BYTE_ARRAY = 5
        BOOL_ARRAY = 6
        INTEGER_ARRAY = 7
        DOUBLE_ARRAY = 8
        STRING_ARRAY = 9
        def check(self, v):
            T = Parameter.Type
            seq = isinstance(v, (list, tuple))
            return {T.BOOL: isinstance(v, bool),
                    T.INTEGER: isinstance(v, int) and not isinstance(v, bool),
                    T.DOUBLE: isinstance(v, float), T.STRING: isinstance(v, str),
                    T.BYTE_ARRAY: seq and all(isinstance(x, bytes) for x in v) and len(v) > 0,
                    T.BOOL_ARRAY: seq and all(isinstance(x, bool) for x in v),
                    T.INTEGER_ARRAY: seq and all(
                        isinstance(x, int) and not isinstance(x, bool) for x in v),
                    T.DOUBLE_ARRAY: seq and all(isinstance(x, float) for x in v),
                    T.STRING_ARRAY: seq and all(isinstance(x, str) for x in v)}[self]
    def __init__(self, name, type_=None, value=None):
        self.name, self.type_, self.value = name, type_, value
    def to_parameter_msg(self):
        return (self.name, list(self.value) if isinstance(self.value, tuple) else self.value)
''',
    "ament_index_python/__init__.py": "",
    "ament_index_python/resources.py": '''
import json, os
_MAP = json.loads(os.environ.get("BENCH_PACKAGES", "{}"))
def has_resource(kind, name):
    return kind == "packages" and name in _MAP
def get_resource(kind, name):
    if not has_resource(kind, name):
        raise LookupError(name)
    return "", os.path.dirname(os.path.dirname(_MAP[name]))  # the prefix
def get_resources(kind):
    return {k: os.path.dirname(os.path.dirname(v)) for k, v in _MAP.items()} if (
        kind == "packages") else {}
''',
    "bin/xacro": f"#!/bin/sh\necho '{COMMAND_OUTPUT}'\n",
    "bin/ros2": "#!/bin/sh\nexit 0\n",
    "ament_index_python/packages.py": '''
import json, os
_MAP = json.loads(os.environ.get("BENCH_PACKAGES", "{}"))
class PackageNotFoundError(KeyError):
    pass
def get_package_share_directory(name, print_warning=True):
    if name not in _MAP:
        raise PackageNotFoundError(name)
    return _MAP[name]
def get_package_prefix(name):  # <prefix>/share/<name> -> <prefix>
    return os.path.dirname(os.path.dirname(get_package_share_directory(name)))
def get_packages_with_prefixes():
    return {k: os.path.dirname(os.path.dirname(v)) for k, v in _MAP.items()}
''',
}

REAL_RUNNER = '''
import json, os, sys
sys.path.insert(0, os.environ["BENCH_STANDINS"])
import standin_finder  # noqa: F401
import importlib.util
spec = importlib.util.spec_from_file_location(
    "rclpy.parameter", os.path.join(os.environ["BENCH_STANDINS"], "rclpy_parameter.py"))
param_module = importlib.util.module_from_spec(spec); spec.loader.exec_module(param_module)
import rclpy
sys.modules["rclpy.parameter"] = param_module; rclpy.parameter = param_module
import launch, launch.actions
from launch.utilities import perform_substitutions, normalize_to_list_of_substitutions
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.launch_description_sources import PythonLaunchDescriptionSource
import launch_ros.actions
from launch_ros.actions import node as node_mod, load_composable_nodes as lcn
from launch_ros.actions.composable_node_container import ComposableNodeContainer
from launch_ros.utilities import evaluate_parameters, to_parameters_list
from launch_ros.utilities.normalize_parameters import normalize_parameter_dict
from launch_ros.parameter_descriptions import ParameterFile

RECORDS = []

def _value(v):
    return list(v) if isinstance(v, tuple) else v

def _params(context, name, ns, params):
    collected = []
    for param in context.launch_configurations.get("global_params", None) or []:
        if isinstance(param, tuple):
            collected.append(normalize_parameter_dict({param[0]: param[1]}))
        else:
            collected.append(ParameterFile(param))
    collected.extend(params or [])
    if not collected:
        return {}
    out = {}
    evaluated = evaluate_parameters(context, collected)
    for p in to_parameters_list(context, name or "", ns or "", evaluated):
        out[p.name] = _value(p.value)
    return out

def node_execute(self, context):
    self._perform_substitutions(context)
    name = self._Node__expanded_node_name
    ns = self._Node__expanded_node_namespace
    if not ns or ns.startswith("<"):
        ns = ""  # unspecified: the node runs in the root namespace
    full = self.node_name.replace("<node_namespace_unspecified>", "")
    words = [perform_substitutions(context, normalize_to_list_of_substitutions(a))
             for a in (self._Node__arguments or [])]
    if "--ros-args" in words:
        words = words[:words.index("--ros-args")]
    RECORDS.append({
        "name": full if full.startswith("/") else "/" + full, "package": perform_substitutions(
            context, normalize_to_list_of_substitutions(self.node_package)),
        "executable": perform_substitutions(
            context, normalize_to_list_of_substitutions(self.node_executable)),
        "namespace": ns or "/",
        "remaps": [list(r) for r in (self._Node__expanded_remappings or [])],
        "args": " ".join(words), "argv": words,
        "params": _params(context, name, ns, self._Node__parameters),
        "container": None, "composable": False})
    return None

def load_execute(self, context):
    target = self._LoadComposableNodes__target_container
    if isinstance(target, ComposableNodeContainer):
        container = target.node_name
    else:
        container = perform_substitutions(context, normalize_to_list_of_substitutions(target))
    for description in self._LoadComposableNodes__composable_node_descriptions:
        request = lcn.get_composable_node_load_request(description, context)
        if request is None:
            continue
        ns = request.node_namespace if isinstance(request.node_namespace, str) else ""
        name = request.node_name or "<node_name_unspecified>"
        params = request.parameters if isinstance(request.parameters, list) else []
        remaps = request.remap_rules if isinstance(request.remap_rules, list) else []
        RECORDS.append({
            "name": (ns.rstrip("/") + "/" + name) if ns else "/" + name,
            "package": request.package_name, "executable": request.plugin_name,
            "namespace": ns or "", "remaps": [r.split(":=", 1) for r in remaps], "args": "",
            "params": {k: _value(v) for k, v in params}, "container": container,
            "composable": True})
    return None

class _Request:
    """A fresh LoadNode request each time (the stand-in module would share one)."""

    def __init__(self):
        self.package_name = self.plugin_name = self.node_name = self.node_namespace = ""
        self.remap_rules, self.parameters, self.extra_arguments = [], [], []

if not hasattr(launch.substitutions, "PathSubstitution"):
    # launch >= 3.7 (newer than the sources here): a path join whose parts are each a
    # list of substitutions, grown by "/ part"; written for the bench from its documentation
    from launch.substitution import Substitution

    class PathSubstitution(Substitution):
        def __init__(self, path, more=()):
            super().__init__()
            self.parts = [normalize_to_list_of_substitutions(path), *more]

        def __truediv__(self, part):
            return PathSubstitution(self.parts[0], [*self.parts[1:],
                                                    normalize_to_list_of_substitutions(part)])

        def describe(self):
            return "PathSubstitution"

        def perform(self, context):
            return os.path.join(*[perform_substitutions(context, p) for p in self.parts])

    launch.substitutions.PathSubstitution = PathSubstitution

lcn.composition_interfaces.srv.LoadNode.Request = _Request
node_mod.Node.execute = node_execute
launch_ros.actions.LifecycleNode.execute = node_execute
lcn.LoadComposableNodes.execute = load_execute
launch.actions.ExecuteLocal.execute = lambda self, context: None

path = sys.argv[1]
args = json.loads(sys.argv[2])
service = launch.LaunchService(noninteractive=True, debug=bool(os.environ.get("BENCH_DEBUG")))
source = (PythonLaunchDescriptionSource if path.endswith(".py") else AnyLaunchDescriptionSource)
service.include_launch_description(launch.actions.IncludeLaunchDescription(
    source(path), launch_arguments=list(args.items())))
code = service.run(shutdown_when_idle=True)
print("@@RESULT@@" + json.dumps({"code": code, "nodes": RECORDS}, default=str))
'''


def write_standins(folder: str) -> None:
    for rel, text in STANDIN_FILES.items():
        path = os.path.join(folder, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as handle:
            handle.write(textwrap.dedent(text))
        if rel.startswith("bin/"):
            os.chmod(path, 0o755)
    with open(os.path.join(folder, "real_runner.py"), "w") as handle:
        handle.write(REAL_RUNNER)


_INSTALL = re.compile(r"install\s*\(\s*DIRECTORY\s+([^)]*?)\s+DESTINATION\s+share/"
                      r"(?:\$\{PROJECT_NAME\}|[\w-]+)(/[^\s)]*)?", re.S)


def install_tree(packages: dict[str, str], dest: str) -> dict[str, str]:
    """An install-like ``share/<pkg>`` tree (copies), from CMake install(DIRECTORY).

    Both sides then read the same files where ``colcon build`` would put them (for
    example ros2_control_demos installs ``bringup/config`` as ``share/<pkg>/config``).
    Packages without such rules are linked as they are. Returns source file -> installed
    path.
    """
    installed: dict[str, str] = {}

    def merge(src: str, dst: str, depth: int = 0) -> None:
        if depth > 12 or os.path.basename(src) in (".git", "build", "install", "log"):
            return
        if os.path.isdir(src):
            os.makedirs(dst, exist_ok=True)
            for entry in sorted(os.listdir(src)):
                merge(os.path.join(src, entry), os.path.join(dst, entry), depth + 1)
        elif os.path.isfile(src) and not os.path.lexists(dst) and (
                os.path.getsize(src) < 4 * 1024 * 1024):
            shutil.copy2(src, dst)  # a copy, as colcon installs (not a symlink install)
            installed.setdefault(os.path.realpath(src), dst)

    for name, root in packages.items():
        share = os.path.join(dest, "share", name)
        os.makedirs(share, exist_ok=True)
        merge(os.path.join(root, "package.xml"), os.path.join(share, "package.xml"))
        rules: list[tuple[str, str]] = []
        cmake = os.path.join(root, "CMakeLists.txt")
        if os.path.isfile(cmake):
            with open(cmake, errors="replace") as handle:
                text = re.sub(r"#[^\n]*", "", handle.read())
            for match in _INSTALL.finditer(text):
                sub = (match.group(2) or "").strip("/")
                for item in match.group(1).split():
                    if item.isupper():
                        break  # FILES_MATCHING, PATTERN, USE_SOURCE_PERMISSIONS...
                    rules.append((item, sub))
        if not rules:
            rules = [(entry, "") for entry in os.listdir(root) if entry != "package.xml"]
        for item, sub in rules:
            src = os.path.join(root, item.rstrip("/"))
            target = os.path.join(share, sub) if item.endswith("/") else os.path.join(
                share, sub, os.path.basename(item.rstrip("/")))
            merge(src, target)
    return installed


def run_real(python: str, standins: str, path: str, packages: dict[str, str],
             extra_path: list[str], given_env: dict[str, str]) -> dict[str, Any]:
    env = dict(os.environ, BENCH_STANDINS=standins, BENCH_PACKAGES=json.dumps(packages),
               PYTHONPATH=os.pathsep.join(extra_path),
               PATH=os.path.join(standins, "bin") + os.pathsep + os.environ.get("PATH", ""))
    env.update(given_env)
    try:
        done = subprocess.run([python, os.path.join(standins, "real_runner.py"), path, "{}"],
                              capture_output=True, text=True, timeout=60, env=env)
    except subprocess.TimeoutExpired:
        return {"error": "timeout"}
    for line in done.stdout.splitlines():
        if line.startswith("@@RESULT@@"):
            result: dict[str, Any] = json.loads(line[len("@@RESULT@@"):])
            if result["code"] != 0:
                result["error"] = _last_error(done.stderr + done.stdout)
            return result
    return {"error": _last_error(done.stderr)}


def _last_error(text: str) -> str:
    lines = [line for line in text.splitlines() if line.strip()]
    errors = [line for line in lines if "[ERROR]" in line or "Error" in line]
    return (errors or lines or ["no output"])[-1][:200]


def _tag_parameters() -> None:
    """Remember which node each parameter was made for (unnamed nodes share '/?')."""
    from haros_arch.launch.ros2 import nodes

    original = nodes.node_params
    if getattr(original, "bench", False):
        return

    def tagged(runner: Any, *args: Any, **kwargs: Any) -> None:
        before = len(runner.model.params)
        original(runner, *args, **kwargs)
        for param in runner.model.params[before:]:
            param.bench_node_index = len(runner.model.nodes) - 1

    tagged.bench = True  # type: ignore[attr-defined]
    nodes.node_params = tagged


def run_ours(path: str, workspace: Any, env: dict[str, str]) -> dict[str, Any]:
    from haros_arch.launch import load

    _tag_parameters()
    model = load(path, workspace, {}, env)
    params: dict[int, dict[str, Any]] = {}
    for param in model.params:
        index = getattr(param, "bench_node_index", None)
        if index is not None and param.pattern is None:  # (pattern: for the graph)
            params.setdefault(index, {})[str(param.key)] = param.value
    nodes = []
    for index, decl in enumerate(model.nodes):
        ns = decl.namespace.rstrip("/") or "/"
        nodes.append({"name": decl.name, "package": decl.package,
                      "executable": decl.executable, "namespace": ns,
                      "remaps": [list(r) for r in decl.remaps], "args": decl.args,
                      "params": params.get(index, {}), "container": decl.container,
                      "composable": decl.composable,
                      "conditional": ",".join(c.statement for c in decl.conditions)})
    return {"nodes": nodes, "diagnostics": [str(d) for d in model.diagnostics]}


def share_form(source: str, workspace: Any) -> str:
    """A source launch file named as ``ros2 launch pkg file`` finds it: through the
    package's share folder (as ``Workspace.find`` gives it), when installed."""
    from haros_arch.share import share_map

    package = workspace.package_of(source)
    if package is None:
        return source
    real = os.path.realpath(source)
    for relative, file in share_map(package, workspace).items():
        if os.path.realpath(file) == real:
            return os.path.join(package.root, relative)
    return source


def as_installed(result: dict[str, Any], workspace: Any, installed: dict[str, str],
                 prefix: str) -> dict[str, Any]:
    """Our values from a source run, with paths into packages written as installed."""
    from haros_arch.share import install_prefix, share_source

    roots = sorted(((p.root, os.path.join(prefix, "share", n))
                    for n, p in workspace.packages.items()), key=lambda r: -len(r[0]))
    # our install prefix of a package (<install>/<pkg>) is the merged prefix here
    roots += [(str(install_prefix(workspace, n)), prefix) for n in workspace.packages]

    def convert(value: Any) -> Any:
        if isinstance(value, list):
            return [convert(v) for v in value]
        if not isinstance(value, str):
            return value
        if os.path.isabs(value):
            file = installed.get(os.path.realpath(share_source(workspace, value)))
            if file is not None:
                return file
        for root, share in roots:
            value = value.replace(root + os.sep, share + os.sep)
            if value == root:
                value = share
        return value

    for node in result["nodes"]:
        node["params"] = {k: convert(v) for k, v in node["params"].items()}
        node["args"] = convert(node["args"])
        node["remaps"] = convert(node["remaps"])
    return result


def _split(args: str) -> list[str]:
    try:
        return shlex.split(args)
    except ValueError:
        return args.split()


def _norm(value: Any) -> Any:
    if isinstance(value, str) and os.path.isabs(value) and os.path.exists(value):
        return os.path.realpath(value)
    if isinstance(value, list):
        return [_norm(v) for v in value]
    return value


def compare(ours: list[dict[str, Any]], real: list[dict[str, Any]], tally: Counter[str],
            notes: list[str]) -> None:
    def key(node: dict[str, Any]) -> str:
        name = str(node["name"]).replace("<node_name_unspecified>", "?")
        if "?" in name:  # unnamed: tell them apart by what they run
            name += f" [{node['package']}/{node['executable']} {node['args']}]"
        return name

    def keyed(nodes: list[dict[str, Any]]) -> dict[str, dict[str, Any]]:
        out: dict[str, dict[str, Any]] = {}
        for node in nodes:  # same names (unnamed nodes): pair them in launch order
            name, index = key(node), 1
            while (name if index == 1 else f"{name}#{index}") in out:
                index += 1
            out[name if index == 1 else f"{name}#{index}"] = node
        return out

    real_by, ours_by = keyed(real), keyed(ours)
    for name in [n for n in ours_by if "?" in n and n not in real_by]:
        pattern = re.escape(name.split(" [")[0]).replace(re.escape("?"), ".+")
        found = [r for r in real_by if r not in ours_by and re.fullmatch(pattern, r)]
        if len(found) == 1:  # $(anon x): 'x_?' stands for the one real name
            tally["nodes.matched_by_pattern"] += 1
            real_by[name] = real_by.pop(found[0])
    for name in sorted(set(real_by) | set(ours_by)):
        tally["nodes.total"] += 1
        if name not in ours_by:
            tally["nodes.missing_in_ours"] += 1
            notes.append(f"  only real: {name}")
            continue
        if name not in real_by:
            tally["nodes.extra_in_ours"] += 1
            statements = ours_by[name].get("conditional")
            conditional = f" (conditional: {statements})" if statements else ""
            notes.append(f"  only ours: {name}{conditional}")
            continue
        tally["nodes.matched"] += 1
        mine, theirs = ours_by[name], real_by[name]
        for field in ("package", "executable", "namespace", "container", "args"):
            a, b = mine[field], theirs[field]
            if field == "args" and "argv" in theirs:  # one argv, however it is quoted
                a, b = _split(a), theirs["argv"]
            if field == "namespace" and theirs["composable"] and b == "":
                b = a  # an empty request namespace: the container decides
            if field == "container" and isinstance(b, str) and b and not b.startswith("/"):
                b = "/" + b  # <name>/_container/load_node from launch_ros' node, in "/"
            same = a == b
            tally[f"{field}.{'agree' if same else 'differ'}"] += 1
            if not same:
                notes.append(f"  {name} {field}: ours {a!r} real {b!r}")
        same = mine["remaps"] == theirs["remaps"]
        tally[f"remaps.{'agree' if same else 'differ'}"] += 1
        if not same:
            notes.append(f"  {name} remaps: ours {mine['remaps']} real {theirs['remaps']}")
        for pname in sorted(set(mine["params"]) | set(theirs["params"])):
            a, b = mine["params"].get(pname, "<absent>"), theirs["params"].get(pname, "<absent>")
            same = _norm(a) == _norm(b)
            if b == COMMAND_OUTPUT:  # a Command's output: never run, so unknown (None)
                same = a is None
                tally["params.command_output"] += 1
            tally[f"params.{'agree' if same else 'differ'}"] += 1
            if not same:
                notes.append(f"  {name} param {pname}: ours {a!r} real {b!r}"[:240])


FACTS = ("package", "executable", "namespace", "container", "args", "remaps")


def ros2_launch_files(roots: list[str]) -> list[str]:
    """The launch files under ``roots`` by name (``*.launch.py``, ``*_launch.xml`` ...,
    or any .py / .xml / .yaml in a ``launch`` folder), tests left out."""
    files: list[str] = []
    for root in roots:
        for folder, dirs, names in os.walk(root):
            dirs[:] = sorted(d for d in dirs if d not in ("test", "tests", ".git"))
            for name in sorted(names):
                if name.endswith((".launch.py", ".launch.xml", ".launch.yaml", "_launch.py",
                                  "_launch.xml", "_launch.yaml")) or (
                        name.endswith((".py", ".xml", ".yaml"))
                        and os.path.basename(folder) == "launch"):
                    files.append(os.path.join(folder, name))
    return files


def share(agree: int, total: int) -> str:
    return f"{agree}/{total} ({100.0 * agree / total if total else 100.0:.1f}%)"


def summary(counts: Counter[str]) -> str:
    facts = [sum(counts[f"{f}.{k}"] for f in FACTS) for k in ("agree", "differ")]
    params = [counts[f"params.{k}"] for k in ("agree", "differ")]
    return (f"node names {share(counts['nodes.matched'], counts['nodes.total'])}, "
            f"node facts {share(facts[0], sum(facts))}, "
            f"parameters {share(params[0], sum(params))}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("src", help="folder with launch, launch_ros and the target repos")
    parser.add_argument("--real-python", required=True, help="python of the scratch venv")
    parser.add_argument("--targets", nargs="+", required=True,
                        help="folders under SRC whose launch files are compared")
    parser.add_argument("--limit", type=int, default=0)
    parser.add_argument("--launch-share", help="share/launch of the launch sources used "
                        "(default SRC/launch/launch/share/launch)")
    parser.add_argument("--env", action="append", default=[], metavar="NAME=VALUE",
                        help="environment for both sides (e.g. TURTLEBOT3_MODEL=burger)")
    parser.add_argument("--ours-from-source", action="store_true",
                        help="run our side on the source folders (share folders from the "
                        "packages' install rules, haros_arch.share) instead of the "
                        "install-like tree; our path values are compared as installed")
    parser.add_argument("-v", "--verbose", action="store_true")
    options = parser.parse_args()
    from haros_arch.workspace import scan

    roots = [os.path.join(options.src, t) for t in options.targets]
    sources = scan(roots, {})
    prefix = tempfile.mkdtemp(prefix="bench_install_")
    installed = install_tree({n: p.root for n, p in sources.packages.items()}, prefix)
    empty = os.path.join(prefix, "empty")
    os.makedirs(empty)
    given_env = dict(item.split("=", 1) for item in options.env)
    # both sides see the same environment: this process's, the given values, the prefix
    ours_env = dict(os.environ, **given_env, AMENT_PREFIX_PATH=prefix)
    workspace = scan([empty], ours_env)
    packages = {name: os.path.join(prefix, "share", name) for name in sources.packages}
    # launch reads its substitution grammar from share/launch/frontend/grammar.lark
    packages.setdefault("launch", options.launch_share or os.path.join(
        options.src, "launch", "launch", "share", "launch"))
    extra_path = [os.path.join(options.src, "navigation2", "nav2_common")]
    files = ros2_launch_files(roots)
    if options.limit:
        files = files[:options.limit]
    tally: Counter[str] = Counter()
    per_target: dict[str, Counter[str]] = {t: Counter() for t in options.targets}
    with tempfile.TemporaryDirectory() as standins:
        write_standins(standins)
        for source in files:
            rel = os.path.relpath(source, options.src)
            target = next(t for t in options.targets
                          if os.path.realpath(source).startswith(
                              os.path.realpath(os.path.join(options.src, t)) + os.sep))
            mark = Counter(tally)
            try:
                path = installed.get(os.path.realpath(source))
                if path is None:
                    tally["files.not_installed"] += 1
                    print(f"{rel}: not installed by its package; skipped")
                    continue
                real = run_real(options.real_python, standins, path, packages, extra_path,
                                given_env)
                if options.ours_from_source:
                    ours = as_installed(run_ours(share_form(source, sources), sources, ours_env),
                                        sources, installed, prefix)
                else:
                    ours = run_ours(path, workspace, ours_env)
                tally["files"] += 1
                if "error" in real:
                    tally["files.real_failed"] += 1
                    print(f"{rel}: real launch failed: {real['error']}")
                    if options.verbose:
                        print(f"  (ours: {len(ours['nodes'])} nodes)")
                    continue
                tally["files.compared"] += 1
                notes: list[str] = []
                compare(ours["nodes"], real["nodes"], tally, notes)
                status = "agree" if not notes else f"{len(notes)} difference(s)"
                print(f"{rel}: {len(real['nodes'])} real / {len(ours['nodes'])} ours nodes: "
                      f"{status}")
                if options.verbose or notes:
                    for note in (notes if options.verbose else notes[:40]):
                        print(note)
            finally:
                per_target[target].update(tally - mark)
    print("\nper repository (node facts: package, executable, namespace, container, args, "
          "remaps of the nodes both found; parameters of those nodes)")
    for target, counts in per_target.items():
        print(f"  {target}: {counts['files.compared']} file(s) compared, "
              f"{counts['files.real_failed']} the real launch refused; " + summary(counts))
    print("\nsummary")
    for key in sorted(tally):
        print(f"  {key}: {tally[key]}")
    for field in ("package", "executable", "namespace", "container", "args", "remaps",
                  "params"):
        agree, differ = tally[f"{field}.agree"], tally[f"{field}.differ"]
        if agree + differ:
            print(f"  {field}: {agree}/{agree + differ} agree "
                  f"({100.0 * agree / (agree + differ):.1f}%)")
    matched, total = tally["nodes.matched"], tally["nodes.total"]
    if total:
        print(f"  node names: {matched}/{total} found by both ({100.0 * matched / total:.1f}%)")
    return 0


if __name__ == "__main__":
    checkout.announce()
    sys.exit(main())
