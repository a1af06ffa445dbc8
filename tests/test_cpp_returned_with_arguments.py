"""A name made by a function of the node's code from its arguments: a call of a function
or a non-virtual method whose body is one ``return`` gives the text of that expression
with each string parameter holding this call's argument (``std::string topic(const
std::string& leaf) { return "arm/" + leaf; }``, ``prefixed("arm", "status")``), read at
each call with its own arguments. Before, only getters without parameters were read so
and every such name was ``?``. mavros_extras' ``utils::format("wheel%i", iwheel++)``
(a variadic template that ``snprintf``s into a ``std::string``'s storage, several
statements) stays unknown, as do functions with more statements, default arguments or
virtual methods."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = r"""#include <ros/ros.h>
#include <std_msgs/String.h>
#include <cstdio>
#include <string>
static std::string prefixed(const std::string& ns, const std::string& name)
{
  return ns + "/" + name;
}
std::string wheel(int i) { return "wheel" + std::to_string(i); }
std::string built(const std::string& leaf)
{
  std::string made = leaf;
  made += "_out";
  return made;
}
std::string with_default(const std::string& leaf, const std::string& ns = "def")
{
  return ns + "/" + leaf;
}
template <typename... Args>
std::string format(const std::string& fmt, Args... args)
{
  std::string ret;
  auto size = std::snprintf(nullptr, 0, fmt.c_str(), args...);
  ret.resize(size);
  std::snprintf(&ret.front(), ret.capacity() + 1, fmt.c_str(), args...);
  return ret;
}
struct Arm {
  std::string topic(const std::string& leaf) const { return "arm/" + leaf; }
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh;
  ros::Publisher a = nh.advertise<std_msgs::String>(prefixed("arm", "status"), 1);
  ros::Publisher b = nh.advertise<std_msgs::String>(prefixed("leg", "status"), 1);
  Arm arm;
  ros::Publisher c = nh.advertise<std_msgs::String>(arm.topic("joints"), 1);
  double x;
  nh.getParam(wheel(2) + "/x", x);
  for (int i = 0; i < 3; i++) {
    std::string w = prefixed("wheels", "w" + std::to_string(i));
    nh.getParam(w, x);
  }
  ros::Publisher d = nh.advertise<std_msgs::String>(built("cmd"), 1);
  ros::Publisher e = nh.advertise<std_msgs::String>(with_default("cmd"), 1);
  int iwheel = 0;
  nh.getParam(format("wheel%i", iwheel++) + "/y", x);
  ros::spin();
}
"""


def _calls(write_tree) -> list[tuple[str, str, int]]:
    root = write_tree({
        "p/package.xml": package_xml("p", "catkin"),
        "p/CMakeLists.txt": "project(p)\nfind_package(catkin REQUIRED COMPONENTS roscpp "
                            "std_msgs)\nadd_executable(n src/n.cpp)\n",
        "p/src/n.cpp": SOURCE,
    })
    ws = scan([str(root)])
    package = ws.packages["p"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    return sorted((c.kind, c.name, c.location.line) for c in package.nodes[0].calls)


def test_a_function_of_its_arguments_names_the_call(write_tree) -> None:
    calls = _calls(write_tree)
    lines = SOURCE.splitlines()

    def at(text: str) -> int:
        return next(n + 1 for n, line in enumerate(lines) if text in line)

    assert ("publish", "arm/status", at('prefixed("arm"')) in calls
    assert ("publish", "leg/status", at('prefixed("leg"')) in calls
    assert ("publish", "arm/joints", at('arm.topic("joints")')) in calls
    assert ("read", "wheel2/x", at("wheel(2)")) in calls
    loop = at("nh.getParam(w, x)")
    assert [name for kind, name, line in calls if line == loop] == [
        "wheels/w0", "wheels/w1", "wheels/w2"]


def test_other_functions_stay_unknown(write_tree) -> None:  # guards
    calls = _calls(write_tree)
    lines = SOURCE.splitlines()

    def named(text: str) -> list[str]:
        line = next(n + 1 for n, line in enumerate(lines) if text in line)
        return [name for _, name, at in calls if at == line]

    assert named('built("cmd")') == ["?"]  # several statements
    assert named('with_default("cmd")') == ["?"]  # a default argument
    assert named('format("wheel%i"') == ["?/y"]  # mavros' utils::format
