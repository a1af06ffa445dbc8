"""The stand-in headers cover the rclcpp, rmw, rcl / rcutils, class_loader and std APIs
that ROS 2 demos use beyond the basics (executor members, QoS liveliness and deadlines,
publisher / subscription options, parameter events, std::pmr), and the fields of common
ROS 2 interfaces whose packages are not in the workspace."""

from __future__ import annotations

import os

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp, interfaces, ros2_interfaces
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "ros2_apis")
SOURCE = os.path.join(ROOT, "src", "api_demo", "src", "map_relay.cpp")


def _extract(tmp_path, manifest: str, text: str, name: str = "a.cpp") -> CppResult:
    """``text`` as the one source (``name``) of the package of ``manifest`` in
    ``tmp_path``, extracted without a cache."""
    (tmp_path / "package.xml").write_text(manifest)
    source = tmp_path / name
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)


@pytest.fixture(scope="module")
def relay() -> CppResult:
    return extract_cpp([SOURCE], scan([ROOT]), cache_dir=None)


def test_parses_without_errors(relay: CppResult) -> None:
    found = [(d.code, d.message) for d in relay.diagnostics
             if d.code in ("CPP_PARSE_ERROR", "CPP_MESSAGE_FIELD", "CPP_INCLUDE_MISSING")]
    assert found == []


def test_calls(relay: CppResult) -> None:
    rows = [(c.kind, c.name, c.type, c.queue_size, c.location.line) for c in relay.calls]
    assert rows == [
        ("publish", "map_out", "nav_msgs/msg/OccupancyGrid", 3, 38),
        ("subscribe", "map_in", "nav_msgs/msg/OccupancyGrid", 10, 45),
        ("subscribe", "/parameter_events", "rcl_interfaces/msg/ParameterEvent", 10, 51),
        ("client", "add_two_ints", "example_interfaces/srv/AddTwoInts", None, 60),
    ]
    assert relay.rosname == "map_relay"


@pytest.mark.parametrize(("name", "kind", "fields"), [
    ("example_interfaces/AddTwoInts", "srv", ["int64_t a;", "int64_t sum;"]),
    ("example_interfaces/Fibonacci", "action", ["int32_t order;",
                                                "std::vector<int32_t> sequence;"]),
    ("nav_msgs/OccupancyGrid", "msg", ["nav_msgs::msg::MapMetaData info;",
                                       "std::vector<int8_t> data;"]),
    ("nav_msgs/MapMetaData", "msg", ["uint32_t width;", "geometry_msgs::msg::Pose origin;"]),
    ("rcl_interfaces/ParameterEvent", "msg", [
        "std::vector<rcl_interfaces::msg::Parameter> changed_parameters;", "std::string node;"]),
    ("rcl_interfaces/ParameterValue", "msg", ["int64_t integer_value;"]),
    ("lifecycle_msgs/State", "msg", ["static constexpr uint8_t PRIMARY_STATE_ACTIVE = 3;"]),
])
def test_well_known_ros2_interfaces(name: str, kind: str, fields: list[str]) -> None:
    package, base = name.split("/")
    definition = interfaces.parse_definition(package, base, interfaces.WELL_KNOWN[name])
    source = ros2_interfaces.render(definition, kind)
    for field in fields:
        assert field in source


def test_fields_declare_their_type_alias() -> None:
    definition = interfaces.parse_definition("sensor_msgs", "Image",
                                             interfaces.WELL_KNOWN["sensor_msgs/Image"])
    assert "using _step_type = uint32_t;" in ros2_interfaces.render(definition, "msg")


def test_type_adapters_serialized_messages_and_generic_topics() -> None:
    """rclcpp::TypeAdapter<Custom, Ros> (as the template argument, through adapt_type<>::as
    and through RCLCPP_USING_CUSTOM_TYPE_AS_ROS_MESSAGE_TYPE) gives the ROS message type;
    SerializedMessage and Serialization parse; a generic publisher's or subscription's
    type is the string it is given."""
    source = os.path.join(ROOT, "src", "api_demo", "src", "adapted_relay.cpp")
    found = extract_cpp([source], scan([ROOT]), cache_dir=None)
    assert [(c.kind, c.name, c.type, c.queue_size, c.location.line) for c in found.calls] == [
        ("publish", "text_out", "std_msgs/msg/String", 10, 43),
        ("publish", "readings", "std_msgs/msg/String", 10, 44),
        ("publish", "text_raw", "std_msgs/msg/String", 10, 45),
        ("subscribe", "text_in", "std_msgs/msg/String", 10, 46),
        ("publish", "forwarded", "std_msgs/msg/String", 5, 57),
        ("subscribe", "tapped", "sensor_msgs/msg/Image", 1, 58),
    ]
    assert [d.code for d in found.diagnostics] == []


def test_lifecycle_rcl_std_and_opencv_apis_parse() -> None:
    """Lifecycle callbacks and publishers, lifecycle and statistics interface fields,
    Node::list_parameters / get_node_options, Publisher QoS checks, rcl errors,
    RCLCPP_DEBUG_FUNCTION, std::regex, std::async into a shared_future, real-time
    pthread / clock_nanosleep calls and OpenCV's imdecode / floodFill / compare."""
    source = os.path.join(ROOT, "src", "api_demo", "src", "lifecycle_monitor.cpp")
    found = extract_cpp([source], scan([ROOT]), cache_dir=None)
    lifecycle = "lifecycle_msgs/srv/"
    assert [(c.kind, c.name, c.type, c.location.line) for c in found.calls] == [
        # what LifecycleNode("lifecycle_monitor") makes by itself: its transitions and
        # the services of its state machine, under the node's name
        ("publish", "~transition_event", "lifecycle_msgs/msg/TransitionEvent", 28),
        ("server", "~change_state", lifecycle + "ChangeState", 28),
        ("server", "~get_state", lifecycle + "GetState", 28),
        ("server", "~get_available_states", lifecycle + "GetAvailableStates", 28),
        ("server", "~get_available_transitions", lifecycle + "GetAvailableTransitions", 28),
        ("server", "~get_transition_graph", lifecycle + "GetAvailableTransitions", 28),
        ("publish", "monitor/report", "std_msgs/msg/String", 30),
        # list_parameters({}, 0): the names of every parameter, which it then reads by
        # them, a read of the node's namespace whole
        ("read", "~", None, 48),
        ("publish", "probe", "std_msgs/msg/String", 74),
    ]
    assert [(d.code, d.message) for d in found.diagnostics] == []


