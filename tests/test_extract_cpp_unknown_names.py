"""Names the stand-in headers do not know never stop a run nor cost a node its calls:
fixtures/cpp/unknown_names."""

from __future__ import annotations

import json
import os
import re

import pytest

from haros_arch.extract import extract_nodes
from haros_arch.extract.cpp import CppResult, extract_cpp, synthesis
from haros_arch.manifest import ros_version
from haros_arch.model.source import Dependency, Node, Package
from haros_arch.workspace import scan
from tests.conftest import package_xml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "unknown_names")
SOURCES = os.path.join(ROOT, "src", "vendor_node", "src")


def extract(name: str) -> CppResult:
    return extract_cpp([os.path.join(SOURCES, name)], scan([ROOT]), cache_dir=None, jobs=1)


def rows(result: CppResult) -> list[tuple[str, str, str | None, int]]:
    return [(c.kind, c.name, c.type, c.location.line) for c in result.calls]


def codes(result: CppResult) -> list[str]:
    return [d.code for d in result.diagnostics]


def test_unbound_name_in_a_value_is_unknown_not_a_crash() -> None:
    result = extract("unbound_name.cpp")
    assert ("publish", "?", "std_msgs/msg/String", 11) in rows(result)


def test_qt_module_headers_beside_their_folders() -> None:
    result = extract("qt_umbrella.cpp")
    assert rows(result) == [("publish", "frames", "std_msgs/msg/String", 13)]
    assert "CPP_INCLUDE_MISSING" not in codes(result)
    assert "CPP_PARSE_ERROR" not in codes(result)


def test_unknown_vendor_type_costs_no_call() -> None:
    result = extract("vendor_member.cpp")
    assert rows(result) == [
        ("declare", "gain", "double", 13),
        ("publish", "out", "std_msgs/msg/String", 14),
        ("subscribe", "in", "std_msgs/msg/String", 15),
    ]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_NAMES_DECLARED" in codes(result)


def test_a_string_takes_a_field_of_an_unknown_class() -> None:
    """``file = config.yaml_cfg_file`` of a Config class whose generated header is not
    there: the permissive class converts to anything, so a string's assignment,
    constructor and ``+=`` were ambiguous, an error in a function that calls the ROS
    API, and the node partial."""
    result = extract("unknown_config.cpp")
    assert rows(result) == [("read", "~yaml_cfg_file", "str", 14),
                            ("publish", "~active", "std_msgs/String", 20)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_names_are_declared_as_they_are_used() -> None:
    names = synthesis.Names()
    text = (b"class A : public vendor::Base {};\nvendor::Tmpl<int> t;\nUnknown u;\n"
            b"int x = ns::CONSTANT;\n")
    names.learn([
        ("use of undeclared identifier 'vendor'", text, text.index(b"vendor")),
        ("use of undeclared identifier 'vendor'", text, text.index(b"vendor::Tmpl")),
        ("unknown type name 'Unknown'", text, text.index(b"Unknown")),
        ("use of undeclared identifier 'ns'", text, text.index(b"ns::")),
        ("no member named 'apply' in 'vendor::Base'", None, 0),
    ])
    header = names.header()
    assert "namespace vendor {" in header
    assert "struct Base : haros_any {" in header
    assert "template <class... T> struct Tmpl : haros_any {" in header
    assert "struct Unknown : haros_any {" in header
    assert "extern haros_any CONSTANT;" in header
    assert "static haros_any apply;" in header


def test_a_macro_alone_on_its_line_is_defined_empty_not_declared_a_type() -> None:
    """kobuki's ``KobukiRos`` writes ``EIGEN_MAKE_ALIGNED_OPERATOR_NEW`` alone in its
    class body, Eigen's header reached only through a missing one: declared a type, it
    swallowed the next member (``std::string name;``) and made 28 errors of its uses."""
    names = synthesis.Names()
    text = (b"class KobukiRos {\n public:\n  EIGEN_MAKE_ALIGNED_OPERATOR_NEW  // aligned\n"
            b"private:\n  std::string name;\n  VENDOR_HANDLE handle;\n};\n")
    names.learn([
        ("unknown type name 'EIGEN_MAKE_ALIGNED_OPERATOR_NEW'", text,
         text.index(b"EIGEN")),
        ("unknown type name 'VENDOR_HANDLE'", text, text.index(b"VENDOR")),
    ])
    header = names.header()
    assert "#define EIGEN_MAKE_ALIGNED_OPERATOR_NEW\n" in header
    assert "struct EIGEN_MAKE_ALIGNED_OPERATOR_NEW" not in header
    assert "struct VENDOR_HANDLE : haros_any {" in header  # it declares ``handle``


def test_a_macro_call_written_as_a_declaration_is_defined_empty() -> None:
    """naoqi_driver's event/audio.hpp ends its namespace with ``QI_REGISTER_OBJECT(
    AudioEventRegister, processRemote)`` and no ``;`` (libqi's header missing): clang
    took it for a function's declaration, the namespace's ``}`` for its body, and the
    rest of the unit (naoqi_driver.cpp's every function) was lost."""
    names = synthesis.Names()
    text = (b"namespace naoqi {\nclass A {\n}; // class\n\n"
            b"QI_REGISTER_OBJECT( A,\n  start, /* rpc */ stop )\n\n} //naoqi\n")
    assert names.learn([("expected function body after function declarator", text,
                         text.rindex(b"}"))])
    assert "#define QI_REGISTER_OBJECT(...)\n" in names.header()
    # a declaration that is no macro call is left as it is
    other = synthesis.Names()
    text = b"namespace n {\nvoid handler(int a)\n}\n"
    assert not other.learn([("expected function body after function declarator", text,
                             text.rindex(b"}"))])


def test_unresolved_calls_are_kept_by_name() -> None:
    result = extract("invalid_object.cpp")
    assert rows(result) == [
        ("declare", "rate", "double", 11),
        ("publish", "status", "vendor_msgs/msg/Status", 12),
        ("publish", "frames", "?", 13),
        ("publish", "echo", "std_msgs/msg/String", 14),
    ]
    assert codes(result).count("CPP_CALL_UNRESOLVED") == 4


def test_completeness_of_nodes() -> None:
    workspace = scan([ROOT])
    base = "src/vendor_node/src/"
    clean = Node("vendor_node", "filtered", sources=[base + "vendor_member.cpp"])
    broken = Node("vendor_node", "helper", sources=[base + "invalid_object.cpp"])
    nothing = Node("vendor_node", "ghost", sources=[])
    found = extract_nodes([clean, broken, nothing], workspace, cache_dir=None, jobs=1)
    assert (clean.completeness, clean.completeness_reasons) == ("complete", [])
    assert broken.completeness == "partial"
    assert broken.completeness_reasons[0].startswith(base + "invalid_object.cpp:9: ")
    assert nothing.completeness == "unknown"
    partial = [d for d in found if d.code == "CPP_NODE_PARTIAL"]
    assert [(d.severity, "vendor_node/helper" in d.message) for d in partial] == [
        ("warning", True)]


def test_completeness_of_python_nodes(tmp_path) -> None:
    package = tmp_path / "src" / "py_node"
    (package / "scripts").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>py_node</name><version>0.0.1</version>'
        '<description>d</description><maintainer email="a@b.c">m</maintainer>'
        "<license>BSD</license></package>\n")
    (package / "scripts" / "good.py").write_text(
        "import rospy\nrospy.init_node('good')\nrospy.Publisher('out', String)\n")
    (package / "scripts" / "bad.py").write_text("import rospy\ndef broken(:\n")
    workspace = scan([str(tmp_path / "src")])
    good = Node("py_node", "good.py", language="python", sources=["py_node/scripts/good.py"])
    bad = Node("py_node", "bad.py", language="python", sources=["py_node/scripts/bad.py"])
    found = extract_nodes([good, bad], workspace, cache_dir=None)
    assert (good.completeness, bad.completeness) == ("complete", "partial")
    assert bad.completeness_reasons[0].startswith("py_node/scripts/bad.py:2")
    assert [d.code for d in found if d.code.endswith("NODE_PARTIAL")] == ["PY_NODE_PARTIAL"]


def test_parameter_forms_of_real_nodes() -> None:
    result = extract("parameters.cpp")
    assert [(c.kind, c.name, c.type, c.has_default, c.default) for c in result.calls] == [
        ("declare", "gain", "double", False, None),
        ("declare", "frame_id", "str", True, "map"),
        # a ParameterType constant: typed by it, no default
        ("declare", "map_file", "str", False, None),
        # declare_parameters: each key of the map written there, its value the default,
        # typed by the template argument (the element of the std::vector<T> it returns)
        ("declare", "limits.low", "int", True, None),
        ("declare", "limits.high", "int", True, None),
        ("read", "retries", "int", True, 3),
        ("read", "mode", "str", False, None),
    ]
    assert "CPP_PARSE_ERROR" not in codes(result)


def test_ros_version_comes_from_the_package() -> None:
    result = extract("tf_only.cpp")
    # at the constructor's initialiser ``broadcaster_(node)``, the member's one
    # construction (not at its declaration: tests/test_extract_cpp_member_initialised.py)
    assert rows(result) == [("publish", "/tf", "tf2_msgs/msg/TFMessage", 9)]


@pytest.mark.parametrize(("build_type", "depends", "version", "fmt"), [
    ("ament_cmake", [], 2, 2), ("ament_python", [], 2, 2), ("cmake", ["rclcpp"], 2, 2),
    ("catkin", ["roscpp"], 1, 2), ("cmake", ["catkin"], 1, 2), ("cmake", ["eigen"], None, 2),
    ("cmake", ["eigen"], 1, 1),  # package.xml format 1 is ROS 1 only (ROS 2 needs 2 or 3)
])
def test_package_ros_version(build_type: str, depends: list[str], version: int | None,
                             fmt: int) -> None:
    package = Package("p", "p", build_type=build_type,  # type: ignore[arg-type]
                      format=fmt, dependencies=[Dependency(d, "depend") for d in depends])
    assert ros_version(package) == version


def test_ros1_forms_of_real_nodes() -> None:
    result = extract_cpp([os.path.join(ROOT, "src", "legacy_node", "src", "forms.cpp")],
                         scan([ROOT]), cache_dir=None, jobs=1)
    assert [(c.kind, c.name, c.queue_size, c.callback,
             tuple((k.statement, k.text) for k in c.conditions)) for c in result.calls] == [
        ("publish", "planner/plan", 7, None, ()),
        ("subscribe", "planner/goal", 1, "Planner::onGoal", (("switch", "mode == 1"),)),
        ("subscribe", "planner/goal_alt", 1, "Planner::onGoal", (("switch", "mode == 2"),)),
        ("subscribe", "planner/goal_any", 1, None,
         (("switch", "mode != 1 && mode != 2"),)),
    ]


def test_lowercase_message_of_a_missing_package() -> None:
    result = extract_cpp([os.path.join(ROOT, "src", "legacy_node", "src", "lowercase.cpp")],
                         scan([ROOT]), cache_dir=None, jobs=1)
    assert rows(result) == [("publish", "final_waypoints", "waypoint_follower/lane", 10)]


