"""A component library's sources, narrowed to one class: its own files, the helper files
it names (a base class, a strategy it builds), not another component's helpers."""

from __future__ import annotations

from pathlib import Path

from haros_arch.plugins.classes import narrow
from haros_arch.workspace import scan

FILES = {
    "package.xml": "<package format='2'><name>pre</name><version>1.0.0</version>"
                   "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
                   "<license>BSD</license></package>",
    "include/pre/filter.hpp": "namespace pre { class Filter { public: Filter(); }; }\n",
    "include/pre/crop_box.hpp": '#include "pre/filter.hpp"\n'
                                "namespace pre { class CropBox : public Filter {}; }\n",
    "include/pre/concat.hpp": "namespace pre { class MatchingStrategy;\n"
                              "class Concat { MatchingStrategy * strategy_; }; }\n",
    "src/filter.cpp": '#include "pre/filter.hpp"\nnamespace pre {\nFilter::Filter() {}\n}\n',
    "src/matching.cpp": "namespace pre {\nvoid MatchingStrategy::match(int x) {}\n}\n",
    "src/util.cpp": "int clamp(int x) { return x; }\n",
    "src/crop_box.cpp": '#include "pre/crop_box.hpp"\n'
                        "int limit(int x) { return clamp(x); }\n"
                        "RCLCPP_COMPONENTS_REGISTER_NODE(pre::CropBox)\n",
    "src/test_utils.cpp": "void publish_mandatory_topics(int node) {\n}\n",
    "src/concat.cpp": '#include "pre/concat.hpp"\n'
                      "RCLCPP_COMPONENTS_REGISTER_NODE(pre::Concat)\n",
}
SOURCES = ["pre/src/filter.cpp", "pre/src/matching.cpp", "pre/src/util.cpp",
           "pre/src/test_utils.cpp", "pre/src/crop_box.cpp", "pre/src/concat.cpp"]


def test_a_component_keeps_the_helpers_it_names(tmp_path: Path) -> None:
    for name, text in FILES.items():
        path = tmp_path / "pre" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    # the base class's file (named in its header) and the free function it calls stay;
    # the other component's strategy and functions no file calls (test helpers) go
    assert narrow(SOURCES, "pre::CropBox", ws) == [
        "pre/src/filter.cpp", "pre/src/util.cpp", "pre/src/crop_box.cpp"]
    assert narrow(SOURCES, "pre::Concat", ws) == ["pre/src/matching.cpp", "pre/src/concat.cpp"]


def test_a_class_no_built_file_exports_has_no_sources(tmp_path: Path) -> None:
    """ouster_ros's OusterPcap: its description lists it with the library's other
    nodelets, but the file that exports it is added only under a CMake option that is
    off. The library's files export other classes: this one's code is not there, so
    its node has no source (its interface unknown, with a PLUGIN_CLASS_NOT_BUILT
    warning), not the helpers' calls (which made the parameters the launch file gives
    it 'set but never read')."""
    for name, text in FILES.items():
        path = tmp_path / "pre" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    assert narrow(SOURCES, "pre::Replay", ws) == []
    # a class template's specialisation, as its description and export name it
    # (nav2_behaviors::DriveOnHeading<>): its own file, not none (as the first version
    # of this rule had it)
    (tmp_path / "pre" / "src" / "heading.cpp").write_text(
        "PLUGINLIB_EXPORT_CLASS(pre::Heading<>, pre::Behavior)\n")
    assert narrow([*SOURCES, "pre/src/heading.cpp"], "pre::Heading<>", ws) == [
        "pre/src/heading.cpp"]
    # a library whose files export nothing: its classes keep the helpers (as before)
    assert narrow(["pre/src/filter.cpp", "pre/src/util.cpp"], "pre::Replay", ws) == [
        "pre/src/filter.cpp", "pre/src/util.cpp"]


