"""An executable that loads a nodelet by name through ``nodelet::Loader`` (image_view's
``image_view`` node: ``nodelet.load(ros::this_node::getName(), "image_view/image", ...)``)
makes the nodelet's calls in its own process, under its own name, and none in its
code. Each instance of it makes the calls of the nodelet class, found as a launch file's
``nodelet standalone`` finds it, with the node's namespace and remaps; a class found
nowhere, or a load under another name, leaves it partial, so a parameter a launch file
gives it is not called unread (image_view's ``autosize``, read by the nodelet)."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.extract.cpp import plugin_loads
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.query.catalogue import UNDECIDED
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>viewer</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
           "<depend>nodelet</depend></package>\n")

WRAPPER = """#include <ros/ros.h>
#include <nodelet/loader.h>

int main(int argc, char ** argv) {
  ros::init(argc, argv, "viewer");
  nodelet::Loader manager;
  nodelet::M_string remap(ros::names::getRemappings());
  nodelet::V_string nargv;
  BODY
  ros::spin();
  return 0;
}
"""

LOAD = 'manager.load(ros::this_node::getName(), "viewer/view", remap, nargv);'

LAUNCH = """<launch>
  <node pkg="viewer" type="viewer" name="viewer">
    <param name="autosize" value="true"/>
  </node>
</launch>
"""


def test_a_nodelet_loaders_load_is_a_plugin_load_site(tmp_path: Any) -> None:
    ws = scan([str(tmp_path)])
    found = plugin_loads(str(tmp_path / "a.cpp"), WRAPPER.replace("BODY", LOAD), ws)
    assert [(d.code, d.location.line) for d in found] == [("CPP_PLUGINS_LOADED", 9)]
    # a load() in a file that names no nodelet Loader is someone else's (yaml, atomics)
    other = WRAPPER.replace("#include <nodelet/loader.h>\n", "").replace(
        "nodelet::Loader manager;", "Config manager;").replace("BODY", LOAD)
    assert plugin_loads(str(tmp_path / "a.cpp"), other, ws) == []
    # nor is a load() without arguments (std::atomic<T>::load())
    assert plugin_loads(str(tmp_path / "a.cpp"),
                        WRAPPER.replace("BODY", "int n = counter.load();"), ws) == []


def _run(write_tree: Any, body: str) -> tuple[Any, dict[str, list[tuple[str, ...]]]]:
    root = write_tree({
        "src/viewer/package.xml": PACKAGE,
        "src/viewer/CMakeLists.txt":
            "project(viewer)\nfind_package(catkin REQUIRED COMPONENTS roscpp nodelet)\n"
            "catkin_package()\nadd_executable(viewer src/viewer.cpp)\n",
        "src/viewer/src/viewer.cpp": WRAPPER.replace("BODY", body),
        "src/viewer/launch/viewer.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [viewer/launch/viewer.launch]\n",
    })
    return _analyse(root)


def _analyse(root: Any) -> tuple[Any, dict[str, list[tuple[str, ...]]]]:
    """The /viewer instance of the project at ``root``, and the findings by rule."""
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[tuple[str, ...]]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.entities)
    instance = next(n for n in model.configurations[0].nodes if n.name == "/viewer")
    return instance, found


def test_a_node_that_loads_a_nodelet_is_partial_and_does_not_decide(write_tree: Any) -> None:
    # its own name, but a class that no package here or model exports
    instance, found = _run(write_tree, LOAD)
    assert instance.completeness == "partial"
    assert instance.node.nodelets == ["viewer/view"] and not instance.node.plugin_loads
    assert "runs the class viewer/view" in instance.node.completeness_reasons[0]
    assert "parameter-set-not-read" not in found
    assert found["parameter-set-not-read" + UNDECIDED] == [("node:/viewer",)]


def test_a_load_under_another_name_stays_a_load_by_name(write_tree: Any) -> None:
    # image_proc's: each nodelet a node of its own beside the program's
    instance, found = _run(write_tree, LOAD.replace("ros::this_node::getName()",
                                                    'ros::this_node::getName() + "_x"'))
    assert instance.completeness == "partial" and not instance.node.nodelets
    assert instance.node.plugin_loads == ["viewer/src/viewer.cpp:9"]
    assert "parameter-set-not-read" not in found


def test_a_load_with_remappings_of_its_own_stays_a_load_by_name(write_tree: Any) -> None:
    # the nodelet's names remapped by the program's map first: not known here
    instance, _ = _run(write_tree, 'remap["image"] = "/other";\n  ' + LOAD)
    assert instance.completeness == "partial" and not instance.node.nodelets
    assert instance.node.plugin_loads == ["viewer/src/viewer.cpp:10"]


def test_the_same_node_without_the_load_decides(write_tree: Any) -> None:
    instance, found = _run(write_tree, "")
    assert instance.completeness == "complete" and not instance.node.plugin_loads
    assert found["parameter-set-not-read"] == [("parameter:/viewer/autosize",)]


NODELET = """#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>

