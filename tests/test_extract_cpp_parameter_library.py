"""generate_parameter_library: the header it writes at build time (``<project>/<target>.hpp``)
is synthesised from the YAML its CMake call names, and a ``ParamListener`` built on the
node declares every parameter of the YAML there, typed, with its default."""

from __future__ import annotations

import os
import shutil

import pytest

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.extract.cpp import parameter_library as gpl
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "parameter_library", "src")
PACKAGE = os.path.join(ROOT, "joint_gain_controller")
CONTROLLER = os.path.join(PACKAGE, "src", "joint_gain_controller.cpp")
YAML = os.path.join(PACKAGE, "src", "joint_gain_controller_parameters.yaml")
UNCLEAN = ("CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_CALL_UNRESOLVED",
           "CPP_NAMES_DECLARED", "CPP_ERROR_NEAR_CALL", "CPP_PARAMETER_LIBRARY")
DECLARED = [
    ("joints", "str[]", True, ["shoulder", "elbow"], None),
    ("interface_name", "str", True, "position", None),
    ("update_rate", "int", True, 100, None),
    ("command_joints", "str[]", True, [], None),
    ("open_loop", "bool", True, False, None),
    ("limits.max_velocity", "double", True, 1.5, None),
    ("limits.max_effort", "double", False, None, None),  # no default_value: required
    # __map_joints: one per element of ``joints`` in the configuration (the graph names
    # them from its value, else its default)
    ("gains.?.p", "double", True, 1.0, "joints"),
    ("gains.?.i", "double", True, 0.0, "joints"),
    ("feedforward.?.scale", "double", True, 1.0, "command_joints"),
]


@pytest.fixture(scope="module")
def controller() -> CppResult:
    return extract_cpp([CONTROLLER], scan([ROOT]), cache_dir=None)


def _declares(result: CppResult, line: int
              ) -> list[tuple[str, str | None, bool, object, str | None]]:
    """Each declare's (name, type, has default, default, the list parameter whose
    elements name it)."""
    found = [(c.name, c.type, c.has_default, c.default, c.name_param) for c in result.calls
             if c.kind == "declare" and c.location.line == line]
    assert all((c.name_each == ".") == (c.name_param is not None) for c in result.calls
               if c.kind == "declare" and c.location.line == line)
    return found


def test_cmake_records_the_target_and_its_yaml() -> None:
    workspace = scan([ROOT])
    interpreter, _ = cmake.interpret(workspace.packages["joint_gain_controller"], workspace)
    assert interpreter.parameter_libraries == [
        ("joint_gain_controller_parameters", YAML, "joint_gain_controller")]


def test_the_listener_declares_every_parameter_of_the_yaml(controller: CppResult) -> None:
    # std::make_shared<ParamListener>(get_node()) in on_init
    assert _declares(controller, 16) == DECLARED


def test_a_prefix_given_to_the_listener_heads_every_name(controller: CppResult) -> None:
    # ParamListener backup(get_node(), "backup"), a local
    assert _declares(controller, 65) == [
        (f"backup.{name}", kind, has, default, listed and f"backup.{listed}")
        for name, kind, has, default, listed in DECLARED]


def test_the_params_struct_parses_cleanly(controller: CppResult) -> None:
    """params_.joints, params_.gains.joints_map.at(joint).p, params_.limits.max_velocity,
    is_old, refresh_dynamic_parameters, try_update_params: all declared."""
    assert [(d.code, d.message) for d in controller.diagnostics if d.code in UNCLEAN] == []
    assert ("publish", "~gains") in [(c.kind, c.name) for c in controller.calls]


def test_the_controller_node_is_complete() -> None:
    workspace = scan([ROOT])
    package = workspace.packages["joint_gain_controller"]
    package.nodes, _ = cmake.parse_package(package, workspace)
    nodes = [n for n in package.nodes if n.language == "cpp"]
    found = extract_nodes(nodes, workspace, cache_dir=None, jobs=1)
    node = next(n for n in nodes if n.name.endswith("JointGainController"))
    assert ("declare", "gains.?.p", "joints") in [
        (c.kind, c.name, c.name_param) for c in node.calls]
    assert not [d for d in found if d.code == "CPP_NODE_PARTIAL"]


@pytest.mark.parametrize(("text", "line"), [
    ("joint_gain_controller:\n  joints: [unclosed\n", 3),
    ("- not\n- a mapping\n", 1),
])
def test_bad_yaml_is_a_diagnostic_at_the_file(tmp_path, text: str, line: int) -> None:
    shutil.copytree(PACKAGE, tmp_path / "joint_gain_controller")
    (tmp_path / "joint_gain_controller" / "src" / os.path.basename(YAML)).write_text(text)
    source = tmp_path / "joint_gain_controller" / "src" / os.path.basename(CONTROLLER)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    found = [d for d in result.diagnostics if d.code == "CPP_PARAMETER_LIBRARY"]
    assert [(d.location.file, d.location.line) for d in found] == [
        ("joint_gain_controller/src/joint_gain_controller_parameters.yaml", line)]
    # the header is then an empty stand-in: no parameter is invented
    assert "CPP_INCLUDE_MISSING" in [d.code for d in result.diagnostics]
    assert not [c for c in result.calls if c.kind == "declare"]


