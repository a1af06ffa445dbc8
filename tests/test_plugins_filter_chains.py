"""A node that builds a ``filters::FilterChain<T>`` (the ROS package filters, installed,
not in the workspace) reads the parameters that describe the chain and loads, through
pluginlib, the filter classes they name; each filter makes its own calls on the node.
laser_filters' scan_to_scan_filter_chain was partial (``filters::FilterChain ... is
built here and its code is not read``) and its filters' calls unseen. ROS 1: the list
``configure(name, nh)`` reads on the handle, ``{name, type, params}`` entries, a filter
naming its handle ``"~" + getName()``. ROS 2: ``<prefix>.filter1.name`` / ``.type``,
filter2, ..., a filter's ``getParam`` declaring ``<prefix>.filterN.params.<name>``.
Not set: the chain is empty; a class not found: the instance is partial."""

from __future__ import annotations

import os
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

ROS1_NODE = """
    #include <ros/ros.h>
    #include <sensor_msgs/LaserScan.h>
    #include <filters/filter_chain.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "chain");
      ros::NodeHandle nh;
      ros::NodeHandle pnh("~");
      filters::FilterChain<sensor_msgs::LaserScan> chain("sensor_msgs::LaserScan");
      chain.configure("scan_filter_chain", pnh);
      ros::spin();
    }
    """

ROS1_FILTER = """
    #include <string>
    #include <ros/ros.h>
    #include <std_msgs/Int32.h>
    #include <sensor_msgs/LaserScan.h>
    #include <filters/filter_base.h>
    #include <pluginlib/class_list_macros.h>

    namespace demo {
    class Clip : public filters::FilterBase<sensor_msgs::LaserScan> {
     public:
      bool configure() override {
        getParam("limit", limit_);
        ros::NodeHandle private_nh("~" + getName());
        pub_ = private_nh.advertise<std_msgs::Int32>("clipped", 1);
        return true;
      }
      bool update(const sensor_msgs::LaserScan& in, sensor_msgs::LaserScan& out) override {
        out = in;
        return true;
      }
     private:
      double limit_;
      ros::Publisher pub_;
    };
    }  // namespace demo
    PLUGINLIB_EXPORT_CLASS(demo::Clip, filters::FilterBase<sensor_msgs::LaserScan>)
    """

# with ``<`` in an attribute, as laser_filters writes it: TinyXML, pluginlib's reader,
# takes it
PLUGINS_XML = """
    <library path="lib/libclip">
      <class name="demo/Clip" type="demo::Clip"
             base_class_type="filters::FilterBase<sensor_msgs::LaserScan>">
        <description>clips</description>
      </class>
    </library>
    """

ROS1_LAUNCH = """
    <launch>
      <node pkg="demo" type="chain_node" name="chain">
        {params}
      </node>
    </launch>
    """

ROS1_CHAIN = """
        <rosparam>
          scan_filter_chain:
            - name: clip_a
              type: {cls}
              params: {{limit: 2.0}}
        </rosparam>
"""


def _manifest(name: str, *deps: str, build_type: str | None = None,
              exports: str = "") -> str:
    text = package_xml(name, build_type).replace(
        "</package>", "".join(f"<depend>{d}</depend>" for d in deps) + "</package>")
    if exports:
        text = text.replace("</package>", f"<export>{exports}</export></package>")
    return text


def _analyse(write_tree: Any, files: dict[str, str], launch: str) -> tuple[Any, Any, Any]:
    root = write_tree({**files, "project.yaml": (
        f"project: p\nworkspace: [src]\nconfigurations:\n  c: [{launch}]\n")})
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    return model, model.configurations[0], project


def _ros1(write_tree: Any, params: str, more: dict[str, str] | None = None,
          ) -> tuple[Any, Any, Any]:
    return _analyse(write_tree, {
        "src/demo/package.xml": _manifest(
            "demo", "roscpp", "filters", "sensor_msgs", "std_msgs",
            exports='<filters plugin="${prefix}/demo_filters.xml"/>'),
        "src/demo/demo_filters.xml": PLUGINS_XML,
        "src/demo/CMakeLists.txt": (
            "project(demo)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
            "add_library(clip src/clip.cpp)\n"
            "add_executable(chain_node src/chain_node.cpp)\n"),
        "src/demo/src/chain_node.cpp": ROS1_NODE,
        "src/demo/src/clip.cpp": ROS1_FILTER,
        "src/demo/launch/demo.launch": ROS1_LAUNCH.format(params=params),
        **{f"src/demo/{path}": text for path, text in (more or {}).items()},
    }, "demo/launch/demo.launch")


