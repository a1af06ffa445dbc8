"""A class template of another package built where its constructor cannot be chosen,
the arguments depending on a template parameter (component_interface_utils'
``NodeAdaptor(D * node)`` builds ``make_shared<NodeInterface<NodeT>>(node)``, whose
constructor template declares ``component_interface.service_introspection``): any of
the class's constructors may run there, so their calls are the node's. They were
dropped as made by a constructor no file of the node calls (kept only in units whose
errors hid something), and every NodeAdaptor user lost the parameter."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

ADAPTOR = """
#include <rclcpp/rclcpp.hpp>
namespace utils {
template <class NodeT = rclcpp::Node> struct NodeInterface {
  template <class D> explicit NodeInterface(D * node) : node(node) {
    const std::string param = "component.introspection";
    mode = node->has_parameter(param) ? node->get_parameter(param).as_string()
                                      : node->template declare_parameter<std::string>(param, "off");
  }
  NodeT * node;
  std::string mode;
};
template <class NodeT = rclcpp::Node> class NodeAdaptor {
 public:
  template <class D> explicit NodeAdaptor(D * node) { BUILD }
  std::shared_ptr<NodeInterface<NodeT>> interface_;
};
}
"""

NODE = """
#include <utils/adaptor.hpp>
class Planner : public rclcpp::Node {
 public:
  Planner() : rclcpp::Node("planner") {}
  utils::NodeAdaptor<rclcpp::Node> adaptor_{this};
};
int main() { auto node = std::make_shared<Planner>(); }
"""


@pytest.mark.parametrize("build", [
    "interface_ = std::make_shared<NodeInterface<NodeT>>(node);",
    "NodeInterface<NodeT> made(node);",
    "interface_.reset(new NodeInterface<NodeT>(node));",
])
def test_the_constructor_a_dependent_construction_may_run_is_the_nodes(
        tmp_path, build: str) -> None:
    files = {
        "utils/package.xml": package_xml("utils", "ament_cmake"),
        "utils/include/utils/adaptor.hpp": ADAPTOR.replace("BUILD", build),
        "planner/package.xml": package_xml("planner", "ament_cmake"),
        "planner/src/planner.cpp": NODE,
    }
    for rel, text in files.items():
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    batch = extract_cpp_nodes([[str(tmp_path / "planner/src/planner.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    calls = sorted((c.kind, c.name) for c in batch.results[0].calls)
    assert ("declare", "component.introspection") in calls
    assert ("read", "component.introspection") in calls