def test_the_description_of_a_class_nobody_builds(write_tree) -> None:
    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    root = write_tree({
        "src/lidar/package.xml": (
            "<package format='2'><name>lidar</name><version>1.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
            "<license>BSD</license><buildtool_depend>catkin</buildtool_depend>"
            "<depend>nodelet</depend><export>"
            "<nodelet plugin='${prefix}/nodelets.xml'/></export></package>"),
        "src/lidar/CMakeLists.txt": (
            "project(lidar)\noption(BUILD_PCAP \"pcap\" OFF)\n"
            "set(SRC src/driver.cpp)\nif (BUILD_PCAP)\n  list(APPEND SRC src/pcap.cpp)\n"
            "endif()\nadd_library(lidar_nodelets ${SRC})\n"),
        "src/lidar/nodelets.xml": (
            "<library path='lib/liblidar_nodelets'>\n"
            "<class name='lidar/Driver' type='lidar::Driver' "
            "base_class_type='nodelet::Nodelet'/>\n"
            "<class name='lidar/Pcap' type='lidar::Pcap' "
            "base_class_type='nodelet::Nodelet'/>\n</library>\n"),
        "src/lidar/src/driver.cpp": (
            "#include <nodelet/nodelet.h>\n#include <pluginlib/class_list_macros.h>\n"
            "namespace lidar { class Driver : public nodelet::Nodelet {\n"
            "  void onInit() override { getPrivateNodeHandle().param(\"port\", port_, 7); }\n"
            "  int port_; }; }\nPLUGINLIB_EXPORT_CLASS(lidar::Driver, nodelet::Nodelet)\n"),
        "src/lidar/src/pcap.cpp": (
            "#include <nodelet/nodelet.h>\n#include <pluginlib/class_list_macros.h>\n"
            "namespace lidar { class Pcap : public nodelet::Nodelet {\n"
            "  void onInit() override { getPrivateNodeHandle().param(\"file\", f_, 0); }\n"
            "  int f_; }; }\nPLUGINLIB_EXPORT_CLASS(lidar::Pcap, nodelet::Nodelet)\n"),
        "src/lidar/launch/replay.launch": (
            "<launch>\n<node pkg='nodelet' type='nodelet' name='mgr' args='manager'/>\n"
            "<node pkg='nodelet' type='nodelet' name='pcap' args='load lidar/Pcap mgr'>\n"
            "  <param name='file' value='1'/>\n</node>\n</launch>\n"),
        "project.yaml": "project: p\nworkspace: src\nconfigurations:\n"
                        "  c: [lidar/launch/replay.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None))
    pcap = next(n for n in model.nodes if n.name == "lidar/lidar/Pcap")
    assert pcap.sources == [] and pcap.completeness == "unknown"
    driver = next(n for n in model.nodes if n.name == "lidar/lidar/Driver")
    assert driver.sources == ["lidar/src/driver.cpp"]
    assert "PLUGIN_CLASS_NOT_BUILT" in [d.code for d in model.diagnostics]


def test_an_export_macro_in_a_comment_exports_nothing(tmp_path: Path) -> None:
    """perception_pcl (ros2): pcl_ros' filter.cpp, the base class Filter's file (whose
    subscribe() and constructor make every filter's input / indices subscriptions and
    output publisher), keeps ``//PLUGINLIB_EXPORT_CLASS(PixelGrid,nodelet::Nodelet);``
    inside a block comment. Taken as exporting other classes, it was left out of every
    filter component: CropBox, PassThrough, VoxelGrid... had no input and no output. A
    component registered in a comment is no component either."""
    files = dict(FILES)
    files["src/filter.cpp"] = (
        '#include "pre/filter.hpp"\n/*//PLUGINLIB_EXPORT_CLASS(PixelGrid,nodelet::Nodelet);\n'
        "//PLUGINLIB_EXPORT_CLASS(Dimension, nodelet::Nodelet);*/\n"
        "namespace pre {\nFilter::Filter() {}  // RCLCPP_COMPONENTS_REGISTER_NODE(pre::Old)\n}\n"
        'const char * url = "http://x"; PLUGINLIB_EXPORT_CLASS(pre::Kept, pre::Base)\n')
    for name, text in files.items():
        path = tmp_path / "pre" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    from haros_arch.plugins.classes import exported_classes
    assert exported_classes(str(tmp_path / "pre" / "src" / "filter.cpp"), ws) == [
        ("pre::Kept", 7)]
    files["src/filter.cpp"] = files["src/filter.cpp"].rsplit("const char", 1)[0]
    (tmp_path / "pre" / "src" / "filter.cpp").write_text(files["src/filter.cpp"])
    ws = scan([str(tmp_path)])
    assert narrow(SOURCES, "pre::CropBox", ws) == [
        "pre/src/filter.cpp", "pre/src/util.cpp", "pre/src/crop_box.cpp"]