def _links(config: Any, node: str) -> set[tuple[str, str]]:
    return {(link.kind, link.name) for link in config.links if link.node.name == node}


def test_ros1_chain_reads_its_list_and_loads_the_filters_it_names(write_tree: Any) -> None:
    model, config, project = _ros1(write_tree, ROS1_CHAIN.format(cls="demo/Clip"))
    node = next(n for p in model.packages for n in p.nodes if n.name == "demo/chain_node")
    assert node.completeness == "complete", node.completeness_reasons
    instance = next(n for n in config.nodes if n.name == "/chain")
    assert instance.completeness == "complete", instance.completeness_reasons
    links = _links(config, "/chain")
    assert ("read", "/chain/scan_filter_chain") in links
    # the filter's handle "~" + getName(): its name in the list
    assert ("publish", "/chain/clip_a/clipped") in links
    # the filter reads its ``limit`` from its entry, not the parameter server
    assert not any("limit" in name for _, name in links)
    assert not any(f.rule == "parameter-set-not-read" for f in run_catalogue(model, project))


def test_ros1_chain_not_set_loads_nothing_and_stays_complete(write_tree: Any) -> None:
    model, config, project = _ros1(write_tree, "")
    instance = next(n for n in config.nodes if n.name == "/chain")
    assert instance.completeness == "complete"
    links = _links(config, "/chain")
    assert ("read", "/chain/scan_filter_chain") in links
    assert not any(kind == "publish" for kind, _ in links)
    # the library takes a chain not set as empty: no read that fails
    assert not any(f.rule == "parameter-read-not-set" for f in run_catalogue(model, project))


def test_ros1_chain_of_a_class_not_found_makes_the_instance_partial(write_tree: Any) -> None:
    _, config, _ = _ros1(write_tree, ROS1_CHAIN.format(cls="other_pkg/Median"))
    instance = next(n for n in config.nodes if n.name == "/chain")
    assert instance.completeness == "partial"
    assert any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics)


# laser_filters' layout (ROS 1): one file exports every filter of the library, each
# filter's members are defined in a file of its own
FILTERS_H = """
    #include <string>
    #include <ros/ros.h>
    #include <sensor_msgs/LaserScan.h>
    #include <filters/filter_base.h>
    namespace demo {
    class Clip : public filters::FilterBase<sensor_msgs::LaserScan> {
     public:
      bool configure() override;
      bool update(const sensor_msgs::LaserScan& in, sensor_msgs::LaserScan& out) override;
     private:
      ros::Publisher pub_;
    };
    class Other : public filters::FilterBase<sensor_msgs::LaserScan> {
     public:
      bool configure() override;
      bool update(const sensor_msgs::LaserScan& in, sensor_msgs::LaserScan& out) override;
     private:
      ros::Publisher pub_;
    };
    }  // namespace demo
    """

MEMBERS = """
    #include <std_msgs/Int32.h>
    #include "demo/filters.h"
    namespace demo {
    bool CLASS::configure() {
      ros::NodeHandle private_nh("~" + getName());
      pub_ = private_nh.advertise<std_msgs::Int32>("TOPIC", 1);
      return true;
    }
    bool CLASS::update(const sensor_msgs::LaserScan& in, sensor_msgs::LaserScan& out) {
      out = in;
      return true;
    }
    }  // namespace demo
    """

EXPORTS = """
    #include <pluginlib/class_list_macros.h>
    #include "demo/filters.h"
    PLUGINLIB_EXPORT_CLASS(demo::Clip, filters::FilterBase<sensor_msgs::LaserScan>)
    PLUGINLIB_EXPORT_CLASS(demo::Other, filters::FilterBase<sensor_msgs::LaserScan>)
    """


