"""A program made by a CMake function of a package outside the workspace that is given a
nodelet class of the package: jsk_topic_tools' ``jsk_nodelet(src/x.cpp "pkg/Class" exe
SRCS EXECS)`` writes a ``main()`` that loads the class under the node's own name (as
``nodelet standalone``) and adds the source to SRCS, which the package's library builds.
jsk_robot_startup's ``lightweight_logger`` was a launch-missing-reference error ("not in
the workspace") in jsk_fetch_startup's fetch_bringup.launch; it is now the nodelet
LightweightLogger run alone, with its calls."""

from __future__ import annotations

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

MANIFEST = """<?xml version="1.0"?>
<package format="2"><name>pkg</name><version>0.1.0</version><description>d</description>
  <maintainer email="a@b.c">m</maintainer><license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>roscpp</depend><depend>nodelet</depend><depend>std_msgs</depend>
  <depend>jsk_topic_tools</depend>
  <export><nodelet plugin="${prefix}/plugins.xml"/></export>
</package>
"""

PLUGINS = """
    <library path="lib/libpkg">
      <class name="pkg/Logger" type="pkg::Logger" base_class_type="nodelet::Nodelet">
        <description>logs</description>
      </class>
    </library>
    """

CMAKE = """
    cmake_minimum_required(VERSION 3.0.2)
    project(pkg)
    find_package(catkin REQUIRED COMPONENTS roscpp nodelet std_msgs jsk_topic_tools)
    catkin_package()
    macro(add_logger_nodelet _cpp _cls _bin)
      jsk_nodelet(${_cpp} ${_cls} ${_bin} ${PROJECT_NAME}_NODELET_SRCS
                  ${PROJECT_NAME}_NODELET_EXECUTABLES)
    endmacro()
    add_logger_nodelet(src/logger.cpp "pkg/Logger" "logger")
    add_library(pkg_nodelets ${${PROJECT_NAME}_NODELET_SRCS})
    other_function(src/tool.cpp helper)
    """

LOGGER = """
    #include <ros/ros.h>
    #include <nodelet/nodelet.h>
    #include <std_msgs/String.h>
    #include <pluginlib/class_list_macros.h>
    namespace pkg {
    class Logger : public nodelet::Nodelet {
      void onInit() override {
        pub_ = getPrivateNodeHandle().advertise<std_msgs::String>("out", 1);
      }
      ros::Publisher pub_;
    };
    }  // namespace pkg
    PLUGINLIB_EXPORT_CLASS(pkg::Logger, nodelet::Nodelet)
    """

LAUNCH = """
    <launch>
      <node pkg="pkg" type="logger" name="logger"/>
      <node pkg="pkg" type="helper" name="helper"/>
    </launch>
    """


def test_a_program_a_foreign_function_makes_of_a_nodelet_runs_it(write_tree):
    root = write_tree({
        "src/pkg/package.xml": MANIFEST,
        "src/pkg/plugins.xml": PLUGINS,
        "src/pkg/CMakeLists.txt": CMAKE,
        "src/pkg/src/logger.cpp": LOGGER,
        "src/pkg/src/tool.cpp": "void helper() {}\n",
        "src/pkg/launch/a.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\nconfigurations:\n"
                        "  c: [pkg/launch/a.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    logger = next(n for n in config.nodes if n.name == "/logger")
    assert logger.node is not None and logger.node.name == "pkg/pkg/Logger"
    assert [(link.kind, link.name) for link in logger.links] == [("publish", "/logger/out")]
    said = [(d.code, d.location.line) for d in config.diagnostics
            if d.code in ("NODE_STANDALONE_NODELET", "NODE_NOT_FOUND")]
    # helper: the function it is given to names no nodelet class
    assert ("NODE_STANDALONE_NODELET", 2) in said
    assert ("NODE_NOT_FOUND", 3) in said
    missing = [f.message for f in run_catalogue(model) if f.rule == "launch-missing-reference"]
    assert missing == ["node type pkg/helper is not in the workspace; its interface is unknown"
                       "; package pkg is in the workspace, with no program found in its "
                       "build files"]
