"""Fuzz targets: one per reader entry point, seeded from the files under fixtures/.

Each target takes bytes (a mutation of a real input) and runs one reader on them; it may end
with a diagnostic or with the reader's documented error (``ProjectError``, ``QueryError``,
``ModelDataError``, ...), never with another exception, and never after more than
``TIME_BOUND`` seconds (an alarm interrupts it: ``Hang``). ``tests/test_fuzz.py`` runs every
target briefly; ``scripts/fuzz SECONDS`` runs each longer and prints executions and findings.
"""

from __future__ import annotations

import atexit
import json
import shutil
import signal
import tempfile
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager, suppress
from dataclasses import dataclass
from pathlib import Path

from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"
TIME_BOUND = 10.0  # seconds per example
MAX_SEED = 64 * 1024  # bytes of a seed file kept


class Hang(Exception):
    """An example ran past TIME_BOUND."""


@contextmanager
def time_bound(seconds: float = TIME_BOUND) -> Iterator[None]:
    """Interrupt the example with ``Hang`` once it runs past ``seconds`` (main thread only)."""

    fired: list[bool] = []

    def alarm(signum, frame):
        fired.append(True)
        raise Hang(f"example ran past {seconds} s")

    if not hasattr(signal, "SIGALRM"):
        yield
        return
    previous = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    if fired:  # the alarm's exception was swallowed (a gc callback, a library's except)
        raise Hang(f"example ran past {seconds} s")


# -- mutations of real inputs --------------------------------------------------------------

ODD = ["\ud800", "\udfff", "\x00", "\x7f", "\x0c", "\x1b", "\u202e", "\ufeff", "\u2028",
       "\U0001f600", "e\u0301", "\x85"]
HUGE = ["9" * 5000, "10**10", "10**200", "1e400", "-1e400", "nan", "inf", "99999999999999999999"]


def _encode(text: str) -> bytes:
    return text.encode("utf-8", "surrogatepass")


@st.composite
def mutated(draw: st.DrawFn, seeds: list[bytes], tokens: list[str]) -> bytes:
    """A seed with a few mutations: byte flips, truncation, duplication, deep nesting, huge
    numbers, odd unicode (lone surrogates, control characters) and format tokens."""
    data = bytearray(draw(st.sampled_from(seeds)))
    for _ in range(draw(st.integers(0, 4))):
        op = draw(st.integers(0, 7))
        at = draw(st.integers(0, len(data))) if data else 0
        if op == 0 and data:  # byte flip
            i = min(at, len(data) - 1)
            data[i] ^= 1 << draw(st.integers(0, 7))
        elif op == 1:  # truncation
            del data[at:]
        elif op == 2:  # duplicate a slice, maybe many times
            end = draw(st.integers(at, min(len(data), at + 200)))
            data[at:at] = bytes(data[at:end]) * draw(st.sampled_from([1, 2, 10, 1000]))
        elif op == 3:  # deep nesting with the format's own brackets
            open_, close = draw(st.sampled_from(NESTING))
            depth = draw(st.sampled_from([10, 100, 3000]))
            data[at:at] = _encode(open_ * depth + close * depth)
        elif op == 4:
            data[at:at] = _encode(draw(st.sampled_from(HUGE)))
        elif op == 5:
            data[at:at] = _encode(draw(st.sampled_from(ODD)))
        elif op == 6 and tokens:
            data[at:at] = _encode(draw(st.sampled_from(tokens)))
        elif op == 7:
            data[at:at] = draw(st.binary(max_size=8))
    return bytes(data)


NESTING = [("[", "]"), ("{", "}"), ("(", ")"), ("<group>", "</group>"), ("- ", ""),
           ("if(TRUE)\n", "endif()\n"), ("$(eval ", ")")]


def _seeds(patterns: list[str]) -> list[bytes]:
    found = []
    for pattern in patterns:
        for path in sorted(FIXTURES.glob(pattern)):
            if path.is_file() and not path.is_symlink():
                found.append(path.read_bytes()[:MAX_SEED])
    return found or [b""]


