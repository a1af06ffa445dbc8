"""An integer a C++ source writes in octal, ``03``, or with the other prefixes and digit
separators C++ has (``0x1F``, ``0b101``, ``1'000``): read as C++ reads it. Python's
``int("03", 0)`` refuses it, and the run stopped with an internal error (ValueError) on
sbg_ros2_driver's config_store.cpp, whose wrapper ``getParameter<uint8_t>(node,
"sensorParameters.year", 03)`` passes the month's default in octal."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.ctext import integer_literal
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "config/package.xml": package_xml("config", "ament_cmake"),
    "config/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(config)
        find_package(rclcpp REQUIRED)
        add_executable(config src/config.cpp)
        ament_package()
        """,
    "config/src/config.cpp": """
        #include <string>
        #include "rclcpp/rclcpp.hpp"
        class Config : public rclcpp::Node {
        public:
          Config() : rclcpp::Node("config")
          {
            month_ = getParameter<unsigned char>("month", 03);
            mask_ = getParameter<unsigned int>("mask", 0x1F);
            flags_ = getParameter<unsigned int>("flags", 0b101);
            rate_ = getParameter<unsigned int>("rate", 1'000);
          }
        private:
          template <typename T>
          T getParameter(const std::string & key, int default_value)
          {
            int value;
            this->get_parameter_or<int>(key, value, default_value);
            return static_cast<T>(value);
          }
          unsigned char month_;
          unsigned int mask_, flags_, rate_;
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<Config>());
        }
        """,
}


def test_an_octal_default_passed_to_a_wrapper_is_read_as_cpp_does(write_tree) -> None:
    ws = scan([str(write_tree(FILES))])
    package = ws.packages["config"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    defaults = {c.name: c.default for c in package.nodes[0].calls if c.kind == "read"}
    assert defaults == {"month": 3, "mask": 31, "flags": 5, "rate": 1000}, defaults


def test_integer_literals_as_cpp_writes_them() -> None:
    assert [integer_literal(text) for text in (
        "03", "0", "10", "0x1F", "0b101", "1'000", "-3", "12UL", "7llu")] == [
        3, 0, 10, 31, 5, 1000, -3, 12, 7]
    # an octal literal with a digit 8 or 9 is no C++, and a name is no literal
    assert [integer_literal(text) for text in ("09", "0x", "abc", "")] == [None] * 4
