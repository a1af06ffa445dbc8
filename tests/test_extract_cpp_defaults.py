"""C++ parameter reads record whether the code gives a default; searchParam is marked."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <string>
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("~");
  double rate; int n; std::string frame; bool on;
  nh.param("rate", rate, 0.5);
  nh.param("n", n, 3);
  nh.param<std::string>("frame", frame, "base_link");
  on = nh.param("on", true);
  nh.getParam("plain", rate);
  std::string key;
  nh.searchParam("robot_model", key);
  return 0;
}
"""


def test_defaults_and_searches(tmp_path):
    source = tmp_path / "n.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = [(c.name, c.has_default, c.default, c.searched) for c in result.calls]
    assert got == [("~rate", True, 0.5, False), ("~n", True, 3, False),
                   ("~frame", True, "base_link", False), ("~on", True, True, False),
                   ("~plain", False, None, False), ("~robot_model", False, None, True)]


SEARCHED = """
#include <ros/ros.h>
#include <string>
std::string prefix(ros::NodeHandle& n_tilde) {
  std::string tf_prefix, tf_prefix_key;
  n_tilde.searchParam("tf_prefix", tf_prefix_key);
  n_tilde.param(tf_prefix_key, tf_prefix, std::string(""));
  return tf_prefix;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh, pnh("~");
  std::string found, robot, other;
  if (ros::param::search("robot_name", found))
    ros::param::get(found, robot);
  nh.getParam(other, other);
  prefix(pnh);
  return 0;
}
"""


def test_a_name_searchParam_found_is_the_parameter_searched_for(tmp_path):
    """robot_state_publisher reads tf_prefix as ``searchParam("tf_prefix", key)`` then
    ``param(key, ...)``: the second read was of ``~?``, a read of any private parameter,
    so every parameter a launch file set on a robot_state_publisher was undecided. The
    name found is the key searched for (the read is searched too); a key with no known
    value stays '?'."""
    source = tmp_path / "n.cpp"
    source.write_text(SEARCHED)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = sorted((c.location.line, c.name, c.searched, c.type) for c in result.calls)
    assert got == [(6, "~tf_prefix", True, None), (7, "~tf_prefix", True, "str"),
                   # ros::param::search searches from the node's own name: ~robot_name
                   (14, "~robot_name", True, None), (15, "~robot_name", True, "str"),
                   (16, "?", False, "str")]


SEARCHED_PARAMETER = """
#include <ros/ros.h>
#include <string>
class Kinematics {
 public:
  bool init();
 private:
  ros::NodeHandle nh;
};
bool Kinematics::init() {
  std::string urdf_xml, full_urdf_xml;
  nh.param("urdf_xml", urdf_xml, std::string("robot_description"));
  nh.searchParam(urdf_xml, full_urdf_xml);
  std::string result;
  if (!nh.getParam(full_urdf_xml, result))
    return false;
  return true;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Kinematics k;
  return k.init() ? 0 : 1;
}
"""


def test_the_name_searchParam_found_for_a_key_a_parameter_holds(tmp_path):
    """baxter_sim_kinematics' arm_kinematics (the pattern of ROS's arm_kinematics):
    the key searched for is the value of the parameter urdf_xml (its default
    robot_description), and getParam reads what the search found. That read was of
    ``?`` named by a parameter ``?``: the searchParam's result taken for the value of a
    read; it is the searched read of the parameter urdf_xml names, as the search is."""
    source = tmp_path / "n.cpp"
    source.write_text(SEARCHED_PARAMETER)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = sorted((c.location.line, c.name, c.searched, c.name_param, c.name_default)
                 for c in result.calls)
    assert got == [(12, "urdf_xml", False, None, None),
                   (13, "?", True, "urdf_xml", "robot_description"),
                   (15, "?", True, "urdf_xml", "robot_description")]


