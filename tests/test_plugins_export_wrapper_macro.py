"""A macro of the workspace that wraps pluginlib's export: swri_nodelet (marti_common)
defines ``SWRI_NODELET_EXPORT_CLASS(NS, CLASS)`` as ``PLUGINLIB_EXPORT_CLASS(NS::CLASS,
nodelet::Nodelet)`` plus a factory function, and swri_transform_util's and swri_nodelet's
own nodelets export themselves with it. Those files were read as exporting nothing, so
where the library's other file exports its class with pluginlib's macro (swri_transform_
util's DynamicPublisher) the two classes exported through the wrapper had no source
(PLUGIN_CLASS_NOT_BUILT, interface unknown), and swri_nodelet's TestNodelet lost its only
file as a helper no exported class names. The wrapper's invocation exports what its body
does, its parameters replaced by the arguments (``##`` pastes)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from haros_arch.plugins.classes import exported_classes
from haros_arch.workspace import scan

WRAPPER = """#ifndef TOOLS_CLASS_LIST_MACROS_H
#define TOOLS_CLASS_LIST_MACROS_H
#include <pluginlib/class_list_macros.h>
// TOOLS_EXPORT_CLASS(NS, CLASS): PLUGINLIB_EXPORT_CLASS(NS::CLASS, nodelet::Nodelet)
#define TOOLS_EXPORT_CLASS(NS, CLASS) PLUGINLIB_EXPORT_CLASS(NS::CLASS, nodelet::Nodelet);\\
namespace NS\\
{\\
  boost::shared_ptr<nodelet::Nodelet> create ## CLASS()\\
  {\\
    return boost::make_shared<CLASS>();\\
  }\\
}
#define TOOLS_PASTED(NAME) PLUGINLIB_EXPORT_CLASS(tools::NAME ## Nodelet, nodelet::Nodelet)
#endif
"""

PACKAGE = (
    "<package format='2'><name>tools</name><version>1.0.0</version>"
    "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
    "<license>BSD</license><buildtool_depend>catkin</buildtool_depend>"
    "<depend>nodelet</depend><depend>roscpp</depend><depend>std_msgs</depend><export>"
    "<nodelet plugin='${prefix}/nodelets.xml'/></export></package>")


def _nodelet(cls: str, topic: str, export: str, macros: str = "tools") -> str:
    return (
        "#include <nodelet/nodelet.h>\n#include <ros/ros.h>\n#include <std_msgs/Int32.h>\n"
        f"#include <{macros}/class_list_macros.h>\n#include <pluginlib/class_list_macros.h>\n"
        f"namespace tools {{ class {cls} : public nodelet::Nodelet {{\n"
        "  void onInit() override {\n"
        f'    pub_ = getNodeHandle().advertise<std_msgs::Int32>("{topic}", 1); }}\n'
        f"  ros::Publisher pub_; }}; }}\n{export}\n")


def test_a_wrapper_of_the_export_macro_exports(tmp_path: Path) -> None:
    root = tmp_path / "tools"
    (root / "include" / "tools").mkdir(parents=True)
    (root / "src").mkdir()
    (root / "package.xml").write_text(PACKAGE)
    (root / "include" / "tools" / "class_list_macros.h").write_text(WRAPPER)
    (root / "src" / "gps.cpp").write_text(
        _nodelet("Gps", "fix", "TOOLS_EXPORT_CLASS(tools, Gps)"))
    (root / "src" / "pasted.cpp").write_text(
        _nodelet("ImuNodelet", "imu", "TOOLS_PASTED(Imu)"))
    (root / "src" / "plain.cpp").write_text(_nodelet("Other", "other", "int x = 1;"))
    ws = scan([str(tmp_path)])
    assert exported_classes(str(root / "src" / "gps.cpp"), ws) == [("tools::Gps", 10)]
    assert exported_classes(str(root / "src" / "pasted.cpp"), ws) == [
        ("tools::ImuNodelet", 10)]
    assert exported_classes(str(root / "src" / "plain.cpp"), ws) == []
    # the header defines the macros; it exports no class of its own
    assert exported_classes(str(root / "include" / "tools" / "class_list_macros.h"), ws) == []


def test_a_known_export_macro_defined_in_the_workspace(tmp_path: Path) -> None:
    """mavros defines its own ``MAVROS_PLUGIN_REGISTER(PluginClass)`` as a class loader
    registration of ``PluginFactoryTemplate<PluginClass>``; its invocations name the
    plugin class as they are read (``_EXPORT``), not the factory of its expansion."""
    root = tmp_path / "mav"
    (root / "include" / "mav").mkdir(parents=True)
    (root / "src").mkdir()
    (root / "package.xml").write_text(PACKAGE.replace("tools", "mav"))
    (root / "include" / "mav" / "register.hpp").write_text(
        "#define MAVROS_PLUGIN_REGISTER(PluginClass) \\\n"
        "  CLASS_LOADER_REGISTER_CLASS( \\\n"
        "    mav::Factory<PluginClass>, \\\n"
        "    mav::FactoryBase)\n")
    (root / "src" / "gps.cpp").write_text(
        "#include <mav/register.hpp>\nnamespace mav { class Gps {}; }\n"
        "MAVROS_PLUGIN_REGISTER(mav::Gps)\n")
    ws = scan([str(tmp_path)])
    assert exported_classes(str(root / "src" / "gps.cpp"), ws) == [("mav::Gps", 3)]
    assert exported_classes(str(root / "include" / "mav" / "register.hpp"), ws) == []


def test_nodelets_exported_through_the_wrapper_have_their_code(write_tree: Any) -> None:
    """The wrapper in another package of the workspace (swri_transform_util's nodelets
    include ``<swri_nodelet/class_list_macros.h>``)."""
    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    root = write_tree({
        "src/macros/package.xml": PACKAGE.replace("<name>tools</name>",
                                                  "<name>macros</name>").replace(
            "<export><nodelet plugin='${prefix}/nodelets.xml'/></export>", ""),
        "src/macros/CMakeLists.txt": "project(macros)\nfind_package(catkin REQUIRED)\n",
        "src/macros/include/macros/class_list_macros.h": WRAPPER,
        "src/tools/package.xml": PACKAGE,
        "src/tools/CMakeLists.txt": (
            "project(tools)\nfind_package(catkin REQUIRED roscpp nodelet std_msgs)\n"
            "include_directories(include)\n"
            "add_library(tools_nodelets src/dynamic.cpp src/gps.cpp)\n"
            "add_library(tools_test src/test.cpp)\n"),
        "src/tools/nodelets.xml": (
            "<library path='lib/libtools_nodelets'>\n"
            "<class name='tools/dynamic' type='tools::Dynamic' "
            "base_class_type='nodelet::Nodelet'/>\n"
            "<class name='tools/gps' type='tools::Gps' "
            "base_class_type='nodelet::Nodelet'/>\n</library>\n"
            "<library path='lib/libtools_test'>\n"
            "<class name='tools/Test' type='tools::Test' "
            "base_class_type='nodelet::Nodelet'/>\n</library>\n"),
        "src/tools/src/dynamic.cpp": _nodelet(
            "Dynamic", "tf", "PLUGINLIB_EXPORT_CLASS(tools::Dynamic, nodelet::Nodelet)",
            "macros"),
        "src/tools/src/gps.cpp": _nodelet("Gps", "fix", "TOOLS_EXPORT_CLASS(tools, Gps)",
                                          "macros"),
        "src/tools/src/test.cpp": _nodelet("Test", "count", "TOOLS_EXPORT_CLASS(tools, Test)",
                                           "macros"),
        "src/tools/launch/tools.launch": (
            "<launch>\n<node pkg='nodelet' type='nodelet' name='mgr' args='manager'/>\n"
            "<node pkg='nodelet' type='nodelet' name='gps' args='load tools/gps mgr'/>\n"
            "<node pkg='nodelet' type='nodelet' name='test' args='load tools/Test mgr'/>\n"
            "</launch>\n"),
        "project.yaml": "project: p\nworkspace: src\ndistro: noetic\nconfigurations:\n"
                        "  c: [tools/launch/tools.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    assert "PLUGIN_CLASS_NOT_BUILT" not in [d.code for d in model.diagnostics]
    gps = next(n for n in model.nodes if n.name == "tools/tools/gps")
    assert gps.sources == ["tools/src/gps.cpp"]
    test = next(n for n in model.nodes if n.name == "tools/tools/Test")
    assert test.sources == ["tools/src/test.cpp"]
    (config,) = model.configurations
    assert sorted(t.name for t in config.topics) == ["/count", "/fix"]