namespace viewer {
class View : public nodelet::Nodelet {
  void onInit() override {
    bool autosize = false;
    getPrivateNodeHandle().param("autosize", autosize, false);
  }
};
}  // namespace viewer

PLUGINLIB_EXPORT_CLASS(viewer::View, nodelet::Nodelet)
"""


def test_a_wrapper_that_links_its_nodelet_runs_its_code(write_tree: Any) -> None:
    # pointcloud_to_laserscan_node: the executable links the nodelet's library, whose
    # calls are read with it; its load() hides nothing
    root = write_tree({
        "src/viewer/package.xml": PACKAGE.replace(
            "</package>", '<export><nodelet plugin="${prefix}/nodelets.xml"/></export>'
                          "</package>"),
        "src/viewer/nodelets.xml":
            '<library path="lib/libview"><class name="viewer/view" type="viewer::View" '
            'base_class_type="nodelet::Nodelet"/></library>\n',
        "src/viewer/CMakeLists.txt":
            "project(viewer)\nfind_package(catkin REQUIRED COMPONENTS roscpp nodelet)\n"
            "catkin_package()\nadd_library(view src/view.cpp)\n"
            "add_executable(viewer src/viewer.cpp)\ntarget_link_libraries(viewer view)\n",
        "src/viewer/src/view.cpp": NODELET,
        "src/viewer/src/viewer.cpp": WRAPPER.replace("BODY", LOAD),
        "src/viewer/launch/viewer.launch": LAUNCH.replace(
            '<param name="autosize" value="true"/>',
            '<param name="autosize" value="true"/><param name="autosise" value="1"/>'),
        "project.yaml": "project: p\nconfigurations:\n  c: [viewer/launch/viewer.launch]\n",
    })
    instance, found = _analyse(root)
    assert instance.completeness == "complete" and not instance.node.plugin_loads
    assert found["parameter-set-not-read"] == [("parameter:/viewer/autosise",)]


VIEW = """#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <sensor_msgs/Image.h>

namespace viewer {
class View : public nodelet::Nodelet {
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    bool autosize = false;
    getPrivateNodeHandle().param("autosize", autosize, false);
    std::string topic = nh.resolveName("image");
    sub_ = nh.subscribe(topic, 1, &View::onImage, this);
  }
  void onImage(const sensor_msgs::Image::ConstPtr& msg) {}
  ros::Subscriber sub_;
};
}  // namespace viewer

PLUGINLIB_EXPORT_CLASS(viewer::View, nodelet::Nodelet)
"""


def test_a_nodelet_run_under_the_nodes_name_gives_it_its_calls(write_tree: Any) -> None:
    # image_view's: the executable links no nodelet library, the package exports it
    root = write_tree({
        "src/viewer/package.xml": PACKAGE.replace(
            "</package>", '<export><nodelet plugin="${prefix}/nodelets.xml"/></export>'
                          "</package>"),
        "src/viewer/nodelets.xml":
            '<library path="lib/libview"><class name="viewer/view" type="viewer::View" '
            'base_class_type="nodelet::Nodelet"/></library>\n',
        "src/viewer/CMakeLists.txt":
            "project(viewer)\nfind_package(catkin REQUIRED COMPONENTS roscpp nodelet)\n"
            "catkin_package()\nadd_library(view src/view.cpp)\n"
            "add_executable(viewer src/viewer.cpp)\n",
        "src/viewer/src/view.cpp": VIEW,
        "src/viewer/src/viewer.cpp": WRAPPER.replace("BODY", LOAD.replace(
            "ros::this_node::getName()", "name")).replace(
            "nodelet::V_string nargv;",
            "nodelet::V_string nargv;\n  std::string name = ros::this_node::getName();"),
        "src/viewer/launch/viewer.launch": LAUNCH.replace(
            '<param name="autosize" value="true"/>',
            '<param name="autosize" value="true"/><param name="autosise" value="1"/>'
            '<remap from="image" to="/camera/image_raw"/>'),
        "project.yaml": "project: p\nconfigurations:\n  c: [viewer/launch/viewer.launch]\n",
    })
    instance, found = _analyse(root)
    assert instance.node.name == "viewer/viewer" and instance.node.nodelets == ["viewer/view"]
    assert instance.completeness == "complete" and not instance.node.plugin_loads
    assert sorted((link.kind, link.rosname.full) for link in instance.links) == [
        ("read", "/viewer/autosize"), ("subscribe", "/camera/image_raw")]
    assert found["parameter-set-not-read"] == [("parameter:/viewer/autosise",)]