def test_xmlrpc_values_as_ros_1_nodes_read_them(tmp_path) -> None:
    """move_base's recovery behaviours: ``list[i]["name"]`` (a string key), conversions
    to std::string / double / int, iteration over a struct."""
    from haros_arch.workspace import Workspace

    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <string>\n"
        "void f(ros::NodeHandle& n) {\n"
        "  XmlRpc::XmlRpcValue v;\n"
        "  n.getParam(\"~recovery_behaviors\", v);\n"
        "  for (int i = 0; i < v.size(); ++i) {\n"
        "    std::string name = v[i][\"name\"];\n"
        "    double x = static_cast<double>(v[i][\"x\"]);\n"
        "    int k = v[i][\"k\"];\n"
        "  }\n"
        "  for (auto it = v.begin(); it != v.end(); ++it) { std::string key = it->first; }\n"
        "}\n")
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~recovery_behaviors")]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_ros_1_code_has_boost_placeholders_in_the_global_namespace(tmp_path) -> None:
    """pointcloud_to_laserscan (noetic): ``boost::bind(&C::cb, this, _1)`` with only
    roscpp's and tf2_ros' headers included, as Boost 1.71 allowed."""
    from haros_arch.workspace import Workspace

    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <sensor_msgs/LaserScan.h>\n"
        "#include <tf2_ros/message_filter.h>\n#include <message_filters/subscriber.h>\n"
        "struct Relay {\n"
        "  void cb(const sensor_msgs::LaserScan::ConstPtr& m);\n"
        "  void failed(const sensor_msgs::LaserScan::ConstPtr& m, int reason);\n"
        # virtual: nothing here calls it, a host may (a non-virtual start nothing
        # calls makes no call)
        "  virtual void start(ros::NodeHandle& nh) {\n"
        "    sub_ = nh.subscribe<sensor_msgs::LaserScan>(\n"
        "      \"scan\", 1, boost::bind(&Relay::cb, this, _1));\n"
        "    filter_->registerFailureCallback(boost::bind(&Relay::failed, this, _1, _2));\n"
        "    ROS_INFO_COND_NAMED(true, \"relay\", \"topic %s\", in_.getTopic().c_str());\n"
        "  }\n"
        "  ros::Subscriber sub_;\n"
        "  message_filters::Subscriber<sensor_msgs::LaserScan> in_;\n"
        "  tf2_ros::MessageFilter<sensor_msgs::LaserScan>* filter_;\n"
        "};\n")
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "?/scan")]  # nh: a parameter
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_nav2_lifecycle_and_std_forms_parse_clean(tmp_path) -> None:
    """What nav2's LifecycleNode, SimpleActionServer and robot_state_publisher use: the
    four-argument rclcpp_lifecycle constructor, managed entities, the current state,
    pre-shutdown callbacks, rcl_action's default options, std::void_t, duration::max,
    std::ios seek / tell; message_filters' synchronizer bounds."""
    from haros_arch.workspace import Workspace

    (tmp_path / "package.xml").write_text(
        '<package format="3"><name>p</name><version>0.0.1</version><description>d'
        '</description><maintainer email="a@b.c">m</maintainer><license>BSD</license>'
        "<depend>rclcpp</depend><export><build_type>ament_cmake</build_type></export>"
        "</package>\n")
    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <chrono>\n#include <fstream>\n#include <type_traits>\n"
        "#include <rclcpp_lifecycle/lifecycle_node.hpp>\n"
        "#include <rclcpp_action/rclcpp_action.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "#include <message_filters/subscriber.h>\n#include <message_filters/synchronizer.h>\n"
        "template<class T, class = void> struct has_x : std::false_type {};\n"
        "template<class T> struct has_x<T, std::void_t<decltype(T::x)>> : std::true_type {};\n"
        "class Managed : public rclcpp_lifecycle::LifecycleNode {\n"
        "public:\n"
        "  Managed() : rclcpp_lifecycle::LifecycleNode(\"managed\", \"\", rclcpp::NodeOptions(),"
        " false) {\n"
        "    auto pub = create_publisher<std_msgs::msg::String>(\"out\", 1);\n"
        "    add_managed_entity(pub);\n"
        "    auto id = get_current_state().id(); (void)id;\n"
        "    auto handle = get_node_base_interface()->get_context()->add_pre_shutdown_callback(\n"
        "      [] {});\n"
        "    get_node_base_interface()->get_context()->remove_pre_shutdown_callback(handle);\n"
        "    auto options = rcl_action_server_get_default_options(); (void)options;\n"
        "    auto forever = std::chrono::nanoseconds::max(); (void)forever;\n"
        "    std::ifstream file(\"urdf\");\n"
        "    file.seekg(0, std::ios::end); auto size = file.tellg(); (void)size;\n"
        "  }\n"
        "};\n")
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert ("publish", "out") in [(c.kind, c.name) for c in result.calls]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_numeric_and_algorithm_forms_of_ros2_controllers_parse(tmp_path) -> None:
    """std::iota (JointTrajectoryController's command-to-joint map), accumulate with an
    operation, adjacent_find: a parse error there would hide the calls beside them."""
    from haros_arch.workspace import Workspace

    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <algorithm>\n#include <numeric>\n#include <vector>\n"
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "void f(rclcpp::Node::SharedPtr node) {\n"
        "  std::vector<size_t> map(4);\n"
        "  std::iota(map.begin(), map.end(), 0);\n"
        "  auto sum = std::accumulate(map.begin(), map.end(), 0.0,\n"
        "    [](double a, size_t b) { return a + b; }); (void)sum;\n"
        "  if (std::adjacent_find(map.begin(), map.end()) == map.end()) {\n"
        "    node->create_publisher<std_msgs::msg::String>(\"out\", 1);\n"
        "  }\n"
        "}\n")
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert ("publish", "out") in [(c.kind, c.name) for c in result.calls]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_ros_1_asserts_shared_ptr_null_tokenizer_and_angles_parse(tmp_path) -> None:
    """Forms of the navigation stack's plugins (base_local_planner, costmap_2d's obstacle
    layer, rotate_recovery) parse clean, so their calls are not near an error."""
    (tmp_path / "package.xml").write_text(
        '<package format="2"><name>p</name><version>1.0.0</version>'
        "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
        "<license>BSD</license></package>")
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <boost/shared_ptr.hpp>\n"
        "#include <boost/tokenizer.hpp>\n#include <angles/angles.h>\n#include <cmath>\n"
        "#include <std_msgs/Empty.h>\n"
        "struct S { void subscribe(); };\n"
        "double f(boost::shared_ptr<S> s, std::string text, double a, double b) {\n"
        "  ROS_ASSERT_MSG(a > 0, \"a is %f\", a);\n"
        "  if (s != NULL) { s->subscribe(); }\n"
        "  typedef boost::tokenizer<boost::char_separator<char> > tokenizer;\n"
        "  boost::char_separator<char> sep(\", \");\n"
        "  tokenizer tokens(text, sep);\n"
        "  double sum = 0;\n"
        "  for (tokenizer::iterator i = tokens.begin(); i != tokens.end(); ++i) {\n"
        "    sum += i->size(); }\n"
        "  ros::NodeHandle nh;\n"
        "  ros::Publisher p = nh.advertise<std_msgs::Empty>(\"out\", 1);\n"
        "  double wrapped = 0;\n"
        "  // joint_trajectory_controller's continuous joints: limits wider than a turn\n"
        "  angles::shortest_angular_distance_with_large_limits(a, b, -10, 10, wrapped);\n"
        "  return sum + wrapped + std::fabs(angles::shortest_angular_distance(a, b));\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_urdf_models_parse_and_initparam_reads_the_description(tmp_path) -> None:
    """ros_controllers' forms: urdf::parseURDF and its joints and links, and
    urdf::Model::initParamWithNodeHandle / initParam, which read the description."""
    (tmp_path / "package.xml").write_text(
        '<package format="2"><name>p</name><version>1.0.0</version>'
        "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
        "<license>BSD</license></package>")
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <urdf/model.h>\n"
        "#include <urdf/urdfdom_compatibility.h>\n#include <urdf_parser/urdf_parser.h>\n"
        "double f(ros::NodeHandle &n, const std::string &text) {\n"
        "  urdf::ModelInterfaceSharedPtr model(urdf::parseURDF(text));\n"
        "  urdf::JointConstSharedPtr joint(model->getJoint(\"left\"));\n"
        "  if (!joint) return 0;\n"
        "  urdf::LinkConstSharedPtr link = model->getLink(joint->child_link_name);\n"
        "  if (!link || !link->collision) return 0;\n"
        "  if (link->collision->geometry->type != urdf::Geometry::CYLINDER) return 0;\n"
        "  urdf::Model urdf;\n"
        "  if (!urdf.initParamWithNodeHandle(\"robot_description\", n)) return 0;\n"
        "  urdf::Model other;\n"
        "  other.initParam(\"robot_description\");\n"
        "  if (urdf.getJoint(\"j\")->type == urdf::Joint::REVOLUTE)\n"
        "    return urdf.getJoint(\"j\")->limits->lower;\n"
        "  return static_cast<urdf::Cylinder*>(link->collision->geometry.get())->radius\n"
        "    + joint->parent_to_joint_origin_transform.position.x;\n"
        "}\n"
        # f runs (an f nothing calls makes no call named on its handle)
        "int main() { ros::NodeHandle nh; return f(nh, \"\") > 0; }\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert [(c.kind, c.name, c.searched, c.location.line) for c in result.calls] == [
        ("read", "robot_description", True, 13), ("read", "robot_description", True, 15)]


