"""A free function of an API row called in a function template with a node of a template
parameter (Autoware's ``VehicleInfoUtils(NodeT & node)``, a header's constructor template
that declares the vehicle's ten parameters with ``get_or_declare_parameter<double>(node,
"wheel_base")``): clang leaves the call unresolved, the names it was looked up to kept
(through a function's own ``using autoware_utils_rclcpp::get_or_declare_parameter;`` too).
It is the row's call, made where a file of the node builds the class; a function of the
same name the lookup found elsewhere is not. Before, the declarations were lost and the
node said complete: autoware_core's simple_pure_pursuit got ten false
parameter-set-not-read warnings for its vehicle_info.param.yaml."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

INFO = """#include <autoware_utils_rclcpp/parameter.hpp>
#include <rclcpp/node.hpp>
namespace util {
class Info {
public:
  template <typename NodeT>
  explicit Info(NodeT & node)
  {
    static constexpr const char * WHEEL = "wheel_base";
    %s
    wheel_ = %s<double>(node, WHEEL);
    radius_ = %s<double>(node, "wheel_radius");
  }
  double get() const { return wheel_; }
private:
  double wheel_;
  double radius_;
};
}
"""

# another function of that name: the workspace's own, no API row
OWN = """#include <rclcpp/node.hpp>
namespace mine {
template <class T, class N> T get_or_declare_parameter(N & node, const char * name)
{ return T{}; }
}
namespace util {
class Info {
public:
  template <typename NodeT>
  explicit Info(NodeT & node) { wheel_ = mine::get_or_declare_parameter<double>(node, "w"); }
  double get() const { return wheel_; }
private:
  double wheel_;
};
}
"""

NODE = """#include <rclcpp/rclcpp.hpp>
#include <util/info.hpp>
class PP : public rclcpp::Node {
public:
  PP() : Node("pp") {
    const auto info = util::Info(*this).get();
    gain_ = declare_parameter<double>("gain");
  }
  double gain_;
};
int main(int argc, char ** argv) { rclcpp::init(argc, argv); rclcpp::spin(std::make_shared<PP>()); }
"""

FORMS = {
    "qualified": INFO % ("", "autoware_utils_rclcpp::get_or_declare_parameter",
                         "autoware_utils_rclcpp::get_or_declare_parameter"),
    "using": INFO % ("using autoware_utils_rclcpp::get_or_declare_parameter;",
                     "get_or_declare_parameter", "get_or_declare_parameter"),
}


def _calls(write_tree, info: str) -> set[tuple[str, str, str | None]]:
    root = write_tree({
        "src/util/package.xml": package_xml("util", "ament_cmake"),
        "src/util/CMakeLists.txt": "project(util)\n",
        "src/util/include/util/info.hpp": info,
        "src/node/package.xml": package_xml("node", "ament_cmake"),
        "src/node/CMakeLists.txt": "project(node)\nadd_executable(pp src/pp.cpp)\n",
        "src/node/src/pp.cpp": NODE,
    })
    ws = scan([str(root)])
    result = extract_cpp([str(root / "src/node/src/pp.cpp")], ws, cache_dir=None)
    return {(c.kind, c.name, c.type) for c in result.calls}


@pytest.mark.parametrize("form", sorted(FORMS))
def test_the_rows_free_function_in_a_template_declares_on_the_node(write_tree, form):
    assert _calls(write_tree, FORMS[form]) == {
        ("declare", "gain", "double"), ("declare", "wheel_base", "double"),
        ("declare", "wheel_radius", "double")}


def test_a_function_of_that_name_elsewhere_is_not_the_row(write_tree):
    assert _calls(write_tree, OWN) == {("declare", "gain", "double")}
