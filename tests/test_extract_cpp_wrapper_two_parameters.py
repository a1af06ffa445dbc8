"""A wrapper whose name joins two of its parameters (``getParam(prefix + param, v)``) reads,
at each call site, that site's two values, not every value either is given anywhere.
elevation_mapping_cupy 20a8a26's convex_plane_decomposition_ros: ``loadParameter(nh,
prefix, "epsilon", v)`` in five loaders, each given its own prefix (``"preprocessing/"``,
``"ransac_plane_refinement/"``, ...): the node read each prefix with each of the 27
names, 100 false "read but never set" warnings. The loaders in another file than the
calls that give their prefixes, too."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.api import analyse_path
from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import Options
from haros_arch.workspace import scan

LOADING = r"""
#include <ros/ros.h>
#include "loading.h"
template <typename T>
bool loadParameter(const ros::NodeHandle& nh, const std::string& prefix,
                   const std::string& param, T& value) {
  if (!nh.getParam(prefix + param, value)) { return false; }
  return true;
}
A loadA(const ros::NodeHandle& nh, const std::string& prefix) {
  A a;
  loadParameter(nh, prefix, "alpha", a.a);
  loadParameter(nh, prefix, "beta", a.b);
  return a;
}
B loadB(const ros::NodeHandle& nh, const std::string& prefix) {
  B b;
  loadParameter(nh, prefix, "gamma", b.c);
  return b;
}
"""

HEADER = r"""
#pragma once
#include <ros/ros.h>
struct A { double a; int b; };
struct B { double c; };
A loadA(const ros::NodeHandle& nh, const std::string& prefix);
B loadB(const ros::NodeHandle& nh, const std::string& prefix);
"""

MAIN = r"""
#include <ros/ros.h>
#include "loading.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "planes");
  ros::NodeHandle nh("~");
  A a = loadA(nh, "first/");
  B b = loadB(nh, "second/");
  double x;
  nh.getParam(std::string("direct/") + "delta", x);
  ros::spin();
}
"""


def _package(tmp_path: Path, sources: dict[str, str], executable: str) -> Path:
    package = tmp_path / "src" / "demo"
    (package / "src").mkdir(parents=True)
    (package / "include").mkdir()
    (package / "package.xml").write_text(package_xml("demo"))
    (package / "include" / "loading.h").write_text(HEADER)
    (package / "CMakeLists.txt").write_text(
        "project(demo)\nfind_package(catkin REQUIRED roscpp)\ninclude_directories(include)\n"
        f"add_executable(planes {executable})\n")
    for name, text in sources.items():
        (package / "src" / name).write_text(text)
    return package


def test_each_site_reads_its_own_prefix_and_name(tmp_path: Path) -> None:
    package = _package(tmp_path, {"main.cpp": LOADING + MAIN.replace(
        '#include "loading.h"', "")}, "src/main.cpp")
    result = extract_cpp([str(package / "src" / "main.cpp")], scan([str(tmp_path / "src")]),
                         cache_dir=None)
    assert sorted(c.name for c in result.calls if c.kind == "read") == [
        "~direct/delta", "~first/alpha", "~first/beta", "~second/gamma"]


def test_loaders_in_another_file(tmp_path: Path) -> None:
    _package(tmp_path, {"main.cpp": MAIN, "loading.cpp": LOADING},
             "src/main.cpp src/loading.cpp")
    analysis = analyse_path(str(tmp_path / "src"), Options(cache_dir=None, jobs=1))
    (node,) = analysis.model.nodes
    assert sorted(c.name for c in node.calls if c.kind == "read") == [
        "~direct/delta", "~first/alpha", "~first/beta", "~second/gamma"]