def test_a_message_of_a_package_our_stand_ins_shadow_is_synthesised(tmp_path) -> None:
    """tf/tfMessage.h (tf's headers are our stand-ins) is tf's message, with its fields."""
    (tmp_path / "package.xml").write_text(
        '<package format="2"><name>p</name><version>1.0.0</version>'
        "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
        "<license>BSD</license></package>")
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <tf/tfMessage.h>\n"
        "void f(ros::NodeHandle &n) {\n"
        "  tf::tfMessage m;\n  m.transforms.resize(1);\n"
        "  m.transforms[0].child_frame_id = \"base\";\n"
        "  ros::Publisher p = n.advertise<tf::tfMessage>(\"/tf\", 100);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "/tf", "tf/tfMessage")]


@pytest.mark.parametrize("std", [None, "c++14", "c++17"])
def test_the_stand_in_prelude_precompiles(std: str | None) -> None:
    # an error anywhere in the stand-ins leaves every unit without the precompiled
    # prelude, and the names it gave to code that reaches rclcpp only through a missing
    # header are gone (a node class derived from an undeclared rclcpp::Node)
    from haros_arch.extract.cpp import headers, toolchain

    headers._PCH.clear()
    assert headers.precompiled_prelude(toolchain.base_arguments(False, std)) is not None


def test_every_nodelet_log_macro_parses(tmp_path) -> None:
    """Ouster's nodelets log with NODELET_FATAL_STREAM, NODELET_WARN_COND and the other
    variants of every level; the function around them is read clean."""
    result = _extract(
        tmp_path, package_xml("p"),
        "#include <nodelet/nodelet.h>\n#include <std_msgs/Empty.h>\n"
        "class Driver : public nodelet::Nodelet {\n"
        "  void onInit() override {\n"
        "    int n = 3;\n"
        "    NODELET_FATAL_STREAM(\"no sensor \" << n);\n"
        "    NODELET_WARN_COND(n > 2, \"many: %d\", n);\n"
        "    NODELET_ERROR_THROTTLE(1.0, \"late\");\n"
        "    NODELET_WARN_STREAM_THROTTLE(1.0, \"late \" << n);\n"
        "    NODELET_DEBUG_ONCE(\"once\");\n"
        "    NODELET_INFO_STREAM_DELAYED_THROTTLE(2.0, \"slow\");\n"
        "    pub_ = getNodeHandle().advertise<std_msgs::Empty>(\"out\", 1);\n"
        "  }\n"
        "  ros::Publisher pub_;\n"
        "};\n")
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_limits_mem_fn_rdbuf_and_time_from_nanoseconds_parse(tmp_path) -> None:
    """Forms of ouster-ros' nodelets: ULLONG_MAX, std::mem_fn, a stream's rdbuf(),
    ros::Time::fromNSec."""
    result = _extract(
        tmp_path, package_xml("p"),
        "#include <ros/ros.h>\n#include <climits>\n#include <functional>\n"
        "#include <fstream>\n#include <sstream>\n#include <std_msgs/Empty.h>\n"
        "struct S { int size() const; };\n"
        "int main(int argc, char** argv) {\n"
        "  unsigned long long big = ULLONG_MAX; long small = LONG_MIN;\n"
        "  auto size = std::mem_fn(&S::size);\n"
        "  std::ifstream in(\"m.json\"); std::stringstream text; text << in.rdbuf();\n"
        "  ros::Time stamp; stamp.fromNSec(big);\n"
        "  ros::NodeHandle nh;\n"
        "  ros::Publisher p = nh.advertise<std_msgs::Empty>(\"out\", 1);\n"
        "  return static_cast<int>(small);\n"
        "}\n")
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_a_stringstream_has_one_ios_base(tmp_path) -> None:
    """slam_toolbox's Karto.h sets ``stream.precision(...)`` on a stringstream: istream
    and ostream share one (virtual) ios_base, as in the standard library."""
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <sstream>\n#include <string>\n"
        "std::string f(double v) {\n"
        "  std::stringstream s; s.precision(4); s.setf(std::ios::fixed); s << v;\n"
        "  return s.str();\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_a_vector_parameter_is_an_array_of_its_element_type(tmp_path) -> None:
    """``declare_parameter<std::vector<std::string>>("devices")`` declares a string array
    (Autoware's net_monitor, behavior_path_planner's ``slots``), not a string: a launch
    file that sets a list is no type mismatch."""
    result = _extract(
        tmp_path, package_xml("p", build_type="ament_cmake"),
        "#include <rclcpp/rclcpp.hpp>\n#include <string>\n#include <vector>\n"
        "class N : public rclcpp::Node {\n public:\n  N() : Node(\"n\") {\n"
        "    auto a = declare_parameter<std::vector<std::string>>(\"devices\");\n"
        "    auto b = declare_parameter(\"gains\", std::vector<double>{1.0});\n"
        "    auto c = declare_parameter<std::vector<int64_t>>(\"ids\", std::vector<int64_t>{});\n"
        "    auto d = declare_parameter<std::string>(\"name\");\n  }\n};\n")
    assert [(c.name, c.type) for c in result.calls if c.kind == "declare"] == [
        ("devices", "str[]"), ("gains", "double[]"), ("ids", "int[]"), ("name", "str")]


