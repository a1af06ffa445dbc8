"""A call in a function template whose arguments depend on its template parameters
calls, in each specialisation, the overload C++ picks there. quori_ros a09c7e5's
quori_face_node: ``template<T> Vector2<T> param(nh, name, const Vector2<T>& value)``
calls ``param(nh, name + "/x", value.x)``, the non-template overloads for ``uint32_t``
and ``double`` (defined in param.cpp); the reads came out as one ``?/?`` of the first
overload, and the ``double`` ones not at all. Each specialisation the node calls reads
its caller's name with ``/x`` and ``/y``, by the overload of its type."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.api import analyse_path
from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options
from haros_arch.workspace import scan

HEADER = r"""
#pragma once
#include <string>
#include <cstdint>
#include <ros/ros.h>
template <typename T> struct V2 { V2() : x(), y() {} V2(T a, T b) : x(a), y(b) {} T x; T y; };
namespace demo {
std::uint32_t param(ros::NodeHandle& nh, const std::string& name, const std::uint32_t value);
double param(ros::NodeHandle& nh, const std::string& name, const double value);
template <typename T>
V2<T> param(ros::NodeHandle& nh, const std::string& name, const V2<T>& value) {
  T second = value.y;
  return V2<T>(param(nh, name + "/x", value.x), param(nh, name + "/y", second));
}
}
"""

OVERLOADS = r"""
#include "param.h"
std::uint32_t demo::param(ros::NodeHandle& nh, const std::string& name,
                          const std::uint32_t value) {
  int res = 0;
  return nh.getParam(name, res) ? static_cast<std::uint32_t>(res) : value;
}
double demo::param(ros::NodeHandle& nh, const std::string& name, const double value) {
  double res = 0;
  return nh.getParam(name, res) ? res : value;
}
"""

MAIN = r"""
#include "param.h"
using namespace demo;
int main(int argc, char** argv) {
  ros::init(argc, argv, "face");
  ros::NodeHandle pnh("~");
  const V2<std::uint32_t> RESOLUTION = {1, 2};
  auto a = param(pnh, "resolution", RESOLUTION);
  auto b = param(pnh, "center", V2<double>(0.5, 0.5));
  double d = param(pnh, "scale", 1.0);
  ros::spin();
}
"""

READS = [("~center/x", "double"), ("~center/y", "double"), ("~resolution/x", "int"),
         ("~resolution/y", "int"), ("~scale", "double")]


def _package(tmp_path: Path, sources: dict[str, str]) -> Path:
    package = tmp_path / "src" / "demo"
    (package / "src").mkdir(parents=True)
    (package / "include").mkdir()
    (package / "package.xml").write_text(package_xml("demo"))
    (package / "include" / "param.h").write_text(HEADER)
    (package / "CMakeLists.txt").write_text(
        "project(demo)\nfind_package(catkin REQUIRED roscpp)\ninclude_directories(include)\n"
        f"add_executable(face {' '.join('src/' + name for name in sources)})\n")
    for name, text in sources.items():
        (package / "src" / name).write_text(text)
    return package


def test_overloads_in_another_file(tmp_path: Path) -> None:
    _package(tmp_path, {"main.cpp": MAIN, "param.cpp": OVERLOADS})
    analysis = analyse_path(str(tmp_path / "src"), Options(cache_dir=None, jobs=1))
    (node,) = analysis.model.nodes
    assert sorted((c.name, c.type) for c in node.calls if c.kind == "read") == READS


def test_overloads_in_the_same_file(tmp_path: Path) -> None:
    package = _package(tmp_path, {"main.cpp": OVERLOADS + MAIN})
    result = extract_cpp([str(package / "src" / "main.cpp")], scan([str(tmp_path / "src")]),
                         cache_dir=None)
    assert sorted((c.name, c.type) for c in result.calls if c.kind == "read") == READS
