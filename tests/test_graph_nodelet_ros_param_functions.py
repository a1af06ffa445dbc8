"""roscpp's free functions that take no handle, in a nodelet: the manager's names.

``ros::param::has / get / param / set / del / search`` and ``ros::service::call`` resolve
their name with ``ros::names::resolve``, against ``ros::this_node``: the process's node,
in a nodelet loaded into a manager the manager's, so ``~x`` is the manager's private
``x``, not the nodelet's. jsk_robot 6f921c679^'s LightweightLogger nodelet read its
``database`` only if ``ros::param::has("~database")`` (lightweight_logger_nodelet.cpp:52),
which asked ``/mongodb_lifelog_nodelet_manager/database``, set by nothing, so the database
common_logger.launch gave each logger was never read. A global name is the same from
either; run standalone, the process is the nodelet's own."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>logr</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
           "<depend>nodelet</depend><depend>pluginlib</depend>"
           '<export><nodelet plugin="${prefix}/nodelets.xml"/></export></package>\n')

CMAKE = """project(logr)
find_package(catkin REQUIRED COMPONENTS roscpp nodelet pluginlib)
catkin_package()
add_library(logr_nodelet src/logger.cpp)
"""

PLUGINS = """<library path="lib/liblogr_nodelet">
  <class name="logr/Logger" type="logr::Logger" base_class_type="nodelet::Nodelet">
    <description>d</description>
  </class>
</library>
"""

SOURCE = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
namespace logr {
class Logger : public nodelet::Nodelet {
 public:
  void onInit() override {
    std::string db;
    if (ros::param::has("~database")) db = "given";
    ros::param::get("/robot/name", db);
    getPrivateNodeHandle().param<int>("rate", rate_, 1);
  }
 private:
  int rate_;
};
}
PLUGINLIB_EXPORT_CLASS(logr::Logger, nodelet::Nodelet)
"""

LAUNCH = """<launch>
  <param name="robot/name" value="r1"/>
  <node pkg="nodelet" type="nodelet" name="mgr" args="manager"/>
  <node pkg="nodelet" type="nodelet" name="logger" args="load logr/Logger /mgr">
    <param name="database" value="db"/>
    <param name="rate" value="2"/>
  </node>
  <node pkg="nodelet" type="nodelet" name="alone" args="standalone logr/Logger"/>
</launch>
"""


def _model(write_tree: Any) -> Any:
    root = write_tree({
        "src/logr/package.xml": PACKAGE, "src/logr/CMakeLists.txt": CMAKE,
        "src/logr/nodelets.xml": PLUGINS, "src/logr/src/logger.cpp": SOURCE,
        "src/logr/launch/logr.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [logr/launch/logr.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    return model


def _read(instance: Any) -> list[tuple[int, str]]:
    return sorted((link.location.line, link.rosname.full) for link in instance.links
                  if link.kind == "read")


def test_ros_param_in_a_nodelet_asks_the_managers_private_namespace(write_tree: Any
                                                                    ) -> None:
    model = _model(write_tree)
    (config,) = model.configurations
    # line 9: the manager's ~database; line 10: a global name, the same; line 11: the
    # nodelet's own private handle
    assert _read(config.node("/logger")) == [
        (9, "/mgr/database"), (10, "/robot/name"), (11, "/logger/rate")]
    assert _read(config.node("/alone")) == [
        (9, "/alone/database"), (10, "/robot/name"), (11, "/alone/rate")]
    # so the nodelet's /logger/database is set and read by nothing
    unread = [f.message for f in run_catalogue(model) if f.rule == "parameter-set-not-read"]
    assert [m for m in unread if "/logger/database" in m] and not [
        m for m in unread if "/logger/rate" in m]
    (said,) = [d for d in config.diagnostics if d.code == "NODELET_PROCESS_HANDLES"]
    assert "1 call(s)" in said.message and "/mgr's" in said.message
