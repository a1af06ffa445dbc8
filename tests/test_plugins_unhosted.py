"""A node whose code creates plugin instances by name (pluginlib) makes calls that are not
in its code. Unless it is a host whose plugins the graph attaches, each instance of it
is partial, so a check that claims an absence does not decide on it (Autoware's
motion_velocity_planner loads its modules so, and they read its parameters)."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.extract import completeness
from haros_arch.extract.cpp import library_loads, plugin_loads
from haros_arch.model.source import Node
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.query.catalogue import UNDECIDED
from haros_arch.workspace import scan


def test_the_sites_that_create_plugin_instances_are_found(tmp_path: Any) -> None:
    text = (
        "#include <pluginlib/class_loader.hpp>\n"
        "void load(Loader & loader, const std::string & name) {\n"
        "  auto a = loader_.createSharedInstance(name);\n"
        "  // auto b = loader_.createSharedInstance(name);\n"
        "  auto c = loader_ptr_->createUniqueInstance(name);\n"
        "  Module * d = loader.template createUnmanagedInstance<Module>(name);\n"
        "  auto e = createInstance(name);  // a function of its own, not a loader's\n"
        "}\n")
    ws = scan([str(tmp_path)])
    found = plugin_loads(str(tmp_path / "a.cpp"), text, ws)
    assert [(d.code, d.location.line) for d in found] == [
        ("CPP_PLUGINS_LOADED", 3), ("CPP_PLUGINS_LOADED", 5), ("CPP_PLUGINS_LOADED", 6)]
    # the loader declared in a header (a member): the names of its own are enough, but
    # without pluginlib or class_loader in the file, a createInstance is another's
    text = text.replace("#include <pluginlib/class_loader.hpp>\n", "").replace(
        "createSharedInstance", "createInstance")
    assert [d.location.line for d in plugin_loads(str(tmp_path / "a.cpp"), text, ws)] == [4, 5]


NODE = """
    #include <memory>
    #include <string>
    #include <vector>
    #include <pluginlib/class_loader.hpp>
    #include <rclcpp/rclcpp.hpp>

    namespace planner {
    class Module {
     public:
      virtual ~Module() = default;
      virtual void init(rclcpp::Node & node, const std::string & name) = 0;
    };

    class PlannerNode : public rclcpp::Node {
     public:
      PlannerNode() : Node("planner"), loader_("planner", "planner::Module") {
        rate_ = declare_parameter<double>("rate", 10.0);
        LOAD
      }
     private:
      pluginlib::ClassLoader<Module> loader_;
      std::vector<std::shared_ptr<Module>> modules_;
      double rate_;
    };
    }  // namespace planner

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<planner::PlannerNode>());
    }
    """

LOAD = """
        for (const auto & name : declare_parameter<std::vector<std::string>>(
                 "modules", std::vector<std::string>{})) {
          auto module = loader_.createSharedInstance(name);
          module->init(*this, name);
          modules_.push_back(module);
        }