def test_a_builtin_template_argument_types_the_parameter_not_its_default(tmp_path) -> None:
    """``declare_parameter<double>("receive_timeout", 20)`` declares a double (UR's
    dashboard_client_ros.cpp:55): the literal 20 converts to it. A launch file that
    sets 20.0 is no type mismatch. A builtin template argument has no cursor."""
    result = _extract(
        tmp_path, package_xml("p", build_type="ament_cmake"),
        "#include <rclcpp/rclcpp.hpp>\n"
        "class N {\n public:\n"
        "  explicit N(const rclcpp::Node::SharedPtr & node) : node_(node) {\n"
        "    node_->declare_parameter<double>(\"receive_timeout\", 20);\n"
        "    node_->declare_parameter<bool>(\"flag\", 1);\n"
        "    node_->declare_parameter(\"count\", 20);\n"
        "    node_->declare_parameter<int>(\"ticks\", 2);\n  }\n"
        "  rclcpp::Node::SharedPtr node_;\n};\n")
    assert [(c.name, c.type) for c in result.calls if c.kind == "declare"] == [
        ("receive_timeout", "double"), ("flag", "bool"), ("count", "int"), ("ticks", "int")]


def test_a_vector_parameter_of_an_unresolved_call_is_an_array(tmp_path) -> None:
    """A class an error made invalid (Autoware's control_evaluator): its
    ``declare_parameter<std::vector<std::string>>`` is kept by name, typed str[]."""
    result = _extract(
        tmp_path, package_xml("p", build_type="ament_cmake"),
        "#include <rclcpp/rclcpp.hpp>\n#include <string>\n#include <vector>\n"
        "class Helper {\n public:\n"
        "  explicit Helper(rclcpp::Node::MissingInterface::SharedPtr node) {\n"
        "    auto m = node->declare_parameter<std::vector<std::string>>(\"module_list\");\n"
        "  }\n};\n")
    assert [(c.name, c.type) for c in result.calls if c.kind == "declare"] == [
        ("module_list", "str[]")]


NAV2_FORMS = """
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/create_timer.hpp>
#include <pluginlib/class_loader.hpp>
#include <pluginlib/exceptions.hpp>
#include <ament_index_cpp/get_package_share_directory.hpp>
#include <tf2/time.hpp>
#include <tf2/convert.hpp>
#include <tf2_eigen/tf2_eigen.hpp>
#include <Eigen/Sparse>
#include <std_msgs/msg/string.hpp>
namespace demo {
class Plugin { public: virtual ~Plugin() = default; virtual void configure() = 0; };
class Server : public rclcpp::Node {
public:
  Server() : rclcpp::Node("server"), loader_("demo", "demo::Plugin") {
    rclcpp::SubscriptionOptions options;
    rclcpp::QOSMessageLostCallbackType lost = nullptr;
    options.event_callbacks.message_lost_callback = lost;
    sub_ = create_subscription<std_msgs::msg::String>(
      "in", 10, [](std_msgs::msg::String::SharedPtr) {}, options);
    timer_ = rclcpp::create_timer(this, get_clock(), rclcpp::Duration::from_seconds(1.0),
                                  [] {});
    tf2::Duration timeout = tf2::durationFromSec(0.5);
    (void)timeout;
    std::string share = ament_index_cpp::get_package_share_directory("demo");
    Eigen::ArrayXf costs = Eigen::ArrayXf::Zero(10);
    Eigen::Ref<const Eigen::MatrixXd> view = Eigen::MatrixXd::Zero(2, 2);
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::SparseMatrix<double> sparse(3, 3);
    sparse.setFromTriplets(triplets.begin(), triplets.end());
    try {
      plugin_ = loader_.createSharedInstance("demo::Impl");
      plugin_->configure();
    } catch (const pluginlib::PluginlibException & ex) {
      throw rclcpp::exceptions::InvalidParameterValueException(ex.what());
    }
    pub_ = create_publisher<std_msgs::msg::String>(share + "/out", 10);
  }
  pluginlib::ClassLoader<Plugin> loader_;
  std::shared_ptr<Plugin> plugin_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};
}
"""


def test_forms_of_navigation2_servers_parse_without_declared_names(tmp_path) -> None:
    """pluginlib's ClassLoader, rclcpp::create_timer, the QoS event callback types,
    rclcpp's exceptions, tf2's Duration, ament_index_cpp, Eigen's arrays, references and
    sparse matrices: every navigation2 unit and most of Autoware's named one of them,
    and each was parsed a second time with the names declared permissively."""
    result = _extract(tmp_path, package_xml("demo", "ament_cmake"), NAV2_FORMS,
                      name="server.cpp")
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_NAMES_DECLARED", "CPP_INCLUDE_MISSING")] == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "?/out"), ("subscribe", "in")]


AUTOWARE_POLLING = """
#include <rclcpp/rclcpp.hpp>
#include <nav_msgs/msg/odometry.hpp>
#include <std_msgs/msg/string.hpp>
#include <autoware_utils/ros/polling_subscriber.hpp>
#include <autoware_utils_rclcpp/polling_subscriber.hpp>
class Checker : public rclcpp::Node {
 public:
  Checker() : Node("checker") {
    sub_limit_ = autoware_utils_rclcpp::InterProcessPollingSubscriber<
      std_msgs::msg::String, autoware_utils_rclcpp::polling_policy::Newest>::create_subscription(
      this, "~/input/limit", rclcpp::QoS{1}.transient_local());
  }
  void tick() { auto odom = sub_odom_.take_data(); (void)odom; }
 private:
  autoware_utils::InterProcessPollingSubscriber<nav_msgs::msg::Odometry> sub_odom_{
    this, "~/input/odometry"};
  autoware_utils_rclcpp::InterProcessPollingSubscriber<
    std_msgs::msg::String, autoware_utils_rclcpp::polling_policy::Newest>::SharedPtr sub_limit_;
};
"""


def test_autoware_polling_subscribers_without_autoware_utils(tmp_path) -> None:
    """Autoware's nodes subscribe through autoware_utils' InterProcessPollingSubscriber,
    built as a member with ``this`` or through its static create_subscription; without
    autoware_utils in the workspace (installed) the fallback stand-in and its API rows
    give each subscription, its topic and message."""
    result = _extract(tmp_path, package_xml("checker", "ament_cmake"), AUTOWARE_POLLING,
                      name="node.cpp")
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("subscribe", "~input/limit", "std_msgs/msg/String"),
        ("subscribe", "~input/odometry", "nav_msgs/msg/Odometry")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED", "CPP_NODE_TO_UNKNOWN")]


