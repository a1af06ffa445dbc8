"""The standard library parts nlohmann/json uses, which ROS packages vendor
(DOBOT_6Axis_ROS2_V4's dobot_bringup_v4/include/nlohmann): ``<version>``,
``std::forward_list`` and ``std::front_inserter``, ``std::valarray`` (its from_json
overloads), ``std::char_traits<char>::int_type`` / ``eof()`` / ``to_int_type`` (its
input adapters), ``std::is_copy_assignable`` / ``is_move_assignable``: the stand-ins had
none of them (51 CPP_PARSE_ERROR and 2 CPP_INCLUDE_MISSING in DOBOT's driver node)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <version>
#include <algorithm>
#include <forward_list>
#include <iterator>
#include <string>
#include <type_traits>
#include <valarray>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

template<class J, class T>
void from_json(const J& j, std::forward_list<T>& l) {
  l.clear();
  std::transform(j.rbegin(), j.rend(), std::front_inserter(l), [](const T& i) { return i; });
}

template<class J, class T>
void from_json(const J& j, std::valarray<T>& l) {
  l.resize(j.size());
  std::copy(j.begin(), j.end(), std::begin(l));
}

struct Adapter {
  std::char_traits<char>::int_type get_character(const char* c) {
    if (*c == 0) { return std::char_traits<char>::eof(); }
    return std::char_traits<char>::to_int_type(*c);
  }
};

static_assert(std::is_copy_assignable<std::string>::value, "");
static_assert(std::is_move_assignable<std::string>::value, "");

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
  std::forward_list<int> numbers{1, 2};
  numbers.push_front(0);
  std::valarray<double> values(3);
  Adapter adapter;
  if (adapter.get_character("a") != std::char_traits<char>::eof() && !numbers.empty()
      && values.size() == 3) {
    auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);
  }
  rclcpp::spin(node);
}
"""


def test_the_json_library_s_standard_parts_are_declared(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
