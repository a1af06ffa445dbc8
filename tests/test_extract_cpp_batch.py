"""The C++ stage over a whole workspace: every translation unit of every node parsed once
(a library source shared by an executable and a nodelet too), in worker processes,
through a cache that a later process reads; the CLI's --no-cache and --jobs."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from haros_arch import cli, cmake
from haros_arch.extract import cpp, extract_node, extract_nodes
from haros_arch.extract.cpp import headers
from haros_arch.model.source import Node
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import Workspace, scan

SHARED = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "shared"
ENV = {"PATH": os.environ.get("PATH", "")}


def calls(node: Node) -> list[tuple[object, ...]]:
    return [(c.kind, c.name, c.type, c.queue_size, c.latch, c.location.file, c.location.line)
            for c in node.calls]


def nodes_of(workspace: Workspace) -> list[Node]:
    found: list[Node] = []
    for package in workspace.packages.values():
        package.nodes, _ = cmake.parse_package(package, workspace)
        found.extend(package.nodes)
    return found


@pytest.fixture
def copy(tmp_path: Path) -> Path:
    target = tmp_path / "ws"
    shutil.copytree(SHARED, target)
    return target


@pytest.fixture
def counted(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    parses: list[str] = []
    real = cpp._parse

    def counting(path: str, *args: object) -> object:
        parses.append(os.path.basename(path))
        return real(path, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(cpp, "_parse", counting)
    return parses


def test_shared_library_source_is_parsed_once(counted: list[str]) -> None:
    workspace = scan([str(SHARED)])
    nodes = {n.name: n for n in nodes_of(workspace)}
    assert sorted(nodes) == ["relay/relay", "relay/relay/RelayNodelet", "ticker/ticker"]
    extract_nodes(list(nodes.values()), workspace, cache_dir=None, jobs=1)
    assert sorted(counted) == ["relay.cpp", "relay_main.cpp", "relay_nodelet.cpp",
                               "ticker.cpp"]
    # the handles come from each node's own file (links: across translation units)
    library = [("read", "~min_range", "double", None, False, "src/relay/src/relay.cpp", 6),
               ("subscribe", "range_in", "std_msgs/Float32", 5, False,
                "src/relay/src/relay.cpp", 7),
               ("publish", "range_out", "std_msgs/Float32", 5, False,
                "src/relay/src/relay.cpp", 8)]
    assert calls(nodes["relay/relay"]) == library
    assert nodes["relay/relay"].rosname == "range_relay"
    assert calls(nodes["relay/relay/RelayNodelet"]) == [
        ("publish", "~ready", "std_msgs/Empty", 1, True, "src/relay/src/relay_nodelet.cpp", 13),
        *library]


def test_batch_equals_node_by_node() -> None:
    workspace = scan([str(SHARED)])
    batch = nodes_of(workspace)
    extract_nodes(batch, workspace, cache_dir=None, jobs=1)
    single = nodes_of(scan([str(SHARED)]))
    for node in single:
        extract_node(node, scan([str(SHARED)]))
    assert [calls(n) for n in batch] == [calls(n) for n in single]
    assert [n.rosname for n in batch] == [n.rosname for n in single]


def test_ros_version_is_read_per_translation_unit() -> None:
    """A ROS 2 source in the batch must not make ROS 1 types look like ROS 2 ones."""
    workspace = scan([str(SHARED)])
    nodes = {n.name: n for n in nodes_of(workspace)}
    extract_nodes(list(nodes.values()), workspace, cache_dir=None, jobs=1)
    assert {c.type for c in nodes["relay/relay"].calls} == {"double", "std_msgs/Float32"}
    ticker = nodes["ticker/ticker"].calls
    assert [(c.name, c.type, c.qos) for c in ticker] == [
        ("tick", "std_msgs/msg/UInt32", {"depth": 3, "history": "keep_last",
                                         "reliability": "reliable",
                                         "durability": "volatile"})]


def test_worker_processes_give_the_same_result() -> None:
    serial = nodes_of(scan([str(SHARED)]))
    extract_nodes(serial, scan([str(SHARED)]), cache_dir=None, jobs=1)
    workspace = scan([str(SHARED)])
    parallel = nodes_of(workspace)
    found = extract_nodes(parallel, workspace, cache_dir=None, jobs=2)
    assert [calls(n) for n in parallel] == [calls(n) for n in serial]
    assert len(found) == len(set(found))  # a shared source reports its findings once


def test_cache_written_by_another_process_is_used(copy: Path, tmp_path: Path,
                                                  counted: list[str],
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    store = tmp_path / "cache"
    script = ("import sys; from haros_arch.workspace import scan; "
              "from haros_arch.extract.cpp import extract_cpp_nodes; "
              "ws = scan([sys.argv[1]]); "
              "extract_cpp_nodes([[sys.argv[2]], [sys.argv[3]]], ws, cache_dir=sys.argv[4])")
    main = str(copy / "src" / "relay" / "src" / "relay_main.cpp")
    ticker = str(copy / "src" / "ticker" / "src" / "ticker.cpp")
    subprocess.run([sys.executable, "-c", script, str(copy), main, ticker, str(store)],
                   check=True, cwd=Path(__file__).resolve().parent.parent)
    written: list[str] = []
    real_write = headers.write_whole
    monkeypatch.setattr(headers, "write_whole", lambda path, text: written.append(path))
    workspace = scan([str(copy)])
    batch = cpp.extract_cpp_nodes([[main], [ticker]], workspace, cache_dir=str(store))
    assert counted == []  # nothing parsed: the PCH path of the other process is no key
    assert written == []  # and no synthesised header written to disk
    assert [c.name for c in batch.results[1].calls] == ["tick"]
    (copy / "src" / "relay" / "include" / "relay" / "relay.h").write_text(
        (copy / "src" / "relay" / "include" / "relay" / "relay.h").read_text() + "\n// x\n")
    monkeypatch.setattr(headers, "write_whole", real_write)
    cpp.extract_cpp_nodes([[main], [ticker]], scan([str(copy)]), cache_dir=str(store))
    assert counted == ["relay_main.cpp"]  # only the unit whose header changed


def test_pipeline_extracts_every_package_in_one_batch(copy: Path, tmp_path: Path,
                                                      counted: list[str]) -> None:
    project = load(str(copy / "project.yaml"))
    model = analyse(project, ENV, Options(cache_dir=str(tmp_path / "cache"), jobs=1))
    nodes = {n.name: n for p in model.packages for n in p.nodes}
    assert len(counted) == 4
    assert nodes["relay/relay/RelayNodelet"].calls[0].name == "~ready"
    counted.clear()
    analyse(project, ENV, Options(cache_dir=str(tmp_path / "cache"), jobs=1))
    assert counted == []
    analyse(project, ENV, Options(cache_dir=None, jobs=1))
    assert len(counted) == 4


def test_cli_no_cache_and_jobs(copy: Path, tmp_path: Path,
                               monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    project, out = str(copy / "project.yaml"), str(tmp_path / "model.json")
    assert cli.main(["extract", project, "-q", "-o", out, "--no-cache", "--jobs", "1"]) == 0
    assert not (tmp_path / "xdg").exists()
    assert cli.main(["check", project, "--no-cache", "--fail-on", "never",
                     "-o", str(tmp_path / "check.txt")]) == 0
    assert not (tmp_path / "xdg").exists()
    assert cli.main(["extract", project, "-q", "-o", out, "--jobs", "2"]) == 0
    assert list((tmp_path / "xdg" / "haros-arch" / "cpp").glob("*.json"))
    parsed = cli._parser().parse_args(["report", project, "-o", "r.html", "--no-cache",
                                       "--jobs", "0"])
    assert cli._options(parsed) == Options(cache_dir=None, jobs=1)


def test_a_header_every_unit_includes_is_read_once(write_tree, monkeypatch) -> None:
    """The include scan before parsing reads a workspace header once per run, however
    many units include it, and gives each unit the same calls."""
    unit = """
        #include <ros/ros.h>
        #include "talk/names.h"
        int main(int argc, char** argv) {{
          ros::init(argc, argv, "{0}");
          ros::NodeHandle n;
          n.advertise<std_msgs::String>(TOPIC, 1);
          return 0;
        }}
        """
    root = write_tree({
        "src/talk/package.xml": "<package><name>talk</name></package>",
        "src/talk/include/talk/names.h": '#include <std_msgs/String.h>\n'
                                         '#define TOPIC "chatter"\n',
        **{f"src/talk/src/{name}.cpp": unit.format(name) for name in ("a", "b", "c")}})
    read: list[str] = []
    real = headers.read_text

    def reading(path: str, *args: object, **kwargs: object) -> object:
        read.append(os.path.basename(path))
        return real(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(headers, "read_text", reading)
    workspace = scan([str(root / "src")], ENV)
    nodes = [Node("talk", name, sources=[f"talk/src/{name}.cpp"]) for name in "abc"]
    extract_nodes(nodes, workspace, cache_dir=None, jobs=1)
    assert read.count("names.h") == 1
    assert [[(c.kind, c.name) for c in n.calls] for n in nodes] == [
        [("publish", "chatter")]] * 3