# -- a small workspace the readers run in -------------------------------------------------

PACKAGE_XML = ('<?xml version="1.0"?>\n<package format="2"><name>{name}</name>'
               '<version>0.1.0</version><description>d</description>'
               '<maintainer email="m@e.org">m</maintainer><license>BSD</license>'
               '<buildtool_depend>{tool}</buildtool_depend></package>\n')


class _Workspace:
    """A ROS 1 package and a ROS 2 package in a temporary folder, made once per process."""

    def __init__(self) -> None:
        from haros_arch.workspace import scan

        self.root = Path(tempfile.mkdtemp(prefix="haros-arch-fuzz-"))
        atexit.register(shutil.rmtree, self.root, True)
        for name, tool in (("fz1", "catkin"), ("fz2", "ament_cmake"),
                           ("fz3", "ament_python")):
            folder = self.root / "src" / name
            (folder / "launch").mkdir(parents=True)
            (folder / "config").mkdir()
            (folder / "package.xml").write_text(PACKAGE_XML.format(name=name, tool=tool))
            if tool == "ament_python":
                (folder / name).mkdir()
                (folder / name / "__init__.py").write_text("")
            else:
                (folder / "CMakeLists.txt").write_text(f"project({name})\n")
        self.workspace = scan([str(self.root / "src")], {"ROS_DISTRO": "noetic"})

    def write(self, rel: str, data: bytes) -> str:
        path = self.root / "src" / rel
        path.write_bytes(data)
        return str(path)


_WS: _Workspace | None = None


def workspace() -> _Workspace:
    global _WS
    if _WS is None:
        _WS = _Workspace()
    return _WS


# -- the targets ----------------------------------------------------------------------------


def _project(data: bytes) -> None:
    from haros_arch.project import ProjectError, load

    path = workspace().write("project.yaml", data)
    with suppress(ProjectError):
        load(path)


def _package_xml(data: bytes) -> None:
    from haros_arch.manifest import parse_manifest
    from haros_arch.model.source import Location

    path = workspace().write("fz1/package.xml.fuzz", data)
    parse_manifest(path, Location("fz1", "package.xml"), "fz1", {"ROS_DISTRO": "noetic"})


def _cmake(data: bytes) -> None:
    from haros_arch.cmake import interpret

    ws = workspace()
    ws.write("fz1/CMakeLists.txt", data)
    interpret(ws.workspace.packages["fz1"], ws.workspace)


def _launch(rel: str) -> Callable[[bytes], None]:
    def run(data: bytes) -> None:
        from haros_arch.launch import load

        ws = workspace()
        load(ws.write(rel, data), ws.workspace, {"x": "1"}, {"ROS_DISTRO": "noetic"})

    return run


def _rosparam(data: bytes) -> None:
    """rosparam YAML, both through the ROS 1 reader and as a ROS 2 parameter file."""
    from haros_arch.launch import load
    from haros_arch.launch.ros1.params import ParamError, load_yaml

    with suppress(ParamError):
        load_yaml(data.decode("utf-8", "surrogateescape"))
    ws = workspace()
    ws.write("fz2/config/params.yaml", data)
    launch = ws.write("fz2/launch/params.launch.xml",
                      b'<launch><node pkg="fz2" exec="n" name="n">'
                      b'<param from="$(find-pkg-share fz2)/config/params.yaml"/>'
                      b'</node></launch>')
    load(launch, ws.workspace, {}, {"ROS_DISTRO": "humble"})


def _setup_py(data: bytes) -> None:
    """setup.py of an ament_python package: entry points and the share map (data_files),
    both through the one safe evaluator."""
    from haros_arch import pysetup
    from haros_arch.share import share_map

    ws = workspace()
    ws.write("fz3/setup.py", data)
    package = ws.workspace.packages["fz3"]
    ws.workspace.share_maps.pop("fz3", None)  # read again for every example
    pysetup.parse_package(package, ws.workspace)
    share_map(package, ws.workspace)


