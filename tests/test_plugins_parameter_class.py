"""A node whose own code loads one plugin class through pluginlib's ClassLoader, the class
named by the value of a parameter it reads (slam_toolbox's ``solver_plugin``, default
``solver_plugins::CeresSolver``, ``solver_loader_.createSharedInstance(solver_plugin)``
then ``solver_->Configure(node)``): the class the configuration sets, or the default,
makes its calls on the node. It was partial ("loads plugin classes by name whose calls
are not known here") and the plugin's parameters were read by nobody. A class written
in the code makes its calls too (where the load runs whenever the code does); a
parameter's value naming a class no package exports stays partial."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

SOLVER_H = """
    #pragma once
    #include <rclcpp/rclcpp.hpp>
    namespace demo {
    class Solver {
     public:
      virtual ~Solver() {}
      virtual void configure(rclcpp::Node::SharedPtr node) = 0;
    };
    }  // namespace demo
    """

FAST = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/int32.hpp>
    #include <pluginlib/class_list_macros.hpp>
    #include "demo/solver.hpp"
    namespace demo {
    class FastSolver : public Solver {
     public:
      void configure(rclcpp::Node::SharedPtr node) override {
        node->declare_parameter("fast_gain", 1.0);
        pub_ = node->create_publisher<std_msgs::msg::Int32>("solver_status", 10);
      }
     private:
      rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
    };
    }  // namespace demo
    PLUGINLIB_EXPORT_CLASS(demo::FastSolver, demo::Solver)
    """

HOST = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <pluginlib/class_loader.hpp>
    #include "demo/solver.hpp"

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("host");
      pluginlib::ClassLoader<demo::Solver> loader("demo", "demo::Solver");
      std::string solver_plugin = std::string("demo::FastSolver");
      if (!node->has_parameter("solver_plugin")) {
        node->declare_parameter("solver_plugin", solver_plugin);
      }
      solver_plugin = node->get_parameter("solver_plugin").as_string();
      std::shared_ptr<demo::Solver> solver = LOAD;
      solver->configure(node);
      rclcpp::spin(node);
    }
    """

PLUGINS_XML = """
    <library path="fast_solver">
      <class name="demo::FastSolver" type="demo::FastSolver" base_class_type="demo::Solver">
        <description>fast</description>
      </class>
    </library>
    """

LAUNCH = """
    <launch>
      <node pkg="demo" exec="host" name="host">
        {params}
      </node>
    </launch>
    """


def _analyse(write_tree: Any, params: str = "",
             load_call: str = "loader.createSharedInstance(solver_plugin)",
             host: str | None = None) -> tuple[Any, Any]:
    manifest = package_xml("demo", "ament_cmake").replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("rclcpp", "pluginlib", "std_msgs")) + "</package>")
    root = write_tree({
        "src/demo/package.xml": manifest,
        "src/demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(pluginlib REQUIRED)\nfind_package(std_msgs REQUIRED)\n"
            "include_directories(include)\n"
            "add_library(fast_solver SHARED src/fast_solver.cpp)\n"
            "ament_target_dependencies(fast_solver rclcpp pluginlib std_msgs)\n"
            "pluginlib_export_plugin_description_file(demo plugins.xml)\n"
            "add_executable(host src/host.cpp)\n"
            "ament_target_dependencies(host rclcpp pluginlib)\n"
            "install(TARGETS fast_solver host DESTINATION lib/${PROJECT_NAME})\n"
            "ament_package()\n"),
        "src/demo/plugins.xml": PLUGINS_XML,
        "src/demo/include/demo/solver.hpp": SOLVER_H,
        "src/demo/src/fast_solver.cpp": FAST,
        "src/demo/src/host.cpp": (host or HOST).replace("LOAD", load_call),
        "src/demo/launch/demo.launch.xml": LAUNCH.format(params=params),
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: jazzy\nconfigurations:\n"
                         "  c: [demo/launch/demo.launch.xml]\n"),
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    return model, model.configurations[0]


def _links(config: Any, node: str) -> set[tuple[str, str]]:
    return {(link.kind, link.name) for link in config.links if link.node.name == node}


def test_the_default_class_makes_its_calls_on_the_node(write_tree: Any) -> None:
    model, config = _analyse(write_tree)
    node = next(n for p in model.packages for n in p.nodes if n.name == "demo/host")
    assert not node.plugin_loads, node.plugin_loads
    assert [n.name for p in model.packages for n in p.nodes if n.kind == "plugin"] == [
        "demo/demo::FastSolver"]
    assert node.completeness == "complete", node.completeness_reasons
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "complete", instance.completeness_reasons
    links = _links(config, "/host")
    assert ("read", "/host/solver_plugin") in links
    assert ("publish", "/solver_status") in links
    assert ("read", "/host/fast_gain") in links  # a declaration links as a read


DECLARED_APART = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <pluginlib/class_loader.hpp>
    #include "demo/solver.hpp"

    void declare_if_not_declared(rclcpp::Node::SharedPtr node, const std::string & name,
                                 const rclcpp::ParameterValue & value) {
      if (!node->has_parameter(name)) {
        node->declare_parameter(name, value);
      }
    }

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("host");
      pluginlib::ClassLoader<demo::Solver> loader("demo", "demo::Solver");
      declare_if_not_declared(node, "solver_plugin",
                              rclcpp::ParameterValue(std::string("demo::FastSolver")));
      std::string solver_plugin;
      node->get_parameter("solver_plugin", solver_plugin);
      std::shared_ptr<demo::Solver> solver = LOAD;
      solver->configure(node);
      rclcpp::spin(node);
    }
    """


