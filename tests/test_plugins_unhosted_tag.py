"""A plugin description exported under a tag no host's ClassLoader names: pluginlib's
``ClassLoader(tag, base)`` finds only the classes exported under its own tag, so none of
its classes is a host's plugin, whatever its base (navigation2's dwb_plugins exports
goal checkers of ``nav2_core::GoalChecker`` under ``dwb_core``; the controller server's
loader is ``ClassLoader("nav2_core", "nav2_core::GoalChecker")``). A class of it is a
node only as one a ClassLoader in its package's or its dependencies' code may load by
its base (``deferred``). Before, such a goal checker was a host's plugin node when
the package happened to hold some ClassLoader (of any base), and nothing otherwise."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.cmake import parse_package
from haros_arch.workspace import scan

PLUGINS = """<class_libraries>
  <library path="goal_checker">
    <class type="demo::Checker" base_class_type="nav2_core::GoalChecker"/>
  </library>
  <library path="generator">
    <class type="demo::Generator" base_class_type="demo::TrajectoryGenerator"/>
  </library>
</class_libraries>
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo)
find_package(ament_cmake REQUIRED)
find_package(pluginlib REQUIRED)
add_library(goal_checker SHARED src/checker.cpp)
add_library(generator SHARED src/generator.cpp)
add_executable(planner src/planner.cpp)
pluginlib_export_plugin_description_file(dwb_core plugins.xml)
ament_package()
"""

CHECKER = """#include <pluginlib/class_list_macros.hpp>
namespace nav2_core { class GoalChecker { public: virtual ~GoalChecker() {} }; }
namespace demo { class Checker : public nav2_core::GoalChecker {}; }
PLUGINLIB_EXPORT_CLASS(demo::Checker, nav2_core::GoalChecker)
"""

GENERATOR = """#include <pluginlib/class_list_macros.hpp>
namespace demo { class TrajectoryGenerator { public: virtual ~TrajectoryGenerator() {} }; }
namespace demo { class Generator : public TrajectoryGenerator {}; }
PLUGINLIB_EXPORT_CLASS(demo::Generator, demo::TrajectoryGenerator)
"""

PLANNER = """#include <pluginlib/class_loader.hpp>
namespace demo { class TrajectoryGenerator; }
int main() {
  pluginlib::ClassLoader<demo::TrajectoryGenerator> loader("dwb_core",
                                                          "demo::TrajectoryGenerator");
}
"""


def _plugins(tmp_path, with_loader: bool) -> dict[str, bool]:
    root = tmp_path / "src" / "demo"
    (root / "src").mkdir(parents=True)
    (root / "package.xml").write_text(package_xml("demo", "ament_cmake"))
    (root / "plugins.xml").write_text(PLUGINS)
    (root / "src" / "checker.cpp").write_text(CHECKER)
    (root / "src" / "generator.cpp").write_text(GENERATOR)
    (root / "src" / "planner.cpp").write_text(
        PLANNER if with_loader else "int main() {}\n")
    (root / "CMakeLists.txt").write_text(CMAKE)
    workspace = scan([str(tmp_path / "src")])
    nodes, _ = parse_package(workspace.packages["demo"], workspace)
    return {n.name: n.deferred for n in nodes if n.kind == "plugin"}


def test_a_hosted_base_under_an_unhosted_tag_is_no_plugin_node(tmp_path):
    # a ClassLoader in the package: the generator it loads is a deferred node; the goal
    # checker, which no ClassLoader of nav2_core::GoalChecker reads under dwb_core, none
    assert _plugins(tmp_path, with_loader=True) == {"demo/demo::Generator": True}


def test_without_a_loader_neither_is_a_node(tmp_path):
    assert _plugins(tmp_path, with_loader=False) == {}
