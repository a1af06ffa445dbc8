"""A node whose own code loads one plugin per element of a list parameter, each class
named by the parameter ``<element>.plugin`` (navigation2's convention, outside its
servers that the host table knows: the route server's ``edge_cost_functions`` and
``operations``, the docking server's ``dock_plugins``): ``ids = declare_parameter("layers",
...)``, then for each ``type = get_plugin_type(node, ids[i])`` (a helper reading
``ids[i] + ".plugin"``), ``loader.createSharedInstance(type)`` and
``layer->configure(node, ids[i])``. Each element's class makes its calls on the node
with the element as its plugin name. The node was partial ("loads plugin classes by name
whose calls are not known here") and a misspelt plugin parameter went unreported."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

LAYER_H = """
    #pragma once
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    namespace demo {
    class Layer {
     public:
      virtual ~Layer() {}
      virtual void configure(rclcpp::Node::SharedPtr node, const std::string & name) = 0;
    };
    inline std::string get_plugin_type(rclcpp::Node::SharedPtr node,
                                       const std::string & name) {
      node->declare_parameter(name + ".plugin", std::string(""));
      return node->get_parameter(name + ".plugin").as_string();
    }
    }  // namespace demo
    """

FAST = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/int32.hpp>
    #include <pluginlib/class_list_macros.hpp>
    #include "demo/layer.hpp"
    namespace demo {
    class FastLayer : public Layer {
     public:
      void configure(rclcpp::Node::SharedPtr node, const std::string & name) override {
        node->declare_parameter(name + ".gain", 1.0);
        pub_ = node->create_publisher<std_msgs::msg::Int32>(name + "/status", 10);
      }
     private:
      rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr pub_;
    };
    }  // namespace demo
    PLUGINLIB_EXPORT_CLASS(demo::FastLayer, demo::Layer)
    """

HOST = """
    #include <memory>
    #include <string>
    #include <vector>
    #include <rclcpp/rclcpp.hpp>
    #include <pluginlib/class_loader.hpp>
    #include "demo/layer.hpp"

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("host");
      pluginlib::ClassLoader<demo::Layer> loader("demo", "demo::Layer");
      std::vector<std::string> ids = node->declare_parameter(
        "layers", std::vector<std::string>{"fast"});
      std::vector<std::shared_ptr<demo::Layer>> layers;
      for (size_t i = 0; i != ids.size(); i++) {
        std::string type = CLASS;
        std::shared_ptr<demo::Layer> layer = loader.createSharedInstance(type);
        layer->configure(node, ids[i]);
        layers.push_back(layer);
      }
      rclcpp::spin(node);
    }
    """

PLUGINS_XML = """
    <library path="fast_layer">
      <class type="demo::FastLayer" base_class_type="demo::Layer">
        <description>fast</description>
      </class>
    </library>
    """

LAUNCH = """
    <launch>
      <node pkg="demo" exec="host" name="host">
        <param name="layers" value="[front, back]"/>
        <param name="front.plugin" value="demo::FastLayer"/>
        <param name="back.plugin" value="BACK"/>
        <param name="front.gain" value="2.0"/>
        <param name="back.gian" value="2.0"/>
      </node>
    </launch>
    """


def _analyse(write_tree: Any, back: str = "demo::FastLayer",
             cls: str = "demo::get_plugin_type(node, ids[i])") -> tuple[Any, Any]:
    manifest = package_xml("demo", "ament_cmake").replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("rclcpp", "pluginlib", "std_msgs")) + "</package>")
    root = write_tree({
        "src/demo/package.xml": manifest,
        "src/demo/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(demo)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "find_package(pluginlib REQUIRED)\nfind_package(std_msgs REQUIRED)\n"
            "include_directories(include)\n"
            "add_library(fast_layer SHARED src/fast_layer.cpp)\n"
            "ament_target_dependencies(fast_layer rclcpp pluginlib std_msgs)\n"
            "pluginlib_export_plugin_description_file(demo plugins.xml)\n"
            "add_executable(host src/host.cpp)\n"
            "ament_target_dependencies(host rclcpp pluginlib)\n"
            "install(TARGETS fast_layer host DESTINATION lib/${PROJECT_NAME})\n"
            "ament_package()\n"),
        "src/demo/plugins.xml": PLUGINS_XML,
        "src/demo/include/demo/layer.hpp": LAYER_H,
        "src/demo/src/fast_layer.cpp": FAST,
        "src/demo/src/host.cpp": HOST.replace("CLASS", cls),
        "src/demo/launch/demo.launch.xml": LAUNCH.replace("BACK", back),
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: jazzy\nconfigurations:\n"
                         "  c: [demo/launch/demo.launch.xml]\n"),
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    return model, model.configurations[0]


def _links(config: Any, node: str) -> set[tuple[str, str]]:
    return {(link.kind, link.name) for link in config.links if link.node.name == node}


def test_each_element_loads_its_class_with_its_name(write_tree: Any) -> None:
    model, config = _analyse(write_tree)
    node = next(n for p in model.packages for n in p.nodes if n.name == "demo/host")
    assert not node.plugin_loads, node.plugin_loads
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "complete", instance.completeness_reasons
    links = _links(config, "/host")
    for plugin in ("front", "back"):
        assert ("read", f"/host/{plugin}.gain") in links, links
        assert ("publish", f"/{plugin}/status") in links, links
    assert not [n for n in config.nodes if n.name != "/host"]
    # made once per element, not under the loop that walks the list
    publish = next(link for link in config.links if link.name == "/front/status")
    assert not publish.conditions, publish.conditions
    findings = run_catalogue(model)
    unread = [f for f in findings if f.rule == "parameter-set-not-read"]
    assert [f.entities[0] for f in unread] == ["parameter:/host/back.gian"], unread


def test_an_element_whose_class_is_not_found_leaves_the_node_partial(
        write_tree: Any) -> None:
    _, config = _analyse(write_tree, back="other::Missing")
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "partial"
    assert any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics)
    links = _links(config, "/host")
    assert ("publish", "/front/status") in links
    assert ("publish", "/back/status") not in links


def test_a_class_name_built_otherwise_stays_partial(write_tree: Any) -> None:
    """The element itself with a prefix (MPPI's ``"mppi::critics::" + name``) is no
    parameter's value: not loaded here, the node partial for it."""
    model, config = _analyse(write_tree, cls='"demo::" + ids[i]')
    node = next(n for p in model.packages for n in p.nodes if n.name == "demo/host")
    assert node.plugin_loads
    instance = next(n for n in config.nodes if n.name == "/host")
    assert instance.completeness == "partial"
