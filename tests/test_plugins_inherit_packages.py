"""A plugin or component class whose base class is built by another workspace package's
library runs that base's code: ros2_controllers' position_controllers class derives
from forward_command_controller's ``ForwardCommandController`` (which derives from
``ForwardControllersBase``), whose files subscribe ``~/commands`` and declare
``joints``; the file that defines a base exports a plugin of its own, so only the
derivation brings it, never the package's files of other classes."""

from __future__ import annotations

from pathlib import Path

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.model.source import Node
from haros_arch.workspace import scan
from tests.conftest import package_xml

BASE = "controller_interface::ControllerInterface"


def _ament(name: str, depends: tuple[str, ...] = ()) -> str:
    return package_xml(name, "ament_cmake").replace(
        "<export>", "".join(f"<depend>{d}</depend>" for d in depends) + "<export>")


def _plugins_xml(library: str, *classes: str) -> str:
    listed = "".join(f'<class type="{c}" base_class_type="{BASE}"/>' for c in classes)
    return f'<library path="{library}">{listed}</library>\n'


FILES = {
    # the base package: two plugin classes over one base, a helper the base calls, a
    # file of a class nothing names
    "fwd/package.xml": _ament("fwd", ("rclcpp", "std_msgs")),
    "fwd/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.16)
        project(fwd)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        find_package(std_msgs REQUIRED)
        add_library(fwd SHARED src/base.cpp src/forward.cpp src/multi.cpp src/gains.cpp
                    src/other.cpp)
        target_link_libraries(fwd PUBLIC rclcpp::rclcpp ${std_msgs_TARGETS})
        pluginlib_export_plugin_description_file(controller_interface plugins.xml)
        install(TARGETS fwd EXPORT export_fwd LIBRARY DESTINATION lib)
        ament_export_targets(export_fwd HAS_LIBRARY_TARGET)
        ament_package()
        """,
    "fwd/plugins.xml": _plugins_xml("fwd", "fwd::Forward", "fwd::Multi"),
    "fwd/include/fwd/base.hpp": """
        #include <memory>
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/float64_multi_array.hpp"
        namespace fwd {
        class Base {
        public:
          virtual ~Base() {}
          virtual int on_init();
          int on_configure();
        protected:
          virtual void declare_parameters() = 0;
          std::shared_ptr<rclcpp::Node> node_;
          rclcpp::Subscription<std_msgs::msg::Float64MultiArray>::SharedPtr sub_;
        };
        }
        """,
    "fwd/include/fwd/gains.hpp": """
        #include "rclcpp/rclcpp.hpp"
        namespace fwd {
        void read_gains(rclcpp::Node & node);
        }
        """,
    "fwd/src/base.cpp": """
        #include "fwd/base.hpp"
        #include "fwd/gains.hpp"
        namespace fwd {
        int Base::on_init()
        {
          node_->declare_parameter("base_init", 1);
          declare_parameters();
          return 0;
        }

        int Base::on_configure()
        {
          sub_ = node_->create_subscription<std_msgs::msg::Float64MultiArray>(
            "~/commands", 10, [](std_msgs::msg::Float64MultiArray::SharedPtr) {});
          read_gains(*node_);
          return 0;
        }
        }
        """,
    "fwd/src/gains.cpp": """
        #include "fwd/gains.hpp"
        namespace fwd {
        void read_gains(rclcpp::Node & node)
        {
          node.declare_parameter("gains", 1.0);
        }
        }
        """,
    "fwd/include/fwd/forward.hpp": """
        #include "fwd/base.hpp"
        namespace fwd {
        class Forward : public Base {
        protected:
          void declare_parameters() override;
        };
        }
        """,
    "fwd/src/forward.cpp": """
        #include "fwd/forward.hpp"
        #include "pluginlib/class_list_macros.hpp"
        namespace fwd {
        void Forward::declare_parameters()
        {
          node_->declare_parameter("joints", std::vector<std::string>{});
        }
        }
        PLUGINLIB_EXPORT_CLASS(fwd::Forward, controller_interface::ControllerInterface)
        """,
    "fwd/include/fwd/multi.hpp": """
        #include "fwd/base.hpp"
        namespace fwd {
        class Multi : public Base {
        protected:
          void declare_parameters() override;
        };
        }
        """,
    "fwd/src/multi.cpp": """
        #include "fwd/multi.hpp"
        #include "pluginlib/class_list_macros.hpp"
        namespace fwd {
        void Multi::declare_parameters()
        {
          node_->declare_parameter("multi_only", 1);
        }
        }
        PLUGINLIB_EXPORT_CLASS(fwd::Multi, controller_interface::ControllerInterface)
        """,
    "fwd/src/other.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/float64_multi_array.hpp"
        namespace fwd {
        class Other { public: void start(rclcpp::Node & node); };
        void Other::start(rclcpp::Node & node)
        {
          node.create_publisher<std_msgs::msg::Float64MultiArray>("other_topic", 1);
        }
        }
        """,
    # a package with a class of the same plain name in another namespace, linked too
    "shadow/package.xml": _ament("shadow", ("rclcpp", "std_msgs")),
    "shadow/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.16)
        project(shadow)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        add_library(shadow SHARED src/forward.cpp)
        target_link_libraries(shadow PUBLIC rclcpp::rclcpp)
        install(TARGETS shadow EXPORT export_shadow LIBRARY DESTINATION lib)
        ament_export_targets(export_shadow HAS_LIBRARY_TARGET)
        ament_package()
        """,
    "shadow/src/forward.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/float64_multi_array.hpp"
        namespace shadow {
        class Forward { public: void start(rclcpp::Node & node); };
        void Forward::start(rclcpp::Node & node)
        {
          node.create_publisher<std_msgs::msg::Float64MultiArray>("shadow_topic", 1);
        }
        }
        """,
    # the derived plugin, in its own package
    "pos/package.xml": _ament("pos", ("fwd", "shadow", "rclcpp")),
    "pos/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.16)
        project(pos)
        find_package(ament_cmake REQUIRED)
        find_package(fwd REQUIRED)
        find_package(shadow REQUIRED)
        add_library(pos SHARED src/position.cpp)
        target_link_libraries(pos PUBLIC fwd::fwd shadow::shadow)
        pluginlib_export_plugin_description_file(controller_interface plugins.xml)
        install(TARGETS pos EXPORT export_pos LIBRARY DESTINATION lib)
        ament_export_targets(export_pos HAS_LIBRARY_TARGET)
        ament_package()
        """,
    "pos/plugins.xml": _plugins_xml("pos", "pos::Position"),
    "pos/include/pos/position.hpp": """
        #include "fwd/forward.hpp"
        namespace pos {
        class Position : public fwd::Forward {
        public:
          int on_init() override;
        };
        }
        """,
    "pos/src/position.cpp": """
        #include "pos/position.hpp"
        #include "pluginlib/class_list_macros.hpp"
        namespace pos {
        int Position::on_init()
        {
          int ret = fwd::Forward::on_init();
          node_->set_parameter(rclcpp::Parameter("interface_name", "position"));
          return ret;
        }
        }
        PLUGINLIB_EXPORT_CLASS(pos::Position, controller_interface::ControllerInterface)
        """,
    # a plugin two packages away from its bases' code: grip links pos only
    "grip/package.xml": _ament("grip", ("pos", "rclcpp")),
    "grip/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.16)
        project(grip)
        find_package(ament_cmake REQUIRED)
        find_package(pos REQUIRED)
        add_library(grip SHARED src/grip.cpp)
        target_link_libraries(grip PUBLIC pos::pos)
        pluginlib_export_plugin_description_file(controller_interface plugins.xml)
        ament_package()
        """,
    "grip/plugins.xml": _plugins_xml("grip", "grip::Grip"),
    "grip/include/grip/grip.hpp": """
        #include "pos/position.hpp"
        namespace grip {
        class Grip : public pos::Position {};
        }
        """,
    "grip/src/grip.cpp": """
        #include "grip/grip.hpp"
        #include "pluginlib/class_list_macros.hpp"
        PLUGINLIB_EXPORT_CLASS(grip::Grip, controller_interface::ControllerInterface)
        """,
    # a component deriving from another package's component
    "cam/package.xml": _ament("cam", ("rclcpp", "rclcpp_components", "std_msgs")),
    "cam/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.16)
        project(cam)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        find_package(rclcpp_components REQUIRED)
        add_library(driver SHARED src/driver.cpp)
        target_link_libraries(driver PUBLIC rclcpp::rclcpp rclcpp_components::component)
        rclcpp_components_register_nodes(driver "cam::Driver")
        install(TARGETS driver EXPORT export_cam LIBRARY DESTINATION lib)
        ament_export_targets(export_cam HAS_LIBRARY_TARGET)
        ament_package()
        """,
    "cam/include/cam/driver.hpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/float64_multi_array.hpp"
        namespace cam {
        class Driver : public rclcpp::Node {
        public:
          explicit Driver(const rclcpp::NodeOptions & options);
        protected:
          rclcpp::Publisher<std_msgs::msg::Float64MultiArray>::SharedPtr pub_;
        };
        }
        """,
    "cam/src/driver.cpp": """
        #include "cam/driver.hpp"
        #include "rclcpp_components/register_node_macro.hpp"
        namespace cam {
        Driver::Driver(const rclcpp::NodeOptions & options)
        : rclcpp::Node("driver", options)
        {
          pub_ = create_publisher<std_msgs::msg::Float64MultiArray>("image_raw", 1);
          declare_parameter("frame_id", std::string("camera"));
        }
        }
        RCLCPP_COMPONENTS_REGISTER_NODE(cam::Driver)
        """,
    "stereo/package.xml": _ament("stereo", ("cam", "rclcpp", "rclcpp_components")),
    "stereo/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.16)
        project(stereo)
        find_package(ament_cmake REQUIRED)
        find_package(cam REQUIRED)
        find_package(rclcpp_components REQUIRED)
        add_library(stereo SHARED src/stereo.cpp)
        target_link_libraries(stereo PUBLIC cam::driver rclcpp_components::component)
        rclcpp_components_register_nodes(stereo "stereo::Stereo")
        ament_package()
        """,
    "stereo/include/stereo/stereo.hpp": """
        #include "cam/driver.hpp"
        namespace stereo {
        class Stereo : public cam::Driver {
        public:
          explicit Stereo(const rclcpp::NodeOptions & options);
        };
        }
        """,
    "stereo/src/stereo.cpp": """
        #include "stereo/stereo.hpp"
        #include "rclcpp_components/register_node_macro.hpp"
        namespace stereo {
        Stereo::Stereo(const rclcpp::NodeOptions & options)
        : cam::Driver(options)
        {
          declare_parameter("baseline", 0.1);
        }
        }
        RCLCPP_COMPONENTS_REGISTER_NODE(stereo::Stereo)
        """,
}


def _nodes(write_tree, names: tuple[str, ...]) -> dict[str, Node]:
    root: Path = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    nodes = {n.executable: n for p in ws.packages.values() for n in p.nodes
             if n.executable in names}
    extract_nodes(list(nodes.values()), ws, cache_dir=None, jobs=1)
    return nodes


def _calls(node: Node) -> list[tuple[str, str]]:
    return sorted((c.kind, c.name) for c in node.calls)


def test_a_plugin_runs_its_base_classes_code_from_another_package(write_tree) -> None:
    node = _nodes(write_tree, ("pos::Position",))["pos::Position"]
    # the bases' files (one of them exports a plugin of its own) and the helper the
    # base calls; not the other plugin's file, nor a file nothing names, nor a class
    # of the same plain name in another namespace
    assert node.sources == ["pos/src/position.cpp", "fwd/src/base.cpp",
                            "fwd/src/forward.cpp", "fwd/src/gains.cpp"]
    assert _calls(node) == [
        ("declare", "base_init"),  # fwd::Forward::on_init() runs Base's
        ("declare", "gains"),
        ("declare", "joints"),
        ("subscribe", "~commands"),
        ("write", "interface_name"),
    ]
    assert node.completeness == "complete"


def test_a_base_two_packages_away_is_followed(write_tree) -> None:
    # grip links pos, which links fwd: Position's own bases are fwd's
    node = _nodes(write_tree, ("grip::Grip",))["grip::Grip"]
    assert node.sources == ["grip/src/grip.cpp", "pos/src/position.cpp", "fwd/src/base.cpp",
                            "fwd/src/forward.cpp", "fwd/src/gains.cpp"]
    assert ("subscribe", "~commands") in _calls(node)


def test_a_component_runs_its_base_components_code_from_another_package(write_tree) -> None:
    node = _nodes(write_tree, ("stereo::Stereo",))["stereo::Stereo"]
    assert node.sources == ["stereo/src/stereo.cpp", "cam/src/driver.cpp"]
    assert ("publish", "image_raw") in _calls(node)
    assert ("declare", "frame_id") in _calls(node)
    assert ("declare", "baseline") in _calls(node)
