"""A name made of each element of a constant list the code walks: navigation2's
controller server declares ``default_progress_checker_ids_[i] + ".plugin"`` for each of
its default ids (a ``const std::vector<std::string>`` member initialised with a braced
list), which was ``?.plugin``. One call per element, the loop no condition of it; a list
that is not constant, or whose texts are not all known, keeps the ``?``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
class N : public rclcpp::Node {
public:
  N() : rclcpp::Node("n") {
    ids_ = declare_parameter("checker_plugins", default_ids_);
    if (ids_ == default_ids_) {
      for (size_t i = 0; i < default_ids_.size(); ++i) {
        declare_parameter(default_ids_[i] + ".plugin", default_types_[i]);
      }
    }
    for (const auto & name : kNames) {
      declare_parameter(std::string(name) + ".enabled", true);
    }
    for (const auto & name : ids_) {
      declare_parameter(name + ".scale", 1.0);  // a parameter's list, not a constant
    }
    std::vector<std::string> changing{"a", "b"};
    changing.push_back(get_name());
    for (const auto & name : changing) {
      declare_parameter(name + ".other", 1.0);  // not constant
    }
  }
  std::vector<std::string> ids_;
  const std::vector<std::string> default_ids_{"progress_checker", "goal_checker"};
  const std::vector<std::string> default_types_{"pkg::A", "pkg::B"};
  static constexpr const char * kNames[] = {"x", "y"};
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<N>());
}
"""


def test_each_element_of_a_constant_list(write_tree) -> None:
    root = write_tree({"cl/package.xml": package_xml("cl", "ament_cmake"),
                       "cl/src/n.cpp": NODE})
    result = extract_cpp([str(root / "cl" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    declared = {c.name: [cond.statement for cond in c.conditions]
                for c in result.calls if c.kind == "declare"}
    assert declared["progress_checker.plugin"] == ["if"]  # the loop is no condition
    assert declared["goal_checker.plugin"] == ["if"]
    assert declared["x.enabled"] == [] and declared["y.enabled"] == []
    assert "?.plugin" not in declared and "?.enabled" not in declared
    assert "?.other" in declared  # a list the code changes
    scale = [c for c in result.calls if c.kind == "declare" and c.name == "?.scale"]
    assert scale and scale[0].name_param == "checker_plugins"  # the graph's, per element


HANDED = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/bool.hpp>
template <class T>
std::vector<typename rclcpp::Subscription<T>::SharedPtr> init_factors(
  rclcpp::Node * node, const std::vector<std::string> & topics)
{
  std::vector<typename rclcpp::Subscription<T>::SharedPtr> subs;
  for (size_t index = 0; index < topics.size(); ++index) {
    subs.push_back(node->create_subscription<T>(topics[index], rclcpp::QoS(1),
      [](const typename T::ConstSharedPtr) {}));
  }
  return subs;
}
class Planning : public rclcpp::Node {
public:
  Planning() : rclcpp::Node("planning") {
    std::vector<std::string> factor_topics = {
      "/planning/planning_factors/crosswalk", "/planning/planning_factors/stop_line"};
    subs_ = init_factors<std_msgs::msg::Bool>(this, factor_topics);
    std::vector<std::string> grown = {"/a"};
    grown.push_back(get_name());
    more_ = init_other(grown);
  }
  std::vector<rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr> init_other(
    const std::vector<std::string> & names)
  {
    std::vector<rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr> out;
    for (const auto & name : names) {
      out.push_back(create_subscription<std_msgs::msg::Bool>(name, 1,
        [](const std_msgs::msg::Bool::ConstSharedPtr) {}));
    }
    return out;
  }
  std::vector<rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr> subs_, more_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Planning>());
}
"""


def test_a_constant_list_handed_to_a_function(write_tree) -> None:
    """Autoware's ADAPI planning node subscribes to 28 planning-factor topics of a local
    list it hands to ``init_factors``: one subscription each (was one, ``?``); a list
    the code grows keeps the ``?``."""
    root = write_tree({"pl/package.xml": package_xml("pl", "ament_cmake"),
                       "pl/src/n.cpp": HANDED})
    result = extract_cpp([str(root / "pl" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    subscribed = sorted(c.name for c in result.calls if c.kind == "subscribe")
    assert subscribed == ["/planning/planning_factors/crosswalk",
                          "/planning/planning_factors/stop_line", "?"]


MEMBER_NODE = """
#include <rclcpp/rclcpp.hpp>
class S : public rclcpp::Node {
public:
  S();
  void configure();
  void extend() { others_.push_back("late"); }
  std::vector<std::string> ids_;
  std::vector<std::string> default_ids_;
  std::vector<std::string> default_types_;
  std::vector<std::string> others_;
};
S::S()
: rclcpp::Node("s"),
  default_ids_{"simple_smoother"},
  default_types_{"nav2_smoother::SimpleSmoother"},
  others_{"first"}
{
}
void S::configure() {
  ids_ = declare_parameter("smoother_plugins", default_ids_);
  if (ids_ == default_ids_) {
    for (size_t i = 0; i < default_ids_.size(); ++i) {
      declare_parameter(default_ids_[i] + ".plugin", default_types_[i]);
    }
  }
  for (const auto & name : others_) {
    declare_parameter(name + ".other", 1.0);  // extend() changes it: not constant
  }
}
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<S>();
  node->configure();
  rclcpp::spin(node);
}
"""


def test_each_element_of_a_member_the_constructor_initialises(write_tree) -> None:
    """navigation2's smoother and behavior servers keep their default ids in a member
    the constructor initialises with a braced list (``default_ids_{"simple_smoother"}``)
    and nothing else writes: its elements, as a constant's (was ``?.plugin``)."""
    root = write_tree({"cl/package.xml": package_xml("cl", "ament_cmake"),
                       "cl/src/s.cpp": MEMBER_NODE})
    result = extract_cpp([str(root / "cl" / "src" / "s.cpp")], scan([str(root)]),
                         cache_dir=None)
    declared = sorted(c.name for c in result.calls if c.kind == "declare")
    assert declared == ["?.other", "simple_smoother.plugin", "smoother_plugins"]
