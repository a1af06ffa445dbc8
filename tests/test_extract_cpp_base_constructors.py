"""A workspace base class over rclcpp::Node with two constructors, ``(name, ns,
options)`` and ``(name, options)``, each passing its parameters to rclcpp::Node
(aerostack2's ``as2::Node``). A subclass calls one of them; the other is called by no
file of the node and names no node. The node was named ``/?/?`` (from the constructor
nobody calls, met first) in every aerostack2 executable."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

BASE = """\
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace fly {
class Node : public rclcpp::Node {
public:
  Node(const std::string & name, const std::string & ns,
       const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : rclcpp::Node(name, ns, options) {}
  explicit Node(const std::string & name,
                const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : rclcpp::Node(name, options) {}
  std::string global(const std::string & name);
};
}  // namespace fly
"""
# the base's own file: includes the header, constructs nothing
BASE_SOURCE = """\
#include "fly/node.hpp"
std::string fly::Node::global(const std::string & name) { return "/" + name; }
"""
NODE = """\
#include <memory>
#include <std_msgs/msg/string.hpp>
#include "fly/node.hpp"
class Zones : public fly::Node {
public:
  Zones() : fly::Node(%s) {
    pub_ = create_publisher<std_msgs::msg::String>("zones", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Zones>());
}
"""


def _rosname(write_tree, arguments: str, base_source: str = BASE_SOURCE) -> str | None:
    root = write_tree({"fly/package.xml": package_xml("fly", "ament_cmake").replace(
                           "</package>", "<depend>rclcpp</depend></package>"),
                       "fly/include/fly/node.hpp": BASE,
                       "fly/src/node.cpp": base_source,
                       "fly/src/zones.cpp": NODE % arguments})
    sources = [str(root / "fly" / "src" / "node.cpp"), str(root / "fly" / "src" / "zones.cpp")]
    return extract_cpp(sources, scan([str(root)]), cache_dir=None).rosname


def test_the_constructor_the_subclass_calls_names_the_node(write_tree) -> None:
    assert _rosname(write_tree, '"geozones"') == "geozones"


def test_the_other_constructor_when_it_is_the_one_called(write_tree) -> None:
    assert _rosname(write_tree, '"platform", "drone0"') == "/drone0/platform"


def test_a_name_passed_at_run_time_stays_unknown(write_tree) -> None:
    assert _rosname(write_tree, 'std::getenv("NAME")') == "?"


def test_an_error_near_the_base_class_does_not_make_its_other_constructor_win(
        write_tree) -> None:
    # an error in code that names the base class: a construction by the other
    # constructor could hide there, but the subclass's is seen
    broken = BASE_SOURCE + "void broken(fly::Node * node) { node->no_such_method(); }\n"
    assert _rosname(write_tree, '"geozones"', broken) == "geozones"


UNBUILT = """\
#pragma once
#include <memory>
#include "fly/node.hpp"
// a node class of the library that this executable never constructs
class Helper : public fly::Node {
public:
  Helper() : fly::Node("helper") {}
};
// the node the executable makes: named through a class template, whose call of the
// base constructor clang keeps no call for (aerostack2's BehaviorServer<ActionT>)
template<class T> class Server : public fly::Node {
public:
  explicit Server(const std::string & name) : fly::Node(name) {}
};
class Zones : public Server<int> {
public:
  Zones() : Server<int>("zones") {}
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Zones>());
}
"""


def test_a_node_class_the_process_never_makes_does_not_name_it(write_tree) -> None:
    """Only the never-made Helper passes the base constructor a name the parse sees:
    the node's name is not known, not "helper"."""
    root = write_tree({"fly/package.xml": package_xml("fly", "ament_cmake").replace(
                           "</package>", "<depend>rclcpp</depend></package>"),
                       "fly/include/fly/node.hpp": BASE,
                       "fly/src/node.cpp": BASE_SOURCE,
                       "fly/src/zones.cpp": UNBUILT})
    sources = [str(root / "fly" / "src" / "node.cpp"), str(root / "fly" / "src" / "zones.cpp")]
    assert extract_cpp(sources, scan([str(root)]), cache_dir=None).rosname == "?"


SERVER = """\
#pragma once
#include <string>
#include "fly/node.hpp"
// aerostack2's BehaviorServer<actionT>: a class template over the base, its constructor
// defined outside the class (an implementation header), initialising the base with
// its own parameter (clang keeps the argument list there, no call)
template<class T> class Server : public fly::Node {
public:
  explicit Server(const std::string & name,
                  const rclcpp::NodeOptions & options = rclcpp::NodeOptions());
};
template<class T>
Server<T>::Server(const std::string & name, const rclcpp::NodeOptions & options)
: fly::Node(name, options) {}
"""
BEHAVIOR = """\
#include <memory>
#include "fly/server.hpp"
namespace names { const char go_to[] = "GoToBehavior"; }
class GoTo : public Server<int> {
public:
  explicit GoTo(const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : Server<int>(names::go_to, options) {}
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<GoTo>());
}
"""


def test_a_name_passed_through_a_class_template_s_constructor(write_tree) -> None:
    root = write_tree({"fly/package.xml": package_xml("fly", "ament_cmake").replace(
                           "</package>", "<depend>rclcpp</depend></package>"),
                       "fly/include/fly/node.hpp": BASE,
                       "fly/include/fly/server.hpp": SERVER,
                       "fly/src/node.cpp": BASE_SOURCE,
                       "fly/src/go_to.cpp": BEHAVIOR})
    sources = [str(root / "fly" / "src" / "node.cpp"), str(root / "fly" / "src" / "go_to.cpp")]
    assert extract_cpp(sources, scan([str(root)]), cache_dir=None).rosname == "GoToBehavior"


def test_a_class_template_no_file_instantiates_passes_no_name(write_tree) -> None:
    """aerostack2's platform_emulator includes a header's class template over the base
    that it never instantiates, beside its own ``: Node("platform_emulator")``."""
    root = write_tree({"fly/package.xml": package_xml("fly", "ament_cmake").replace(
                           "</package>", "<depend>rclcpp</depend></package>"),
                       "fly/include/fly/node.hpp": BASE,
                       "fly/include/fly/server.hpp": SERVER,
                       "fly/src/node.cpp": BASE_SOURCE,
                       "fly/src/zones.cpp": '#include "fly/server.hpp"\n' + NODE % (
                           '"geozones"')})
    sources = [str(root / "fly" / "src" / "node.cpp"), str(root / "fly" / "src" / "zones.cpp")]
    assert extract_cpp(sources, scan([str(root)]), cache_dir=None).rosname == "geozones"


def test_a_namespace_passed_empty_adds_no_slash(write_tree) -> None:
    """nav2's ``LifecycleNode(name, ns = "", options)``: the jazzy interface models were
    written with ``//controller_server``."""
    assert _rosname(write_tree, '"server", ""') == "server"
    assert _rosname(write_tree, '"server", "/robot"') == "/robot/server"


def test_a_member_function_template_called_from_many_places_keeps_each_name(
        write_tree) -> None:
    """OrbbecSDK_ROS2's ``setAndGetNodeParameter<T>(value, name, default)``, a member
    function template of a plain class defined outside it and called for 25 parameters:
    each declaration keeps its name (the calls of a class template's members found by
    their definition's place must not take these beyond the sites read one by one)."""
    names = [f"p{i}" for i in range(20)]
    calls = "\n".join(f'    set<int>(v_, "{name}", {i});' for i, name in enumerate(names))
    source = (
        "#include <string>\n#include <rclcpp/rclcpp.hpp>\n"
        "class Camera : public rclcpp::Node {\npublic:\n"
        "  Camera() : rclcpp::Node(\"camera\") {\n" + calls + "\n  }\n"
        "  template <typename T>\n"
        "  void set(T & value, const std::string & name, const T & fallback);\n"
        "  int v_;\n};\n"
        "template <typename T>\n"
        "void Camera::set(T & value, const std::string & name, const T & fallback) {\n"
        "  value = this->declare_parameter<T>(name, fallback);\n}\n")
    root = write_tree({"cam/package.xml": package_xml("cam", "ament_cmake").replace(
                           "</package>", "<depend>rclcpp</depend></package>"),
                       "cam/src/camera.cpp": source})
    result = extract_cpp([str(root / "cam" / "src" / "camera.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted(c.name for c in result.calls if c.kind == "declare") == sorted(names)