def test_a_vendor_namespace_s_unknown_names_leave_the_stand_in_s_class(tmp_path) -> None:
    """Another autoware_utils name the workspace does not have (a debug publisher whose
    header is missing) gets every ``autoware_utils::`` name of the file declared
    permissively, but not the polling subscriber the stand-in declares."""
    # the unknown name comes first, where the namespace is not declared yet (a header of
    # the package that names it, included before the polling subscriber's)
    code = AUTOWARE_POLLING.replace(
        "#include <autoware_utils/ros/polling_subscriber.hpp>\n",
        "#include <autoware_utils/ros/debug_publisher.hpp>\n"
        "autoware_utils::DebugPublisher * make_debug();\n"
        "#include <autoware_utils/ros/polling_subscriber.hpp>\n").replace(
        " private:\n", " private:\n  autoware_utils::DebugPublisher debug_{this, \"~/debug\"};\n")
    result = _extract(tmp_path, package_xml("checker", "ament_cmake"), code, name="node.cpp")
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("subscribe", "~input/limit", "std_msgs/msg/String"),
        ("subscribe", "~input/odometry", "nav_msgs/msg/Odometry")]
    assert [d.code for d in result.diagnostics if d.code == "CPP_NODE_TO_UNKNOWN"] == [
        "CPP_NODE_TO_UNKNOWN"]  # the debug publisher, given the node


def test_autoware_get_or_declare_parameter_without_autoware_utils(tmp_path) -> None:
    """Autoware's nodes declare most parameters through autoware_utils'
    ``get_or_declare_parameter<T>(node, name)`` (641 calls on universe 0.43); without
    autoware_utils in the workspace each is a declaration of ``name`` typed ``T`` on the
    node, and the node is complete."""
    result = _extract(
        tmp_path, package_xml("checker", "ament_cmake"),
        "#include <rclcpp/rclcpp.hpp>\n"
        "#include <autoware_utils/ros/parameter.hpp>\n"
        "#include <autoware_utils_rclcpp/parameter.hpp>\n"
        "using autoware_utils::get_or_declare_parameter;\n"
        "struct Params { double threshold; std::string frame; };\n"
        "Params load(rclcpp::Node & node) {\n"
        "  Params p;\n"
        "  p.threshold = get_or_declare_parameter<double>(node, \"threshold\");\n"
        "  p.frame = autoware_utils_rclcpp::get_or_declare_parameter<std::string>(\n"
        "    node, \"frame\");\n"
        "  return p;\n"
        "}\n"
        "class Checker : public rclcpp::Node {\n public:\n"
        "  Checker() : Node(\"checker\") { params_ = load(*this); }\n"
        "  Params params_;\n};\n", name="node.cpp")
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("declare", "frame", "str"), ("declare", "threshold", "double")]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED", "CPP_NODE_TO_UNKNOWN")]


def test_a_message_filters_subscriber_takes_a_member_callback(tmp_path) -> None:
    """imu_tools (noetic): ``sub->registerCallback(&C::cb, this)`` on a
    message_filters::Subscriber, ros::Time::isSystemTime(), tf's
    Matrix3x3::setRotation and tf2's Quaternion::normalize() parse: the errors made
    the filters partial (an error in a function that calls the ROS API)."""
    result = _extract(tmp_path, package_xml("imu", "catkin"), (
        "#include <ros/ros.h>\n#include <sensor_msgs/Imu.h>\n"
        "#include <message_filters/subscriber.h>\n#include <tf/transform_datatypes.h>\n"
        "#include <tf2/LinearMath/Quaternion.h>\n"
        "struct Filter {\n"
        "  void cb(const sensor_msgs::Imu::ConstPtr& m);\n"
        "  Filter(ros::NodeHandle& nh) : sub_(nh, \"imu/data_raw\", 5) {\n"
        "    sub_.registerCallback(&Filter::cb, this);\n"
        "    pub_ = nh.advertise<sensor_msgs::Imu>(\"imu/data\", 5);\n"
        "    if (ros::Time::isSystemTime()) { ROS_INFO(\"wall\"); }\n"
        "    tf::Matrix3x3 m; tf::Quaternion q; m.setRotation(q);\n"
        "    tf2::Quaternion r; r.normalize();\n"
        "  }\n"
        "  message_filters::Subscriber<sensor_msgs::Imu> sub_;\n"
        "  ros::Publisher pub_;\n"
        "};\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"filter\"); ros::NodeHandle nh; Filter f(nh);\n}\n"))
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "imu/data_raw"), ("publish", "imu/data")]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


@pytest.mark.parametrize("ros2", [False, True])
def test_a_message_filters_subscriber_on_an_empty_topic_subscribes_to_nothing(
        tmp_path, ros2: bool) -> None:
    """fake_localization (noetic): ``new message_filters::Subscriber<M>(nh, "", 100)`` is
    a filter fed by ``add()``: message_filters subscribes only when the topic is not
    empty, in ROS 1 and ROS 2 alike; it was a subscription to the node's namespace."""
    if ros2:
        manifest, text = package_xml("fake", "ament_cmake"), (
            "#include <rclcpp/rclcpp.hpp>\n#include <nav_msgs/msg/odometry.hpp>\n"
            "#include <message_filters/subscriber.h>\n"
            "using Odom = nav_msgs::msg::Odometry;\n"
            "struct Fake : rclcpp::Node {\n"
            "  Fake() : Node(\"fake\") {\n"
            "    feed_ = new message_filters::Subscriber<Odom>(this, \"\");\n"
            "    odom_.subscribe(this, \"odom\");\n"
            "  }\n"
            "  message_filters::Subscriber<Odom>* feed_;\n"
            "  message_filters::Subscriber<Odom> odom_;\n"
            "};\n")
    else:
        manifest, text = package_xml("fake", "catkin"), (
            "#include <ros/ros.h>\n#include <nav_msgs/Odometry.h>\n"
            "#include <message_filters/subscriber.h>\n"
            "struct Fake {\n"
            "  Fake(ros::NodeHandle& nh) {\n"
            "    feed_ = new message_filters::Subscriber<nav_msgs::Odometry>(nh, \"\", 100);\n"
            "    odom_.subscribe(nh, \"odom\", 10);\n"
            "  }\n"
            "  message_filters::Subscriber<nav_msgs::Odometry>* feed_;\n"
            "  message_filters::Subscriber<nav_msgs::Odometry> odom_;\n"
            "};\n"
            "int main(int argc, char** argv) {\n"
            "  ros::init(argc, argv, \"fake\");\n  ros::NodeHandle nh;\n  Fake fake(nh);\n"
            "}\n")
    result = _extract(tmp_path, manifest, text)
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "odom")]


def test_tf_get_prefix_param_searches_tf_prefix_from_the_handle_given(tmp_path) -> None:
    """velodyne (melodic-devel, driver.cc:57, transform.cc:30):
    ``tf::getPrefixParam(private_nh)`` (tf/transform_listener.h) is
    ``searchParam("tf_prefix")`` on the handle given, then a read of what it found. The
    stand-in lacked it: the node given to a function the parse did not know
    (CPP_NODE_TO_UNKNOWN) made the driver and transform nodes partial."""
    result = _extract(tmp_path, package_xml("velo", "catkin"), (
        "#include <ros/ros.h>\n#include <tf/transform_listener.h>\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"driver\");\n"
        "  ros::NodeHandle private_nh(\"~\"), nh;\n"
        "  std::string prefix = tf::getPrefixParam(private_nh);\n"
        "  std::string other = tf::getPrefixParam(nh);\n"
        "  return prefix.size() + other.size();\n}\n"))
    assert [(c.kind, c.name, c.searched) for c in result.calls] == [
        ("read", "~tf_prefix", True), ("read", "tf_prefix", True)]
    assert not [d for d in result.diagnostics if d.code in (
        "CPP_NODE_TO_UNKNOWN", "CPP_PARSE_ERROR")]


