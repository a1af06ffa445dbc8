"""compile_commands.json: each translation unit parsed with its own include folders,
macros and standard; the file is untrusted data (bounded, only flags we understand, no
folder outside the workspace, our stand-ins still first for ROS headers)."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import pytest

from haros_arch import compile_commands
from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.workspace import scan

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "compile_db"


def calls(result: object) -> list[tuple[object, ...]]:
    return [(c.kind, c.name, c.type, c.queue_size)
            for c in result.calls]  # type: ignore[attr-defined]


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    """The fixture with a catkin-style build folder beside src/ holding the commands."""
    root = tmp_path / "ws"
    shutil.copytree(FIXTURE, root)
    return root


def write_commands(ws: Path, entries: list[dict[str, object]],
                   where: str = "build/compile_commands.json") -> Path:
    path = ws / where
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(entries))
    return path


def driver_entry(ws: Path, *flags: str) -> dict[str, object]:
    source = ws / "src" / "lidar" / "src" / "driver.cpp"
    return {"directory": str(ws / "build" / "lidar"), "file": str(source),
            "arguments": ["/usr/bin/c++", *flags, "-o", "driver.o", "-c", str(source)]}


def extract(ws: Path, **options: object) -> object:
    source = ws / "src" / "lidar" / "src" / "driver.cpp"
    return extract_cpp([str(source)], scan([str(ws / "src")]), cache_dir=None,
                       **options)  # type: ignore[arg-type]


FULL = [("publish", "scan", "sensor_msgs/LaserScan", 4),
        ("publish", "health", "std_msgs/String", 1),
        ("publish", "laser/status", "std_msgs/String", 1)]
LOST = [("publish", "scan", "sensor_msgs/LaserScan", 4),
        ("publish", "lidar_link/status", "std_msgs/String", 1)]


def test_flags_of_the_unit_are_used(ws: Path) -> None:
    config = ws / "src" / "lidar" / "config"
    write_commands(ws, [driver_entry(ws, "-DWITH_HEALTH", '-DLIDAR_FRAME="laser"',
                                     "-I", str(config), "-std=gnu++14")])
    result = extract(ws)
    assert calls(result) == FULL
    assert result.diagnostics == []  # type: ignore[attr-defined]


def test_without_the_file_the_cmake_gives_the_macros(ws: Path) -> None:
    # the CMakeLists defines WITH_HEALTH and LIDAR_FRAME for the target (under the
    # option WITH_HEALTH, ON by default): applied (``build_macros.cmake_flags``); the
    # include folder it gives (config) too: the scan topic's header is read
    result = extract(ws)
    assert calls(result) == FULL
    assert "CPP_INCLUDE_MISSING" not in [d.code for d in result.diagnostics]  # type: ignore[attr-defined]


def without_cmake_macros(ws: Path) -> None:
    """The CMakeLists without its ``target_compile_definitions``: the unit's macros can
    come from a compile command only."""
    cmake = ws / "src" / "lidar" / "CMakeLists.txt"
    cmake.write_text(cmake.read_text().replace("target_compile_definitions", "message"))


def test_without_the_file_what_depends_on_flags_is_lost(ws: Path) -> None:
    without_cmake_macros(ws)
    # the macros the build would give (WITH_HEALTH, LIDAR_FRAME) are lost
    assert calls(extract(ws)) == LOST


def test_without_the_file_nor_the_cmake_folder_the_header_is_lost(ws: Path) -> None:
    cmake = ws / "src" / "lidar" / "CMakeLists.txt"
    cmake.write_text(cmake.read_text().replace("include_directories(config ", "(config "))
    result = extract(ws)
    # the missing header's macros (LIDAR_SCAN_TOPIC, LIDAR_QUEUE) are declared as
    # values: the scan publisher is kept, its name and queue size unknown
    assert calls(result) == [("publish", "?", "sensor_msgs/LaserScan", None),
                             ("publish", "lidar_link/status", "std_msgs/String", 1)]
    assert "CPP_INCLUDE_MISSING" in [d.code for d in result.diagnostics]  # type: ignore[attr-defined]


def test_command_string_with_relative_folders(ws: Path) -> None:
    source = ws / "src" / "lidar" / "src" / "driver.cpp"
    command = ("/usr/bin/c++ -DWITH_HEALTH '-DLIDAR_FRAME=\"laser\"' "
               f"-I../../src/lidar/config -o driver.o -c {source}")
    write_commands(ws, [{"directory": str(ws / "build" / "lidar"), "file": str(source),
                         "command": command}], "build/lidar/compile_commands.json")
    assert calls(extract(ws)) == FULL  # a colcon-style per-package file is found too


def test_stand_ins_stay_first_and_unknown_flags_are_dropped(ws: Path) -> None:
    vendor = ws / "src" / "vendor"  # holds a ros/ros.h that is an #error
    write_commands(ws, [driver_entry(
        ws, "-I", str(vendor), f"-I{ws / 'src' / 'lidar' / 'config'}", "-I/usr/include",
        "-isystem", "/opt/ros/noetic/include", "-include", "/etc/hostname",
        "-fplugin=evil.so", "-Xclang", "-load", "-DWITH_HEALTH", "-D", "1BAD", "-std=c++99x",
        '-DLIDAR_FRAME="laser"')])
    result = extract(ws)
    assert calls(result) == FULL
    flags, problems = compile_commands.load([str(ws / "build" / "compile_commands.json")],
                                            scan([str(ws / "src")]))
    assert problems == []
    (unit,) = flags.values()
    assert unit.include_dirs == (str(vendor), str(ws / "src" / "lidar" / "config"))
    assert unit.macros == ("-DWITH_HEALTH", '-DLIDAR_FRAME="laser"')
    assert unit.std is None


@pytest.mark.parametrize("text", ["{not json", '{"a": 1}', "[" * 100_000])
def test_bad_file_is_a_diagnostic(ws: Path, text: str) -> None:
    without_cmake_macros(ws)
    path = ws / "build" / "compile_commands.json"
    path.parent.mkdir(parents=True)
    path.write_text(text)
    result = extract(ws)
    codes = [d.code for d in result.diagnostics]  # type: ignore[attr-defined]
    assert "CPP_COMPILE_COMMANDS" in codes
    assert calls(result) == LOST


def test_size_is_bounded(ws: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    without_cmake_macros(ws)
    write_commands(ws, [driver_entry(ws, "-DWITH_HEALTH")])
    monkeypatch.setattr(compile_commands, "MAX_BYTES", 16)
    result = extract(ws)
    (problem,) = result.diagnostics[:1]  # type: ignore[attr-defined]
    assert problem.code == "CPP_COMPILE_COMMANDS" and "larger than" in problem.message
    assert ("publish", "health", "std_msgs/String", 1) not in calls(result)


def test_malformed_entries_are_skipped(ws: Path) -> None:
    good = driver_entry(ws, "-DWITH_HEALTH")
    write_commands(ws, [3, {"file": 1}, {"directory": "relative", "file": "x.cpp",
                                         "arguments": []},
                        {"directory": "/", "file": "a.cpp", "arguments": [1, 2]},
                        {"directory": "/", "file": "b.cpp", "command": "c++ 'unclosed"},
                        good])
    assert ("publish", "health", "std_msgs/String", 1) in calls(extract(ws))


def test_project_key_names_the_folder_and_flags_key_the_cache(ws: Path,
                                                              tmp_path: Path) -> None:
    elsewhere = tmp_path / "out"
    path = write_commands(ws, [driver_entry(ws, "-DWITH_HEALTH")],
                          "../out/compile_commands.json")
    assert path.resolve().parent == elsewhere
    project_file = ws / "project.yaml"
    project_file.write_text("project: lidar\nworkspace: src\ncompile_commands: ../out\n")
    project = load(str(project_file))
    assert project.compile_commands == str(elsewhere)
    store = str(tmp_path / "cache")

    def published() -> list[str]:
        model = analyse(project, {}, Options(cache_dir=store, jobs=1))
        (node,) = [n for p in model.packages for n in p.nodes]
        return [c.name for c in node.calls]

    # no -I of the topics header: the CMakeLists' include folder finds it
    assert published() == ["scan", "health", "lidar_link/status"]
    write_commands(ws, [driver_entry(ws, '-DLIDAR_FRAME="laser"')],
                   "../out/compile_commands.json")
    assert published() == ["scan", "laser/status"]  # new flags: not the cached result
    assert os.path.isdir(os.path.join(store, "cpp"))
