"""A name read from a member whose class's constructors are all defined in another file
(nav2's ClearCostmapService serves ``"clear_entirely_" + costmap_.getName()``, and
``Costmap2DROS::name_`` is set by the constructors in costmap_2d_ros.cpp, one of them
from its argument): the name stays '?', and the diagnostic says which member and why,
not that the name is computed at run time."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

HEADER = """#include <string>
#include "rclcpp/rclcpp.hpp"
namespace grid {
class Costmap
{
public:
  Costmap();
  explicit Costmap(const std::string & name);
  std::string getName() const {return name_;}
private:
  std::string name_;
};
class Inline
{
public:
  Inline() : name_("inline") {}
  std::string getName() const {return name_;}
private:
  std::string name_;
};
}  // namespace grid
"""

SOURCE = """#include "grid/costmap.hpp"
#include "std_msgs/msg/string.hpp"
namespace grid {
class Clearer
{
public:
  Clearer(rclcpp::Node::SharedPtr node, Costmap & costmap, Inline & other)
  : costmap_(costmap)
  {
    pub_ = node->create_publisher<std_msgs::msg::String>("clear_" + costmap_.getName(), 1);
    other_ = node->create_publisher<std_msgs::msg::String>("clear_" + other.getName(), 1);
    got_ = node->create_publisher<std_msgs::msg::String>(last_.data + "/got", 1);
  }
  std_msgs::msg::String last_;
  Costmap & costmap_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, other_, got_;
};
}  // namespace grid
"""


def test_a_member_only_another_files_constructors_set(tmp_path: Path) -> None:
    package = tmp_path / "grid"
    (package / "src").mkdir(parents=True)
    (package / "include" / "grid").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>grid</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>rclcpp</depend><depend>std_msgs</depend>"
        "<export><build_type>ament_cmake</build_type></export></package>")
    (package / "include" / "grid" / "costmap.hpp").write_text(HEADER)
    (package / "src" / "clearer.cpp").write_text(SOURCE)
    batch = extract_cpp_nodes([[str(package / "src" / "clearer.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    result = batch.results[0]
    assert sorted((c.name, c.location.line) for c in result.calls
                  if c.kind == "publish") == [("?/got", 12), ("clear_?", 10),
                                              ("clear_inline", 11)]
    said = sorted((d.code, d.location.line, d.message) for d in result.diagnostics
                  if d.code in ("CPP_DYNAMIC_NAME", "CPP_NAME_MEMBER_ELSEWHERE"))
    assert said == [
        # a message's field: what it holds is received at run time
        ("CPP_DYNAMIC_NAME", 12, "the name of this publish call is computed at run time; "
         "kept as '?/got'"),
        # (said when the node's files are joined: those constructors' file may give it)
        ("CPP_NAME_MEMBER_ELSEWHERE", 10,
         "the name of this publish call holds Costmap::name_, which nothing in this file "
         "sets (its class's constructors are in another file); kept as 'clear_?'")]
