"""A wrapper that hands its parameter on moved or forwarded (``std::move(v)``,
``std::forward<T>(v)``) hands on the parameter itself. navigation2's MPPI reads every
setting through ``ParametersHandler::getParamGetter(ns)``, a generic lambda passing
``std::move(default_value)`` to ``getParam``, which declares the parameter with
``rclcpp::ParameterValue(default_value)``: each declaration lost its default (the model's
0 of 103 declarations with one), and once MPPI's controller was complete every read was
a false ``parameter-read-not-set``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HANDLER = """
    #include <memory>
    #include <string>
    #include <utility>
    #include "rclcpp/rclcpp.hpp"
    #include "nav2_util/node_utils.hpp"
    namespace pk {
    class Handler {
     public:
      explicit Handler(rclcpp::Node::SharedPtr node) : node_(node) {}
      inline auto getParamGetter(const std::string & ns) {
        return [this, ns](auto & setting, const std::string & name, auto default_value) {
          getParam(setting, ns.empty() ? name : ns + "." + name, std::move(default_value));
        };
      }
      template<typename SettingT, typename ParamT>
      void getParam(SettingT & setting, const std::string & name, ParamT default_value) {
        auto node = node_.lock();
        nav2_util::declare_parameter_if_not_declared(
          node, name, rclcpp::ParameterValue(default_value));
        ParamT param_in{};
        node->get_parameter(name, param_in);
        setting = static_cast<SettingT>(param_in);
      }
      template<typename T>
      void forwarded(const std::string & name, T && value) {
        node_.lock()->declare_parameter(name, std::forward<T>(value));
      }
      std::weak_ptr<rclcpp::Node> node_;
    };
    }  // namespace pk
    """

MAIN = """
    #include "pk/handler.hpp"
    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("h");
      pk::Handler h(node);
      auto getParam = h.getParamGetter("ctrl");
      double weight = 0.0;
      getParam(weight, "cost_weight", 5.0);
      int direct = 0;
      h.getParam(direct, "direct", 3);
      h.forwarded("rate", 10.0);
      rclcpp::spin(node);
    }
    """


def test_a_moved_default_is_the_callers(write_tree) -> None:
    root = write_tree({
        "pk/package.xml": package_xml("pk", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>nav2_util</depend></package>"),
        "pk/include/pk/handler.hpp": HANDLER,
        "pk/src/main.cpp": MAIN})
    result = extract_cpp([str(root / "pk" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    declared = {c.name: (c.has_default, c.default) for c in result.calls
                if c.kind == "declare"}
    assert declared == {"ctrl.cost_weight": (True, 5.0), "direct": (True, 3),
                        "rate": (True, 10.0)}