def _python_node(data: bytes) -> None:
    """A Python node's source (rospy / rclpy), read by the Python node reader."""
    from haros_arch.extract.python import extract_python

    ws = workspace()
    extract_python([ws.write("fz3/fz3/node.py", data)], ws.workspace, package="fz3")


def _xacro(data: bytes) -> None:
    """A robot description, expanded by the xacro reader (its ``${}`` through the one safe
    evaluator), with one argument known and one known only in part; a second file in the
    same folder is there to include."""
    from haros_arch.robot import xacro

    ws = workspace()
    ws.write("fz1/config/part.xacro", b'<robot xmlns:xacro="http://ros.org/wiki/xacro">'
             b'<xacro:property name="w" value="0.5"/><xacro:macro name="m" params="n">'
             b'<link name="${n}"/></xacro:macro></robot>')
    path = ws.write("fz1/config/r.urdf.xacro", data)
    xacro.expand(path, {"x": "1", "u": xacro.partial_text("a_?", "u is not known")},
                 ws.workspace, {"HOME": "/home/u"})


_MODEL_JSON: str | None = None


def _query(data: bytes) -> None:
    from haros_arch.model.load import from_data
    from haros_arch.query import compile, model_scope
    from haros_arch.query.errors import QueryError

    global _MODEL_JSON
    if _MODEL_JSON is None:
        _MODEL_JSON = (FIXTURES / "paper_minimal" / "expected.json").read_text()
    model = from_data(json.loads(_MODEL_JSON))
    text = data.decode("utf-8", "surrogateescape")
    with suppress(QueryError):
        compile(text).run(model_scope(model), max_seconds=5)


def _saved_model(data: bytes) -> None:
    from haros_arch.model.load import ModelDataError, from_data

    try:
        document = json.loads(data)
    except (ValueError, RecursionError):
        return  # not JSON: the CLI's reader says so before the model reader runs
    with suppress(ModelDataError):
        from_data(document)


def _discovery_info(data: bytes) -> None:
    """A ros_discovery_info sample as any participant in the domain may send it: read, or
    None; nothing else."""
    from haros_arch.live.entities import read_entities

    read_entities(data)


def _discovery_seeds() -> list[bytes]:
    try:
        from haros_arch.live.dds_types import BY_WIDTH
    except ImportError:
        return []
    found = []
    for width, (gid, node, info) in BY_WIDTH.items():
        nodes = [node(node_namespace="/ns", node_name=f"n{i}", reader_gid_seq=[gid(
            data=list(range(width)))], writer_gid_seq=[]) for i in range(2)]
        found.append(info(gid=gid(data=[7] * width), node_entities_info_seq=nodes).serialize())
    return found


def _bag(suffix: str) -> Callable[[bytes], None]:
    def run(data: bytes) -> None:
        from haros_arch.live import CaptureError, capture_bag

        with suppress(CaptureError):
            capture_bag(workspace().write(f"fz1/config/f{suffix}", data))

    return run


def _bag_seeds(suffix: str) -> Callable[[], list[bytes]]:
    def seeds() -> list[bytes]:
        try:
            from rosbags.rosbag1 import Writer as Writer1
            from rosbags.rosbag2 import StoragePlugin
            from rosbags.rosbag2 import Writer as Writer2
            from rosbags.typesys import Stores, get_typestore
        except ImportError:
            return []
        with tempfile.TemporaryDirectory(prefix="haros-arch-fuzz-bag-") as made:
            folder = Path(made)
            if suffix == ".bag":
                store = get_typestore(Stores.ROS1_NOETIC)
                with Writer1(folder / "s.bag") as writer:
                    for topic in ("/a", "/b"):
                        writer.add_connection(topic, "std_msgs/msg/String", typestore=store,
                                              callerid="/talker")
                return [(folder / "s.bag").read_bytes()]
            store = get_typestore(Stores.ROS2_HUMBLE)
            with Writer2(folder / "s", version=9, storage_plugin=StoragePlugin.MCAP) as writer:
                for topic in ("/a", "/b"):
                    writer.add_connection(topic, "std_msgs/msg/String", typestore=store)
            return [next((folder / "s").glob("*.mcap")).read_bytes()]

    return seeds


