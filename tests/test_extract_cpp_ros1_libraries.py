"""dynamic_reconfigure, diagnostic_updater and tf2 message filters parse with stand-ins and
give the topics and services they create."""

from __future__ import annotations

from conftest import FIXTURES

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace


def test_ros1_helper_libraries(tmp_path):
    root = FIXTURES / "cpp/ros1_libraries"
    result = extract_cpp([str(root / "node.cpp")], Workspace(root=str(root)),
                         cache_dir=str(tmp_path))
    assert [d for d in result.diagnostics if d.code.startswith("CPP_PARSE")] == []
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "/diagnostics", "diagnostic_msgs/DiagnosticArray"),
        ("publish", "out", "sensor_msgs/LaserScan"),
        ("publish", "~parameter_descriptions", "dynamic_reconfigure/ConfigDescription"),
        ("publish", "~parameter_updates", "dynamic_reconfigure/Config"),
        ("server", "~set_parameters", "dynamic_reconfigure/Reconfigure"),
        ("subscribe", "scan", "sensor_msgs/LaserScan"),
    ]