def test_the_default_a_separate_declaration_gives_names_the_class(write_tree: Any) -> None:
    """navigation2's DWB (2023) declares ``<name>.trajectory_generator_name`` with its
    default through ``declare_parameter_if_not_declared`` and reads it into a local with
    ``get_parameter(name, out)``, which has no default of its own: the declaration's is
    the class loaded (was: partial, "not set and has no default")."""
    _model, config = _analyse(write_tree, host=DECLARED_APART)
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "complete", instance.completeness_reasons
    assert ("publish", "/solver_status") in _links(config, "/host")


def test_the_class_the_launch_sets_is_loaded_and_one_not_found_is_said(
        write_tree: Any) -> None:
    _, config = _analyse(write_tree, '<param name="solver_plugin" value="demo::FastSolver"/>')
    assert ("publish", "/solver_status") in _links(config, "/host")
    _, config = _analyse(write_tree, '<param name="solver_plugin" value="other::Slow"/>')
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "partial"
    assert ("publish", "/solver_status") not in _links(config, "/host")
    assert any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics)


def test_a_class_written_in_the_code_makes_its_calls_on_the_node(write_tree: Any) -> None:
    # ``createSharedInstance("demo::FastSolver")``, run whenever the node runs: the class
    # is known (CPP_PLUGIN_IN_PROCESS), read as a plugin node, and its calls are the
    # node's; the load is no cause of partial
    model, config = _analyse(
        write_tree, load_call='loader.createSharedInstance("demo::FastSolver")')
    node = next(n for p in model.packages for n in p.nodes if n.name == "demo/host")
    assert not node.plugin_loads and node.nodelets == ["demo::FastSolver"]
    assert [n.name for p in model.packages for n in p.nodes if n.kind == "plugin"] == [
        "demo/demo::FastSolver"]
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "complete", instance.completeness_reasons
    assert {("publish", "/solver_status"), ("read", "/host/fast_gain")} <= _links(
        config, "/host")


def test_a_class_written_in_the_code_under_a_condition_or_not_exported_stays_partial(
        write_tree: Any) -> None:
    # under an ``if`` the class may not be loaded: a load by name as before
    model, config = _analyse(write_tree, load_call=(
        'argc > 1 ? loader.createSharedInstance("demo::FastSolver") : nullptr'))
    node = next(n for p in model.packages for n in p.nodes if n.name == "demo/host")
    assert node.plugin_loads and not node.nodelets
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "partial"
    # a class no package exports: the instance is partial for it
    _, config = _analyse(write_tree, load_call='loader.createSharedInstance("other::Slow")')
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "partial"
    assert any("other::Slow" in reason for reason in instance.completeness_reasons)


