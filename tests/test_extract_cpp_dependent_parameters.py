"""A parameter call on a node of a template parameter's type (``node.template
declare_parameter<double>("rate", 34)`` in ``template <typename NodeT>``) is one the
parse cannot resolve: it is kept by its name, and its type is the one written as the
template argument, not the default value's (sick_safetyscanners2's
initializeParameters)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.msg_types import written_param_type
from haros_arch.workspace import scan

SOURCE = """\
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
struct Config {
  template <typename NodeT> static void declare(NodeT & node) {
    node.template declare_parameter<double>("rate", 34);
    node.template declare_parameter<std::string>("frame", "scan");
    node.template declare_parameter<int>("skip", 0.0);
    node.template declare_parameter<bool>("on", 1);
    node.template declare_parameter<std::vector<int64_t>>("ids", std::vector<int64_t>{});
    node.template declare_parameter("plain", 2);
  }
  template <typename NodeT> void load(NodeT & node) {
    node.template get_parameter<double>("rate", rate_);
  }
  double rate_{0.0};
};
class Scanner : public rclcpp::Node {
 public:
  Scanner() : Node("scanner") { Config::declare(*this); config_.load(*this); }
  Config config_;
};
"""


def test_a_dependent_parameter_call_takes_its_written_type(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("scan", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    source = tmp_path / "scanner.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("declare", "rate", "double"), ("declare", "frame", "str"),
        ("declare", "skip", "int"), ("declare", "on", "bool"),
        ("declare", "ids", "int[]"), ("declare", "plain", "int"),
        ("read", "rate", "double")]
    unresolved = [d for d in result.diagnostics if d.code == "CPP_CALL_UNRESOLVED"]
    assert "with type double" in unresolved[0].message


def test_written_parameter_types() -> None:
    assert [written_param_type(t) for t in (
        "double", "float", "bool", "std::string", "int", "unsigned long", "std::int64_t",
        "uint8_t", "std::vector<std::string>", "std::vector<double>", "char", "long double",
        "Foo", "std::vector<Foo>", "std::vector<std::vector<int>>", "const std::string",
    )] == ["double", "double", "bool", "str", "int", "int", "int", "int", "str[]",
           "double[]", None, None, None, None, None, "str"]


def test_a_header_template_no_file_calls_makes_no_call(write_tree) -> None:
    """hdl_graph_slam's InformationMatrixCalculator has a member template
    ``load(ParamServer& params)`` of ``params.template param<double>(...)`` reads that
    nothing calls (its constructor reads the same names on a NodeHandle): the reads were
    kept, named ``?/...`` (an unknown handle), nine unresolved names and parameters of
    the node's that no code reads. Like a dependent ``make_shared`` there, a call the
    parse cannot resolve in a header's function template is made only where a file of
    the node calls the template; one called is named from its call site. A call not
    made is not said to be unresolved either (its CPP_CALL_UNRESOLVED stayed)."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin").replace(
            "</package>", "<depend>roscpp</depend></package>"),
        "pkg/include/pkg/calc.hpp": """\
            #pragma once
            #include <ros/ros.h>
            class Calc {
             public:
              template <typename ParamServer> void load(ParamServer& params) {
                gain_ = params.template param<double>("gain", 1.0);
              }
              template <typename ParamServer> void loadLimits(ParamServer& params) {
                limit_ = params.template param<double>("limit", 2.0);
              }
              double gain_ = 0.0, limit_ = 0.0;
            };
            """,
        "pkg/src/node.cpp": """\
            #include <pkg/calc.hpp>
            int main(int argc, char** argv) {
              ros::init(argc, argv, "calc");
              ros::NodeHandle pnh("~");
              Calc calc;
              calc.loadLimits(pnh);
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("read", "~limit", 9)]
    assert [d.location.line for d in result.diagnostics
            if d.code == "CPP_CALL_UNRESOLVED"] == [9]


def test_a_header_template_called_through_another_template_keeps_its_calls(
        write_tree) -> None:
    """navigation2's ``declare_or_get_parameter<ParamType, NodeT>(node, name, value)``
    reads ``warn_on_missing_params`` on ``node``; its LifecycleNode calls it from a
    member template, a call the parse cannot resolve either, so no fact says the
    template is called. A template the unit names elsewhere keeps its calls (they were
    lost from every navigation2 node); one named nowhere else makes none (above)."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "pkg/include/pkg/base.hpp": """\
            #pragma once
            #include <string>
            #include <rclcpp/rclcpp.hpp>
            namespace nav {
            template<typename ParamType, typename NodeT>
            ParamType declare_or_get(NodeT node, const std::string & name,
                                     const ParamType & value)
            {
              bool strict{false};
              node->get_parameter("strict_loading", strict);
              return value;
            }
            class Base : public rclcpp::Node {
             public:
              explicit Base(const std::string & n) : rclcpp::Node(n) {}
              template<typename ParamType>
              ParamType declare_or_get(const std::string & name, const ParamType & value)
              {
                return nav::declare_or_get(this, name, value);
              }
            };
            }  // namespace nav
            """,
        "pkg/src/node.cpp": """\
            #include <pkg/base.hpp>
            class Planner : public nav::Base {
             public:
              Planner() : nav::Base("planner") { rate_ = declare_or_get("rate", 2.0); }
              double rate_;
            };
            int main(int argc, char ** argv) {
              rclcpp::init(argc, argv);
              rclcpp::spin(std::make_shared<Planner>());
            }
            """})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert ("read", "strict_loading") in [(c.kind, c.name) for c in result.calls]