def test_ros1_filters_exported_by_one_file_keep_their_own_calls(write_tree: Any) -> None:
    _, config, _ = _ros1(write_tree, ROS1_CHAIN.format(cls="demo/Clip"), {
        "CMakeLists.txt": (
            "project(demo)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
            "include_directories(include)\n"
            "add_library(clip src/exports.cpp src/clip.cpp src/other.cpp)\n"
            "add_executable(chain_node src/chain_node.cpp)\n"),
        "demo_filters.xml": PLUGINS_XML.replace("</library>", (
            '<class name="demo/Other" type="demo::Other" '
            'base_class_type="filters::FilterBase<sensor_msgs::LaserScan>"/></library>')),
        "include/demo/filters.h": FILTERS_H,
        "src/exports.cpp": EXPORTS,
        "src/clip.cpp": MEMBERS.replace("CLASS", "Clip").replace("TOPIC", "clipped"),
        "src/other.cpp": MEMBERS.replace("CLASS", "Other").replace("TOPIC", "other")})
    links = _links(config, "/chain")
    assert ("publish", "/chain/clip_a/clipped") in links
    assert not any(name.endswith("/other") for _, name in links)


ROS2_NODE = """
    #include <memory>
    #include <rclcpp/rclcpp.hpp>
    #include <sensor_msgs/msg/laser_scan.hpp>
    #include <filters/filter_chain.hpp>

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("chain");
      filters::FilterChain<sensor_msgs::msg::LaserScan> chain("sensor_msgs::msg::LaserScan");
      chain.configure("scan_filter_chain", node->get_node_logging_interface(),
                      node->get_node_parameters_interface());
      rclcpp::spin(node);
    }
    """

ROS2_FILTER = """
    #include <rclcpp/rclcpp.hpp>
    #include <sensor_msgs/msg/laser_scan.hpp>
    #include <filters/filter_base.hpp>
    #include <pluginlib/class_list_macros.hpp>

    namespace demo {
    class Clip : public filters::FilterBase<sensor_msgs::msg::LaserScan> {
     public:
      bool configure() override {
        getParam("limit", limit_);
        return true;
      }
      bool update(const sensor_msgs::msg::LaserScan& in,
                  sensor_msgs::msg::LaserScan& out) override {
        out = in;
        return true;
      }
     private:
      double limit_;
    };
    }  // namespace demo
    PLUGINLIB_EXPORT_CLASS(demo::Clip, filters::FilterBase<sensor_msgs::msg::LaserScan>)
    """

ROS2_LAUNCH = """
    <launch>
      <node pkg="demo" exec="chain_node" name="chain">
        {params}
      </node>
    </launch>
    """


def _ros2(write_tree: Any, params: str, filter_source: str = ROS2_FILTER
          ) -> tuple[Any, Any, Any]:
    return _analyse(write_tree, {
        "src/demo/package.xml": _manifest("demo", "rclcpp", "filters", "sensor_msgs",
                                          build_type="ament_cmake"),
        "src/demo/demo_filters.xml": PLUGINS_XML.replace("sensor_msgs::LaserScan",
                                                         "sensor_msgs::msg::LaserScan"),
        "src/demo/CMakeLists.txt": (
            "project(demo)\nfind_package(ament_cmake REQUIRED)\n"
            "add_library(clip src/clip.cpp)\n"
            "pluginlib_export_plugin_description_file(filters demo_filters.xml)\n"
            "add_executable(chain_node src/chain_node.cpp)\n"
            "install(TARGETS chain_node DESTINATION lib/${PROJECT_NAME})\n"),
        "src/demo/src/chain_node.cpp": ROS2_NODE,
        "src/demo/src/clip.cpp": filter_source,
        "src/demo/launch/demo.launch.xml": ROS2_LAUNCH.format(params=params),
    }, "demo/launch/demo.launch.xml")


ROS2_CHAIN = """
        <param name="scan_filter_chain.filter1.name" value="clip_a"/>
        <param name="scan_filter_chain.filter1.type" value="{cls}"/>
        <param name="scan_filter_chain.filter1.params.limit" value="2.0"/>
"""


def test_ros2_chain_declares_its_filters_and_their_parameters(write_tree: Any) -> None:
    model, config, project = _ros2(write_tree, ROS2_CHAIN.format(cls="demo/Clip"))
    instance = next(n for n in config.nodes if n.name == "/chain")
    assert instance.completeness == "complete", instance.completeness_reasons
    links = _links(config, "/chain")
    for key in ("filter1.name", "filter1.type", "filter2.name", "filter2.type",
                "filter1.params.limit"):
        assert ("read", f"/chain/scan_filter_chain.{key}") in links, key
    assert not any(f.rule == "parameter-set-not-read" for f in run_catalogue(model, project))


