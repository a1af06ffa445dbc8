"""A plugin class runs its base classes' code: a base compiled into another library of
the package (nav2's CostmapFilter in nav2_costmap_2d_core, the filters in ``filters``)
gives the plugin's node the reads its methods make with the plugin's name, but not those
of a base method the plugin redefines without calling it."""

from __future__ import annotations

from pathlib import Path

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

LAYER = "maps::Layer"
FILES = {
    "maps/package.xml": package_xml("maps", "ament_cmake").replace(
        "</export>", '<nav2_costmap_2d plugin="${prefix}/filters.xml"/></export>'),
    "maps/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(maps)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        add_library(core SHARED src/layer.cpp src/costmap.cpp src/filter.cpp)
        add_library(filters SHARED src/keep.cpp src/tight.cpp src/loose.cpp)
        target_link_libraries(filters core)
        ament_package()
        """,
    "maps/filters.xml": """
        <library path="filters">
          <class type="maps::KeepFilter" base_class_type="nav2_costmap_2d::Layer"/>
          <class type="maps::TightFilter" base_class_type="nav2_costmap_2d::Layer"/>
          <class type="maps::LooseFilter" base_class_type="nav2_costmap_2d::Layer"/>
        </library>
        """,
    "maps/include/maps/layer.hpp": """
        #include <string>
        #include "rclcpp/rclcpp.hpp"
        namespace maps {
        class Layer {
        public:
          virtual ~Layer() {}
          void initialize(rclcpp::Node * node, const std::string & name);
          virtual void onInitialize() {}
        protected:
          rclcpp::Node * node_;
          std::string name_;
        };
        }
        """,
    "maps/include/maps/filter.hpp": """
        #include "maps/layer.hpp"
        namespace maps {
        class Filter : public Layer {
        public:
          void onInitialize() override;
          void activate();
          virtual void process() = 0;
        };
        }
        """,
    "maps/include/maps/keep.hpp": """
        #include "maps/filter.hpp"
        namespace maps {
        class KeepFilter final : public Filter {
        public:
          void process() override;
        };
        }
        """,
    "maps/include/maps/tight.hpp": """
        #include "maps/filter.hpp"
        namespace maps {
        class TightFilter : public Filter {
        public:
          void onInitialize() override;
          void process() override;
        };
        }
        """,
    "maps/include/maps/loose.hpp": """
        #include "maps/filter.hpp"
        namespace maps {
        class LooseFilter : public Filter {
        public:
          void onInitialize() override
          {
            node_->declare_parameter(name_ + ".loose", 1);
          }
          void process() override {}
        };
        }
        """,
    "maps/src/loose.cpp": """
        #include "maps/loose.hpp"
        #include "pluginlib/class_list_macros.hpp"
        PLUGINLIB_EXPORT_CLASS(maps::LooseFilter, maps::Layer)
        """,
    "maps/include/maps/costmap.hpp": """
        #include "rclcpp/rclcpp.hpp"
        namespace maps {
        class Costmap { public: explicit Costmap(rclcpp::Node * node); };
        }
        """,
    "maps/src/layer.cpp": """
        #include "maps/layer.hpp"
        namespace maps {
        void Layer::initialize(rclcpp::Node * node, const std::string & name)
        {
          node_ = node;
          name_ = name;
          onInitialize();
        }
        }
        """,
    "maps/src/costmap.cpp": """
        #include "maps/costmap.hpp"
        namespace maps {
        Costmap::Costmap(rclcpp::Node * node)
        {
          node->declare_parameter("resolution", 0.05);
        }
        }
        """,
    "maps/src/filter.cpp": """
        #include "maps/filter.hpp"
        namespace maps {
        void Filter::onInitialize()
        {
          node_->declare_parameter(name_ + ".enabled", true);
          node_->declare_parameter(name_ + ".filter_info_topic", std::string("info"));
        }

        void Filter::activate()
        {
          node_->declare_parameter(name_ + ".transform_tolerance", 0.5);
        }
        }
        """,
    "maps/src/keep.cpp": """
        #include "maps/keep.hpp"
        #include "pluginlib/class_list_macros.hpp"
        namespace maps {
        void KeepFilter::process()
        {
          node_->declare_parameter(name_ + ".keep", 1);
        }
        }
        PLUGINLIB_EXPORT_CLASS(maps::KeepFilter, maps::Layer)
        """,
    "maps/src/tight.cpp": """
        #include "maps/tight.hpp"
        #include "pluginlib/class_list_macros.hpp"
        namespace maps {
        void TightFilter::onInitialize()
        {
          node_->declare_parameter(name_ + ".margin", 0.1);
        }

        void TightFilter::process()
        {
        }
        }
        PLUGINLIB_EXPORT_CLASS(maps::TightFilter, maps::Layer)
        """,
}


def _plugins(write_tree) -> dict[str, list[tuple[str, str]]]:
    root: Path = write_tree(FILES)
    ws = scan([str(root)])
    package = ws.packages["maps"]
    package.nodes, _ = cmake.parse_package(package, ws)
    plugins = [n for n in package.nodes if n.kind == "plugin"]
    extract_nodes(plugins, ws, cache_dir=None, jobs=1)
    return {n.executable: [(c.name, c.location.file) for c in n.calls if c.kind == "declare"]
            for n in plugins}


def test_a_plugin_carries_its_base_class_code_from_another_library(write_tree) -> None:
    found = _plugins(write_tree)
    # the base's reads, made with the plugin's name (``?`` until a host names it); the
    # costmap's file, linked but no base of the filter, is not the plugin's
    assert found["maps::KeepFilter"] == [
        ("?.keep", "maps/src/keep.cpp"),
        ("?.enabled", "maps/src/filter.cpp"),
        ("?.filter_info_topic", "maps/src/filter.cpp"),
        ("?.transform_tolerance", "maps/src/filter.cpp"),
    ]


def test_a_base_method_the_plugin_redefines_is_not_run(write_tree) -> None:
    found = _plugins(write_tree)
    # TightFilter::onInitialize replaces Filter's (and does not call it): the base's
    # other method still runs
    assert found["maps::TightFilter"] == [
        ("?.margin", "maps/src/tight.cpp"),
        ("?.transform_tolerance", "maps/src/filter.cpp"),
    ]
    # redefined in the class's body
    assert found["maps::LooseFilter"] == [
        ("?.loose", "maps/include/maps/loose.hpp"),
        ("?.transform_tolerance", "maps/src/filter.cpp"),
    ]


def test_a_factory_registered_plugin_is_its_registered_class_for_redefinitions(
        write_tree) -> None:
    """mavros (ROS 2) describes each plugin as ``PluginFactoryTemplate<X>`` and registers
    ``X``: the base methods X redefines are those of X's bases, not the factory's."""
    from haros_arch.model.source import Node
    from haros_arch.plugins.inherit import overridden
    from haros_arch.workspace import Workspace

    root = write_tree({
        "fac/package.xml": package_xml("fac", "ament_cmake"),
        "fac/include/fac/plugin.hpp": """
            namespace fac {
            class Plugin {
            public:
              virtual void connect();
              void spin();
            };
            class Factory { public: virtual ~Factory() {} };
            template<class T> class FactoryTemplate : public Factory {};
            }
            """,
        "fac/src/plugin.cpp": """
            #include "fac/plugin.hpp"
            namespace fac {
            void Plugin::connect() {
              node->create_publisher<std_msgs::msg::String>("connected", 1);
            }
            void Plugin::spin() {
            }
            }
            """,
        "fac/src/imu.cpp": """
            #include "fac/plugin.hpp"
            namespace fac {
            class ImuPlugin : public Plugin {
            public:
              void connect() override;
            };
            void ImuPlugin::connect() {
            }
            }
            REGISTER_PLUGIN(fac::ImuPlugin)
            """,
    })
    node = Node("fac", "fac/imu", "plugin", sources=["fac/src/imu.cpp", "fac/src/plugin.cpp"],
                plugin_class="fac::FactoryTemplate<fac::ImuPlugin>")
    # before: [] (the chain was the factory's, FactoryTemplate and Factory)
    assert overridden(node, Workspace(root=str(root))) == [("fac/src/plugin.cpp", 3, 5)]


def test_the_methods_a_class_body_defines_are_its_own_inline_definitions() -> None:
    """A class's inline methods (read to tell a base method its derived class redefines)
    are the functions its body defines at its own level: not one it only declares, not
    a nested class's, not a static constant; the first text that declares the class
    with a body is read, and the same class asked again of the same text (another
    plugin of the family) gives the same."""
    from haros_arch.plugins.inherit import _inline_methods

    header = """
        namespace demo {
        class Base { public: virtual void onInitialize(); };
        class Layer : public Base
        {
        public:
          ~Layer() override = default;
          void onInitialize() override { auto n = ns::make(); if (n) { count_ = 1; } }
          void reset();
          int count() const { return count_; }
          struct Inner { void hidden() {} };
          std::map<std::string, int> table() const noexcept { return {{"a", 1}}; }
        private:
          static constexpr int kMax = 3;
          int count_;
        };
        }
        """
    found = _inline_methods("Layer", ["class Unrelated {};", header])
    assert {"onInitialize", "count", "table"} <= found
    assert not found & {"reset", "hidden", "kMax", "Inner", "count_"}
    assert _inline_methods("Layer", [header]) == found
    assert _inline_methods("Inner", [header]) == {"hidden"}
    assert _inline_methods("Missing", [header]) == set()


def test_a_constructor_initialising_its_base_redefines_no_base_method(write_tree) -> None:
    """A plugin class whose inline constructor initialises its base in its list
    (``Camera() : Sensor("camera"), rate_{30} {}``) defines a constructor, not a method
    named after the base: the base's own constructor, out of line, still runs (its
    publisher is the plugin's), while the base method the class redefines does not."""
    from haros_arch.model.source import Node
    from haros_arch.plugins.inherit import overridden
    from haros_arch.workspace import Workspace

    root = write_tree({
        "cams/package.xml": package_xml("cams", "catkin"),
        "cams/include/cams/sensor.h": """
            #include <ros/ros.h>
            namespace cams {
            class Sensor {
            public:
              explicit Sensor(const std::string& name);
              virtual void start();
            protected:
              ros::Publisher status_;
            };
            }
            """,
        "cams/src/sensor.cpp": """
            #include "cams/sensor.h"
            namespace cams {
            Sensor::Sensor(const std::string& name) {
              ros::NodeHandle nh("~");
              status_ = nh.advertise<std_msgs::String>(name + "/status", 1);
            }
            void Sensor::start() {
              ros::NodeHandle nh("~");
              nh.advertise<std_msgs::String>("started", 1);
            }
            }
            """,
        "cams/include/cams/camera.h": """
            #include "cams/sensor.h"
            namespace cams {
            class Camera : public Sensor {
            public:
              Camera() : Sensor("camera"), rate_{30} {}
              void start() override { rate_ = 10; }
            private:
              int rate_;
            };
            }
            """,
        "cams/src/camera.cpp": """
            #include "cams/camera.h"
            #include <pluginlib/class_list_macros.h>
            PLUGINLIB_EXPORT_CLASS(cams::Camera, cams::Sensor)
            """,
    })
    node = Node("cams", "cams::Camera", "plugin",
                sources=["cams/src/camera.cpp", "cams/src/sensor.cpp"],
                plugin_class="cams::Camera")
    # before: Sensor::Sensor's span too (the constructor's list read as a method
    # ``Sensor`` of Camera), and the plugin lost its status publisher
    assert overridden(node, Workspace(root=str(root))) == [("cams/src/sensor.cpp", 7, 12)]
