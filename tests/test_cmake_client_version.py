"""``find_package(rclcpp)`` / ``roscpp`` sets the client library's version, when the
distribution the sources are read for is known (a project's ``distro:``, ``ROS_DISTRO``):
the release the C++ stand-ins announce. mavros builds with ``-DUSE_OLD_DECLARE_PARAMETER``
only ``if(rclcpp_VERSION VERSION_LESS 9.0.0)`` (Foxy), around its parameter
declarations: with the version unknown every plugin was partial (CPP_BUILD_MACRO); with a
distribution known the branch is decided. Unknown stays unknown."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(old)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
if(rclcpp_VERSION VERSION_LESS 9.0.0)
  add_definitions(-DUSE_OLD_DECLARE)
endif()
if(rclcpp_VERSION_MAJOR GREATER_EQUAL 28)
  add_definitions(-DJAZZY_OR_NEWER)
endif()
add_executable(node src/node.cpp)
"""

NODE = r"""
#include <memory>
#include <rclcpp/rclcpp.hpp>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
#ifdef USE_OLD_DECLARE
  node->declare_parameter("old_rate", rclcpp::ParameterValue());
#else
  node->declare_parameter<double>("rate", 1.0);
#endif
#ifdef JAZZY_OR_NEWER
  node->declare_parameter<bool>("jazzy", true);
#endif
  rclcpp::spin(node);
}
"""


def _node(write_tree, distro: str):
    root = write_tree({
        "src/old/package.xml": package_xml("old", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/old/CMakeLists.txt": CMAKE,
        "src/old/src/node.cpp": NODE,
        "project.yaml": "project: p\n" + (f"distro: {distro}\n" if distro else "")
                        + "configurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.executable == "node")
    said = sorted(d.message.split(":")[-1].split(",")[0].strip() for d in model.diagnostics
                  if d.code == "CPP_BUILD_MACRO")
    return node, said


def test_a_known_distribution_decides_a_test_of_rclcpp_s_version(write_tree):
    node, said = _node(write_tree, "humble")
    assert sorted(c.name for c in node.calls if c.kind == "declare") == ["rate"]
    assert node.completeness == "complete"
    assert said == []
    node, said = _node(write_tree, "jazzy")
    assert sorted(c.name for c in node.calls if c.kind == "declare") == ["jazzy", "rate"]
    assert said == []


def test_an_unknown_distribution_leaves_it_undecided(write_tree):
    node, said = _node(write_tree, "")
    assert node.completeness == "partial"
    assert len(said) == 2
