"""A default given through an explicit cast has the cast's type: ros_gz_sim's ``create``
declares ``declare_parameter("x", static_cast<double>(0))``, a double parameter. The
extractor typed the declaration by the literal under the cast (``int``), and a launch
file setting ``x: 1.5`` then read as a type mismatch against that int."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
class Create : public rclcpp::Node {
 public:
  Create() : Node("create") {
    declare_parameter("x", static_cast<double>(0));
    declare_parameter("y", (float)1);
    declare_parameter("z", double(2));
    declare_parameter("count", static_cast<int>(2.5));
    declare_parameter("flag", static_cast<bool>(1));
    declare_parameter("scale", rclcpp::ParameterValue(static_cast<double>(3)));
    declare_parameter("plain", 4);
    declare_parameter("name", std::string("a"));
  }
};
"""


def test_the_cast_gives_the_declared_type(write_tree) -> None:
    root = write_tree({"gz/package.xml": package_xml("gz", "ament_cmake"),
                       "gz/src/create.cpp": NODE})
    result = extract_cpp([str(root / "gz" / "src" / "create.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("declare", "x", "double"), ("declare", "y", "double"), ("declare", "z", "double"),
        ("declare", "count", "int"), ("declare", "flag", "bool"),
        ("declare", "scale", "double"), ("declare", "plain", "int"),
        ("declare", "name", "str")]
