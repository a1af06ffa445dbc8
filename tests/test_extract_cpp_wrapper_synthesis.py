"""Names declared for errors in functions that call only the unit's own wrappers of the
API (``_translation_unit``'s second synthesis): the synthesis looks for the API's call
sites before the walk knows the wrappers, so an error beside a wrapper call (navigation2's
vector object server: ``uuid_parse`` of <uuid/uuid.h>, missing then, next to
nav2_ros_common's ``declare_or_get_parameter``; here a library with no stand-in) left its
names undeclared and the node partial."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

UTILS = """\
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>

namespace util {
template<typename T>
T declare_or_get(rclcpp::Node * node, const std::string & name, const T & value)
{
  if (!node->has_parameter(name)) {
    return node->declare_parameter(name, value);
  }
  return node->get_parameter(name).get_value<T>();
}
}  // namespace util
"""

NODE = """\
#include <string>
#include <idgen/idgen.h>
#include <std_msgs/msg/string.hpp>
#include "utils.hpp"

class Shape : public rclcpp::Node
{
public:
  Shape() : Node("shape")
  {
    unsigned char out[16];
    std::string id = util::declare_or_get(this, "uuid", std::string(""));
    if (id.empty()) {
      idgen_generate(out);
    } else if (idgen_parse(id.c_str(), out)) {
      pub_ = create_publisher<std_msgs::msg::String>("bad_uuid", 1);
    }
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_errors_beside_wrapper_calls_get_their_names_declared(tmp_path: Path) -> None:
    (tmp_path / "utils.hpp").write_text(UTILS)
    (tmp_path / "n.cpp").write_text(NODE.replace(
        '      pub_ = create_publisher<std_msgs::msg::String>("bad_uuid", 1);\n', ""))
    result = extract_cpp([str(tmp_path / "n.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    codes = [d.code for d in result.diagnostics]
    assert "CPP_NAMES_DECLARED" in codes
    assert not {"CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED", "CPP_PARSE_ERROR"} & set(codes)
    assert ("declare", "uuid") in [(c.kind, c.name) for c in result.calls]


def test_a_unit_whose_errors_are_beside_api_calls_is_parsed_as_before(tmp_path: Path) -> None:
    """With an API call in the same function, the first synthesis already declares the
    names: one synthesis, the same result."""
    (tmp_path / "utils.hpp").write_text(UTILS)
    (tmp_path / "n.cpp").write_text(NODE)
    result = extract_cpp([str(tmp_path / "n.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert [d.code for d in result.diagnostics].count("CPP_NAMES_DECLARED") == 1
    assert ("publish", "bad_uuid") in [(c.kind, c.name) for c in result.calls]