def test_errors_on_fields_of_messages_known_only_by_name_are_not_code_errors(tmp_path):
    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <rclcpp/rclcpp.hpp>\n"
        "#include <unknown_msgs/msg/grid.hpp>\n"
        "void f(const unknown_msgs::msg::Grid & g) { auto w = g.info.width; (void)w; }\n"
        "int main() { int x = ; return 0; }\n")
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    found = [(d.code, d.location.line) for d in result.diagnostics
             if d.code.startswith("CPP_") and d.code != "CPP_MESSAGE_UNKNOWN"]
    # neither error is in a function that calls the ROS API, so no names are declared
    # (message_fields.cpp in test_extract_cpp_unknown_names: where they are)
    assert ("CPP_MESSAGE_FIELD", 3) in found
    assert ("CPP_PARSE_ERROR", 4) in found
    assert ("CPP_PARSE_ERROR", 3) not in found


def test_a_field_error_next_to_a_call_costs_no_second_parse(tmp_path):
    """clang reads on past a field it does not find on a valid message struct: such an
    error hides no call, so no names are declared for it and the node stays complete."""
    from haros_arch.extract import extract_nodes
    from haros_arch.model.source import Node

    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <rclcpp/rclcpp.hpp>\n"
        "#include <unknown_msgs/msg/grid.hpp>\n"
        "void f(rclcpp::Node & node, const unknown_msgs::msg::Grid & g) {\n"
        "  auto pub = node.create_publisher<unknown_msgs::msg::Grid>(\"grid\", 1);\n"
        "  auto w = g.info.width; (void)w;\n"
        "}\n")
    node = Node("p", "n", sources=["n.cpp"])
    found = extract_nodes([node], Workspace(root=str(tmp_path)), cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "grid")]
    assert [d.code for d in found if d.code.startswith("CPP_") and d.code not in (
        "CPP_MESSAGE_UNKNOWN",)] == ["CPP_MESSAGE_FIELD"]
    assert node.completeness == "complete"


KEPT = """
#include <ros/ros.h>
#include <string>
bool g_lazy;
std::string g_name;
class Relay {
 public:
  Relay() : rate_(2.0) {
    ros::NodeHandle pnh("~");
    pnh.getParam("rate", rate_);
    pnh.getParam("frame", frame_);
  }
  double rate_;
  std::string frame_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "throttle");
  ros::NodeHandle pnh("~");
  bool unreliable = false;
  int count;
  pnh.getParam("lazy", g_lazy);
  pnh.getParam("unreliable", unreliable);
  pnh.getParam("count", count);
  pnh.getParam("name", g_name);
  Relay relay;
  return 0;
}
"""


def test_a_read_into_a_variable_that_holds_a_value_has_that_default(tmp_path):
    """topic_tools' throttle: ``getParam(name, out)`` leaves ``out`` as it is when the
    parameter is not there; a global of a builtin type starts as zero, a local with an
    initialiser and a member its constructor initialises hold their values. A local
    without one, and a string that starts empty, give the read no default."""
    source = tmp_path / "n.cpp"
    source.write_text(KEPT)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = {c.name: (c.has_default, c.default) for c in result.calls}
    assert got == {"~lazy": (True, False), "~unreliable": (True, False),
                   "~count": (False, None), "~name": (False, None),
                   "~rate": (True, 2.0), "~frame": (False, None)}


STATIC_MEMBERS = """
#include <ros/ros.h>
#include <string>
class Camera {
 public:
  Camera();
  static std::string io_method;   // defined (= "mmap") in another file of the node
  static int width;               // defined (= 320) in another file of the node
  static std::string here;        // defined below, empty
  static int counted;             // defined below, with a value
  static int zeroed;              // defined below, without one
};
std::string Camera::here;
int Camera::counted = 4;
int Camera::zeroed;
Camera::Camera() {
  ros::NodeHandle pnh("~");
  pnh.getParam("io_method", io_method);
  pnh.getParam("width", width);
  pnh.getParam("here", here);
  pnh.getParam("counted", counted);
  pnh.getParam("zeroed", zeroed);
}
"""


