"""A unit whose analysis does not end (ros2_canopen's ``using FiberDriver::FiberDriver;``
once made the synthesised names a cycle that was walked for ever) is stopped after
``UNIT_CPU_SECONDS`` of processor time: that unit gives no calls and says so
(CPP_TIME_LIMIT, its node partial), and the other units are analysed as before."""

from __future__ import annotations

import time

import pytest
from conftest import package_xml

from haros_arch import processes
from haros_arch.extract import cpp
from haros_arch.extract.cpp import cursors, toolchain, visitor
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {{
  ros::init(argc, argv, "{name}");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("{name}_out", 1);
}}
"""


def _busy(seconds: float) -> None:
    end = time.process_time() + seconds
    while time.process_time() < end:
        pass


def _workspace(tmp_path):
    (tmp_path / "package.xml").write_text(package_xml("pkg").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    paths = []
    for name in ("stuck", "fine"):
        path = tmp_path / f"{name}.cpp"
        path.write_text(SOURCE.format(name=name))
        paths.append(str(path))
    return paths, scan([str(tmp_path)])


def test_a_unit_past_its_time_gives_no_calls_and_the_run_goes_on(tmp_path, monkeypatch):
    paths, workspace = _workspace(tmp_path)
    run = visitor.CallFinder.run

    def looping(self) -> None:
        if self.tu.spelling.endswith("stuck.cpp"):
            while True:  # the analysis of this unit never ends
                pass
        run(self)

    monkeypatch.setattr(cpp, "UNIT_CPU_SECONDS", 1.0)
    monkeypatch.setattr(visitor.CallFinder, "run", looping)
    monkeypatch.setattr(cpp, "CallFinder", visitor.CallFinder)
    result = cpp.extract_cpp(paths, workspace, cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "fine_out")]
    stopped = [d for d in result.diagnostics if d.code == "CPP_TIME_LIMIT"]
    assert [(d.location.file.rsplit("/", 1)[-1], d.severity) for d in stopped] == [
        ("stuck.cpp", "error")]
    assert "1 s of processor time" in stopped[0].message
    assert processes.held_signals.requested is None


def test_the_limit_comes_at_the_end_of_a_visit_it_passes_in(monkeypatch):
    """Within a call into libclang that runs our callbacks the limit is held (ctypes
    would print the exception and go on) and raised when the call ends."""
    asked: list[int] = []

    def judged(_judge):
        def of(_location):
            if not asked:
                _busy(0.5)  # past the limit, in the visit's first callback
            asked.append(1)
            return True
        return of

    monkeypatch.setattr(cursors, "by_file", judged)
    unit = cursors.root(toolchain.index().parse(
        "three.cpp", args=["-x", "c++", "-std=c++17", "-nostdinc"],
        unsaved_files=[("three.cpp", "int a;\nint b;\nint c;\n")]))
    with pytest.raises(processes.OverTime), processes.cpu_limit(0.2):
        cursors.children_in(unit, lambda _name: True)
    assert len(asked) == 3  # the visit went on to its end, then the limit was raised
    assert processes.held_signals.requested is None
    with processes.cpu_limit(5.0):  # a block within its time ends as it would
        assert len(cursors.children_in(unit, lambda _name: False)) == 3
