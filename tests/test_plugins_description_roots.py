"""A plugin description with several top-level <library> elements (pointcloud_to_laserscan's
nodelets.xml, ROS 1): not well-formed XML, but pluginlib reads the first element and the
<library> elements after it, so every class is there; a file broken otherwise is still
PLUGIN_XML_SYNTAX at its line."""

from __future__ import annotations

PACKAGE = (
    "<package format='2'><name>conv</name><version>1.0.0</version>"
    "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
    "<license>BSD</license><buildtool_depend>catkin</buildtool_depend>"
    "<depend>nodelet</depend><export>"
    "<nodelet plugin='${prefix}/nodelets.xml'/></export></package>")
CMAKE = ("project(conv)\nadd_library(to_scan src/to_scan.cpp)\n"
         "add_library(to_cloud src/to_cloud.cpp)\n")
TWO_ROOTS = (
    "<?xml version='1.0'?>\n"
    "<library path='lib/libto_scan'>\n"
    "  <class name='conv/to_scan' type='conv::ToScan' base_class_type='nodelet::Nodelet'/>\n"
    "</library>\n\n"
    "<library path='lib/libto_cloud'>\n"
    "  <class name='conv/to_cloud' type='conv::ToCloud' base_class_type='nodelet::Nodelet'/>\n"
    "</library>\n")
SOURCE = (
    "#include <nodelet/nodelet.h>\n#include <pluginlib/class_list_macros.h>\n"
    "#include <sensor_msgs/LaserScan.h>\n"
    "namespace conv {{ class {cls} : public nodelet::Nodelet {{\n"
    "  void onInit() override {{\n"
    "    pub_ = getNodeHandle().advertise<sensor_msgs::LaserScan>(\"{topic}\", 1); }}\n"
    "  ros::Publisher pub_; }}; }}\nPLUGINLIB_EXPORT_CLASS(conv::{cls}, nodelet::Nodelet)\n")
LAUNCH = (
    "<launch>\n<node pkg='nodelet' type='nodelet' name='mgr' args='manager'/>\n"
    "<node pkg='nodelet' type='nodelet' name='cloud' args='load conv/to_cloud mgr'/>\n"
    "<node pkg='nodelet' type='nodelet' name='scan' args='load conv/to_scan mgr'/>\n"
    "</launch>\n")


def _analyse(write_tree, description: str):
    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    root = write_tree({
        "src/conv/package.xml": PACKAGE,
        "src/conv/CMakeLists.txt": CMAKE,
        "src/conv/nodelets.xml": description,
        "src/conv/src/to_scan.cpp": SOURCE.format(cls="ToScan", topic="scan"),
        "src/conv/src/to_cloud.cpp": SOURCE.format(cls="ToCloud", topic="cloud"),
        "src/conv/launch/both.launch": LAUNCH,
        "project.yaml": "project: p\nworkspace: src\nconfigurations:\n"
                        "  c: [conv/launch/both.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None))


def test_every_top_level_library_of_a_description_is_read(write_tree) -> None:
    model = _analyse(write_tree, TWO_ROOTS)
    codes = [d.code for d in model.diagnostics]
    assert "PLUGIN_XML_SYNTAX" not in codes
    nodes = {n.name: n for n in model.nodes}
    assert nodes["conv/conv/to_scan"].sources == ["conv/src/to_scan.cpp"]
    assert nodes["conv/conv/to_cloud"].sources == ["conv/src/to_cloud.cpp"]
    assert (nodes["conv/conv/to_scan"].location.line,
            nodes["conv/conv/to_cloud"].location.line) == (3, 7)  # lines kept
    assert "LAUNCH_NODE_NOT_FOUND" not in codes


def test_a_description_broken_otherwise_is_still_an_error_at_its_line(write_tree) -> None:
    broken = TWO_ROOTS.replace("</library>\n\n", "</libary>\n\n")
    model = _analyse(write_tree, broken)
    errors = [d for d in model.diagnostics if d.code == "PLUGIN_XML_SYNTAX"]
    assert [(d.location.file, d.location.line) for d in errors] == [("conv/nodelets.xml", 4)]
    assert not [n for n in model.nodes if n.name.startswith("conv/conv/")]