def test_a_modelled_node_loads_the_class_of_its_own_package_from_the_model(
        tmp_path: Any) -> None:
    """slam_toolbox installed: its model's node reads ``solver_plugin`` to load a class
    whose namespace (``solver_plugins``) names no package; it is the model's own
    package's plugin node, whose parameters are then read on the node."""
    import json

    from haros_arch.graph import build
    from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
    from haros_arch.model import Configuration
    from haros_arch.model.source import Package
    from haros_arch.models.attach import Attacher
    from haros_arch.models.library import Library
    from haros_arch.workspace import Workspace

    where = {"package": "slam", "file": "slam/src/a.cpp", "line": 3, "column": 1}
    path = tmp_path / "slam.json"
    path.write_text(json.dumps({"schema": "haros-arch-model/1", "package": "slam",
                                "distro": "jazzy", "nodes": [
        {"package": "slam", "executable": "slam_node", "calls": [
            {"kind": "read", "name": "solver_plugin", "type": "str", "has_default": True,
             "default": "solvers::Ceres", "loads": "pluginlib", "location": where}]},
        {"package": "slam", "executable": "solvers::Ceres", "kind": "plugin",
         "plugin_class": "solvers::Ceres", "calls": [
             {"kind": "declare", "name": "ceres_loss", "type": "str", "has_default": True,
              "location": where}]}]}))

    def links(params: list[ParamDecl]) -> tuple[Any, set[tuple[str, str]]]:
        launch = LaunchModel(nodes=[NodeDecl("/slam", "slam", "slam_node", ros_version=2)],
                             params=params)
        packages: list[Package] = []
        attacher = Attacher(Library([str(path)], shipped=None), "jazzy", packages)
        config = Configuration("c")
        workspace = Workspace(root=str(tmp_path))
        nodes = attacher.nodes_for(launch, workspace, {}, {}, config.diagnostics)
        build(config, launch, workspace, nodes, attacher.plugin_models(launch, {}))
        return config, {(link.kind, link.resource.name) for link in config.links}

    config, found = links([])
    assert ("read", "/slam/ceres_loss") in found, found
    assert not [d for d in config.diagnostics if d.code.startswith("PLUGIN")]
    config, found = links([ParamDecl("/slam/solver_plugin", "solvers::Other")])
    assert ("read", "/slam/ceres_loss") not in found
    assert [d for d in config.diagnostics if d.code == "PLUGIN_NOT_FOUND"]


# slam_toolbox's shape: the base class's header is of a library the parse does not have
# (its names declared permissively), the loader a member beside the object, the object's
# class written only as that base; the topic's name a member written twice in one method
VENDOR_HOST = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/int32.hpp>
    #include <pluginlib/class_loader.hpp>
    #include <vendor/solver.h>

    class Host : public rclcpp::Node {
     public:
      Host() : Node("host"), loader_("demo", "vendor::Solver") {}
      void setParams() {
        map_name_ = std::string("/map");
        if (!has_parameter("map_name")) {
          declare_parameter("map_name", map_name_);
        }
        map_name_ = get_parameter("map_name").as_string();
      }
      void setInterfaces() {
        pub_ = create_publisher<std_msgs::msg::Int32>(map_name_, 1);
      }
      void setSolver() {
        std::string solver_plugin = std::string("demo::FastSolver");
        if (!has_parameter("solver_plugin")) {
          declare_parameter("solver_plugin", solver_plugin);
        }
        solver_plugin = get_parameter("solver_plugin").as_string();
        solver_ = loader_.createSharedInstance(solver_plugin);
        solver_->Configure(shared_from_this());
      }
     private:
      std::string map_name_;
      pluginlib::ClassLoader<vendor::Solver> loader_;
      std::shared_ptr<vendor::Solver> solver_;
      rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
    };

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<Host>();
      node->setParams();
      node->setInterfaces();
      node->setSolver();
      rclcpp::spin(node);
    }
    """


def test_a_method_of_the_loaded_object_hides_nothing_and_a_member_holds_the_parameter(
        write_tree: Any) -> None:
    global HOST
    kept = HOST
    HOST = VENDOR_HOST
    try:
        model, config = _analyse(write_tree, '<param name="map_name" value="/grid"/>')
    finally:
        HOST = kept
    node = next(n for p in model.packages for n in p.nodes if n.name == "demo/host")
    assert node.completeness == "complete", node.completeness_reasons
    assert not [d for d in model.diagnostics if d.code == "CPP_NODE_TO_UNKNOWN"]
    links = _links(config, "/host")
    assert ("publish", "/grid") in links  # the parameter's value, not ``?``
    assert ("publish", "/solver_status") in links


def test_a_host_rows_own_slot_is_left_to_the_row() -> None:
    """move_base reads ``base_local_planner`` and creates that class through a ClassLoader
    (a read marked ``loads``): the host row attaches it with the plugin name it
    initialises it with; loaded again by the read, its names were ``~?/...``."""
    from haros_arch.model.runtime import NodeInstance
    from haros_arch.model.source import Node
    from haros_arch.plugins.attach import _host_slot_reads

    host = NodeInstance("/move_base", Node("move_base", "move_base", sources=["a.cpp"]))
    assert _host_slot_reads(host, "/move_base/base_local_planner")
    assert not _host_slot_reads(host, "/move_base/other_plugin")
    assert not _host_slot_reads(host, "/move_base_extra/base_local_planner")
    other = NodeInstance("/slam", Node("slam", "slam_node", sources=["a.cpp"]))
    assert not _host_slot_reads(other, "/slam/solver_plugin")


NAMED_BY_ID = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <pluginlib/class_loader.hpp>
    #include "demo/solver.hpp"

    std::string get_plugin_type_param(rclcpp::Node::SharedPtr node, const std::string & id) {
      if (!node->has_parameter(id + ".plugin")) {
        node->declare_parameter(id + ".plugin", rclcpp::PARAMETER_STRING);
      }
      std::string plugin_type;
      node->get_parameter(id + ".plugin", plugin_type);
      return plugin_type;
    }

    class Loader {
     public:
      explicit Loader(rclcpp::Node::SharedPtr node)
      : loader_("demo", "demo::Solver"), default_id_("Fast") {
        auto id = node->declare_parameter("solver_id", default_id_);
        if (id == default_id_) {
          node->declare_parameter(default_id_ + ".plugin", std::string("demo::FastSolver"));
        }
        plugin_type_ = get_plugin_type_param(node, id);
        solver_ = loader_.createSharedInstance(plugin_type_);
        solver_->configure(node);
      }
     private:
      pluginlib::ClassLoader<demo::Solver> loader_;
      std::string default_id_;
      std::string plugin_type_;
      std::shared_ptr<demo::Solver> solver_;
    };

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("host");
      Loader loader(node);
      rclcpp::spin(node);
    }
    """