def test_ros2_chain_not_set_looks_for_its_first_filter_only(write_tree: Any) -> None:
    model, config, project = _ros2(write_tree, "")
    assert not any(f.rule == "parameter-read-not-set" for f in run_catalogue(model, project))
    instance = next(n for n in config.nodes if n.name == "/chain")
    assert instance.completeness == "complete"
    names = {name for _, name in _links(config, "/chain")}
    assert "/chain/scan_filter_chain.filter1.type" in names
    assert not any("filter2" in name or "params" in name for name in names)


def test_ros2_chain_of_an_unknown_class_makes_the_instance_partial(write_tree: Any) -> None:
    _, config, _ = _ros2(write_tree, ROS2_CHAIN.format(cls="other_pkg/Median"))
    instance = next(n for n in config.nodes if n.name == "/chain")
    assert instance.completeness == "partial"
    assert any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics)


def test_a_chain_named_at_run_time_makes_the_instance_partial(write_tree: Any) -> None:
    """laser_filters' ROS 2 LaserArrayFilter configures chains under its own parameter
    prefix (``param_prefix_ + "range_filter_chain"``), a value the parse does not have."""
    node = ROS2_NODE.replace('chain.configure("scan_filter_chain"',
                             'chain.configure(std::string(std::getenv("CHAIN")) + ".chain"')
    _, config, _ = _analyse(write_tree, {
        "src/demo/package.xml": _manifest("demo", "rclcpp", "filters", "sensor_msgs",
                                          build_type="ament_cmake"),
        "src/demo/CMakeLists.txt": (
            "project(demo)\nfind_package(ament_cmake REQUIRED)\n"
            "add_executable(chain_node src/chain_node.cpp)\n"
            "install(TARGETS chain_node DESTINATION lib/${PROJECT_NAME})\n"),
        "src/demo/src/chain_node.cpp": node,
        "src/demo/launch/demo.launch.xml": ROS2_LAUNCH.format(params=""),
    }, "demo/launch/demo.launch.xml")
    instance = next(n for n in config.nodes if n.name == "/chain")
    assert instance.completeness == "partial"
    assert any("whose name is not known statically" in r
               for r in instance.completeness_reasons)


ROS2_ARRAY_FILTER = """
    #include <rclcpp/rclcpp.hpp>
    #include <sensor_msgs/msg/laser_scan.hpp>
    #include <filters/filter_base.hpp>
    #include <filters/filter_chain.hpp>
    #include <pluginlib/class_list_macros.hpp>

    namespace demo {
    class Clip : public filters::FilterBase<sensor_msgs::msg::LaserScan> {
     public:
      bool configure() override {
        inner_ = new filters::MultiChannelFilterChain<float>("float");
        return inner_->configure(3, param_prefix_ + "inner_chain", logging_interface_,
                                 params_interface_);
      }
      bool update(const sensor_msgs::msg::LaserScan& in,
                  sensor_msgs::msg::LaserScan& out) override {
        out = in;
        return true;
      }
     private:
      filters::MultiChannelFilterChain<float>* inner_;
    };
    }  // namespace demo
    PLUGINLIB_EXPORT_CLASS(demo::Clip, filters::FilterBase<sensor_msgs::msg::LaserScan>)
    """


def test_ros2_filter_names_a_chain_of_its_own_under_its_prefix(write_tree: Any) -> None:
    """laser_filters' ROS 2 LaserArrayFilter configures chains under its own parameter
    prefix (``param_prefix_ + "range_filter_chain"``): the chain gives the filter
    ``<prefix>.filterN.params.``, so its chain reads ``filter1.params.inner_chain...``
    (they were ``?inner_chain...``, names not known)."""
    _, config, _ = _ros2(write_tree, ROS2_CHAIN.format(cls="demo/Clip"), ROS2_ARRAY_FILTER)
    names = {name for _kind, name in _links(config, "/chain")}
    assert "/chain/scan_filter_chain.filter1.params.inner_chain.filter1.type" in names
    assert not any("?" in name for name in names)