def test_a_vector_takes_a_value_of_an_unknown_name_by_assignment(tmp_path) -> None:
    """joint_state_controller (ros_controllers noetic, joint_state_controller.cpp:56):
    ``joint_names = hw->getNames();`` with hardware_interface not in the workspace: the
    value is of the permissive class, and std::vector's three assignments (copy, move,
    initializer_list) were equally good, an ambiguity error in a function that calls
    the ROS API, so the controller was partial. As std::string already does, the
    stand-in vector takes such a value, and is built from one (rosserial_server's
    ``std::vector<uint8_t> message(length)``, its length of an unknown type)."""
    result = _extract(tmp_path, package_xml("ctl", "catkin"), (
        "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
        "#include <vendor_interface/hw.h>\n#include <vector>\n#include <string>\n"
        "class Ctl : public vendor_interface::Controller<vendor_interface::Hw> {\n"
        " public:\n"
        "  bool init(vendor_interface::Hw* hw, ros::NodeHandle& nh) {\n"
        "    std::vector<std::string> names;\n"
        "    if (!nh.getParam(\"joints\", names)) { names = hw->getNames(); }\n"
        "    std::vector<unsigned char> buffer(hw->length());\n"
        "    pub_ = nh.advertise<std_msgs::String>(\"out\", 1);\n"
        "    return true;\n  }\n"
        "  ros::Publisher pub_;\n};\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"n\");\n  ros::NodeHandle nh;\n"
        "  Ctl c;\n  c.init(nullptr, nh);\n}\n"))
    assert [(c.kind, c.name) for c in result.calls] == [("read", "joints"), ("publish", "out")]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []


def test_a_callback_held_in_a_function_object_gives_the_message_type(tmp_path) -> None:
    """franka_example_controllers (dual_arm_cartesian_impedance_example_controller.cpp:
    118-123): ``boost::function<void(const geometry_msgs::PoseStamped::ConstPtr&)>
    callback = boost::bind(...); subscribe_options.init("target", 1, callback);``: the
    type is the message of the function type the variable holds (it was unknown)."""
    result = _extract(tmp_path, package_xml("arm", "catkin"), (
        "#include <ros/ros.h>\n#include <geometry_msgs/PoseStamped.h>\n"
        "#include <boost/function.hpp>\n#include <boost/bind.hpp>\n#include <functional>\n"
        "struct Ctl {\n"
        "  void target(const geometry_msgs::PoseStamped::ConstPtr& m);\n"
        "  void init(ros::NodeHandle& nh) {\n"
        "    boost::function<void(const geometry_msgs::PoseStamped::ConstPtr&)> callback =\n"
        "        boost::bind(&Ctl::target, this, _1);\n"
        "    ros::SubscribeOptions options;\n"
        "    options.init(\"target\", 1, callback);\n"
        "    sub_ = nh.subscribe(options);\n"
        "    std::function<void(const geometry_msgs::PoseStamped::ConstPtr&)> other =\n"
        "        [](const geometry_msgs::PoseStamped::ConstPtr&) {};\n"
        "    sub2_ = nh.subscribe(\"other\", 1, other);\n"
        "  }\n"
        "  ros::Subscriber sub_, sub2_;\n};\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"arm\");\n  ros::NodeHandle nh;\n  Ctl c;\n  c.init(nh);\n}\n"))
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "target", "geometry_msgs/PoseStamped"),
        ("subscribe", "other", "geometry_msgs/PoseStamped")]


def test_a_subscription_by_full_callback_type_and_tf_extrapolation_limit(tmp_path) -> None:
    """hector_quadrotor's aerodynamics plugin subscribes its wind topic with
    ``ops.initByFullCallbackType<const geometry_msgs::Vector3&>(topic, 1, f)`` and
    ``nh.subscribe(ops)``; hector_gazebo's servo plugin calls the listener's
    ``setExtrapolationLimit``. Neither was in the stand-ins: errors in functions that
    call the ROS API (both nodes partial) and the subscription lost."""
    result = _extract(tmp_path, package_xml("quad", "catkin"), (
        "#include <ros/ros.h>\n#include <geometry_msgs/Vector3.h>\n"
        "#include <tf/transform_listener.h>\n#include <boost/bind.hpp>\n"
        "struct Model { void setWind(const geometry_msgs::Vector3& wind); };\n"
        "struct Plugin {\n"
        "  void load(ros::NodeHandle& nh) {\n"
        "    ros::SubscribeOptions ops;\n"
        "    ops.initByFullCallbackType<const geometry_msgs::Vector3&>(\n"
        "        \"/wind\", 1, boost::bind(&Model::setWind, &model_, _1));\n"
        "    sub_ = nh.subscribe(ops);\n"
        "    listener_.setExtrapolationLimit(ros::Duration(1.0));\n"
        "  }\n"
        "  Model model_;\n  tf::TransformListener listener_;\n  ros::Subscriber sub_;\n};\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"quad\");\n  ros::NodeHandle nh;\n  Plugin p;\n"
        "  p.load(nh);\n}\n"))
    assert ("subscribe", "/wind", "geometry_msgs/Vector3") in [
        (c.kind, c.name, c.type) for c in result.calls]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []


ROS1_MANIFEST = package_xml("hil").replace(
    "</package>", "<depend>roscpp</depend><depend>urdf</depend></package>")


def test_ros1_stand_ins_for_auto_ptr_eigen_rotations_and_urdf_inertials(tmp_path) -> None:
    """rotors_hil_interface builds its interface with ``std::auto_ptr`` and a quaternion
    from ``AngleAxisd`` products; hector_quadrotor reads the root link's ``inertial``
    from the URDF. Each was an error in a function that calls the ROS API (the node
    partial) and, for the first, hid the construction whose constructor subscribes."""
    result = _extract(tmp_path, ROS1_MANIFEST, """
#include <memory>
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <urdf/model.h>
#include <Eigen/Dense>
class Interface {
 public:
  explicit Interface(const Eigen::Quaterniond& q) {
    ros::NodeHandle pnh("~");
    sub_ = pnh.subscribe<std_msgs::String>("imu", 1, &Interface::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr&) {}
  ros::Subscriber sub_;
};
double mass(const ros::NodeHandle& nh) {
  std::string xml;
  nh.getParam("robot_description", xml);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  urdf::InertialSharedPtr inertial = model->getRoot()->inertial;
  return inertial ? inertial->mass + inertial->ixx : 0.0;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "hil");
  ros::NodeHandle nh;
  Eigen::AngleAxisd roll(0.1, Eigen::Vector3d::UnitX()), yaw(0.2, Eigen::Vector3d::UnitZ());
  const Eigen::Quaterniond q = roll * yaw * roll;
  std::auto_ptr<Interface> hil;
  hil = std::auto_ptr<Interface>(new Interface(q));
  mass(nh);
  ros::spin();
  return 0;
}
""")
    errors = [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")]
    assert errors == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("read", "robot_description"), ("subscribe", "~imu")]