"""

LAUNCH = """
    <launch>
      <node pkg="planner" exec="planner_node" name="planner">
        <param name="rate" value="5.0"/>
        <param name="modules" value="[stop]"/>
        <param name="stop.margin" value="2.0"/>
      </node>
    </launch>
    """


def _run(write_tree: Any, load_code: str) -> tuple[Any, dict[str, list[tuple[str, ...]]]]:
    root = write_tree({
        "src/planner/package.xml": package_xml("planner", build_type="ament_cmake"),
        "src/planner/CMakeLists.txt":
            "project(planner)\nadd_executable(planner_node src/planner_node.cpp)\n"
            "install(TARGETS planner_node DESTINATION lib/${PROJECT_NAME})\n",
        "src/planner/src/planner_node.cpp": NODE.replace("LOAD", load_code),
        "src/planner/launch/planner.launch.xml": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [planner/launch/planner.launch.xml]\n",
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found: dict[str, list[tuple[str, ...]]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.entities)
    instance = next(n for n in model.configurations[0].nodes if n.name == "/planner")
    return instance, found


def test_a_node_that_loads_plugins_no_host_attaches_is_partial(write_tree: Any) -> None:
    instance, found = _run(write_tree, LOAD)
    assert instance.completeness == "partial"
    assert any("loads plugin classes by name" in r
               for r in instance.completeness_reasons)
    assert instance.node.plugin_loads == ["planner/src/planner_node.cpp:21"]
    # stop.margin is the module's: not called unread, counted as undecided
    assert "parameter-set-not-read" not in found
    assert found["parameter-set-not-read" + UNDECIDED] == [("node:/planner",)]


def test_the_same_node_without_plugins_decides(write_tree: Any) -> None:
    instance, found = _run(write_tree, 'declare_parameter<std::vector<std::string>>('
                                       '"modules", std::vector<std::string>{});')
    assert instance.completeness == "complete" and not instance.node.plugin_loads
    assert found["parameter-set-not-read"] == [("parameter:/planner/stop.margin",)]


def test_a_shared_library_opened_by_name_makes_the_node_partial(tmp_path: Any) -> None:
    """MOLA's mola-cli dlopen()s the modules its YAML file lists (its ROS 2 bridge
    among them), in mola_launcher's MolaDLL_Loader.cpp: the node was complete with no
    ROS call, and rviz's displays of the bridge's topics "showed nothing" (4 false
    infos). A dlopen / LoadLibrary call (not a comment, not a method of that name) is
    CPP_LIBRARY_LOADED, a cause of partial."""
    text = (
        "#include <dlfcn.h>\n"
        "void load(const std::string & path) {\n"
        "  void * handle = dlopen(path.c_str(), RTLD_LAZY);\n"
        "  // dlopen(path.c_str(), RTLD_NOW);\n"
        "  HMODULE other = LoadLibrary(path.c_str());\n"
        "  auto same = ::dlopen(nullptr, RTLD_NOLOAD);\n"
        "  loader.dlopen(path);\n"
        "}\n")
    ws = scan([str(tmp_path)])
    assert [(d.code, d.location.line) for d in library_loads(
        str(tmp_path / "a.cpp"), text, ws)] == [
        ("CPP_LIBRARY_LOADED", 3), ("CPP_LIBRARY_LOADED", 5), ("CPP_LIBRARY_LOADED", 6)]
    node = Node("pkg", "cli", language="cpp", sources=["pkg/src/a.cpp"])
    found = library_loads(str(tmp_path / "a.cpp"), text, ws)
    completeness(node, found)
    assert node.completeness == "partial"
    assert node.completeness_reasons[0].endswith(
        "void * handle = dlopen(path.c_str(), RTLD_LAZY);: loads a shared library chosen "
        "at run time")


VENDOR_NODE = """
    #include <dlfcn.h>
    #include <string>
    #include <ros/ros.h>
    #include "arm/api.h"

    int main(int argc, char ** argv) {
      ros::init(argc, argv, "arm");
      ros::NodeHandle nh("~");
      void * usb = dlopen(ARM_USB_LIBRARY, RTLD_NOW | RTLD_GLOBAL);
      void * comm = dlopen("libArm.API.Comm.so", RTLD_NOW);
      OTHER
      ros::Publisher angles = nh.advertise<std_msgs::String>("out/joint_angles", 2);
      ros::spin();
    }
    """


def _vendor_run(write_tree: Any, other: str, cmake: str = "") -> Any:
    root = write_tree({
        "src/arm/package.xml": package_xml("arm", build_type="catkin"),
        "src/arm/CMakeLists.txt":
            "project(arm)\nadd_executable(arm_driver src/arm_driver.cpp)\n" + cmake,
        "src/arm/include/arm/api.h": '#define ARM_USB_LIBRARY "Arm.API.USBCommandLayer.so"\n',
        "src/arm/src/arm_driver.cpp": VENDOR_NODE.replace("OTHER", other),
        "src/arm/launch/arm.launch": '<launch><node pkg="arm" type="arm_driver" name="arm"/>'
                                     '</launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return next(n for n in model.configurations[0].nodes if n.name == "/arm")


def test_a_vendor_library_the_code_names_is_no_plugin(write_tree: Any) -> None:
    """kinova_arm_driver dlopen()s Kinova's USB API by a macro of a file name
    (``#define KINOVA_USB_LIBRARY "Kinova.API.USBCommandLayerUbuntu.so"``): a vendor's
    library, as any it links, not modules chosen at run time. It made the driver partial,
    and the tf updater's subscription to a topic the driver does not publish (a wrong
    remap) undecided. A library named so that the workspace builds, or one named by a
    value, still makes the node partial."""
    instance = _vendor_run(write_tree, "")
    assert instance.completeness == "complete", instance.completeness_reasons
    instance = _vendor_run(write_tree, "", "add_library(Arm.API.Comm src/comm.cpp)\n")
    assert instance.completeness == "partial"
    assert [r for r in instance.completeness_reasons if "dlopen(\"libArm" in r]
    instance = _vendor_run(write_tree, "void * more = dlopen(argv[1], RTLD_NOW);")
    assert instance.completeness == "partial"
    assert [r for r in instance.completeness_reasons if "dlopen(argv[1]" in r]


def test_a_load_in_code_the_preprocessor_leaves_out_is_no_load(write_tree: Any) -> None:
    """vectornav's SDK, vendored in riptide_imu, compiles dllvalidator.cpp whole under
    ``#if defined WIN32 && defined DLL_VALIDATOR``: its ``LoadLibraryEx`` of each DLL a
    Windows binary needs is no code of a Linux build, yet it made the IMU node partial
    (CPP_LIBRARY_LOADED, CPP_NODE_PARTIAL). The same load in code that is built still
    counts."""
    skipped = ("\n#if defined WIN32 && defined DLL_VALIDATOR\n"
               "      void * dll = LoadLibraryEx(argv[1], NULL, 0);\n#endif\n")
    instance = _vendor_run(write_tree, skipped)
    assert instance.completeness == "complete", instance.completeness_reasons
    instance = _vendor_run(write_tree, skipped.replace("defined WIN32 &&", "1 ||"))
    assert instance.completeness == "partial"
    assert [r for r in instance.completeness_reasons if "LoadLibraryEx(argv[1]" in r], \
        instance.completeness_reasons


LOADER = """
    void * load(const char * library, int flags) {
      return dlopen(library, RTLD_NOW | flags);
    }

    int main("""


def test_a_vendor_library_named_by_the_callers_of_the_loading_function(
        write_tree: Any) -> None:
    """A later kinova_arm_driver dlopen()s ``command_lib``, a parameter of its
    ``loadLibraries(const char *command_lib, const char *comm_lib)``, which its file calls
    with the macros of Kinova's USB or Ethernet API: the libraries the calls name, a
    vendor's, as a load that names them itself. It kept the driver partial (kinova-ros
    f014f5e undecided). A call that passes a value, or a library the workspace builds,
    keeps it so."""
    def run(calls: str, cmake: str = "", header: str = "#include <dlfcn.h>",
            other: str = "") -> Any:
        node = VENDOR_NODE.replace("int main(", LOADER).replace("#include <dlfcn.h>", header)
        root = write_tree({
            "src/arm/src/other.cpp": other,
            "src/arm/package.xml": package_xml("arm", build_type="catkin"),
            "src/arm/CMakeLists.txt":
                "project(arm)\nadd_executable(arm_driver src/arm_driver.cpp)\n" + cmake,
            "src/arm/include/arm/api.h":
                '#define ARM_USB_LIBRARY "Arm.API.USBCommandLayer.so"\n',
            "src/arm/src/arm_driver.cpp": node.replace("OTHER", calls),
            "src/arm/launch/arm.launch":
                '<launch><node pkg="arm" type="arm_driver" name="arm"/></launch>\n',
            "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch]\n",
        })
        model = analyse(load(str(root / "project.yaml")),
                        {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
        return next(n for n in model.configurations[0].nodes if n.name == "/arm")

    both = 'load(ARM_USB_LIBRARY, RTLD_NOW); load("libArm.API.Comm.so", RTLD_NOW);'
    instance = run(both)
    assert instance.completeness == "complete", instance.completeness_reasons
    # without <dlfcn.h> (kinova's parse dropped its loads' statements, read then off the
    # function's parameters; here the names the synthesis declares keep it)
    instance = run(both.replace("RTLD_NOW", "2"), header="")
    assert instance.completeness == "complete", instance.completeness_reasons
    instance = run(both + " load(argv[1], RTLD_NOW);")
    assert instance.completeness == "partial"
    assert [r for r in instance.completeness_reasons if "dlopen(library" in r]
    instance = run(both, "add_library(Arm.API.Comm src/comm.cpp)\n")
    assert instance.completeness == "partial"
    instance = run("")  # no call in the file: another may pass anything
    assert instance.completeness == "partial"
    # another source of the package calls it: with what, this unit does not see
    instance = run(both, other="void * load(const char *, int);\n"
                               "void * again(const char * name) { return load(name, 0); }\n")
    assert instance.completeness == "partial"