def _query_seeds() -> list[bytes]:
    import yaml

    found = []
    for path in sorted((ROOT / "queries").glob("*.yaml")):
        query = yaml.safe_load(path.read_text()).get("query")
        if isinstance(query, str):
            found.append(query.encode())
    return [*found, b"nodes[name = '/a']", b"count(topics) > 1", b"round(5, 2)"]


@dataclass
class Target:
    name: str
    run: Callable[[bytes], None]
    seed_patterns: list[str]
    tokens: list[str]
    extra_seeds: Callable[[], list[bytes]] | None = None

    def seeds(self) -> list[bytes]:
        return _seeds(self.seed_patterns) + (self.extra_seeds() if self.extra_seeds else [])

    def strategy(self) -> st.SearchStrategy[bytes]:
        return mutated(self.seeds(), self.tokens)

    def check(self, data: bytes) -> float:
        """Run one example under the time bound; the seconds it took."""
        started = time.monotonic()
        with time_bound():
            self.run(data)
        return time.monotonic() - started


EVAL = ["$(eval ", "'{0:{1}}'.format('a', 10**10)", "'%*d' % (10**9, 1)", "'x' * 10**9",
        "range(10**9)", "sum([[1]] * 10**6, [])", "((10**200)**200)**200", "'{0.__class__}'",
        "__import__", ".__class__", "$(arg x)", "$(env HOME)", "$(find fz1)", "$(anon a)",
        "$(dirname)", "$(optenv A b)", "$(var x)", "$(find-pkg-share fz2)"]
ROS1_TOKENS = [*EVAL, '<arg name="y" default="$(arg x)$(arg x)"/>', '<include file="',
               '<group ns="a">', '<node pkg="fz1" type="n" name="n"/>', '<rosparam>',
               '<param name="p" value="', 'if="', '&#', '<!ENTITY']
ROS2_TOKENS = [*EVAL, '<let name="y" value="$(var x)$(var x)"/>', '<include file="',
               '<node pkg="fz2" exec="n" name="n">', 'OpaqueFunction', 'lambda',
               'LaunchConfiguration(', 'DeclareLaunchArgument(', 'for i in ', 'while ', 'def f(',
               'import os', 'IfCondition(', 'PythonExpression([', '**',
               '\nclass A(DeclareLaunchArgument):\n    def __init__(self, *a, **k):\n'
               '        super().__init__(*a, **k)\n', 'A(', 'self.', 'Node.__init__(self, ']
PYTHON_TOKENS = [*EVAL[1:], "glob(", "os.path.join(", "data_files.append(", "+= [", "f'{",
                 ":{10**9}}'", "rospy.Publisher(", "create_publisher(", "for f in ",
                 "[x for x in ", "'%s' % ", ".format(", "import glob", "package_name"]
YAML_TOKENS = ["&a ", "*a", "<<: *a", "!!binary ", "!!python/object ", "deg(", "rad(", "? ",
               "--- ", "...\n", "\t", "\x7f", "\x0c", "{", "[", ": ", "- ", "'", '"']
CMAKE_TOKENS = ["${", "}", "set(a ${a} ${a})", "list(APPEND a ${a})", "string(REGEX MATCH ",
                "(a*)*b", "macro(m)", "function(f)", "foreach(i RANGE 10000)", "while(1)",
                "include(", "add_subdirectory(", "[==[", "]==]", "$ENV{", "endif()", "if("]
