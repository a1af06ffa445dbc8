// Stand-in for rclcpp_cascade_lifecycle (a lifecycle node whose transitions cascade to
// the nodes it names as activations; PlanSys2 builds its servers on it), for a workspace
// that does not hold it. Declarations only: what its constructor makes (the lifecycle
// node's own services and topic, and the activations and states topics it publishes and
// subscribes to) is extract.cpp.api's IMPLICIT.
#ifndef HAROS_RCLCPP_CASCADE_LIFECYCLE_HPP
#define HAROS_RCLCPP_CASCADE_LIFECYCLE_HPP
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"

namespace rclcpp_cascade_lifecycle {
class CascadeLifecycleNode : public rclcpp_lifecycle::LifecycleNode {
public:
  explicit CascadeLifecycleNode(const std::string& node_name,
                                const rclcpp::NodeOptions& options = rclcpp::NodeOptions());
  CascadeLifecycleNode(const std::string& node_name, const std::string& namespace_,
                       const rclcpp::NodeOptions& options = rclcpp::NodeOptions());
  void add_activation(const std::string& node_name);
  void remove_activation(const std::string& node_name);
  void clear_activation();
  const std::set<std::string>& get_activators() const;
  const std::set<std::string>& get_activations() const;
  const std::map<std::string, std::uint8_t>& get_activators_state() const;
};
}  // namespace rclcpp_cascade_lifecycle
#endif
