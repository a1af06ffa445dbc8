"""``a + b`` in a class template, where an operand's type depends on the template
and unqualified look-up finds some ``operator+`` at the template's definition: clang
keeps a call with no declaration whose children are the left operand, the overload set
and the right operand. That call was read as a wrapper of its last child, so depthai's
``Detection<T>`` published ``"~/" + getName() + "/detections"`` as ``/detections``: one
topic at the root for every camera, and false multiple-publishers warnings where a launch
file starts several. It is a concatenation; an operator other than ``+`` is unknown."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace cam {
struct Flags { int v; };
inline Flags operator+(Flags a, Flags b) { return Flags{a.v + b.v}; }
inline Flags operator-(Flags a, Flags b) { return Flags{a.v - b.v}; }
class Base {
public:
  Base(rclcpp::Node* node, const std::string& name) : node_(node), name_(name) {}
  std::string getName() { return name_; }
  rclcpp::Node* getNode() { return node_; }
  rclcpp::Node* node_;
  std::string name_;
};
template <typename T>
class Det : public Base {
public:
  Det(rclcpp::Node* node, const std::string& name) : Base(node, name) {
    pub_ = getNode()->template create_publisher<T>("~/" + getName() + "/detections", 10);
    odd_ = getNode()->template create_publisher<T>(getName() - "/x", 10);
  }
  typename rclcpp::Publisher<T>::SharedPtr pub_, odd_;
};
}  // namespace cam
class Node : public rclcpp::Node {
public:
  Node() : rclcpp::Node("n") { d_ = std::make_shared<cam::Det<std_msgs::msg::String>>(this, "nn"); }
  std::shared_ptr<cam::Det<std_msgs::msg::String>> d_;
};
"""


def test_an_operator_left_to_instantiation_is_read_as_one(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("cam", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "det.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted(c.name for c in result.calls if c.kind == "publish")
    assert len(names) == 2, names
    # the concatenation keeps its prefix and its unknown middle; no part is dropped
    assert "~?/detections" in names, names
    assert "/detections" not in names and "/x" not in names, names
    assert "?" in names, names  # ``-`` on strings: not known, not its right operand