def test_a_read_into_a_static_member_defined_elsewhere_has_a_default_not_known(tmp_path):
    """usb_cam (develop): ``node.getParam("io_method", io_method_name)`` into a static
    member that camera_driver.cpp defines as "mmap". Its definition is in another
    translation unit: the member holds a value there, not known in this file (not
    "no default", not zero). A definition in this file gives its value as before."""
    source = tmp_path / "n.cpp"
    source.write_text(STATIC_MEMBERS)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = {c.name: (c.has_default, c.default) for c in result.calls}
    assert got == {"~io_method": (True, None), "~width": (True, None),
                   "~here": (False, None), "~counted": (True, 4), "~zeroed": (True, 0)}


SELF_DEFAULT = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
void cb(const std_msgs::String::ConstPtr& m) {}
int main(int argc, char** argv) {
  ros::init(argc, argv, "conv");
  ros::NodeHandle n("~");
  std::string topic = "/move_base/local_costmap/costmap";
  n.param("costmap_topic", topic, topic);
  int size = 100;
  n.param("size", size, size);
  ros::Subscriber s = n.subscribe(topic, 1, cb);
  return 0;
}
"""


def test_a_read_whose_default_is_its_own_variable_has_that_variable_s_value(tmp_path):
    """costmap_converter_node.cpp:72-84: ``n_.param("costmap_topic", costmap_topic,
    costmap_topic)`` after ``std::string costmap_topic = "/move_base/...";``: the default
    is what the variable holds before the call, so the subscribe named by the parameter
    falls back to it when the launch file does not set it (it was ``~?`` whatever)."""
    source = tmp_path / "n.cpp"
    source.write_text(SELF_DEFAULT)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    reads = {c.name: (c.has_default, c.default) for c in result.calls if c.kind == "read"}
    assert reads == {"~costmap_topic": (True, "/move_base/local_costmap/costmap"),
                     "~size": (True, 100)}
    [sub] = [c for c in result.calls if c.kind == "subscribe"]
    assert (sub.name_param, sub.name_default) == (
        "~costmap_topic", "/move_base/local_costmap/costmap")


def test_a_template_argument_written_is_the_type_read(tmp_path):
    """Universal_Robots_ROS_Driver (hardware_interface.cpp:200):
    ``param<bool>("use_tool_communication", "false")`` reads a bool, and its default is
    the string literal converted to bool, a pointer that is not null: true. The literal's
    own type (str) made a false parameter-type-mismatch with the launch file's bool;
    ``param<double>("rate", 10)`` reads a double whose default is 10.0 (a double literal
    is its value: ``param<int>("count", 2.5)``'s default is 2, as C++ converts it)."""
    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <string>\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"n\");\n  ros::NodeHandle nh(\"~\");\n"
        "  bool tool = nh.param<bool>(\"tool\", \"false\");\n"
        "  double rate = nh.param<double>(\"rate\", 10);\n"
        "  int count = nh.param<int>(\"count\", 2.5);\n"
        "  std::string frame = nh.param<std::string>(\"frame\", \"map\");\n"
        "  double gain; nh.param(\"gain\", gain, 1.5);\n"
        "  bool on = ros::param::param<bool>(\"/on\", 0);\n"
        "  return 0;\n}\n")
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = [(c.name, c.type, c.default) for c in result.calls]
    assert got == [("~tool", "bool", True), ("~rate", "double", 10.0), ("~count", "int", 2),
                   ("~frame", "str", "map"), ("~gain", "double", 1.5), ("/on", "bool", False)]
    assert [type(c.default) for c in result.calls[:2]] == [bool, float]


BRANCHED_SEARCH = """
#include <ros/ros.h>
#include <string>
#include <std_msgs/String.h>
void cb(const std_msgs::String::ConstPtr&) {}
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle private_nh("~");
  std::string topic_param, topic;
  if (!private_nh.searchParam("footprint_topic", topic_param))
  {
    topic_param = "footprint_topic";
  }
  private_nh.param(topic_param, topic, std::string("footprint"));
  ros::Subscriber s = private_nh.subscribe(topic, 1, cb);
  if (!private_nh.searchParam("published_footprint_topic", topic_param))
  {
    topic_param = "published_footprint";
  }
  private_nh.param(topic_param, topic, std::string("footprint"));
  ros::Publisher p = private_nh.advertise<std_msgs::String>(topic, 1);
  return 0;
}
"""


