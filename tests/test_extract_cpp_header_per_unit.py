"""A header function's calls are read in each unit that includes it, with what that unit
gives it: the macros its own file defines before the ``#include``, the definitions its
target's CMake gives, and the values its own calls pass. Three executables of one
package include one header and call its two functions, all in one process (``jobs=1``):
a result of the header's functions kept from one unit and used in another (#24, "read a
header function once per process") must keep each of these apart, or a node gets
another's topics."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

CMAKE = """
cmake_minimum_required(VERSION 3.8)
project(hdr)
find_package(ament_cmake REQUIRED)
include_directories(include)
add_executable(alpha src/alpha.cpp)
add_executable(beta src/beta.cpp)
add_executable(gamma src/gamma.cpp)
target_compile_definitions(gamma PRIVATE HDR_FAST HDR_TOPIC="gamma_rate")
ament_package()
"""

HEADER = """
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#ifndef HDR_TOPIC
#define HDR_TOPIC "rate"
#endif
namespace hdr {
inline void setup(rclcpp::Node & node) {
#ifdef HDR_FAST
  auto fast = node.create_publisher<std_msgs::msg::String>("fast", 10);
#else
  auto slow = node.create_publisher<std_msgs::msg::String>("slow", 10);
#endif
  auto rate = node.create_publisher<std_msgs::msg::String>(HDR_TOPIC, 10);
}
inline void advertise(rclcpp::Node & node, const std::string & topic) {
  auto out = node.create_publisher<std_msgs::msg::String>(topic, 10);
}
}  // namespace hdr
"""


def _main(name: str, before: str = "") -> str:
    return f"""
{before}#include "hdr/common.hpp"
int main(int argc, char ** argv) {{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("{name}");
  hdr::setup(*node);
  hdr::advertise(*node, "{name}_out");
  rclcpp::spin(node);
}}
"""


def test_each_unit_reads_the_header_with_its_own_macros_and_values(write_tree) -> None:
    root = write_tree({
        "src/hdr/package.xml": package_xml("hdr", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/hdr/CMakeLists.txt": CMAKE,
        "src/hdr/include/hdr/common.hpp": HEADER,
        # a macro the unit's own file defines before the include: its flags are beta's
        "src/hdr/src/alpha.cpp": _main("alpha", "#define HDR_FAST\n"),
        "src/hdr/src/beta.cpp": _main("beta"),
        # the target's definitions
        "src/hdr/src/gamma.cpp": _main("gamma"),
        "project.yaml": "project: p\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    nodes = {n.executable: n for p in model.packages for n in p.nodes}
    published = {name: sorted(c.name for c in node.calls if c.kind == "publish")
                 for name, node in nodes.items()}
    assert published == {
        "alpha": ["alpha_out", "fast", "rate"],
        "beta": ["beta_out", "rate", "slow"],
        "gamma": ["fast", "gamma_out", "gamma_rate"],
    }
    # setup's calls are the header's, where they are written; advertise wraps the API
    # (``Wrappers``): its call is made at each unit's own call site
    for name, node in nodes.items():
        assert sorted((c.name, c.location.file) for c in node.calls
                      if c.kind == "publish" and not c.name.endswith("_out")) == [
            (n, "hdr/include/hdr/common.hpp") for n in published[name]
            if not n.endswith("_out")]
        assert [c.location.file for c in node.calls if c.name == f"{name}_out"] == [
            f"hdr/src/{name}.cpp"]
