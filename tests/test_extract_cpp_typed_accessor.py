"""rclcpp's ``get_parameter("x").as_int()`` asks for an int: the read is typed by the
accessor taken of it (rclcpp throws ``InvalidParameterTypeException`` when the parameter
holds another type), so a launch value of another type is a parameter-type-mismatch
(Open-RMF's schedule node, ``get_parameter("heartbeat_period").as_int()``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
    #include <rclcpp/rclcpp.hpp>
    #include <string>
    class N : public rclcpp::Node {
     public:
      N() : Node("n") {
        declare_parameter("period", 10);
        auto p = get_parameter("period").as_int();
        double r = this->get_parameter("rate").as_double();
        std::string s = get_parameter("name").as_string();
        bool b = get_parameter("flag").as_bool();
        auto v = get_parameter("ids").as_integer_array();
        rclcpp::Parameter whole = get_parameter("whole");
      }
    };
    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<N>());
    }
    """


def test_a_read_is_typed_by_the_accessor_taken_of_it(write_tree):
    root = write_tree({"src/p/package.xml": package_xml("p", "ament_cmake"),
                       "src/p/CMakeLists.txt": "project(p)\nadd_executable(n src/n.cpp)\n",
                       "src/p/src/n.cpp": NODE})
    result = extract_cpp([str(root / "src/p/src/n.cpp")], scan([str(root)]), cache_dir=None)
    assert [(c.name, c.type) for c in result.calls if c.kind == "read"] == [
        ("period", "int"), ("rate", "double"), ("name", "str"), ("flag", "bool"),
        ("ids", "int[]"), ("whole", None)]