def test_ros1_unique_and_shared_ptr_take_an_auto_ptr(tmp_path) -> None:
    """C++11's ``unique_ptr`` and ``shared_ptr`` are built from an ``auto_ptr<U>&&``
    (libstdc++ keeps it): rotors_hil_interface assigns ``std::auto_ptr<Derived>(new
    Derived(q))`` to its ``std::unique_ptr<Base>`` member
    (hil_interface_node.cpp:51). The stand-ins had no such constructor: an error in a
    function that calls the ROS API, the node partial for nothing."""
    result = _extract(tmp_path, ROS1_MANIFEST, """
#include <memory>
#include <ros/ros.h>
#include <std_msgs/String.h>
struct Base { virtual ~Base() {} };
struct Derived : public Base { explicit Derived(int) {} };
class Node {
 public:
  Node() {
    if (nh_.ok())
      owned_ = std::auto_ptr<Derived>(new Derived(1));
    else
      owned_ = std::auto_ptr<Base>(new Base());
    shared_ = std::shared_ptr<Base>(std::auto_ptr<Derived>(new Derived(2)));
    pub_ = nh_.advertise<std_msgs::String>("out", 1);
  }
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  std::unique_ptr<Base> owned_;
  std::shared_ptr<Base> shared_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Node node;
  ros::spin();
  return 0;
}
""")
    errors = [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")]
    assert errors == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_ros1_string_reverse_iterators(tmp_path) -> None:
    """``std::string`` has ``rbegin`` / ``rend`` as every container does:
    kinova_interactive_control switches on ``*marker_name.rbegin() - '0'``
    (kinova_interactive_control.cpp:278); the stand-in string had none, an error (there
    beside no ROS call, else near one)."""
    result = _extract(tmp_path, ROS1_MANIFEST, """
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh;
  std::string marker_name("joint_3");
  std::string reversed(marker_name.rbegin(), marker_name.rend());
  const std::string& named = marker_name;
  switch (*named.rbegin() - '0') {
    case 3:
      nh.advertise<std_msgs::String>("joint", 1);
      break;
  }
  for (auto it = marker_name.crbegin(); it != marker_name.crend(); ++it) {}
  ros::spin();
  return 0;
}
""")
    errors = [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")]
    assert errors == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "joint")]


def test_ros1_eigen_row_times_column_is_a_scalar(tmp_path) -> None:
    """A row vector times a column vector is Eigen's 1x1 inner product, which converts to
    its scalar: mav_msgs' conversions.h:306-322 (``double(zb.transpose() * jerk)``,
    ``(*w)[0] = -h_w.transpose() * yb``), included by every rotors_control node; the
    stand-in's product kept the row's type, 7 clang errors per unit."""
    result = _extract(tmp_path, ROS1_MANIFEST, """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <Eigen/Dense>
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh;
  Eigen::Vector3d zb(0, 0, 1), jerk(1, 2, 3), w;
  const double along = double(zb.transpose() * jerk);
  w[0] = -jerk.transpose() * zb;
  double d = zb.transpose() * jerk;
  Eigen::Vector3d scaled = zb * along + jerk * d;
  Eigen::RowVector3d row = jerk.transpose() * 2.0;
  nh.advertise<std_msgs::String>("out", 1);
  ros::spin();
  return scaled.size() + row.size() > 0 ? 0 : 1;
}
""")
    errors = [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")]
    assert errors == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_eigen_scalars_array_factories_and_transform_coefficients_parse(tmp_path) -> None:
    """A matrix's ``Scalar`` (grid_map's ``using DataType = Matrix::Scalar``), an array's
    ``Zero()`` without sizes (its ``Index::Zero()`` defaults) and a transform's
    coefficients (LIO-SAM's ``transBt(0, 3)``, 36 errors): grid_map 86 clang errors ->
    78, LIO-SAM 49 -> 13, calls identical. A matrix's ``Index`` and ``RealScalar`` too:
    without them EigenLab's parser, a member of grid_map's math expression filters, left
    those classes invalid and their ``FilterBase::getParam`` calls unresolved, kept by
    name as nine reads of ``?/expression`` and the like (ROS 1's filters read their
    configuration from the chain's entry, no ROS call)."""
    result = _extract(tmp_path, package_xml("demo", "catkin"), """
#include <ros/ros.h>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <std_msgs/Float32.h>
using Matrix = Eigen::MatrixXf;
using DataType = Matrix::Scalar;
// EigenLab's (grid_map's math expression filters) ``typename Derived::Index``
using Size = Matrix::Index;
using Real = Matrix::RealScalar;
using Index = Eigen::Array2i;
DataType corner(const Eigen::Affine3f& t, const Index& start = Index::Zero()) {
  return t(0, 3) + t(1, 3) * start(0) + Eigen::Array3f::Ones()(0);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "demo");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::Float32>("corner", 1);
  std_msgs::Float32 msg;
  msg.data = corner(Eigen::Affine3f::Identity());
  pub.publish(msg);
}
""")
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "corner")]


def test_an_array_shared_pointer_and_symlinks_parse(tmp_path) -> None:
    """C++17's ``shared_ptr<T[]>`` indexed (usb_cam's ``m_buffers[i].start``, 16 errors)
    and ``std::filesystem::read_symlink`` (its devices' by-id links): usb_cam 45 clang
    errors -> 27, calls identical."""
    result = _extract(tmp_path, package_xml("demo", "ament_cmake"), """
#include <filesystem>
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
struct buffer { char * start; std::size_t length; };
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("camera");
  std::shared_ptr<buffer[]> buffers(new buffer[4]);
  buffers[0].length = 0;
  std::string device = std::filesystem::read_symlink("/dev/v4l/by-id/cam").string();
  auto pub = node->create_publisher<std_msgs::msg::String>(device + "/image", 10);
  rclcpp::spin(node);
}
""")
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "?/image")]


