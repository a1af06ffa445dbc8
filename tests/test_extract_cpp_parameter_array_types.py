"""The type of a ROS 2 C++ parameter of each array kind rclcpp has. A
``std::vector<uint8_t>`` (declared, got, ``PARAMETER_BYTE_ARRAY``, ``as_byte_array()``)
is rclcpp's byte array, ``byte[]``: it had no type. A ``std::vector<float>`` is a double
array, ``std::vector<int>`` an integer array, as rclcpp's ParameterValue stores them."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.msg_types import written_param_type
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <cstdint>
class P : public rclcpp::Node {
public:
  P() : Node("p") {
    declare_parameter<std::vector<uint8_t>>("bytes", std::vector<uint8_t>{});
    declare_parameter("bytes_default", std::vector<unsigned char>{1, 2});
    declare_parameter("bytes_typed", rclcpp::ParameterType::PARAMETER_BYTE_ARRAY);
    std::vector<uint8_t> out;
    get_parameter("bytes_got", out);
    auto taken = get_parameter("bytes_taken").as_byte_array();
    declare_parameter("bools", std::vector<bool>{true});
    declare_parameter("ints", std::vector<int64_t>{1});
    declare_parameter("ints32", std::vector<int>{1});
    declare_parameter("doubles", std::vector<double>{1.0});
    declare_parameter("floats", std::vector<float>{1.0f});
    declare_parameter("strings", std::vector<std::string>{"a"});
    declare_parameter<std::vector<bool>>("bools_typed");
    std::vector<int64_t> ints; get_parameter("ints_got", ints);
    declare_parameter("small", static_cast<uint8_t>(3));
  }
};
int main(int argc, char** argv) { rclcpp::init(argc, argv); rclcpp::spin(std::make_shared<P>()); }
"""


def test_each_array_parameter_has_its_rclcpp_type(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("p", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    source = tmp_path / "p.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    types = {c.name: c.type for c in result.calls if c.kind in ("declare", "read")}
    assert types == {
        "bytes": "byte[]", "bytes_default": "byte[]", "bytes_typed": "byte[]",
        "bytes_got": "byte[]", "bytes_taken": "byte[]",
        "bools": "bool[]", "ints": "int[]", "ints32": "int[]", "doubles": "double[]",
        "floats": "double[]", "strings": "str[]", "bools_typed": "bool[]",
        "ints_got": "int[]", "small": "int"}, types


def test_a_written_vector_of_bytes_is_a_byte_array() -> None:
    # a call the parse could not resolve: its template argument as written
    assert written_param_type("std::vector<uint8_t>") == "byte[]"
    assert written_param_type("const std::vector<unsigned char>") == "byte[]"
    assert written_param_type("std::vector<int64_t>") == "int[]"