def test_a_class_named_by_a_parameter_another_names(write_tree: Any) -> None:
    """navigation2's route server: ``plugin_type_ = get_plugin_type_param(node, id)``
    reads ``<id>.plugin``, ``id`` the value of ``graph_file_loader`` (default
    ``GeoJsonGraphFileLoader``, whose ``.plugin`` the code declares with its class),
    then ``createSharedInstance(plugin_type_)``: the class that parameter names, in the
    configuration or by the declaration's default, is loaded (was: partial, "loads
    plugin classes by name")."""
    _model, config = _analyse(write_tree, host=NAMED_BY_ID)
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "complete", instance.completeness_reasons
    links = _links(config, "/host")
    assert ("read", "/host/Fast.plugin") in links
    assert ("publish", "/solver_status") in links


def test_a_class_another_package_creates_by_its_name_is_read_and_run(write_tree: Any) -> None:
    """cyberdog's sensor_manager creates ``cyberdog::sensor::GpsCarpo`` by name with a
    ClassLoader of cyberdog_gps's base; the loader is in the package that depends on the
    plugin's, not in the plugin's or its dependencies: the class is a plugin node all the
    same (``plugins.classes.named_loads``), and the host runs it."""
    def manifest(name: str, *depends: str) -> str:
        return package_xml(name, "ament_cmake").replace("</package>", "".join(
            f"<depend>{d}</depend>" for d in depends) + "</package>")

    root = write_tree({
        "src/solvers/package.xml": manifest("solvers", "rclcpp", "pluginlib", "std_msgs"),
        "src/solvers/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(solvers)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(pluginlib REQUIRED)\nfind_package(std_msgs REQUIRED)\n"
            "include_directories(include)\n"
            "add_library(fast_solver SHARED src/fast_solver.cpp)\n"
            "ament_target_dependencies(fast_solver rclcpp pluginlib std_msgs)\n"
            "pluginlib_export_plugin_description_file(solvers plugins.xml)\n"
            "ament_package()\n"),
        "src/solvers/plugins.xml": PLUGINS_XML,
        "src/solvers/include/demo/solver.hpp": SOLVER_H,
        "src/solvers/src/fast_solver.cpp": FAST,
        "src/demo/package.xml": manifest("demo", "rclcpp", "pluginlib", "solvers"),
        "src/demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(pluginlib REQUIRED)\nfind_package(solvers REQUIRED)\n"
            "add_executable(host src/host.cpp)\n"
            "ament_target_dependencies(host rclcpp pluginlib solvers)\n"
            "ament_package()\n"),
        "src/demo/src/host.cpp": HOST.replace(
            "LOAD", 'loader.createSharedInstance("demo::FastSolver")'),
        "src/demo/launch/demo.launch.xml": LAUNCH.format(params=""),
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: jazzy\nconfigurations:\n"
                         "  c: [demo/launch/demo.launch.xml]\n"),
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    config = model.configurations[0]
    assert [n.name for p in model.packages for n in p.nodes if n.kind == "plugin"] == [
        "solvers/demo::FastSolver"]
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "complete", instance.completeness_reasons
    assert ("publish", "/solver_status") in _links(config, "/host")
