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
        ("read", "~diagnostic_period", "double"),  # the Updater's, from its private handle
        ("server", "~set_parameters", "dynamic_reconfigure/Reconfigure"),
        ("subscribe", "scan", "sensor_msgs/LaserScan"),
    ]


def test_realtime_publisher(tmp_path):
    """ROS 1 realtime_tools' RealtimePublisher advertises its topic on the handle it is
    given, built or initialised later, with its queue and latch."""
    root = FIXTURES / "cpp/realtime_publisher"
    result = extract_cpp([str(root / "controller.cpp")], Workspace(root=str(root)),
                         cache_dir=str(tmp_path))
    assert [d for d in result.diagnostics if d.code.startswith("CPP_PARSE")] == []
    assert sorted((c.kind, c.name, c.type, c.queue_size, c.latch) for c in result.calls) == [
        ("publish", "?/joint_states", "sensor_msgs/JointState", 4, False),
        ("publish", "?/odom", "nav_msgs/Odometry", 100, True),
    ]


def test_reconfigure_server_on_given_handle(tmp_path):
    """A dynamic_reconfigure server is named in the namespace of the handle it is given,
    after a mutex or alone (a controller's own controller_nh: ``?/set_parameters``, which
    its host names after the controller; a driver's handle from its caller), and is
    private without one."""
    root = FIXTURES / "cpp/reconfigure_handles"
    result = extract_cpp([str(root / "controller.cpp")], Workspace(root=str(root)),
                         cache_dir=str(tmp_path))
    assert [d for d in result.diagnostics if d.code.startswith("CPP_PARSE")] == []
    servers = sorted((c.name, c.handle_namespace) for c in result.calls if c.kind == "server")
    assert servers == [("?/gains/set_parameters", "?/gains"), ("?/set_parameters", "?"),
                       ("set_parameters", None), ("~camera/set_parameters", "~camera"),
                       ("~set_parameters", "~")]
    # its two topics in the same handle's namespace (filled from the call sites alike)
    topics = sorted((c.name, c.handle_namespace) for c in result.calls if c.kind == "publish")
    assert topics == sorted(
        (f"{ns}{t}", namespace)
        for ns, namespace in (("?/gains/", "?/gains"), ("?/", "?"), ("", None),
                              ("~camera/", "~camera"), ("~", "~"))
        for t in ("parameter_descriptions", "parameter_updates"))