def test_declared_names_are_cached_with_the_unit(tmp_path) -> None:
    source = [os.path.join(SOURCES, "vendor_member.cpp")]
    first = extract_cpp(source, scan([ROOT]), cache_dir=str(tmp_path), jobs=1)
    # the header of declared names is never on disk: the entry must not need it
    assert len(list((tmp_path / "cpp").glob("*.json"))) == 1
    again = extract_cpp(source, scan([ROOT]), cache_dir=str(tmp_path), jobs=1)
    assert rows(again) == rows(first) and len(rows(first)) == 3
    assert "CPP_NAMES_DECLARED" in codes(again)


def test_parameters_through_the_parameters_interface() -> None:
    result = extract("params_interface.cpp")
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("read", "max_range", 10), ("declare", "max_range", 11), ("read", "max_range", 13),
        ("write", "interactive", 14)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_CALL_UNRESOLVED" not in codes(result)


def test_rclcpp_free_factories() -> None:
    result = extract("free_factories.cpp")
    assert [(c.kind, c.name, c.type, c.queue_size) for c in result.calls] == [
        ("publish", "out", "std_msgs/msg/String", 3),
        ("subscribe", "in", "std_msgs/msg/String", 4),
        ("subscribe", "in_too", "std_msgs/msg/String", None)]
    assert "CPP_PARSE_ERROR" not in codes(result)


def _errors_where(tmp_path, *defines: str) -> tuple[CppResult, Node]:
    """errors_where.cpp extracted as a node, built with ``defines``."""
    source = os.path.join(SOURCES, "errors_where.cpp")
    commands = tmp_path / "compile_commands.json"
    commands.write_text(json.dumps([{
        "directory": str(tmp_path), "file": source,
        "arguments": ["c++", *(f"-D{d}" for d in defines), "-c", source]}]))
    workspace = scan([ROOT])
    node = Node("vendor_node", "talker", sources=[workspace.relpath(source)])
    found = extract_nodes([node], workspace, cache_dir=None, jobs=1,
                          compile_commands=[str(commands)])
    return CppResult(node.calls, diagnostics=found), node


def test_an_error_in_code_that_calls_no_ros_api_leaves_the_node_complete(tmp_path) -> None:
    result, node = _errors_where(tmp_path)
    assert rows(result) == [("publish", "out", "std_msgs/msg/String", 21)]
    assert ("CPP_PARSE_ERROR", 10) in [(d.code, d.location.line) for d in result.diagnostics]
    # the call site under an #ifdef the build does not take is no missed call
    assert (node.completeness, node.completeness_reasons) == ("complete", [])
    assert "CPP_NODE_PARTIAL" not in codes(result)
    # no error can cost a call: the unknown names are not declared (no second parse)
    assert "CPP_NAMES_DECLARED" not in codes(result)
    assert ("CPP_PARSE_ERROR", 43) in [(d.code, d.location.line) for d in result.diagnostics]


def test_an_error_inside_a_function_that_calls_the_api_makes_the_node_partial(
        tmp_path) -> None:
    result, node = _errors_where(tmp_path, "NEAR_CALL")
    assert node.completeness == "partial"
    where = "src/vendor_node/src/errors_where.cpp:33: "
    assert node.completeness_reasons == [
        where + 'pub_ = create_publisher<std_msgs::msg::String>("restart", 10 +); calls '
        "the ROS API, but no call was extracted there",
        where + "C++ error in restart (lines 31-34), which calls the ROS API: expected "
        "expression"]
    assert codes(result).count("CPP_NODE_PARTIAL") == 1
    assert "CPP_NAMES_DECLARED" in codes(result)  # this error may hide one: parsed again


def test_a_call_site_with_no_call_extracted_is_a_reason() -> None:
    from haros_arch.extract.cpp import recall

    text = ("void f(ros::NodeHandle & nh) {\n"
            "  // nh.subscribe(\"commented\", 1, cb);\n"
            "  pub_ = nh.advertise<nav_msgs::Odometry>(\"odometry/filtered\", 20);\n"
            "  /* a->create_publisher<T>(\"old\", 1); */ auto p = declare_parameter<int>(\"n\");\n"
            "void Base::create_publisher(const std::string & name) {\n"
            "  subs_.push_back(nh_.subscribe<sensor_msgs::Imu>(\n"
            "      imu_topic, 10, cb));\n"
            "  helper->make_pub(\"x\");\n"
            "}\n")
    sites = recall.call_sites(text, ["make_pub"])
    assert [s.line for s in sites] == [3, 4, 6, 8]  # no comment, no definition
    assert [s.line for s in recall.missed(sites, {3}, [(8, 8)])] == [6]


def test_a_function_of_a_namespace_is_a_call_site_only_with_its_namespace() -> None:
    """``ros::param::search`` is a function of a namespace: ``layer.search(box)`` (lanelet2's
    spatial search) is no call of it, and no reason for a node to be partial;
    ``ros::param::get(`` and ``ros::service::call(`` are call sites, written qualified."""
    from haros_arch.extract.cpp import recall

    text = ("for (const auto & llt : layer.search(lanelet::BoundingBox2d{a, b})) {\n"
            "  if (!ros::param::get(\"~rate\", rate)) { rate = 10; }\n"
            "  ros::service::call(\"reset\", srv);\n"
            "  mapper.remap(ids);\n"
            "  nh.searchParam(\"robot_description\", key);\n"
            "}\n")
    assert [s.line for s in recall.call_sites(text)] == [2, 3, 5]


def test_a_call_written_in_an_unevaluated_operand_is_no_call_site() -> None:
    """``decltype(std::declval<NodeT &>().template create_publisher<M>(...))`` names the
    publisher's type (Autoware's planning_factor_interface): no call is made there, so it
    is no reason for a node to be partial; a call after a closed ``sizeof(...)`` is one."""
    from haros_arch.extract.cpp import recall

    text = ("using PublisherPtr =\n"
            "  decltype(std::declval<NodeT &>().template create_publisher<Array>(\n"
            "    std::declval<const std::string &>(), 1));\n"
            "const auto n = sizeof(Array); pub_ = node->create_publisher<Array>(\"f\", n);\n")
    assert [s.line for s in recall.call_sites(text)] == [4]



def test_a_wrapper_class_written_as_a_type_is_no_call_site() -> None:
    """A wrapper class template of the unit (nav2::ServiceClient, whose constructor creates
    the client) is a call site where it is built (after ``make_shared<`` or ``new``, its
    template arguments followed by ``(`` / ``{``, a variable with its arguments, as it
    goes on past the line), not where it names a type: an alias, a member's type, a
    base class, a template argument (navigation2's service_client.hpp:35 made
    nav2_lifecycle_manager partial)."""
    from haros_arch.extract.cpp import recall

    text = ("using SharedPtr = std::shared_ptr<nav2::ServiceClient<ServiceT>>;\n"
            "nav2::ServiceClient<GetMap>::SharedPtr map_client_;\n"
            "class TestClient : public ServiceClient<Empty> {\n"
            "std::vector<ServiceClient<Empty>> clients; typedef ServiceClient<S> Client;\n"
            "auto a = std::make_shared<nav2::ServiceClient<GetCosts>>(\n"
            "  nav2::ServiceClient<Trigger>(\"pause\", node);\n"
            "ServiceClient<Empty> client(\"reset\", node);\n"
            ": ServiceClient<S>{name, node} {}\n"
            "c_ = new ServiceClient<S>(name, node);\n"
            "auto b = nav2::ServiceClient<\n"
            "make_client<Empty>(\"x\");\n")
    sites = recall.call_sites(text, ["ServiceClient", "make_client"])
    assert [s.line for s in sites] == [5, 6, 7, 8, 9, 10, 11]