XACRO_TOKENS = [*EVAL, "${", "}", "$(arg u)", "$(eval ", '<xacro:property name="p" value="',
                '<xacro:property name="q" value="${p*p}"/>', "${q}", "${p}",
                '<xacro:macro name="m" params="a b:=1 *c">', "</xacro:macro>",
                '<xacro:m a="${a}" b="${b}"><x/></xacro:m>', '<xacro:insert_block name="c"/>',
                '<xacro:include filename="part.xacro"/>', '<xacro:include filename="$(find ',
                '<xacro:if value="', '<xacro:unless value="', '<xacro:call macro="',
                '<xacro:element xacro:name="', "xacro.load_yaml('", "pi/2", "radians(",
                "${[x for x in range(10**6)]}", "&#", "<!ENTITY"]
QUERY_TOKENS = ["round(5, -10**9)", "int(float('1e400'))", "10**10**10", "[", "]", "(", ")",
                "for x in ", "let x := ", "where ", "return ", "count(", "nodes", "topics",
                "'x' * 10**9", "__class__", ".name", "//", "=~", "'\\'", "1e400"]

TARGETS: dict[str, Target] = {t.name: t for t in [
    Target("project", _project, ["*/project*.yaml", "*/*/project*.yaml"],
           [*YAML_TOKENS, "launch: ", "queries: ", "workspace: ", "severity: "]),
    Target("package_xml", _package_xml, ["**/package.xml", "**/manifest.xml"],
           ['condition="$ROS_VERSION == 1"', "<depend>", "<export>", "&#", "<!ENTITY"]),
    Target("cmake", _cmake, ["**/CMakeLists.txt", "**/*.cmake"], CMAKE_TOKENS),
    Target("ros1_launch", _launch("fz1/launch/f.launch"),
           ["launch_ros1/**/*.launch", "launch_ros1/**/*.launch.xml"], ROS1_TOKENS),
    Target("ros2_xml_launch", _launch("fz2/launch/f.launch.xml"),
           ["launch_ros2/**/*.launch.xml", "**/*.launch.xml"], ROS2_TOKENS),
    Target("ros2_yaml_launch", _launch("fz2/launch/f.launch.yaml"),
           ["**/*.launch.yaml"], ROS2_TOKENS + YAML_TOKENS),
    Target("ros2_python_launch", _launch("fz2/launch/f_launch.py"),
           ["**/*_launch.py", "**/*.launch.py"], ROS2_TOKENS),
    Target("rosparam_yaml", _rosparam, ["launch_ros1/**/*.yaml", "launch_ros2/**/config/*.yaml",
                                        "launch_ros2/**/params/*.yaml"], YAML_TOKENS),
    Target("setup_py", _setup_py, ["**/setup.py"], PYTHON_TOKENS),
    Target("python_node", _python_node, ["**/scripts/*.py", "**/nodes/*.py",
                                         "**/src/*/*/*.py"], PYTHON_TOKENS),
    Target("xacro", _xacro, ["robot/**/*.xacro", "robot/**/*.urdf", "**/*.urdf"],
           XACRO_TOKENS),
    Target("query", _query, [], QUERY_TOKENS, _query_seeds),
    Target("saved_model", _saved_model, ["paper_minimal/expected.json"],
           ['"nodes": ', '"configurations": [', "null", "1e400", '"\\ud800"', "[[[[", "{}"]),
    Target("discovery_info", _discovery_info, [], ["\xff\xff\xff\x7f", "\x00" * 24, "/"],
           _discovery_seeds),
    Target("ros1_bag", _bag(".bag"), ["**/*.bag"], ["\xff\xff\xff\x7f", "op=", "callerid="],
           _bag_seeds(".bag")),
    Target("mcap_bag", _bag(".mcap"), ["**/*.mcap"], ["\xff\xff\xff\x7f", "\x89MCAP0\r\n"],
           _bag_seeds(".mcap")),
]}

