"""ros2_control's controllers and hardware components in a workspace without ros2_control's
sources (installed from Debian packages, as in most robot workspaces): the stand-ins of
``standin/fallback`` give controller_interface's base classes, get_node() and auto_declare,
hardware_interface's handles and components; a workspace that has the package's sources
is read with its own headers, never with the stand-ins."""

from __future__ import annotations

import os

import pytest

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.extract.cpp import CppResult, api, extract_cpp, toolchain
from haros_arch.extract.cpp.headers import FALLBACK, IncludeSetup, _fallback_file
from haros_arch.workspace import scan
from tests.conftest import package_xml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "ros2_control")
INSTALLED = os.path.join(ROOT, "src")  # the controller package alone
PACKAGE = os.path.join(INSTALLED, "wheel_speed_controller")
CONTROLLER = os.path.join(PACKAGE, "src", "wheel_speed_controller.cpp")
SYSTEM = os.path.join(PACKAGE, "src", "two_wheel_system.cpp")
# what a unit the stand-ins parse cleanly has none of
UNCLEAN = ("CPP_PARSE_ERROR", "CPP_MESSAGE_FIELD", "CPP_INCLUDE_MISSING", "CPP_CALL_UNRESOLVED",
           "CPP_NAMES_DECLARED", "CPP_ERROR_NEAR_CALL")


def _rows(result: CppResult) -> list[tuple[str, str, str | None, int]]:
    return [(c.kind, c.name, c.type, c.location.line) for c in result.calls]


@pytest.fixture(scope="module")
def controller() -> CppResult:
    return extract_cpp([CONTROLLER], scan([INSTALLED]), cache_dir=None)


def test_controller_calls_through_get_node_and_auto_declare(controller: CppResult) -> None:
    assert _rows(controller) == [
        ("declare", "wheel_names", "str[]", 19),
        ("declare", "wheel_radius", "double", 20),
        ("declare", "wheel_separation", "double", 52),
        ("subscribe", "~cmd_vel", "geometry_msgs/msg/TwistStamped", 54),
        ("publish", "~wheel_speeds", "std_msgs/msg/Float64MultiArray", 59),
        ("server", "~reset", "std_srvs/srv/Empty", 64),
    ]
    declared = [c for c in controller.calls if c.kind == "declare"]
    assert [c.has_default for c in declared] == [True, True, True]


def test_controller_parses_cleanly(controller: CppResult) -> None:
    """The base class, loaned interfaces, helpers, realtime_tools' box and publisher and
    std::ignore are all declared: every call resolves, nothing is synthesised."""
    assert [(d.code, d.message) for d in controller.diagnostics if d.code in UNCLEAN] == []


def test_hardware_component_humble_and_jazzy_api() -> None:
    """on_init(HardwareInfo), vectors of interfaces made on doubles (Humble), info_,
    lexical casts, and the component's own node (Jazzy's get_node())."""
    result = extract_cpp([SYSTEM], scan([INSTALLED]), cache_dir=None)
    assert [(d.code, d.message) for d in result.diagnostics if d.code in UNCLEAN] == []
    assert _rows(result) == [("publish", "~slowdown", "std_msgs/msg/Float64", 40)]


def test_the_controller_node_is_complete() -> None:
    workspace = scan([INSTALLED])
    package = workspace.packages["wheel_speed_controller"]
    package.nodes, _ = cmake.parse_package(package, workspace)
    nodes = [n for n in package.nodes if n.language == "cpp"]
    found = extract_nodes(nodes, workspace, cache_dir=None, jobs=1)
    node = next(n for n in nodes if n.name.endswith("WheelSpeedController"))
    assert ("subscribe", "~cmd_vel") in [(c.kind, c.name) for c in node.calls]
    assert not [d for d in found if d.code == "CPP_NODE_PARTIAL"]


def test_auto_declare_is_a_parameter_declaration() -> None:
    row = api.ALL[("controller_interface::ControllerInterfaceBase", "auto_declare")]
    assert (row.kind, row.name_arg, row.default_arg) == ("declare", 0, 1)


