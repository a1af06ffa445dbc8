"""A plugin's code that builds an object of a class of a library of its own package that
its library links runs that class's code on the host: MoveIt's OMPL planner
(moveit_ompl_planner_plugin) builds moveit_ompl_interface's ``OMPLInterface``, which
reads the pipeline's ``planner_configs`` and groups' settings (ompl_planner_manager.cpp:111,
ompl_interface.cpp:135-245), its members defined with the class's namespace written
(``ompl_interface::OMPLInterface::OMPLInterface(...)``). A linked class the plugin is only
given stays out."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "planners/package.xml": package_xml("planners", "ament_cmake").replace(
        "</export>", '<nav2_core plugin="${prefix}/planners.xml"/></export>'),
    "planners/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(planners)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        add_library(interface SHARED src/interface.cpp src/scene.cpp)
        add_library(planner_plugins SHARED src/builder.cpp src/given.cpp)
        target_link_libraries(planner_plugins interface)
        ament_package()
        """,
    "planners/planners.xml": """
        <library path="planner_plugins">
          <class type="planners::Builder" base_class_type="nav2_core::GlobalPlanner"/>
          <class type="planners::Given" base_class_type="nav2_core::GlobalPlanner"/>
        </library>
        """,
    "planners/include/planners/interface.hpp": """
        #include "rclcpp/rclcpp.hpp"
        namespace planners {
        class Interface { public: explicit Interface(rclcpp::Node * node); };
        class Scene { public: explicit Scene(rclcpp::Node * node); };
        }
        """,
    "planners/src/interface.cpp": """
        #include "planners/interface.hpp"
        planners::Interface::Interface(rclcpp::Node * node)
        {
          node->declare_parameter("planner_configs", 1);
        }
        """,
    "planners/src/scene.cpp": """
        #include "planners/interface.hpp"
        namespace planners {
        Scene::Scene(rclcpp::Node * node)
        {
          node->declare_parameter("scene", 1);
        }
        }
        """,
    "planners/src/builder.cpp": """
        #include <memory>
        #include "planners/interface.hpp"
        #include "pluginlib/class_list_macros.hpp"
        namespace planners {
        class Builder {
        public:
          void configure(rclcpp::Node * node)
          {
            interface_ = std::make_unique<Interface>(node);
            node->declare_parameter("own", 1);
          }
        private:
          std::unique_ptr<Interface> interface_;
        };
        }
        PLUGINLIB_EXPORT_CLASS(planners::Builder, nav2_core::GlobalPlanner)
        """,
    "planners/src/given.cpp": """
        #include "planners/interface.hpp"
        #include "pluginlib/class_list_macros.hpp"
        namespace planners {
        class Given {
        public:
          void configure(rclcpp::Node * node, Scene * scene)
          {
            scene_ = scene;
            node->declare_parameter("given", 1);
          }
        private:
          Scene * scene_;
        };
        }
        PLUGINLIB_EXPORT_CLASS(planners::Given, nav2_core::GlobalPlanner)
        """,
}


def test_a_plugin_runs_the_code_of_a_class_it_builds_from_a_linked_library(write_tree):
    root = write_tree(FILES)
    ws = scan([str(root)])
    package = ws.packages["planners"]
    package.nodes, _ = cmake.parse_package(package, ws)
    plugins = [n for n in package.nodes if n.kind == "plugin"]
    extract_nodes(plugins, ws, cache_dir=None, jobs=1)
    found = {n.executable: sorted(c.name for c in n.calls if c.kind == "declare")
             for n in plugins}
    assert found["planners::Builder"] == ["own", "planner_configs"]
    assert found["planners::Given"] == ["given"]
