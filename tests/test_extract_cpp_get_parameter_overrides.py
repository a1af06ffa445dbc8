"""rclcpp's ``get_node_parameters_interface()->get_parameter_overrides()`` gives the node
every parameter it was started with (launch values, parameter files), which
mrpt_pf_localization turns into its YAML configuration whole
(mrpt_pf_localization_node.cpp:213-214). It was no call: once the node's parse was
complete, each of the 78 parameters its launch file sets was "set but never read". It
is a read of the node's own namespace, whole: every parameter under it is read."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Node
from haros_arch.workspace import Workspace, scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
class Pf : public rclcpp::Node
{
public:
  Pf() : rclcpp::Node("pf")
  {
    const auto & params = this->get_node_parameters_interface();
    const auto & all = params->get_parameter_overrides();
    for (const auto & kv : all) { names_.push_back(kv.first); }
  }
  std::vector<std::string> names_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Pf>());
}
"""


def test_the_overrides_are_every_parameter_of_the_node_read_whole(write_tree) -> None:
    root = write_tree({"pf/package.xml": package_xml("pf", "ament_cmake"),
                       "pf/src/pf.cpp": NODE})
    result = extract_cpp([str(root / "pf" / "src" / "pf.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~")]
    node = Node("pf", "pf", calls=list(result.calls))
    config = build(Configuration("c"), LaunchModel(
        nodes=[NodeDecl("/loc/pf", "pf", "pf", ros_version=2)],
        params=[ParamDecl("/loc/pf/rate_hz", 10.0, "double"),
                ParamDecl("/loc/pf/pf_options.BETA", 0.5, "double"),
                ParamDecl("/loc/other/rate_hz", 1.0, "double")]),
        Workspace(root="/nowhere"), {node.name: node})
    read = {p.name: p.is_read for p in config.parameters if p.set_by_launch}
    assert read == {"/loc/pf": True, "/loc/pf/rate_hz": True,
                    "/loc/pf/pf_options.BETA": True, "/loc/other/rate_hz": False}


LOOKUP = """
#include <rclcpp/rclcpp.hpp>
class Nav : public rclcpp::Node
{
public:
  Nav() : rclcpp::Node("nav")
  {
    auto params = this->get_node_parameters_interface();
    const bool given = params->get_parameter_overrides().find("rate") !=
      params->get_parameter_overrides().end();
    const bool also = params->get_parameter_overrides().count("rate") > 0;
    if (given && also) { rate_ = declare_parameter("rate", 1.0); }
  }
  double rate_ = 0.0;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Nav>());
}
"""


def test_looking_one_name_up_in_the_overrides_reads_no_other(write_tree) -> None:
    """navigation2's declare_or_get_parameter asks get_parameter_overrides().find(name)
    whether the launch gave that parameter: not a read of every parameter, which would
    hide each parameter the launch sets that the node never reads."""
    root = write_tree({"nav/package.xml": package_xml("nav", "ament_cmake"),
                       "nav/src/nav.cpp": LOOKUP})
    result = extract_cpp([str(root / "nav" / "src" / "nav.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("declare", "rate")]
