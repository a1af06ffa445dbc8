"""A plugin registered for a factory template keeps its own calls.

mavros' plugins are described as ``mavros::plugin::PluginFactoryTemplate<ns::Imu>`` and
exported by ``MAVROS_PLUGIN_REGISTER(ns::Imu)``: the class is the template's argument
(``classes._registered``). The filter that drops the calls a plugin's library makes in
files of other exported classes (``inherit.without_other_classes``, laser_filters' many
filters in one library) took the factory template, which mavros/plugin.hpp defines, for
the plugin's own class, so the plugin's own file defined only "other" classes and every
call of its code was dropped (jazzy mavros' and mavros_extras' plugin nodes kept only
their base's calls, each said complete)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract import extract_nodes
from haros_arch.pipeline import read_build_files
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
namespace mavros {
namespace plugin {
using UASPtr = std::shared_ptr<rclcpp::Node>;
class Plugin {
public:
  Plugin(UASPtr uas_, const std::string & subnode)
  : node(rclcpp::Node::make_shared(subnode, uas_->get_fully_qualified_name())) {}
  virtual ~Plugin() = default;
protected:
  rclcpp::Node::SharedPtr node;
};
class PluginFactory {
public:
  virtual ~PluginFactory() = default;
  virtual std::shared_ptr<Plugin> create_plugin_instance(UASPtr uas) = 0;
};
template<typename _T>
class PluginFactoryTemplate : public PluginFactory {
public:
  std::shared_ptr<Plugin> create_plugin_instance(UASPtr uas) override
  {
    return std::make_shared<_T>(uas);
  }
};
}  // namespace plugin
}  // namespace mavros
#define MAVROS_PLUGIN_REGISTER(PluginClass)
"""


def plugin_source(cls: str, sub: str, topic: str) -> str:
    return f"""\
#include "uas/plugin.hpp"
#include <std_msgs/msg/string.hpp>
namespace uas {{
class {cls} : public mavros::plugin::Plugin {{
public:
  explicit {cls}(mavros::plugin::UASPtr uas_)
  : Plugin(uas_, "{sub}")
  {{
    node->declare_parameter("frame_id", "base_link");
    pub_ = node->create_publisher<std_msgs::msg::String>("{topic}", 10);
  }}
private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
}};
}}  // namespace uas
MAVROS_PLUGIN_REGISTER(uas::{cls})
"""


def test_a_factory_registered_plugin_keeps_the_calls_of_its_own_file(write_tree):
    xml = package_xml("uas", "ament_cmake").replace(
        "<export>", "<export><mavros plugin='${prefix}/plugins.xml'/>")
    root = write_tree({
        "uas/package.xml": xml,
        "uas/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.8)\nproject(uas)\n"
            "find_package(ament_cmake REQUIRED)\ninclude_directories(include)\n"
            "add_library(uas SHARED src/imu.cpp src/sys.cpp)\nament_package()\n"),
        "uas/plugins.xml": (
            '<library path="uas">\n'
            '  <class name="imu" type="mavros::plugin::PluginFactoryTemplate&lt;uas::Imu&gt;"'
            ' base_class_type="mavros::plugin::PluginFactory"/>\n'
            '  <class name="sys" type="mavros::plugin::PluginFactoryTemplate&lt;uas::Sys&gt;"'
            ' base_class_type="mavros::plugin::PluginFactory"/>\n</library>\n'),
        "uas/include/uas/plugin.hpp": HEADER,
        "uas/src/imu.cpp": plugin_source("Imu", "imu", "~/data"),
        "uas/src/sys.cpp": plugin_source("Sys", "sys", "state"),
    })
    workspace = scan([str(root)], {})
    package = workspace.packages["uas"]
    read_build_files(package, workspace)
    extract_nodes(package.nodes, workspace, cache_dir=None, jobs=1, distro="jazzy")
    calls = {node.name: {(c.kind, c.name) for c in node.calls} for node in package.nodes}
    assert ("publish", "~data") in calls["uas/imu"]
    assert ("declare", "frame_id") in calls["uas/imu"]
    assert ("publish", "state") in calls["uas/sys"]
    # each its own class's, not the other plugin's
    assert ("publish", "state") not in calls["uas/imu"]
