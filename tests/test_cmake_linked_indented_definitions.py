"""A library file that defines its members indented inside ``namespace x {`` still
defines them: an executable that names its class runs it (survey Z19: xarm_ros2's
xarm_driver_node links xarm_ros_driver, whose xarm_driver.cpp defines
``XArmDriver::init`` four columns in; the file was left out, with the driver's
publishers and every parameter it reads, because a free function it defines at the
first column was all that could be seen of it)."""

from __future__ import annotations

from tests.conftest import package_xml
from tests.test_cmake_package_links import _node

FILES = {
    "drv/package.xml": package_xml("drv", "ament_cmake"),
    "drv/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(drv)
        find_package(rclcpp REQUIRED)
        find_package(std_msgs REQUIRED)
        add_library(driver SHARED src/driver.cpp src/unrelated.cpp)
        ament_target_dependencies(driver rclcpp std_msgs)
        add_executable(driver_node src/driver_node.cpp)
        target_link_libraries(driver_node driver)
        """,
    "drv/include/drv/driver.h": """
        #include <rclcpp/rclcpp.hpp>
        #include <std_msgs/msg/string.hpp>
        namespace drv
        {
            class Driver
            {
            public:
                void init(rclcpp::Node::SharedPtr node);
            private:
                rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
            };
        }
        """,
    "drv/src/driver.cpp": """
        #include <drv/driver.h>

        void* heart_beat(void* arg)
        {
            return arg;
        }

        namespace drv
        {
            void Driver::init(rclcpp::Node::SharedPtr node)
            {
                int dof = 7;
                node->get_parameter_or("dof", dof, 7);
                pub_ = node->create_publisher<std_msgs::msg::String>("joint_states", 10);
            }
        }
        """,
    "drv/src/unrelated.cpp": """
        #include <rclcpp/rclcpp.hpp>
        #include <std_msgs/msg/string.hpp>
        namespace drv
        {
            void never_named(rclcpp::Node::SharedPtr node)
            {
                node->create_publisher<std_msgs::msg::String>("never", 10);
            }
        }
        """,
    "drv/src/driver_node.cpp": """
        #include <drv/driver.h>
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = rclcpp::Node::make_shared("driver_node");
          drv::Driver driver;
          driver.init(node);
          rclcpp::spin(node);
        }
        """,
}


def test_members_defined_indented_in_a_namespace_bring_their_file(write_tree) -> None:
    node, _ = _node(write_tree, dict(FILES), "drv", "driver_node")
    assert node.sources == ["drv/src/driver_node.cpp", "drv/src/driver.cpp"]
    calls = {(c.kind, c.name) for c in node.calls}
    assert {("publish", "joint_states"), ("read", "dof")} <= calls
    assert ("publish", "never") not in calls


def test_only_lines_at_namespace_scope_move_to_the_first_column() -> None:
    from haros_arch.plugins.classes import at_namespace_scope

    text = ("namespace a {\n  void A::f()\n  {\n    B::g();\n  }\n"
            "  class C {\n    void h();\n  };\n}\n  extern_line();\n")
    assert at_namespace_scope(text).split("\n") == [
        "namespace a {", "void A::f()", "  {", "    B::g();", "  }", "class C {",
        "    void h();", "  };", "}", "  extern_line();", ""]
    # a constructor's member initialisers and a comment stay where they are: they
    # define nothing (navigation2's ``Layer::Layer()`` then ``: current_(false),`` and
    # ``  enabled_(false),``)
    text = ("namespace a {\n  /**\n   * calls tick() once\n   */\n  A::A()\n"
            "  : x_(1),\n    y_(2)\n  {\n  }\n#if X\n  void g(int v)\n  {\n  }\n#endif\n}\n")
    assert at_namespace_scope(text).split("\n") == [
        "namespace a {", "  /**", "   * calls tick() once", "   */", "A::A()",
        "  : x_(1),", "    y_(2)", "  {", "  }", "#if X", "void g(int v)", "  {", "  }",
        "#endif", "}", ""]


def test_a_class_declared_in_the_node_and_defined_in_its_library(write_tree) -> None:
    # the executable's own file declares the class, its library defines the members
    # (indented in the namespace): the library file is the class's code
    files = dict(FILES)
    files["drv/src/driver_node.cpp"] = """
        #include <rclcpp/rclcpp.hpp>
        #include <std_msgs/msg/string.hpp>
        namespace drv
        {
        class Driver
        {
        public:
          void init(rclcpp::Node::SharedPtr node);
        private:
          rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
        };
        }
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = rclcpp::Node::make_shared("driver_node");
          drv::Driver driver;
          driver.init(node);
          rclcpp::spin(node);
        }
        """
    node, _ = _node(write_tree, files, "drv", "driver_node")
    assert node.sources == ["drv/src/driver_node.cpp", "drv/src/driver.cpp"]


def test_a_class_the_node_defines_whole_keeps_the_library_out(write_tree) -> None:
    # every member defined in the class's body: a library class of the same name
    # (defined in driver.cpp) is another one
    files = dict(FILES)
    files["drv/src/driver_node.cpp"] = """
        #include <rclcpp/rclcpp.hpp>
        namespace drv
        {
        class Driver
        {
        public:
          void init(rclcpp::Node::SharedPtr node) { node_ = node; }
        private:
          rclcpp::Node::SharedPtr node_;
        };
        }
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = rclcpp::Node::make_shared("driver_node");
          drv::Driver driver;
          driver.init(node);
          rclcpp::spin(node);
        }
        """
    node, _ = _node(write_tree, files, "drv", "driver_node")
    assert node.sources == ["drv/src/driver_node.cpp"]
