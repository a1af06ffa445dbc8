"""A local variable written several times holds, where a call reads it, the value of
the write before the read (``Scope.written_before``), when nothing else may run between;
``topic += "/x"`` appends to what it held."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
using S = std_msgs::msg::String;
class Cam : public rclcpp::Node {
public:
  Cam() : Node("cam") {
    std::string name;
    std::string prefix = "~/";
    if (on_) {
      name = prefix + status_;
      a_ = create_publisher<S>(name, 1);
      name = prefix + "pose";
      b_ = create_publisher<S>(name, 1);
    }
    std::string branch = "first";
    if (on_) { branch = "then"; } else { branch = "else"; }
    c_ = create_publisher<S>(branch, 1);
    std::string looped = "before";
    for (int i = 0; i < 3; ++i) {
      d_ = create_publisher<S>(looped, 1);
      looped = "after";
    }
    std::string later = "early";
    auto make = [&]() { e_ = create_publisher<S>(later, 1); };
    later = "late";
    make();
    std::string grown = "grown";
    grown += "/more";
    f_ = create_publisher<S>(grown, 1);
    grown = "again";
    g_ = create_publisher<S>(grown, 1);
  }
  bool on_ = true;
  const std::string status_ = "status";
  rclcpp::Publisher<S>::SharedPtr a_, b_, c_, d_, e_, f_, g_;
};
"""


def _extract(tmp_path, text: str) -> CppResult:
    (tmp_path / "package.xml").write_text(package_xml("cam", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    source = tmp_path / "cam.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)


def test_a_local_written_again_is_read_as_last_written(tmp_path) -> None:
    result = _extract(tmp_path, SOURCE)
    assert [(c.name, c.location.line) for c in result.calls if c.kind == "publish"] == [
        # zed_wrapper's pattern: one local for every service name, in turn
        ("~status", 11), ("~pose", 13),
        # either side may have run, and each writes it: one call per side (each
        # under its side's condition: test_extract_cpp_branch_written_name.py)
        ("then", 17), ("else", 17),
        # the loop's next turn sees "after", the lambda runs after "late": not known
        ("?", 20), ("?", 24),
        # += appends (it was read as "grown" before)
        ("grown/more", 29),
        ("again", 31),
    ]


LOOPED = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
using S = std_msgs::msg::String;
class Cam : public rclcpp::Node {
public:
  Cam() : Node("cam") {
    std::string key = "port";
    for (int i = 0; i < 3; ++i) {
      key += "/x";
      a_ = create_publisher<S>(key, 1);
    }
    std::string again = "base";
    for (int i = 0; i < 3; ++i) {
      again = again + "/y";
      b_ = create_publisher<S>(again, 1);
    }
  }
  rclcpp::Publisher<S>::SharedPtr a_, b_;
};
"""


def test_a_local_that_grows_in_a_loop_is_not_its_first_turn(tmp_path) -> None:
    # each turn appends again: what it held before the append is not known
    result = _extract(tmp_path, LOOPED)
    assert [c.name for c in result.calls if c.kind == "publish"] == ["?/x", "?/y"]