def test_the_header_types_the_fields_as_the_library() -> None:
    import datetime

    tree = {"a": {"type": "int_array"}, "b": {"type": "string_fixed_25"},
            "day": {"type": "string", "default_value": datetime.date(2024, 1, 2)},
            "c": {"type": "double_array_fixed_4"}, "n": {"d": {"type": "bool"}},
            "__map_a": {"x": {"type": "string"}}}
    target = gpl.Target("p", "/x.yaml", "pkg", "pkg")
    text = gpl.render(target, "ns", tree, "x.yaml")
    for line in ("std::vector<int64_t> a;", "std::string b;", "std::vector<double> c;",
                 "struct N {", "bool d;", "} n;", "struct MapA {",
                 "std::map<std::string, MapA> a_map;", "class ", "ParamListener(NodeT node"):
        assert line in text
    assert "2024-01-02" in text  # a YAML date as a default: its text, no traceback
    assert gpl.header_target("pkg/p.hpp", [target], "") == target
    assert gpl.header_target("p.hpp", [target], "") == target
    assert gpl.header_target("other/p.hpp", [target], "") is None


def test_a_node_gives_its_parameters_interface(tmp_path) -> None:
    """Autoware's path_generator: ``make_shared<ParamListener>(this->
    get_node_parameters_interface())`` in an rclcpp::Node: the node's own parameters
    (not under the handle's unknown namespace)."""
    shutil.copytree(PACKAGE, tmp_path / "joint_gain_controller")
    source = tmp_path / "joint_gain_controller" / "src" / "standalone.cpp"
    source.write_text(
        "#include <memory>\n#include <rclcpp/rclcpp.hpp>\n"
        '#include "joint_gain_controller/joint_gain_controller_parameters.hpp"\n'
        "class Standalone : public rclcpp::Node {\n public:\n"
        '  Standalone() : rclcpp::Node("standalone") {\n'
        "    listener_ = std::make_shared<::joint_gain_controller::ParamListener>(\n"
        "      this->get_node_parameters_interface());\n  }\n private:\n"
        "  std::shared_ptr<::joint_gain_controller::ParamListener> listener_;\n};\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert _declares(result, 7) == DECLARED


def test_a_class_template_builds_its_listener_on_the_implicit_this(tmp_path) -> None:
    """ros2_controllers' gripper_controllers (Kinova's gen3_lite loads it):
    ``GripperActionController<HardwareInterface>::on_init`` builds
    ``std::make_shared<ParamListener>(get_node())``; in a class template the implicit
    ``this`` depends on the template's parameters, so the call stays unresolved. Its
    parameters were not declared at all, and the controller was said complete."""
    shutil.copytree(PACKAGE, tmp_path / "joint_gain_controller")
    source = tmp_path / "joint_gain_controller" / "src" / "templated.cpp"
    source.write_text(
        "#include <memory>\n"
        '#include "controller_interface/controller_interface.hpp"\n'
        '#include "joint_gain_controller/joint_gain_controller_parameters.hpp"\n'
        "namespace joint_gain_controller {\n"
        "template <const char * Interface>\n"
        "class Templated : public controller_interface::ControllerInterface {\n"
        " public:\n"
        "  controller_interface::CallbackReturn on_init() override;\n"
        " private:\n"
        "  std::shared_ptr<ParamListener> listener_;\n};\n"
        "template <const char * Interface>\n"
        "controller_interface::CallbackReturn Templated<Interface>::on_init() {\n"
        "  listener_ = std::make_shared<ParamListener>(get_node());\n"
        "  return controller_interface::CallbackReturn::SUCCESS;\n}\n"
        'extern const char position[] = "position";\n'
        "template class Templated<position>;\n"
        "}  // namespace joint_gain_controller\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert _declares(result, 14) == DECLARED


def test_a_test_of_a_params_field_is_decided_by_its_parameter(tmp_path) -> None:
    """joint_state_broadcaster's ``params_.use_local_topics ? "~/" : ""``: a field of
    the listener's ``Params`` struct holds the parameter of its name (nested structs
    too), which the graph decides the test by, as a local that holds a parameter."""
    shutil.copytree(PACKAGE, tmp_path / "joint_gain_controller")
    source = tmp_path / "joint_gain_controller" / "src" / "fields.cpp"
    source.write_text(
        "#include <memory>\n#include <string>\n#include <rclcpp/rclcpp.hpp>\n"
        "#include <std_msgs/msg/string.hpp>\n"
        '#include "joint_gain_controller/joint_gain_controller_parameters.hpp"\n'
        "class Fields : public rclcpp::Node {\n public:\n"
        '  Fields() : rclcpp::Node("fields") {\n'
        "    listener_ = std::make_shared<::joint_gain_controller::ParamListener>(\n"
        "      this->get_node_parameters_interface());\n"
        "    params_ = listener_->get_params();\n"
        '    const std::string prefix = params_.open_loop ? "~/" : "";\n'
        "    if (params_.limits.max_velocity > 1.0 && !params_.interface_name.empty()) {\n"
        "      pub_ = create_publisher<std_msgs::msg::String>(prefix + \"fast\", 10);\n"
        "    }\n  }\n private:\n"
        "  std::shared_ptr<::joint_gain_controller::ParamListener> listener_;\n"
        "  ::joint_gain_controller::Params params_;\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    found = sorted((c.name, tuple((k.statement, k.parameters) for k in c.conditions))
                   for c in result.calls if c.kind == "publish")
    # ``interface_name.empty()`` is a call on the field's value, no parameter of its own
    fast = ("if", (("params_.interface_name", "interface_name"),
                   ("params_.limits.max_velocity", "limits.max_velocity")))
    assert found == [
        ("fast", (fast, ("else", (("params_.open_loop", "open_loop"),)))),
        ("~fast", (fast, ("if", (("params_.open_loop", "open_loop"),)))),
    ]