def test_a_wrapper_class_as_a_member_type_leaves_its_node_complete(write_tree) -> None:
    """The node's other error (a vendor call) cannot hide a ROS call: the line that
    declares the wrapper's member is no missed call site."""
    root = write_tree({
        "wrap/package.xml": package_xml("wrap", "ament_cmake"),
        "wrap/include/wrap/service_client.hpp": (
            "#include <memory>\n#include <string>\n#include <rclcpp/rclcpp.hpp>\n"
            "namespace wrap {\n"
            "template<typename ServiceT> class ServiceClient {\n"
            " public:\n"
            "  using SharedPtr = std::shared_ptr<wrap::ServiceClient<ServiceT>>;\n"
            "  template<typename NodeT>\n"
            "  ServiceClient(const std::string & name, const NodeT & node) {\n"
            "    client_ = node->template create_client<ServiceT>(name);\n"
            "  }\n"
            "  typename rclcpp::Client<ServiceT>::SharedPtr client_;\n"
            "};\n"
            "}  // namespace wrap\n"),
        "wrap/src/manager.cpp": (
            "#include <std_srvs/srv/trigger.hpp>\n"
            "#include \"wrap/service_client.hpp\"\n"
            "class Manager : public rclcpp::Node {\n"
            " public:\n"
            "  Manager() : rclcpp::Node(\"manager\") {\n"
            "    client_ = std::make_shared<wrap::ServiceClient<std_srvs::srv::Trigger>>(\n"
            "        \"is_active\", shared_from_this());\n"
            "  }\n"
            "  void report() { vendor::unknown_call(3); }\n"
            "  wrap::ServiceClient<std_srvs::srv::Trigger>::SharedPtr client_;\n"
            "};\n"),
    })
    result = extract_cpp([str(root / "wrap" / "src" / "manager.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert rows(result) == [("client", "is_active", "std_srvs/srv/Trigger", 6)]
    assert "CPP_PARSE_ERROR" in codes(result)
    assert "CPP_CALL_MISSED" not in codes(result)

def test_fields_of_messages_known_only_by_name_leave_no_error() -> None:
    result = extract("message_fields.cpp")
    assert rows(result) == [
        ("publish", "markers", "visualization_msgs/msg/Marker", 17),
        ("subscribe", "tracks", "vendor_radar_msgs/msg/Track", 18),
        ("declare", "limit", "double", 25),
        ("server", "reset", "vendor_radar_msgs/srv/Reset", 26),
    ]
    # fields and constants (``Marker::SPHERE``) are declared on the message's struct; the
    # unqualified ``Pose2`` of ``using namespace vendor_geometry`` is not ambiguous
    assert [c for c in codes(result) if c in ("CPP_PARSE_ERROR", "CPP_MESSAGE_FIELD")] == []


def test_fields_are_declared_static_on_the_record() -> None:
    names = synthesis.Names(["radar_msgs"])
    names.learn([("no member named 'position' in 'radar_msgs::Track'", None, 0),
                 ("no member named 'SPHERE' in 'visualization_msgs::msg::Marker'", None, 0),
                 ("no member named 'size' in 'mavros::router::Endpoint'", None, 0)])
    header = names.header()
    assert "#define HAROS_FIELDS_radar_msgs__Track static haros_any position;" in header
    assert ("#define HAROS_FIELDS_visualization_msgs__msg__Marker static haros_any SPHERE;"
            in header)
    assert "Endpoint" not in header  # a class of the workspace is no message


def test_a_name_that_made_a_use_ambiguous_is_withdrawn() -> None:
    names = synthesis.Names()
    text = b"VerticeMap m;\n"
    names.learn([("unknown type name 'VerticeMap'", text, 0)])
    assert "struct VerticeMap : haros_any" in names.header()
    # once the real typedef is valid, the declared name makes every use ambiguous
    assert names.learn([("reference to 'VerticeMap' is ambiguous", text, 0)])
    assert "VerticeMap" not in names.header()


def test_service_wrappers_of_rclcpp_qos_overloads_keep_the_class_valid() -> None:
    # rclcpp's QoS overloads of create_service / create_client, make_shared of
    # RCLCPP_SMART_PTR_DEFINITIONS, std::is_null_pointer_v and a message's field type
    # (Autoware's component interface wrappers use each of them)
    result = extract("service_wrapper.cpp")
    assert rows(result) == [
        ("server", "reset", "std_srvs/srv/Trigger", 46),
        ("client", "engage", "std_srvs/srv/Trigger", 48),
        ("publish", "status", "status_msgs/msg/Status", 49),
    ]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []


def test_field_types_are_declared_on_the_record() -> None:
    names = synthesis.Names(["status_msgs"])
    assert names.learn([("no type named '_code_type' in 'status_msgs::msg::Status'", None, 0)])
    assert ("#define HAROS_FIELDS_status_msgs__msg__Status typedef haros_any _code_type;"
            in names.header())


def test_nested_types_of_declared_templates_and_standard_library_gaps() -> None:
    # Cloud<Point>::ConstPtr of a vendor template that is nowhere (pcl's, in Autoware's
    # PlannerData), std::conjunction_v, std::lower_bound, std::exception_ptr
    result = extract("nested_type.cpp")
    assert rows(result) == [("declare", "horizon", "double", 32),
                            ("publish", "plan", "std_msgs/msg/String", 33)]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []


def test_a_nested_type_of_a_declared_class_is_declared_in_it() -> None:
    names = synthesis.Names()
    text = b"vendor::Cloud<int>::ConstPtr p;\n"
    names.learn([("use of undeclared identifier 'vendor'", text, 0)])
    assert names.learn([("no type named 'ConstPtr' in 'vendor::Cloud<int>'", text, 0)])
    header = names.header()
    assert "template <class... T> struct Cloud : haros_any {" in header
    assert "struct ConstPtr : haros_any {" in header


def test_a_member_of_a_declared_class_that_declares_a_variable_is_a_type(write_tree) -> None:
    """``vendor::Reg<int, int>::Ptr reg(new ...)`` in a function body: clang says "no
    member named 'Ptr'" (a value, for it), and declared as a static member the line was
    ``expected ';'``, ``reg`` undeclared and each ROS call in the arguments of a call on
    it lost (hdl_graph_slam's registrations.cpp: 18 parameter reads of pcl-style
    registration classes of fast_gicp / ndt_omp, whose headers are missing)."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/src/reg.cpp": """\
            #include <ros/ros.h>
            #include <vendor/reg.hpp>
            void configure(ros::NodeHandle& pnh) {
              vendor::Reg<int, int>::Ptr reg(new vendor::Reg<int, int>());
              reg->setThreads(pnh.param<int>("threads", 0));
              if (vendor::Reg<int, int>::enabled) { pnh.param<double>("epsilon", 0.1); }
            }
            int main(int argc, char** argv) {
              ros::init(argc, argv, "reg");
              ros::NodeHandle pnh("~");
              configure(pnh);
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "reg.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert rows(result) == [("read", "~threads", "int", 5), ("read", "~epsilon", "double", 6)]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
    # a member read as a value stays a static member of the permissive class
    names = synthesis.Names()
    text = b"bool b = vendor::Reg<int>::enabled;\n"
    names.learn([("use of undeclared identifier 'vendor'", text, text.index(b"vendor"))])
    names.learn([("no member named 'enabled' in 'vendor::Reg<int>'", text,
                  text.index(b"enabled"))])
    assert "static haros_any enabled;" in names.header()
    assert "struct enabled" not in names.header()


def test_a_braced_list_given_to_a_permissive_call_is_no_error(write_tree) -> None:
    """asio's ``*resolver.resolve({udp::v4(), host, port})`` with <boost/asio.hpp>
    missing: no template parameter deduces a braced list, so the call of the declared
    member was an error in the function that advertises, and kuka_eki_hw_interface's
    node partial (CPP_CALL_MISSED: ``resolve`` is also a ROS 1 API name)."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/src/udp.cpp": """\
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            #include <boost/asio.hpp>
            struct Driver {
              void start(ros::NodeHandle& nh) {
                boost::asio::ip::udp::resolver resolver(ios_);
                endpoint_ = *resolver.resolve({boost::asio::ip::udp::v4(), host_, port_});
                socket_.send_to({endpoint_}, 2);
                pub_ = nh.advertise<std_msgs::String>("state", 10);
              }
              ros::Publisher pub_;
              boost::asio::io_service ios_;
              boost::asio::ip::udp::endpoint endpoint_;
              boost::asio::ip::udp::socket socket_;
              std::string host_, port_;
            };
            int main(int argc, char** argv) {
              ros::init(argc, argv, "udp");
              ros::NodeHandle nh;
              Driver().start(nh);
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "udp.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert rows(result) == [("publish", "state", "std_msgs/String", 9)]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []


def test_an_api_name_called_on_a_system_librarys_object_is_no_missed_call(write_tree) -> None:
    """ROS 1: ``resolver.resolve(query)`` on asio's resolver (its header missing) is a
    member of a class declared permissively in boost's namespace, a library that makes no
    ROS calls, not tf's ``TransformListener::resolve``: no CPP_CALL_MISSED, and the node
    stays complete. A class of a ROS package the node depends on keeps the warning."""
    source = """\
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        #include <boost/asio.hpp>
        #include <vendor_ros/listener.h>
        void connect(boost::asio::io_service& ios, const std::string& host) {
          boost::asio::ip::udp::resolver resolver(ios);
          boost::asio::ip::udp::resolver::query query(host, "80");


          auto it = resolver.resolve(query);
        }
        void listen(vendor_ros::Listener& listener) {
          std::string prefix;


          prefix = listener.resolve(prefix);
        }
        int main(int argc, char** argv) {
          ros::init(argc, argv, "udp");
          ros::NodeHandle nh;
          ros::Publisher pub = nh.advertise<std_msgs::String>("state", 10);
        }
        void handle() { int wrong = "text"; }  // an error left in the unit
        """
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>boost</depend>"
            "<depend>vendor_ros</depend></package>"),
        "pkg/src/udp.cpp": source})
    result = extract_cpp([str(root / "pkg" / "src" / "udp.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert rows(result) == [("publish", "state", "std_msgs/String", 21)]
    missed = [d.location.line for d in result.diagnostics if d.code == "CPP_CALL_MISSED"]
    assert missed == [16]  # vendor_ros' listener, found nowhere: may be a ROS client


def test_a_constant_a_class_is_built_from_is_an_enumerator(write_tree) -> None:
    """bebop_driver's states: ``AbstractState(ARCONTROLLER_DICTIONARY_KEY_...)``, whose
    constructor takes libARController's enum type (its header missing). Declared a
    permissive value, the constant also converted to ``AbstractState`` itself (``operator
    T &``, for the copy constructor): the construction was ambiguous, an error in each of
    44 constructors that advertise, and the driver's nodes partial. Read so, it is
    declared an enumerator."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/src/states.cpp": """\
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            #include <libARController/ARController.h>
            class AbstractState {
             public:
              AbstractState(eARCONTROLLER_DICTIONARY_KEY key, const bool on = false)
                : key_(key) {}
              virtual ~AbstractState() {}
             protected:
              eARCONTROLLER_DICTIONARY_KEY key_;
              ros::Publisher pub_;
            };
            class PictureState : public AbstractState {
             public:
              PictureState(ros::NodeHandle& nh, ros::NodeHandle& priv_nh, const std::string& topic)
                : AbstractState(ARCONTROLLER_DICTIONARY_KEY_PICTURE_STATE_CHANGED) {
                bool enabled = false;
                if (priv_nh.getParam("states/enable_picture", enabled) && enabled) {
                  pub_ = nh.advertise<std_msgs::String>(topic, 10, true);
                }
              }
            };
            int main(int argc, char** argv) {
              ros::init(argc, argv, "states");
              ros::NodeHandle nh, priv_nh("~");
              PictureState state(nh, priv_nh, "states/picture");
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "states.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert rows(result) == [("read", "~states/enable_picture", "bool", 18),
                            ("publish", "states/picture", "std_msgs/String", 19)]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
    names = synthesis.Names()
    text = b"B b(vendor::KEY_A, f(vendor::KEY_C), vendor::lower);\n"
    names.learn([("use of undeclared identifier 'vendor'", text, text.index(b"vendor"))])
    assert names.learn([("call to constructor of 'B' is ambiguous", text, text.index(b"b("))])
    header = names.header()
    assert "enum : int { KEY_A = " in header
    # only an argument written as a constant, alone
    assert "haros_any KEY_C;" in header and "KEY_C =" not in header


def test_an_eigen_object_initialised_from_a_permissive_value(write_tree) -> None:
    """hdl_graph_slam's ``Eigen::Isometry3d estimate = node->estimate();`` of g2o (its
    headers missing): the Eigen stand-in's converting constructor and the permissive
    value's ``operator T &`` both converted, ambiguously, an error in the function that
    reads the node's parameters; declaring g2o's names made the parse no better, so the
    unit kept its first parse and the error on g2o. Copy-initialised, the value converts
    itself; direct-initialised (``Vector3d v(value)``), the explicit constructor takes it."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/src/graph.cpp": """\
            #include <ros/ros.h>
            #include <Eigen/Dense>
            #include <g2o/types/slam3d/vertex_se3.h>
            #include <std_msgs/String.h>
            void optimize(ros::NodeHandle& pnh, g2o::VertexSE3* node) {
              if (pnh.param<bool>("fix_first_node", true)) {
                Eigen::Isometry3d estimate = node->estimate();
                Eigen::Vector3d position(node->estimate().translation());
                Eigen::Vector3d offset = node->offset();
                Eigen::MatrixXd info = Eigen::MatrixXd::Identity(6, 6);
                node->setEstimate(estimate);
              }
            }
            int main(int argc, char** argv) {
              ros::init(argc, argv, "graph");
              ros::NodeHandle pnh("~");
              optimize(pnh, nullptr);
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "graph.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert rows(result) == [("read", "~fix_first_node", "bool", 6)]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []


def test_names_of_a_vendor_library_in_waves_take_one_more_parse(monkeypatch) -> None:
    from haros_arch.extract import cpp

    parses: list[str] = []
    parse_once = cpp._parse_once

    def counted(path, *args, **kwargs):  # type: ignore[no-untyped-def]
        parses.append(path)
        return parse_once(path, *args, **kwargs)

    monkeypatch.setattr(cpp, "_parse_once", counted)
    result = extract("vendor_waves.cpp")
    # the enumerator read through an alias, the members of vendor objects
    # and the fields of a vendor message are declared with the first wave of names
    assert rows(result) == [
        ("declare", "rate", "double", 18),
        ("publish", "fast", "std_msgs/msg/String", 20),
        ("publish", "status", "std_msgs/msg/String", 22),
    ]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)
    assert len(parses) == 2


def test_members_and_scoped_values_are_read_from_the_text() -> None:
    names = synthesis.Names()
    text = (b"using Mode = vendor::Mode;\n"
            b"int f(vendor::Config c, vendor::Link *l) {\n"
            b"  if (c.as<int>(0) == static_cast<int>(Mode::FAST)) { l->send(c); }\n"
            b"  node->create_publisher<T>(\"x\", 1);\n"
            b"  std::map<vendor::Key, vendor::Value> table;\n"
            b"}\n")
    names.learn([
        ("use of undeclared identifier 'vendor'", text, text.index(b"vendor")),
        ("use of undeclared identifier 'Mode'", text, text.index(b"Mode::FAST")),
    ])
    names.read_members([text])
    header = names.header()
    assert "static haros_any as;" in header  # not a template: see read_members
    assert "static haros_any send;" in header
    assert "static haros_any FAST;" in header
    assert "create_publisher" not in header  # the API's own methods stay the API's
    # the alias declares Mode: no name of its own; its target is a type, not a value
    assert "struct Mode : haros_any {" in header and "haros_any Mode;" not in header
    assert header.replace("Mode *operator&", "").count("Mode") == 1  # (its own address)
    # the alias reached through its namespace (mavros' ``plugin::MTYPE::FENCE``): a
    # namespace ``app::Mode`` would clash with the alias once its target is declared
    use = b"void g() { h(app::Mode::SLOW); }\n"
    names.learn([("no member named 'Mode' in namespace 'app'", use, use.index(b"Mode"))])
    header = names.header()
    assert header.replace("Mode *operator&", "").count("Mode") == 1
    assert "static haros_any SLOW;" in header
    # the alias alone through its namespace, as a type (mavros' ``ftf::Covariance3d``,
    # whose own target the parse does not know): declared there, or the class naming it
    # is invalid
    alone = b"void k() { ns::Mode m; }\n"
    names.learn([("no type named 'Mode' in namespace 'ns'", alone, alone.index(b"Mode"))])
    assert "namespace ns {" in names.header()
    # clang reports only the first unknown name of a declaration: the others written
    # with the same unknown namespace are declared from the text
    for name in ("Config", "Link", "Key", "Value"):
        assert f"struct {name} : haros_any {{" in header


def test_enumerators_and_constants_are_declared_as_values() -> None:
    names = synthesis.Names()
    text = (b"enum class Framing { ok = vendor::FRAMING_OK, bad = vendor::FRAMING_BAD };\n"
            b"Geoid g(vendor::Geoid::ELLIPSOIDTOGEOID);\n"
            b"auto m = make(vendor::Kind, vendor::Custom_Mode);\n"
            b"std::map<vendor::Key, int> table;\n")
    names.learn([("use of undeclared identifier 'vendor'", text, text.index(b"vendor"))])
    header = names.header()
    # an enumerator's initialiser needs a constant: an enumerator, each its own value
    assert "enum : int { FRAMING_BAD = 1 };" in header
    assert "enum : int { FRAMING_OK = 2 };" in header
    assert "extern haros_any ELLIPSOIDTOGEOID;" in header  # an argument: a value
    for kind in ("Kind", "Custom_Mode", "Key"):
        assert f"struct {kind} : haros_any {{" in header
    # read as a value where a class was declared (clang: a type where an expression
    # was expected): a value from the next parse on
    names.learn([("expected '(' for function-style cast or type construction", text,
                  text.index(b", vendor::Custom_Mode)") + len(b", vendor::Custom_Mode"))])
    header = names.header()
    assert "extern haros_any Custom_Mode;" in header
    assert "struct Kind : haros_any {" in header


def test_boost_serialization_keeps_classes_valid() -> None:
    result = extract("serialized.cpp")
    assert rows(result) == [("publish", "map_metadata", "std_msgs/msg/String", 47)]
    assert "CPP_INCLUDE_MISSING" not in codes(result)
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_NAMES_DECLARED" not in codes(result)


def test_a_name_a_using_declaration_brings_is_a_type() -> None:
    names = synthesis.Names()
    text = (b"using vendor_msgs::msg::Limit;\n"
            b"auto pub = create_publisher<Limit>(\"limit\", 1);\n")
    names.learn([("use of undeclared identifier 'vendor_msgs'", text, 6)])
    header = names.header()
    assert "struct Limit : haros_any {" in header
    assert "haros_any Limit;" not in header


def test_a_namespace_the_code_defines_is_not_spread() -> None:
    # clang met ``autoware`` before any header declared it; further on the code defines
    # the namespace: its names are real, not declared from the text
    names = synthesis.Names()
    text = (b"auto p = autoware::tools::make();\n"
            b"namespace autoware::planning\n{\nPlannerNode::PlannerNode() {}\n}\n"
            b"REGISTER(autoware::planning::PlannerNode)\n")
    names.learn([("use of undeclared identifier 'autoware'", text, text.index(b"autoware"))])
    header = names.header()
    assert "tools" in header  # what the error itself named
    assert "planning" not in header and "PlannerNode" not in header


def _server(write_tree, source: str) -> CppResult:
    """``source`` as ``server.cpp`` of a ROS 2 package alone in a workspace, extracted."""
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/server.cpp": source})
    return extract_cpp([str(root / "pkg" / "src" / "server.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_a_message_constant_in_a_ros_calls_arguments_costs_the_call(write_tree) -> None:
    """clang reads on past a field of a message known only by name, but not in a call's
    arguments: the call is lost with it (navigation2's lifecycle nodes declare
    ``bond::msg::Constants::DISABLE_HEARTBEAT_TIMEOUT_PARAM``), so the unit's names are
    declared and the call comes back, named ``?``."""
    result = _server(
        write_tree,
        "#include <rclcpp/rclcpp.hpp>\n#include <lib_msgs/msg/limits.hpp>\n"
        "class Server : public rclcpp::Node {\n public:\n"
        "  Server() : Node(\"server\") {\n"
        "    declare_parameter(lib_msgs::msg::Limits::SPEED_PARAM, 2.0);\n"
        "    rate_ = declare_parameter<double>(\"rate\", 10.0);\n  }\n"
        "  double rate_;\n};\n")
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("declare", "?", 6), ("declare", "rate", 7)]
    # the info names what was declared: the message's constant
    assert [d.message.split("permissively (")[1].split(")")[0] for d in result.diagnostics
            if d.code == "CPP_NAMES_DECLARED"] == ["lib_msgs::msg::Limits::SPEED_PARAM"]


def test_bond_constants_are_known(write_tree) -> None:
    """bondcpp's message of constants is known without its package in the workspace."""
    result = _server(
        write_tree,
        "#include <rclcpp/rclcpp.hpp>\n#include <bond/msg/constants.hpp>\n"
        "class Server : public rclcpp::Node {\n public:\n"
        "  Server() : Node(\"server\") {\n"
        "    declare_parameter(bond::msg::Constants::DISABLE_HEARTBEAT_TIMEOUT_PARAM, true);\n"
        "  }\n};\n")
    # the string constant's value (bond's Constants.msg): nav2's lifecycle nodes
    # declare and set this parameter, which was '?' in each
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "/bond_disable_heartbeat_timeout")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_MESSAGE_FIELD", "CPP_NAMES_DECLARED", "CPP_MESSAGE_UNKNOWN")]


def test_a_string_constant_is_a_literal_the_parse_reads() -> None:
    """A message's string constant is defined with its value, escaped (a quote, a
    backslash, bytes that are not printable ASCII), in ROS 1 and ROS 2 headers."""
    from haros_arch.extract.cpp import interfaces, ros2_interfaces

    assert interfaces.string_literal('a"b\\c\u00e9\n') == '"a\\"b\\\\c\\303\\251\\012"'
    fields = [interfaces.Field("string", "NAME", None, constant="/x")]
    assert '  static inline const std::string NAME = "/x";' in interfaces._struct(
        "C", fields, "pkg")
    assert '  static inline const std::string NAME = "/x";' in ros2_interfaces._struct(
        "C", fields, "pkg")


def test_a_c_librarys_constants_and_functions_are_values(write_tree) -> None:
    """A C library whose header is missing (joy's SDL): its constants, operands of
    ``|`` or arguments, and its prefixed functions are declared as values, so the
    function that uses them and calls the ROS API has no error left (joy's nodes were
    partial for it); a lowercase unqualified name stays undeclared (often a member
    clang could not find through an invalid base)."""
    result = _server(
        write_tree,
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "#include <SDL.h>\n"
        "class Server : public rclcpp::Node {\n public:\n"
        "  Server() : Node(\"server\") {\n"
        "    if (SDL_Init(SDL_INIT_JOYSTICK | SDL_INIT_HAPTIC) < 0) {\n"
        "      RCLCPP_ERROR(get_logger(), \"SDL: %s\", SDL_GetError());\n    }\n"
        "    buttons_.resize(SDL_CONTROLLER_BUTTON_MAX);\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"joy\", 10);\n  }\n"
        "  std::vector<int> buttons_;\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("publish", "joy", 11)]
    assert "CPP_ERROR_NEAR_CALL" not in [d.code for d in result.diagnostics]
    names = synthesis.Names()
    text = (b"void f() { g(SDL_INIT_VIDEO | SDL_INIT_AUDIO); x = SDL_GetTicks();\n"
            b"  h(count_ + 2, update()); }\n")
    names.learn([("use of undeclared identifier '" + n.decode() + "'", text, text.index(n))
                 for n in (b"SDL_INIT_VIDEO", b"SDL_INIT_AUDIO", b"SDL_GetTicks", b"count_",
                           b"update")])
    header = names.header()
    for value in ("SDL_INIT_VIDEO", "SDL_INIT_AUDIO", "SDL_GetTicks"):
        assert f"extern haros_any {value};" in header
    assert "count_" not in header
    # a member clang could not find is not shadowed: the unqualified function is only
    # a friend of the permissive class, which no lookup but by its arguments finds
    assert [line.strip() for line in header.splitlines() if "update" in line] == [
        "template <class... A> friend haros_any &update(const A &...);"]


def test_vendor_constants_where_cpp_needs_a_constant() -> None:
    """A vendor's constants in case labels (unscoped, ``Enum::VALUE``, a C library's
    ``VND_EVENT_ALARM | VND_EVENT_CLEARED``), an array bound, an enumerator's
    initialiser and a constexpr initialiser, on a switch over a vendor object: declared
    permissively they were not constant expressions (``case value is not a constant
    expression``, ``statement requires expression of integer type``), the class was
    invalid and the publishers created in the switch were kept only by their name, the
    node partial. ``A | B`` beside ``C`` is no duplicate case value, and a vendor value
    negated or or-ed into an integer is no ambiguous use."""
    result = extract("vendor_switch.cpp")
    assert rows(result) == [("publish", "state", "std_msgs/msg/String", 41),
                            ("publish", "alarm", "std_msgs/msg/String", 54)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)
    assert "CPP_CALL_UNRESOLVED" not in codes(result)
    assert "CPP_NAMES_DECLARED" in codes(result)


def test_constants_are_enumerators_of_their_own_values() -> None:
    """Where C++ needs a constant the name is an enumerator, each with a value of its
    own that no case label of the code writes (``case 1:`` beside ``case vendor::A:``
    would be a duplicate case value), and a bit of its own when an operator combines it
    (``case A | B:`` must be no other constant's value); the same names elsewhere, and
    names in the other positions, stay permissive objects."""
    names = synthesis.Names()
    text = (b"void f(int x) {\n"
            b"  switch (x) { case 1: case 2: break; case enum_value(vendor::MODE_A): break;\n"
            b"    case vendor::Mode::FAST | vendor::Mode::SLOW: break; }\n"
            b"  static_assert(vendor::VERSION != 0, \"v\");\n"
            b"  static_assert(std::is_enum<T>::value, \"an enum\");\n"
            b"  static constexpr int size = vendor::MAX_LEN + 1;\n"
            b"  char buffer[vendor::BUF_SIZE];\n"
            b"  int at = table[vendor::INDEX];\n"
            b"  g(vendor::GAIN, vendor::Mode::STOP);\n"
            b"  static constexpr long seed = VND_C(0x9e37);\n"
            b"}\n")
    names.learn([("use of undeclared identifier 'vendor'", text, text.index(b"vendor")),
                 ("use of undeclared identifier 'VND_C'", text, text.index(b"VND_C"))])
    names.read_members([text])
    header = names.header()
    tree = header[header.index("namespace vendor {"):]
    values = dict(re.findall(r"enum : int \{ (\w+) = (\d+) \};", tree))
    assert sorted(values) == ["BUF_SIZE", "FAST", "MAX_LEN", "MODE_A", "SLOW", "VERSION"]
    every = [int(v) for v in re.findall(r"enum : int \{ \w+ = (\d+) \};", header)]
    assert len(set(every)) == len(every) and not {1, 2} & set(every)  # 1 and 2: the code's
    for name in ("MODE_A", "VERSION", "BUF_SIZE"):
        assert 2 < int(values[name]) < 100
    for name in ("MAX_LEN", "FAST", "SLOW"):  # combined by ``+`` or ``|``: bits
        assert int(values[name]) >= 1 << 16 and int(values[name]).bit_count() == 1
    assert re.search(r"namespace Mode \{\n    enum : int \{ FAST = \d+ \};\n"
                     r"    enum : int \{ SLOW = \d+ \};\n    extern haros_any STOP;", tree)
    # a subscript, arguments, and a member not in capitals (``::value``): no constants
    assert "extern haros_any GAIN;" in tree and "extern haros_any INDEX;" in tree
    assert "static haros_any value;" in header and "{ value = " not in header
    assert "extern haros_any VND_C;" in header  # called: a macro, no constant


def test_case_labels_the_code_writes_are_read_as_c_reads_them() -> None:
    """Octal and hexadecimal labels are taken by the code; a label that is no C number
    (``case 09:``) is left out, not a crash."""
    text = b"switch (x) { case 010: case 0x1F: case 3u: case 09: case vendor::A: ; }"
    assert synthesis._case_literals(text) == {8, 31, 3}


def test_a_function_declared_with_an_api_name_is_no_call_site() -> None:
    """flir's spinnaker_wrapper_impl.cpp:209 defines a GenICam helper
    ``static std::string set_parameter(`` (rclcpp::Node's method name, called bare in a
    node class): the line declares a function, it calls nothing, and made the camera
    driver partial (CPP_CALL_MISSED). A call after ``return`` / ``else`` or assigned, and
    an API call on the same line as a declaration of another name, stay call sites."""
    from haros_arch.extract.cpp import recall

    text = ("static std::string set_parameter(\n"
            "  rcl_interfaces::msg::SetParametersResult set_parameter(const P & p);\n"
            "  return set_parameter(rclcpp::Parameter(\"x\", 1));\n"
            "  else set_parameter(rclcpp::Parameter(\"x\", 2));\n"
            "  auto r = set_parameter(rclcpp::Parameter(\"x\", 3));\n"
            "  set_parameter(rclcpp::Parameter(\"x\", 4));\n"
            "void f(int a) { node->set_parameter(rclcpp::Parameter(\"x\", a)); }\n"
            "inline auto declare_parameter(int a) { return a; }\n")
    assert [s.line for s in recall.call_sites(text)] == [3, 4, 5, 6, 7]


def test_a_vendor_name_in_parentheses_in_a_case_label_is_a_constant(write_tree) -> None:
    """kobuki_ros' ``case (ecl::OpenError):`` (ecl's headers missing): a CamelCase name
    followed by ``)`` was declared a class, so the label was a cast with no operand
    (``expected expression``) in the constructor that creates the node's publishers,
    and the node partial (CPP_ERROR_NEAR_CALL). In a case label's parentheses it is a
    value, an enumerator of its own."""
    result = _server(
        write_tree,
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "#include <ecl/exceptions.hpp>\n"
        "class Server : public rclcpp::Node {\n public:\n"
        "  Server() : Node(\"server\") {\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"state\", 10);\n"
        "    try { open(); } catch (const ecl::StandardException &e) {\n"
        "      switch (e.flag()) {\n"
        "        case (ecl::OpenError): RCLCPP_ERROR(get_logger(), \"open\"); break;\n"
        "        case (ecl::ConfigurationError): break;\n"
        "        default: break;\n      }\n    }\n  }\n"
        "  void open();\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("publish", "state", 7)]
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)
    assert "CPP_PARSE_ERROR" not in codes(result)


def test_the_node_bound_with_its_own_member_function_is_a_callback_binding(
        write_tree) -> None:
    """kobuki_ros builds 17 ``ecl::Slot<...>(&KobukiRos::publishX, *this)`` members (ecl's
    headers missing): the node given to an unknown class with a pointer to one of its
    own member functions (or a base's) is a callback binding, no CPP_NODE_TO_UNKNOWN
    (the node was partial for it); the member's calls are read where it is defined.
    Given the node alone, or with another class's member, the unknown class still
    makes the node partial."""
    source = (
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "#include <ecl/sigslots.hpp>\n"
        "class Base : public rclcpp::Node {\n public:\n"
        "  Base() : Node(\"server\") {}\n  void ping(const std::string &s);\n};\n"
        "class Other { public: void f(); };\n"
        "class Server : public Base {\n public:\n"
        "  Server() : slot_(&Server::publish, *this), base_slot_(&Base::ping, *this),\n"
        "      OTHER {\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"state\", 10);\n  }\n"
        "  void publish(const std::string &s);\n"
        "  ecl::Slot<const std::string &> slot_, base_slot_, other_;\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    bound = _server(write_tree, source.replace("OTHER", "other_(&Server::publish, this)"))
    assert [(c.kind, c.name) for c in bound.calls] == [("publish", "state")]
    assert "CPP_NODE_TO_UNKNOWN" not in codes(bound)
    for other in ("other_(*this)", "other_(&Other::f, *this)"):
        given = _server(write_tree, source.replace("OTHER", other))
        assert [(d.code, d.location.line) for d in given.diagnostics
                if d.code == "CPP_NODE_TO_UNKNOWN"] == [("CPP_NODE_TO_UNKNOWN", 13)]


def test_the_node_given_with_its_classs_static_function_is_a_callback_binding(
        write_tree) -> None:
    """camera_aravis2 a4fb0c1 connects a GLib signal of its camera (aravis' headers
    missing) with ``g_signal_connect(p_device_, "control-lost",
    (GCallback)CameraAravisNodeBase::handleControlLostSignal, this)``: the node is the
    user data handed back to its own class's static function, whose calls are read where
    it is defined, so no CPP_NODE_TO_UNKNOWN (every driver node was partial for it). With
    a free function or another class's static function the node stays partial."""
    source = (
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "#include <arv.h>\n"
        "void lost(ArvDevice * d, gpointer p);\n"
        "class Other { public: static void lost(ArvDevice * d, gpointer p); };\n"
        "class Camera : public rclcpp::Node {\n public:\n"
        "  Camera() : Node(\"camera\") {\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"lost\", 1);\n"
        "    device_ = arv_camera_get_device(camera_);\n"
        "    g_signal_connect(device_, \"control-lost\", (GCallback)CALLBACK, this);\n"
        "  }\n"
        "  static void onLost(ArvDevice * device, gpointer data);\n"
        "  ArvCamera * camera_;\n  ArvDevice * device_;\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    for callback in ("Camera::onLost", "&Camera::onLost"):
        bound = _server(write_tree, source.replace("CALLBACK", callback))
        assert [(c.kind, c.name) for c in bound.calls] == [("publish", "lost")]
        assert "CPP_NODE_TO_UNKNOWN" not in codes(bound)
    for callback in ("lost", "Other::lost"):
        given = _server(write_tree, source.replace("CALLBACK", callback))
        assert [(d.code, d.location.line) for d in given.diagnostics
                if d.code == "CPP_NODE_TO_UNKNOWN"] == [("CPP_NODE_TO_UNKNOWN", 11)]


def test_a_vendor_constant_given_to_an_objects_method_in_main_is_a_value(
        write_tree) -> None:
    """ydlidar_ros2_driver 6b9f249's main configures the SDK's ``CYdLidar laser`` (its
    header missing) with ``laser.setlidaropt(LidarPropSerialPort, value, size)``: a
    whole argument of a call of an object's method is an expression, so the CamelCase
    enumerator is a value (it was declared a type: "does not refer to a value", twenty
    errors in the function that declares the parameters and publishes the scan, the
    node partial), and in a free function it is declared at namespace scope, where no
    class member can be shadowed."""
    source = (
        "#include <memory>\n#include <string>\n#include \"src/CYdLidar.h\"\n"
        "#include <rclcpp/rclcpp.hpp>\n#include <sensor_msgs/msg/laser_scan.hpp>\n"
        "int main(int argc, char * argv[]) {\n"
        "  rclcpp::init(argc, argv);\n"
        "  auto node = rclcpp::Node::make_shared(\"lidar\");\n"
        "  CYdLidar laser;\n"
        "  std::string port = \"/dev/ydlidar\";\n"
        "  node->declare_parameter(\"port\", port);\n"
        "  node->get_parameter(\"port\", port);\n"
        "  laser.setlidaropt(LidarPropSerialPort, port.c_str(), port.size());\n"
        "  int baud = 230400;\n"
        "  laser.setlidaropt(LidarPropSerialBaudrate, &baud, sizeof(int));\n"
        "  auto pub = node->create_publisher<sensor_msgs::msg::LaserScan>(\"scan\", 10);\n"
        "  rclcpp::spin(node);\n}\n")
    result = _server(write_tree, source)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "port"), ("read", "port"), ("publish", "scan")]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_an_explicit_template_instantiation_is_no_call_site() -> None:
    """OrbbecSDK_ROS2's dynamic_params.cpp instantiates its wrapper for each type
    (``template void Parameters::setParamT<bool>(std::string param_name, ...);``): a
    declaration, no call. Each was a missed call site and made every orbbec camera
    driver instance partial (58 of 96 instances). A call through ``->template`` and an
    ``extern template`` declaration are told apart; a specialisation's body still counts."""
    from haros_arch.extract.cpp import recall

    text = ("template void Parameters::setParamT<bool>(std::string param_name,\n"
            "    rclcpp::ParameterValue initial_value, bool &param);\n"
            "extern template void Parameters::setParamT<int>(std::string n, int &p);\n"
            "  pub_ = node_->template create_publisher<Array>(\"f\", 1);\n"
            "template <class T> void f(T& p) {\n"
            "  setParamT<T>(\"x\", p);\n"
            "  sub_ = node_->\n"
            "    template create_subscription<Array>(\"g\", 1, cb);\n")
    assert [s.line for s in recall.call_sites(text, ["setParamT"])] == [4, 6, 8]


def test_an_unqualified_vendor_function_of_vendor_values_is_found_by_their_lookup() -> None:
    """ouster's ``to_string(info.format.udp_profile_lidar)``: the SDK's header is missing,
    the call's argument a permissive value; the call is found as C++ finds it (by its
    argument), and the error no longer marks the constructor's calls as possibly lost."""
    result = extract("vendor_adl.cpp")
    assert rows(result) == [("publish", "points", "std_msgs/msg/String", 13)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_an_unqualified_api_method_is_no_friend() -> None:
    """A call of an API method's name that the parse cannot resolve is kept by that name
    (``CPP_CALL_UNRESOLVED``); found by its arguments as a friend, it would be a call of
    nothing."""
    names = synthesis.Names()
    text = b"void f() { declare_parameter(\"rate\", v.x); to_string(v.mode); }\n"
    names.learn([("use of undeclared identifier '" + n.decode() + "'", text, text.index(n))
                 for n in (b"declare_parameter", b"to_string")])
    header = names.header()
    assert "friend haros_any &to_string(" in header
    assert "declare_parameter" not in header


def test_an_unqualified_function_of_the_codes_own_values_stays_an_error() -> None:
    result = extract("undeclared_helper.cpp")
    assert rows(result) == [("publish", "out", "std_msgs/msg/String", 10)]
    assert "CPP_PARSE_ERROR" in codes(result)


def test_an_unqualified_call_that_may_be_an_unknown_bases_method_keeps_the_node_partial(
) -> None:
    """Found by the permissive friend, an unqualified call of vendor values in a method of
    a class derived from an unknown vendor class may be that base's method (nav2's
    ``declareParameter`` of a costmap layer declares a ROS parameter): the node is given
    to code nobody reads, not an error gone quiet."""
    result = extract("vendor_base_adl.cpp")
    unknown = [(d.code, d.location.line) for d in result.diagnostics
               if d.code == "CPP_NODE_TO_UNKNOWN"]
    assert unknown == [("CPP_NODE_TO_UNKNOWN", 11)]  # Gradient's, not Node2's describe()
    assert "CPP_PARSE_ERROR" not in codes(result)


def test_a_macro_of_the_vendor_is_no_method_of_its_base() -> None:
    """Onboard-SDK-ROS b7aa9f3's VehicleWrapper derives from the DJI SDK's ``Setup`` and
    logs with its ``DSTATUS(...)`` / ``DERROR(...)`` macros (78 places, "the node (this)
    is given to DSTATUS"): a name in capitals is a macro, not the base's method."""
    result = extract("vendor_base_macro.cpp")
    assert "CPP_PARSE_ERROR" not in codes(result)  # DSTATUS found, as a function
    assert "CPP_NODE_TO_UNKNOWN" not in codes(result)


def test_a_member_a_real_base_has_is_not_the_permissive_classes_too() -> None:
    """rtabmap's ``OdometryROS : public rclcpp::Node, public UThread``: with ``get_logger``
    declared on the permissive class (the code reads it on a vendor object), the class
    found it in both bases, ambiguously, in every function that logs: the member is
    withdrawn and the node's own is the one found."""
    result = extract("vendor_and_node_bases.cpp")
    assert rows(result) == [("publish", "status", "std_msgs/msg/String", 13)]
    messages = [d.message for d in result.diagnostics]
    assert not any("multiple base classes" in m for m in messages), messages
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_a_vendor_member_template_called_as_a_statement_is_declared() -> None:
    """plansys2's ``factory.registerNodeType<ExecuteAction>("ExecuteAction");`` of
    BehaviorTree.CPP's factory, whose header is missing: its result unused, the member
    is declared a member template; one whose result is used stays an error (what it
    returns may make the ROS calls that are kept by their API name)."""
    result = extract("vendor_member_template.cpp")
    assert rows(result) == [("publish", "executing_plan", "std_msgs/msg/String", 11)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    names = synthesis.Names()
    text = (b"void f() {\n  factory.registerNodeType<A>(\"a\");\n"
            b"  auto node = factory.get<B>(\"node\");\n  x = this->tree_.build<C>();\n}\n")
    message = "'%s' does not name a template but is followed by template arguments"
    names.learn([(message % n.decode(), text, text.index(n))
                 for n in (b"registerNodeType", b"get", b"build")])
    header = names.header()
    declared = "template <class... T, class... A> static haros_any &%s(const A &...);"
    assert declared % "registerNodeType" in header
    assert declared % "get" not in header and declared % "build" not in header


def test_shared_from_this_of_a_class_that_is_no_node_is_not_the_node(write_tree) -> None:
    """MOLA's ``ExecutableBase`` (no node: a std::enable_shared_from_this of itself, with
    bases of MRPT, whose headers are missing) returns ``shared_from_this()`` as its ``Ptr``,
    a name declared permissively: that was "the node given to Ptr" (CPP_NODE_TO_UNKNOWN)
    and every program including the header, mola-cli too, partial. Only a node's own
    ``shared_from_this()`` is the node; given to an unknown name it still is."""
    module = (
        "#include <memory>\n#include <mrpt/system/COutputLogger.h>\n"
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "class Module : public mrpt::system::COutputLogger,\n"
        "               public std::enable_shared_from_this<Module> {\n public:\n"
        "  Ptr getAsPtr() { return shared_from_this(); }\n};\n")
    node = (
        "class Server : public rclcpp::Node {\n public:\n"
        "  Server() : Node(\"server\") {\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"state\", 10);\n  }\n"
        "  void start() { helper_ = vendor::make_helper(shared_from_this()); }\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n"
        "  std::shared_ptr<vendor::Helper> helper_;\n};\n")
    alone = _server(write_tree, module + "int main() { return 0; }\n")
    assert "CPP_NODE_TO_UNKNOWN" not in codes(alone)
    both = _server(write_tree, module + node)
    assert [(d.code, d.location.line) for d in both.diagnostics
            if d.code == "CPP_NODE_TO_UNKNOWN"] == [("CPP_NODE_TO_UNKNOWN", 15)]


def test_casts_between_declared_classes_keep_the_calls(write_tree) -> None:
    """A simulator's model classes from a missing header (stage_ros' ``Stg::Model`` and
    ``Stg::ModelPosition`` of <stage.hh>): a ``static_cast`` from a pointer to one to a
    pointer to the other in an advertise call's arguments, and a ``dynamic_cast`` of a
    pointer to the base, were errors left on the declared classes (not related by
    inheritance, not polymorphic) that cost the calls; the classes now derive and have a
    virtual destructor, and the calls are there."""
    root = write_tree({
        "sim/package.xml": package_xml("sim", "catkin").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "sim/src/sim.cpp": (
            "#include <ros/ros.h>\n#include <std_msgs/String.h>\n#include <stage.hh>\n"
            "const char *topic(const char *name, Stg::Model *mod) { return name; }\n"
            "int main(int argc, char **argv) {\n"
            "  ros::init(argc, argv, \"sim\");\n  ros::NodeHandle n;\n"
            "  Stg::Model *mod = Stg::World::Find(\"robot\");\n"
            "  Stg::ModelPosition *pos = dynamic_cast<Stg::ModelPosition *>(mod);\n"
            "  ros::Publisher odom = n.advertise<std_msgs::String>(\n"
            "      topic(\"odom\", static_cast<Stg::Model *>(pos)), 10);\n"
            "  if (Stg::ModelRanger *r = dynamic_cast<Stg::ModelRanger *>(mod))\n"
            "    n.advertise<std_msgs::String>(\"scan\", 10);\n"
            "  ros::spin();\n}\n")})
    result = extract_cpp([str(root / "sim" / "src" / "sim.cpp")], scan([str(root)]),
                         cache_dir=None)
    # the name a one-return function of the node makes of its argument is read with
    # this call's (stage_ros' own mapName, several statements, stays '?')
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("publish", "odom", 10), ("publish", "scan", 13)]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL", "CPP_PARSE_ERROR")]


def test_every_call_of_a_missing_c_librarys_function_is_declared_at_once() -> None:
    """gscam's GStreamer (<gst/gst.h> missing): ``GstCaps *caps = gst_app_sink_get_caps(
    ...)`` shows clang's error on ``GstCaps`` only, its function one parse later, and
    another statement's functions later still: the rounds ran out with errors left in the
    function that advertises the node's publishers. Every call in the file of a function
    named after the library is declared with the first error; not one the file declares
    itself (a word or a ``*`` before it on its line), nor one of another prefix."""
    names = synthesis.Names(libraries=synthesis.library_prefixes(
        ["header gst/gst.h not found; an empty stand-in was used"]))
    text = (b"GstCaps *gst_own_helper(int depth);\n"
            b"void start() {\n  GstCaps *caps = gst_app_sink_get_caps(sink);\n"
            b"#endif\n  gst_app_sink_set_caps(sink, caps);\n"
            b"  if (ok) { helper_call(caps); }\n}\n"
            b"Sink::Sink() : gst_sink_(nullptr) {}\n"
            b"Pipe::Pipe() : gst_caps_pool(4),\n    gst_bus_pool(2) {}\n")
    names.learn([("unknown type name 'GstCaps'", text, text.index(b"GstCaps *caps"))])
    header = names.header()
    for value in ("gst_app_sink_get_caps", "gst_app_sink_set_caps"):
        assert f"extern haros_any {value};" in header
    assert "gst_own_helper" not in header
    assert "helper_call" not in header
    assert "gst_sink_" not in header  # members initialised
    assert "gst_caps_pool" not in header and "gst_bus_pool" not in header


NODELET_WITH_VENDOR_MEMBERS = (
    "#include <ros/ros.h>\n#include <nodelet/nodelet.h>\n#include <std_srvs/Empty.h>\n"
    "#include <vendor/buffer.h>\n#include <vendor/accumulators.h>\n"
    "namespace stats = vendor::accumulators;\n"
    "class Gps : public nodelet::Nodelet {\n public:\n"
    "  void onInit() override {\n"
    "    ros::NodeHandle &priv = getPrivateNodeHandle();\n"
    "    reset_ = priv.advertiseService(\"freset\", &Gps::reset, this);\n  }\n"
    "  bool reset(std_srvs::Empty::Request &, std_srvs::Empty::Response &) { return true; }\n"
    "  ros::ServiceServer reset_;\n"
    "  vendor::Buffer<unsigned char, 10000> socket_buffer_;\n"
    "  stats::accumulator_set<float, stats::stats<stats::tag::max, stats::tag::min,\n"
    "      stats::tag::mean, stats::tag::variance> > offset_stats_;\n"
    "  double k_[9] = {0};\n"
    "  vendor::Buffer<double, 9> matrix_ =\n"
    "      vendor::Buffer<double, 9>{{1, 0, 0, 0, 1, 0, 0, 0, 1}};\n"
    "};\n")


def test_vendor_members_of_a_nodelet_keep_its_class_valid(write_tree) -> None:
    """novatel_gps_driver's nodelet has a ``boost::array<uint8_t, 10000>`` (its boost
    header missing: a declared template of types only, which a value made an error) and
    boost accumulators through a namespace alias of a missing header, whose names came
    one per parse (``stats::tag::max``, then ``min``, ...: the alias was taken for a
    namespace the code defines, and not spread). Either left a member invalid, so the
    class, so ``getPrivateNodeHandle()`` on it: its ``freset`` service was ``?/freset``.
    A declared template takes a value where the code gives one (naoqi's
    ``boost::array<double, 9>{{...}}`` too, braces of braces)."""
    root = write_tree({
        "gps/package.xml": package_xml("gps", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>nodelet</depend></package>"),
        "gps/src/gps.cpp": NODELET_WITH_VENDOR_MEMBERS})
    result = extract_cpp([str(root / "gps" / "src" / "gps.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("server", "~freset")]
    # the alias of a namespace nobody declares names that namespace, declared, and the
    # names written through the alias are its (all spread at once)
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code == "CPP_PARSE_ERROR"] == []
    names = synthesis.Names()
    text = (b"vendor::Buffer<unsigned char, 10000> a;\nvendor::Grid<3> g;\n"
            b"auto p = vendor::make<vendor::io::Builder>();\n")
    names.learn([("no template named 'Buffer' in namespace 'vendor'", text,
                  text.index(b"Buffer")),
                 ("no template named 'Grid' in namespace 'vendor'", text,
                  text.index(b"Grid")),
                 ("no template named 'make' in namespace 'vendor'", text,
                  text.index(b"make"))])
    names.learn([("template argument for template type parameter must be a type", text,
                  text.index(b"10000")),
                 ("template argument for template type parameter must be a type", text,
                  text.index(b"3>")),
                 # a type the parse took for a value: no value parameter there
                 ("template argument for template type parameter must be a type", text,
                  text.index(b"vendor::io"))])
    header = names.header()
    assert ("template <class T0 = haros_any, long long V1 = 0, class... T> struct Buffer"
            in header)
    assert "template <long long V0 = 0, class... T> struct Grid" in header
    assert "template <class... T> struct make" in header


def test_every_use_of_a_declared_template_gives_its_values_at_once() -> None:
    """A-LOAM's ``ceres::AutoDiffCostFunction<LidarEdgeFactor, 3, 4, 3>`` (<ceres/ceres.h>
    missing): clang names one value argument per template-id and parse, and none before
    the template is declared; the numbers written in the files read are values from the
    first parse on. A name, even in capitals (``Foo<T>``), stays a type unless an error
    says it is a value."""
    names = synthesis.Names()
    text = (b"auto *f = new ceres::AutoDiffCostFunction<LidarEdgeFactor, 3, 4, 3>(c);\n"
            b"ceres::Foo<T> foo;\n")
    names.learn([("no template named 'AutoDiffCostFunction' in namespace 'ceres'", text,
                  text.index(b"AutoDiff")),
                 ("no template named 'Foo' in namespace 'ceres'", text, text.index(b"Foo"))])
    header = names.header()
    assert ("template <class T0 = haros_any, long long V1 = 0, long long V2 = 0, "
            "long long V3 = 0, class... T> struct AutoDiffCostFunction") in header
    assert "template <class... T> struct Foo" in header


def test_an_unqualified_call_in_a_class_template_is_no_dependent_base_s_method() -> None:
    """rovio's FeatureOutput, ImuPrediction, ... are class templates derived from
    lightweight_filtering's templates of their own parameter (the library missing): their
    ``MPD(qDC)``, ``gSM(...)`` on vendor values were each "the node (this) given to MPD"
    (54 CPP_NODE_TO_UNKNOWN in rovio_node). C++ never finds a dependent base's member by
    an unqualified name; a base that depends on no parameter still may be called so."""
    result = extract("vendor_dependent_base_adl.cpp")
    assert rows(result) == [("publish", "pose", "std_msgs/String", 34)]
    unknown = [(d.code, d.location.line) for d in result.diagnostics
               if d.code == "CPP_NODE_TO_UNKNOWN"]
    assert unknown == [("CPP_NODE_TO_UNKNOWN", 25)]  # Layer's, not FeatureOutput's


def test_a_declared_value_cast_as_a_shared_pointer(write_tree) -> None:
    """mrpt_map_server reads its map from an MRPT archive (a missing header): the object
    read is a permissive value, and ``std::dynamic_pointer_cast<Map>(obj)`` had no
    overload that deduces its pointee, an error in the function that makes the node's
    calls (4 places, the node partial; survey Z23)."""
    root = write_tree({
        "maps/package.xml": package_xml("maps", "ament_cmake"),
        "maps/src/server.cpp": (
            "#include <memory>\n#include <rclcpp/rclcpp.hpp>\n"
            "#include <std_msgs/msg/string.hpp>\n#include <vendor/archive.h>\n"
            "struct Map { virtual ~Map() = default; };\n"
            "class Server : public rclcpp::Node {\npublic:\n"
            "  Server() : rclcpp::Node(\"maps\") {\n"
            "    auto obj = vendor::archiveFrom(\"map.gz\").ReadObject();\n"
            "    auto map = std::dynamic_pointer_cast<Map>(obj);\n"
            "    std::shared_ptr<const Map> same = std::static_pointer_cast<const Map>(obj);\n"
            "    pub_ = create_publisher<std_msgs::msg::String>(\"map\", 1);\n  }\n"
            "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")})
    result = extract_cpp([str(root / "maps" / "src" / "server.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "map")]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_ERROR_NEAR_CALL", "CPP_PARSE_ERROR")] == []


def test_a_qualified_call_alone_as_a_statement_is_a_function() -> None:
    """OpenMower's mower_comms_v2 (spdlog's headers missing): ``auto logger = ...;`` then
    ``spdlog::set_default_logger(logger);``. Declared a class, the statement declared
    ``logger`` again ("redefinition of 'logger' with a different type"), an error in
    ``main`` that made the node partial; a call alone on its statement is a function's.
    A name followed by a declarator or called as a value keeps its class."""
    names = synthesis.Names()
    text = (b"void f() {\n  auto logger = std::make_shared<vendor::logger>(\"\", sink);\n"
            b"  vendor::set_default_logger(logger);\n  vendor::Guard g(logger);\n"
            b"  auto v = vendor::Scale(2.0);\n}\n")
    names.learn([("use of undeclared identifier 'vendor'", text, text.index(name))
                 for name in (b"vendor::logger", b"vendor::set", b"vendor::Guard",
                              b"vendor::Scale")])
    header = names.header()
    assert "extern haros_any set_default_logger;" in header
    for kind in ("logger", "Guard", "Scale"):
        assert f"struct {kind} : haros_any {{" in header


def test_members_are_read_from_code_not_comments_strings_or_includes() -> None:
    """OpenMower's mower_comms_v1: a comment ``// have reasonable defaults.`` before a
    line ``size_t payload_size = ...`` made ``size_t`` a member of the permissive class,
    and inside every class derived from a permissive base (``boost::noncopyable``, its
    header missing) the name was that member, not the type: "unknown type name
    'size_t'" in the xesc drivers' headers. The same for ``"file.txt"`` and
    ``#include <vendor/crc.hpp>``."""
    names = synthesis.Names()
    text = (b'#include <vendor/crc.hpp>\nvoid f(vendor::Frame& frame) {\n'
            b'  // have reasonable defaults.\n  size_t n = 3;\n'
            b'  /* the end. Since\n  then */ frame.count = n;\n'
            b'  open("file.txt"); char c = \'.\'; frame -> size = 1;\n}\n')
    names.learn([("use of undeclared identifier 'vendor'", text, text.index(b"vendor::"))])
    names.read_members([text])
    assert {"count", "size"} <= names.members
    assert not {"size_t", "Since", "txt", "hpp"} & names.members


def test_a_builders_member_template_assigned_whole_is_declared() -> None:
    """Doosan's dsr_control: ``arm_joint_names = boost::assign::list_of("joint1")(
    "joint2").convert_to_container<ros::V_string>();`` with boost's header not read
    (the stand-ins' include path): the member template of what a chain of calls returns,
    its result assigned whole to a variable that keeps its own type, is declared one, not
    an error in the constructor that makes the node's calls; a member template of a
    member (``x = this->tree_.build<C>()``) or kept in a new ``auto`` stays one."""
    names = synthesis.Names()
    text = (b"void f() {\n"
            b"  names = boost::assign::list_of(\"a\")(\"b\").convert_to_container<V>();\n"
            b"  auto made = make_list(\"a\")(\"b\").to_container<V>();\n"
            b"  other = make_list(\"a\").into<V>() + 1;\n"
            b"  x = this->tree_.build<C>();\n}\n")
    message = "'%s' does not name a template but is followed by template arguments"
    names.learn([(message % n.decode(), text, text.index(n))
                 for n in (b"convert_to_container", b"to_container", b"into", b"build")])
    header = names.header()
    declared = "template <class... T, class... A> static haros_any &%s(const A &...);"
    assert declared % "convert_to_container" in header
    for name in ("to_container", "into", "build"):
        assert declared % name not in header


def test_a_constant_compared_then_anded_is_a_value(write_tree) -> None:
    """A C library's constant right after ``==`` / ``!=`` is a value whatever follows it:
    ``err != UVC_SUCCESS && n == 1`` is no rvalue reference ``UVC_SUCCESS&&`` (libuvc's
    header missing, ros_astra_camera's driver): read as a type it made every
    ``err != UVC_SUCCESS`` an error in a function that calls the ROS API."""
    result = _server(
        write_tree,
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "#include <libuvc/libuvc.h>\n"
        "class Server : public rclcpp::Node {\n public:\n"
        "  Server() : Node(\"server\") {\n"
        "    uvc_error_t err = uvc_init(&ctx_, NULL);\n"
        "    if (err != UVC_SUCCESS && count_ == 1) { return; }\n"
        "    if (err != UVC_SUCCESS) { return; }\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"image\", 10);\n  }\n"
        "  uvc_context_t *ctx_;\n  int count_;\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("publish", "image", 10)]
    assert not [d for d in result.diagnostics
                if d.code in ("CPP_ERROR_NEAR_CALL", "CPP_PARSE_ERROR")]
    names = synthesis.Names()
    text = b"void f(int e) { if (e == UVC_OK || e != VND_DONE && e > 0) {} }\n"
    names.learn([("use of undeclared identifier '" + n.decode() + "'", text, text.index(n))
                 for n in (b"UVC_OK", b"VND_DONE")])
    header = names.header()
    assert "extern haros_any UVC_OK;" in header and "extern haros_any VND_DONE;" in header


def test_a_float_literal_gives_no_member() -> None:
    """The ``.`` of a float literal is no member access: ``1.e5``, ``2.f`` and ``3.e-2``
    give no member ``e5`` / ``f`` / ``e`` of the permissive class (a member ``f`` would
    hide a name of every class derived from one); a name after ``.`` of an object whose
    name ends in a digit is still read."""
    names = synthesis.Names()
    names.read_members([b"double x = 1.e5 + 2.f * 3.e-2 + 0x1.p3;\n"
                        b"int n = obj1.size() + p2->count;\n"])
    assert {"e5", "f", "e", "p3"}.isdisjoint(names.members)
    assert {"size", "count"} <= names.members


def test_a_name_in_a_string_or_character_literal_is_no_call_site() -> None:
    """A log message that names a wrapper of the unit (MoveIt's planning scene monitor:
    ``RCLCPP_FATAL_STREAM(logger_, "requestPlanningSceneState() to self-provided
    service")``) is no call: with errors in the unit it was ``CPP_CALL_MISSED`` and left
    move_group partial. A call after the literal, or after a digit separator, still is;
    the site's text is the line as written."""
    from haros_arch.extract.cpp import recall

    text = ('void f(const std::string & name)\n'
            '{\n'
            '  RCLCPP_FATAL_STREAM(logger_, "requestPlanningSceneState() to " << name);\n'
            '  RCLCPP_INFO(logger_, "called psm.providePlanningSceneService()?");\n'
            '  log("x\\"y", \'"\'); requestPlanningSceneState(name);\n'
            '  const int n = 1\'000; auto c = node->create_client<S>("srv(", n);\n'
            '}\n')
    wrappers = ["requestPlanningSceneState", "providePlanningSceneService"]  # callable with
    sites = recall.call_sites(text, wrappers, wrappers)  # no argument: a default one
    assert [s.line for s in sites] == [5, 6]
    assert sites[1].text == 'const int n = 1\'000; auto c = node->create_client<S>("srv(", n);'


def test_a_vendor_call_as_an_unbraced_body_is_a_call_not_a_declaration() -> None:
    """``if (...) vendor::setLogLevel(vendor::LOG_DEBUG);`` with the header missing
    (realsense2_camera's console_bridge call): the statement after an ``if``, ``else``
    or ``for`` head is a call alone, as after ``;`` or ``{``. Declared a class,
    ``setLogLevel`` made it the declaration of a variable ``vendor::LOG_DEBUG``, an error
    in a function that calls the ROS API, and the node partial."""
    result = extract("vendor_call_statement.cpp")
    assert rows(result) == [("publish", "out", "std_msgs/msg/String", 17)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_a_vendor_member_template_tested_as_a_condition_is_declared_a_template() -> None:
    """``if (profile.is<vendor::VideoProfile>())`` and ``while (!profile.is<..>() &&
    ..)`` of a header not found (realsense2_camera's startPublishers): the result is
    only tested, so ``is`` is declared a member template, as for a call whose result is
    unused; it was an error in a function that calls the ROS API, the node partial."""
    result = extract("vendor_tested_template.cpp")
    assert rows(result) == [("publish", "image", "std_msgs/msg/String", 11),
                            ("publish", "motion", "std_msgs/msg/String", 14)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_an_unqualified_call_of_a_library_base_that_is_no_ros_package_s_keeps_the_node(
) -> None:
    """realsense2_camera 1cbd81be's RosSensor derives from librealsense's ``rs2::sensor``
    (its headers missing) and calls its ``get_info``: each such call was "the node (this)
    is given to get_info" (35 places, the node partial). A base of a namespace that names
    no package of the workspace or the package's dependencies is no ROS code; one that
    does (``vendor::Layer``, the package depends on ``vendor``) still may be."""
    result = extract("library_base_adl.cpp")
    assert rows(result) == [("publish", "out", "std_msgs/msg/String", 21)]
    assert "CPP_NODE_TO_UNKNOWN" not in codes(result)
    assert "CPP_PARSE_ERROR" not in codes(result)


def test_a_member_template_named_with_its_class_is_no_type_of_that_class() -> None:
    """realsense2_camera 1cbd81be: ``sensor->rs2::sensor::is<rs2::depth_sensor>()`` and
    its RosSensor's ``rs2::sensor::is<T>()`` made ``is`` a type of the permissive
    ``rs2::sensor``, and every ``sensor.is<T>()`` an error (startPublishers, which makes
    the camera's publishers, among them); and std::pair had no ``!=``."""
    result = extract("qualified_member_template.cpp")
    assert rows(result) == [("publish", "out", "std_msgs/msg/String", 22)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_which_classes_known_only_by_name_may_be_a_ros_package_s() -> None:
    """``extract.cpp.ros_classes``: a base class known only by name makes "the node
    given to unknown code" only where it may be a ROS package's: its namespace a
    dependency (``vendor``, which vendor_node depends on) or a workspace package, or the
    global namespace, but for Qt's classes (rviz's PropertyTreeModel calls
    QAbstractItemModel's ``createIndex``: rviz's test programs were partial for it)."""
    from haros_arch.extract.cpp import ros_classes

    ros = ros_classes(os.path.join(SOURCES, "vendor_base_adl.cpp"), scan([ROOT]), [])
    assert ros("vendor::Layer") and ros("::vendor::detail::Base") and ros("Helper")
    assert not ros("rs2::sensor") and not ros("QAbstractItemModel")
    assert ros("vendor_node::Base")  # the workspace's own package


def test_a_standard_container_s_first_argument_in_capitals_is_a_type() -> None:
    """zed-ros2-wrapper 33dfefa's ZedCamera holds ``std::unordered_set<sl::MODULE>`` (the
    SDK missing): ``MODULE`` was declared a constant, as a capitals name ending a template's
    arguments is (``std::array<T, N>``), so the class was invalid and every call in it an
    error (86 places partial; 38 after)."""
    result = extract("container_of_vendor_enum.cpp")
    assert rows(result) == [("publish", "out", "std_msgs/msg/String", 12)]
    assert "CPP_PARSE_ERROR" not in codes(result)
    assert "CPP_ERROR_NEAR_CALL" not in codes(result)


def test_a_base_member_of_a_class_derived_from_a_declared_one(tmp_path) -> None:
    """hector_quadrotor's pose estimation node derives from hector_pose_estimation's
    PoseEstimationNode (its header missing) and reads the base's ``pose_estimation_``
    and ``height_subscriber_`` in its methods; ROBOTIS-OP3's modules set their
    framework base's ``module_name_``. Such a name is the base's: a member of the
    permissive class, which a class derived from a declared one finds; the class that
    derives from nothing declared still reads it as an error (no global of that name
    shadows anything)."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
        "#include <vendor_estimation/node.h>\n"
        "class Node : public vendor::EstimationNode {\n"
        " public:\n  bool init();\n  void cb(const std_msgs::String::ConstPtr& m);\n"
        "  ros::Publisher pub_;\n};\n"
        "bool Node::init() {\n"
        "  ros::NodeHandle nh;\n"
        "  height_subscriber_ = nh.subscribe(\"height\", 10, &Node::cb, this);\n"
        "  pose_estimation_->reset();\n"
        "  pub_ = nh.advertise<std_msgs::String>(\"pose\", 1);\n"
        "  return true;\n}\n"
        "struct Plain {\n  void run();\n};\n"
        "void Plain::run() {\n  ros::NodeHandle nh;\n  counter_ = 2;\n"
        "  nh.advertise<std_msgs::String>(\"plain\", 1);\n}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    errors = [(d.location.line, d.message) for d in result.diagnostics
              if d.code == "CPP_PARSE_ERROR"]
    assert errors == [(22, "C++ error: use of undeclared identifier 'counter_'")]
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "height"), ("publish", "pose"), ("publish", "plain")]


def test_a_calling_convention_macro_of_a_missing_header_is_defined_empty(write_tree) -> None:
    """``static void VENDOR_CALLBACK handle(void *data, const vendor_t t);`` with the
    vendor's header missing (vrpn_client_ros' ``VRPN_CALLBACK`` handlers, which
    advertise their pose, twist and accel topics): clang read the macro as a variable of
    type void and the function as lost (``expected ';'``), so the handler's definition
    was no function and its advertise call no call."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/include/pkg/tracker.h": """\
            #include <ros/ros.h>
            #include <geometry_msgs/PoseStamped.h>
            #include <vendor_tracker.h>
            class Tracker {
             public:
              explicit Tracker(ros::NodeHandle nh);
             private:
              ros::NodeHandle nh_;
              ros::Publisher pub_;
              static void VENDOR_CALLBACK handle_pose(void *data, const vendor_POSE pose);
              static int VENDOR_CALLBACK handle_count(void *data, const vendor_POSE pose);
            };
            """,
        "pkg/src/tracker.cpp": """\
            #include <pkg/tracker.h>
            Tracker::Tracker(ros::NodeHandle nh) : nh_(nh) {
              vendor_register(this, &Tracker::handle_pose, &Tracker::handle_count);
            }
            void VENDOR_CALLBACK Tracker::handle_pose(void *data, const vendor_POSE pose) {
              Tracker *self = static_cast<Tracker *>(data);
              self->pub_ = self->nh_.advertise<geometry_msgs::PoseStamped>("pose", 1);
            }
            int VENDOR_CALLBACK Tracker::handle_count(void *data, const vendor_POSE pose) {
              Tracker *self = static_cast<Tracker *>(data);
              return self->nh_.param<int>("count", 0);
            }
            int main(int argc, char** argv) {
              ros::init(argc, argv, "tracker");
              Tracker tracker(ros::NodeHandle("~"));
              ros::spin();
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "tracker.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert rows(result) == [("publish", "~pose", "geometry_msgs/PoseStamped", 7),
                            ("read", "~count", "int", 11)]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
    # a variable declared after a type is no macro: ``int count handle(`` is left alone
    names = synthesis.Names()
    text = b"int count handle(1);\n"
    assert not names.learn([("expected ';' after top level declarator", text,
                             text.index(b" handle"))])


def test_a_vendor_sdks_windows_integer_types_are_integers(write_tree) -> None:
    """IDS uEye's SDK (``ueye.h``, missing) defines the Windows data types ``INT``,
    ``UINT``, ... as integers; ueye_cam's driver takes ``INT&`` members of its
    dynamic_reconfigure config, which are ``int``: as permissive classes they refused
    the ``int``, an error at each such call in ``parseROSParams``, which reads the
    nodelet's parameters and advertises (zeabus' cameras: the nodelet partial). A name
    of that table that the code also casts to (``(INT) 2000``) is still the integer."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin"),
        "pkg/src/camera.cpp": """\
            #include <string>
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            #include <ueye.h>
            struct Config { int master_gain; int red_gain; bool auto_gain; };
            class Camera {
             public:
              INT setGain(bool& automatic, INT& master, INT& red);
              INT parse(ros::NodeHandle& nh) {
                INT is_err = IS_SUCCESS;
                UINT timeout = (INT) 2000;
                nh.param<int>("master_gain", config_.master_gain, 0);
                if ((is_err = setGain(config_.auto_gain, config_.master_gain,
                                      config_.red_gain)) != IS_SUCCESS) return is_err;
                pub_ = nh.advertise<std_msgs::String>("image_raw", 1);
                return is_err;
              }
             private:
              Config config_;
              HIDS handle_;
              ros::Publisher pub_;
            };
            int main(int argc, char** argv) {
              ros::init(argc, argv, "camera");
              ros::NodeHandle nh("~");
              Camera camera;
              camera.parse(nh);
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "camera.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert rows(result) == [("read", "~master_gain", "int", 12),
                            ("publish", "~image_raw", "std_msgs/String", 15)]
    assert [c for c in codes(result) if c in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