def test_a_key_both_sides_of_a_searchParam_branch_name_is_read(tmp_path):
    """costmap_2d's Costmap2DROS: ``if (!nh.searchParam("footprint_topic", key)) key =
    "footprint_topic";`` then ``nh.param(key, topic, ...)``: the key is the one searched
    for whichever side runs, so the read is of ``footprint_topic`` (searched), where it
    was ``~?``; and the subscriber's topic is that parameter's value. Where the sides
    differ (``published_footprint_topic`` searched, else ``published_footprint``) the
    key is one or the other: a read of each under its side of the ``if``, where it was
    one read of ``~?`` (any
    parameter of the node: move_base's every setting undecided); the advertise's topic
    is the value of one of them, not of the first read (``topic`` is read into
    twice)."""
    source = tmp_path / "n.cpp"
    source.write_text(BRANCHED_SEARCH)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = sorted((c.location.line, c.kind, c.name, c.searched, c.name_param)
                 for c in result.calls)
    assert got == [(10, "read", "~footprint_topic", True, None),
                   (14, "read", "~footprint_topic", True, None),
                   (15, "subscribe", "~?", False, "~footprint_topic"),
                   (16, "read", "~published_footprint_topic", True, None),
                   (20, "read", "~published_footprint", False, None),
                   (20, "read", "~published_footprint_topic", True, None),
                   (21, "publish", "~?", False, "~?")]
    # each under its side of the if that decides the key
    test = '!private_nh.searchParam("published_footprint_topic", topic_param)'
    assert sorted((c.name, [(x.statement, x.text, x.location.line) for x in c.conditions])
                  for c in result.calls if c.location.line == 20) == [
        ("~published_footprint", [("if", test, 16)]),
        ("~published_footprint_topic", [("else", test, 16)])]


PREFIXED_WRAPPER = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

ros::Publisher advertise_prefixed(ros::NodeHandle& nh, const std::string& name)
{
  return nh.advertise<std_msgs::String>("robot/" + name, 1);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "n");
  ros::NodeHandle nh;
  std::string topic = "status";
  topic = "state";
  ros::Publisher p = advertise_prefixed(nh, topic);
  return 0;
}
"""


def test_a_variable_written_twice_given_to_a_wrapper_that_adds_text(tmp_path):
    """A wrapper that writes text around its name argument reads it in a scope of its
    own (``wrappers._NamedScope``, which keeps that text in attributes of its own); the
    argument, a local written twice, is the last value written: ``robot/state``."""
    source = tmp_path / "n.cpp"
    source.write_text(PREFIXED_WRAPPER)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.location.line, c.kind, c.name) for c in result.calls] == [
        (16, "publish", "robot/state")]


NUMBERS = """
#include <ros/ros.h>
#include <std_msgs/String.h>
const double kRate = 2.5;
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("~");
  double a, b, c, d, e;
  int f;
  nh.param("a", a, 0.5);
  nh.param("b", b, -0.1);
  nh.param("c", c, 1e-3);
  nh.param("d", d, kRate);
  nh.param("e", e, 2.0f);
  nh.param("f", f, -3);
  ros::Publisher p;
  if (b < 0.0)
    p = nh.advertise<std_msgs::String>("negative", 1);
  ros::spin();
  return 0;
}
"""


def test_a_floating_or_signed_default_is_its_value(tmp_path):
    """A default written as a floating literal (``0.5``, ``1e-3``, ``2.0f``), signed
    (``-0.1``, ``-3``) or held by a constant (``kRate``) is its value: a condition on the
    parameter (``if (b < 0.0)``) is decided by it where nothing sets it. They were kept
    with no value (only booleans, unsigned integers, strings and lists were read)."""
    source = tmp_path / "n.cpp"
    source.write_text(NUMBERS)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    got = {c.name: c.default for c in result.calls if c.kind == "read"}
    assert got == {"~a": 0.5, "~b": -0.1, "~c": 0.001, "~d": 2.5, "~e": 2.0, "~f": -3}
    assert [type(got[k]) for k in ("~a", "~f")] == [float, int]