def test_the_workspace_headers_win_over_the_stand_ins() -> None:
    """With controller_interface's sources in the workspace, its header is read: its
    auto_declare, defined there, declares or reads (a wrapper of the node's calls); the
    headers it lacks (hardware_interface) still come from the stand-ins."""
    result = extract_cpp([CONTROLLER], scan([ROOT]), cache_dir=None)
    assert _rows(result)[:4] == [
        ("read", "wheel_names", None, 19),
        ("declare", "wheel_names", "str[]", 19),
        ("read", "wheel_radius", None, 20),
        ("declare", "wheel_radius", "double", 20),
    ]
    setup = IncludeSetup(scan([ROOT]), [], False, sources=[CONTROLLER])
    try:
        with open(CONTROLLER, encoding="utf-8") as handle:
            assert setup.scan(CONTROLLER, handle.read())  # ROS 2 code
        written = {os.path.relpath(p, setup.generated) for p in setup.written}
        assert "hardware_interface/loaned_command_interface.hpp" in written
        assert not [h for h in written if h.startswith("controller_interface/")]
    finally:
        setup.close()


def test_a_stand_in_that_includes_rclcpp_makes_the_unit_ros2() -> None:
    """A unit that includes only ros2_control headers is ROS 2 code by its headers (what
    ``_is_ros2`` goes by when the package's manifest does not tell): the stand-in it reads
    includes rclcpp."""
    setup = IncludeSetup(scan([INSTALLED]), [], False)
    try:
        text = '#include "controller_interface/controller_interface.hpp"\n'
        assert setup.scan(os.path.join(PACKAGE, "src", "other.cpp"), text)
        assert not setup.scan(os.path.join(PACKAGE, "src", "plain.cpp"), "#include <vector>\n")
    finally:
        setup.close()


def test_a_header_name_that_leads_out_of_the_stand_ins_has_none() -> None:
    """``../rclcpp/rclcpp.hpp`` is not FALLBACK's (with the system's headers, it would
    otherwise bring in our rclcpp stand-in)."""
    assert _fallback_file("controller_interface/helpers.hpp") == os.path.join(
        FALLBACK, "controller_interface", "helpers.hpp")
    assert _fallback_file("controller_interface/../hardware_interface/handle.hpp") == (
        os.path.join(FALLBACK, "hardware_interface", "handle.hpp"))
    assert _fallback_file("../rclcpp/rclcpp.hpp") is None
    assert _fallback_file(os.path.join(FALLBACK, "controller_interface", "helpers.hpp")) is None
    assert _fallback_file("controller_interface/missing.hpp") is None


def test_every_fallback_header_parses_without_error(write_tree) -> None:
    """Each stand-in of FALLBACK parses, included alone (what it uses, it includes) and
    all together (clang's errors inside a stand-in are never reported as the unit's: a
    mistake there would go unseen)."""
    headers = sorted(os.path.relpath(os.path.join(folder, name), FALLBACK)
                     for folder, _, names in os.walk(FALLBACK) for name in names)
    assert len(headers) > 20
    files = {"user/package.xml": package_xml("user", "ament_cmake")}
    files.update({f"user/src/unit{i}.cpp": f"#include <{h}>\n" for i, h in enumerate(headers)})
    files["user/src/all.cpp"] = "".join(f"#include <{h}>\n" for h in headers)
    root = write_tree(files)
    sources = [str(p) for p in sorted((root / "user" / "src").iterdir())]
    setup = IncludeSetup(scan([str(root)]), [], False, sources=sources)
    try:
        for source in sources:
            with open(source, encoding="utf-8") as handle:
                setup.scan(source, handle.read())
        setup.materialise()
        for source in sources:
            tu = toolchain.index().parse(source, args=setup.arguments(source=source))
            errors = [(source, d.spelling) for d in tu.diagnostics if d.severity >= 3
                      and d.location.file is not None
                      and d.location.file.name.startswith(FALLBACK + os.sep)]
            assert errors == []
    finally:
        setup.close()