def test_tf_conversions_eigen_functions_parse(tmp_path) -> None:
    """tf_conversions' ``tf_eigen.h`` (industrial_training's perception exercises,
    spencer_people_tracking, kinova-ros, franka_ros): its conversions between tf, Eigen
    and geometry_msgs were errors (the header missing, ``tf::transformTFToEigen`` no
    member of our tf) beside the node's calls; a fallback stand-in declares them."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <tf/transform_listener.h>\n"
        "#include <tf_conversions/tf_eigen.h>\n#include <geometry_msgs/PoseStamped.h>\n"
        "void f(const tf::StampedTransform& t, const geometry_msgs::PoseStamped& p) {\n"
        "  Eigen::Affine3d a; Eigen::Isometry3d i; Eigen::Vector3d v;\n"
        "  tf::transformTFToEigen(t, a);\n  tf::poseMsgToEigen(p.pose, i);\n"
        "  tf::vectorTFToEigen(t.getOrigin(), v);\n"
        "  geometry_msgs::Pose back; tf::poseEigenToMsg(i, back);\n"
        "  ros::NodeHandle nh;\n"
        "  ros::Publisher out = nh.advertise<geometry_msgs::PoseStamped>(\"out\", 1);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_numeric_limits_are_constant_expressions(tmp_path) -> None:
    """igvc-software's UnrollingLayer keeps ``std::array<uint8_t,
    std::numeric_limits<char>::max()>``: the limits were declared constexpr without a
    value, so the member was an error, the class invalid, and every call of a base
    method (``matchSize()`` beside its ROS calls) 'cannot initialize object parameter'."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <array>\n#include <cstdint>\n#include <limits>\n#include <ros/ros.h>\n"
        "#include <std_msgs/Int8.h>\n"
        "static_assert(std::numeric_limits<char>::max() == 127, \"char\");\n"
        "static_assert(std::numeric_limits<int>::min() < 0, \"int\");\n"
        "static_assert(std::numeric_limits<uint16_t>::max() == 65535, \"u16\");\n"
        "static_assert(std::numeric_limits<double>::max() > 1e300, \"double\");\n"
        "static_assert(std::numeric_limits<float>::infinity() > 1e38f, \"inf\");\n"
        "struct Base { void size(); };\n"
        "struct Table : Base {\n"
        "  std::array<uint8_t, std::numeric_limits<char>::max()> translator;\n"
        "  ros::Publisher pub;\n"
        "  void start(ros::NodeHandle& nh);\n"
        "};\n"
        "void Table::start(ros::NodeHandle& nh) {\n"
        "  size();\n"
        "  pub = nh.advertise<std_msgs::Int8>(\"cost\", 1);\n"
        "}\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"table\");\n"
        "  ros::NodeHandle nh;\n"
        "  Table t;\n"
        "  t.start(nh);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "cost")]


def test_a_set_erases_by_position(tmp_path) -> None:
    """people's leg_detector erases a multiset's element by its iterator
    (``matches.erase(matched_iter)``): the stand-in's set erased only by key."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <set>\n"
        "void f(std::multiset<int>& s, std::set<double>& d) {\n"
        "  std::multiset<int>::iterator it = s.find(3);\n"
        "  s.erase(it);\n  s.erase(s.begin(), s.end());\n  s.erase(4);\n"
        "  std::set<double>::iterator low = d.lower_bound(1.0);\n"
        "  d.erase(low, d.upper_bound(2.0));\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []


def test_a_roscpp_header_without_a_file_of_ours_stands_in_as_ros_h(tmp_path) -> None:
    """gazebo_plugins, fuse, amcl, VINS-Mono include roscpp headers our stand-ins have no
    file for (``ros/advertise_options.h``, ``ros/assert.h``,
    ``ros/callback_queue_interface.h``): each was an empty stand-in and said missing;
    it now brings the API our ``ros/ros.h`` declares."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/node_handle.h>\n#include <ros/advertise_options.h>\n"
        "#include <ros/assert.h>\n#include <ros/callback_queue_interface.h>\n"
        "#include <std_msgs/Int8.h>\n"
        "#include <ros/init.h>\n#include <ros/callback_queue.h>\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"level\");\n  ros::NodeHandle nh;\n"
        "  ros::CallbackQueueInterface* queue = nh.getCallbackQueue();\n"
        "  ROS_ASSERT(queue != nullptr);\n"
        "  ros::AdvertiseOptions ops = ros::AdvertiseOptions::create<std_msgs::Int8>(\n"
        "      \"level\", 1, ros::SubscriberStatusCallback(), ros::SubscriberStatusCallback(),\n"
        "      ros::VoidConstPtr(), queue);\n"
        "  ros::Publisher pub = nh.advertise(ops);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "level")]


def test_vikit_get_param_reads_through_ros_param(tmp_path) -> None:
    """uzh-rpg's SVO reads every parameter with rpg_vikit's ``vk::getParam<T>(name,
    default)`` (another repository): its header was missing, the reads unseen and the
    camera topic, a parameter's value, unknown."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
        "#include <vikit/params_helper.h>\n"
        "void cb(const std_msgs::String::ConstPtr& m) {}\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"svo\");\n  ros::NodeHandle nh;\n"
        "  std::string topic(vk::getParam<std::string>(\"svo/cam_topic\", \"camera/image\"));\n"
        "  bool markers = vk::getParam<bool>(\"svo/publish_markers\", true);\n"
        "  double rx = vk::getParam<double>(\"svo/init_rx\");\n"
        "  ros::Subscriber sub = nh.subscribe(topic, 5, cb);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING")] == []
    calls = {(c.kind, c.name, c.type, c.default, c.name_param) for c in result.calls}
    assert ("read", "svo/cam_topic", "str", "camera/image", None) in calls
    assert ("read", "svo/publish_markers", "bool", True, None) in calls
    assert ("subscribe", "?", "std_msgs/String", None, "svo/cam_topic") in calls
    (required,) = [c for c in result.calls if c.name == "svo/init_rx"]
    assert (required.type, required.has_default) == ("double", False)


def test_two_argument_math_of_mixed_types_is_not_ambiguous(tmp_path) -> None:
    """autonomous_exploration_development_environment's terrainAnalysis takes
    ``atan2(pointZ1 - minDyObsRelZ, dis1)`` of a double and a float: the stand-in had the
    float and the double overloads and a template for integers only, so the call was
    ambiguous and main, which makes every ROS call of the node, partial. The library
    computes a mix of arithmetic types in the promoted type."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <math.h>\n#include <cmath>\n#include <ros/ros.h>\n"
        "#include <std_msgs/Float32.h>\n"
        "using namespace std;\n"
        "double d = 1.0; float f = 2.0f; int i = 3;\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"m\");\n"
        "  ros::NodeHandle nh;\n"
        "  float a = atan2(d - f, f);\n"
        "  double b = std::atan2(f, i) + atan2(i, d) + atan2(f, f) + atan2(d, d);\n"
        "  double c = atan2(i, i) + pow(f, 2) + hypot(f, d) + fmin(f, d);\n"
        "  ros::Publisher p = nh.advertise<std_msgs::Float32>(\"out\", 1);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_adaptable_function_bases_and_container_adaptor_swap(tmp_path) -> None:
    """ego-planner's grid_map.h (a header of every planner unit) hashes voxels with
    ``struct matrix_hash : std::unary_function<T, size_t>``, and its A* clears a
    ``std::priority_queue`` with ``swap``: libstdc++ declares both in C++14 (the
    package's standard) and later, the stand-in did not."""
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <functional>\n#include <queue>\n#include <vector>\n"
        "#include <ros/ros.h>\n#include <std_msgs/Int32.h>\n"
        "template <typename T> struct matrix_hash : std::unary_function<T, size_t> {\n"
        "  size_t operator()(T const& m) const { return 0; }\n};\n"
        "struct closer : std::binary_function<int, int, bool> {\n"
        "  bool operator()(int a, int b) const { return a > b; }\n};\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"m\");\n"
        "  ros::NodeHandle nh;\n"
        "  matrix_hash<int>::result_type h = matrix_hash<int>()(1);\n"
        "  closer::first_argument_type a = 1;\n"
        "  std::priority_queue<int, std::vector<int>, closer> open, empty;\n"
        "  open.emplace(a);\n"
        "  open.swap(empty);\n"
        "  std::queue<int> q, r;\n"
        "  q.swap(r);\n"
        "  ros::Publisher p = nh.advertise<std_msgs::Int32>(\"out\", 1);\n"
        "}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
