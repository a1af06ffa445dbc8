// haros_arch stand-in: the component registration macro
#ifndef HAROS_STANDIN_RCLCPP_COMPONENTS_REGISTER_NODE_MACRO_HPP
#define HAROS_STANDIN_RCLCPP_COMPONENTS_REGISTER_NODE_MACRO_HPP
#include <rclcpp/rclcpp.hpp>
namespace rclcpp_components {
class NodeInstanceWrapper {
public:
  NodeInstanceWrapper();
  template<class N, class I> NodeInstanceWrapper(std::shared_ptr<N> node, I interface_getter);
  std::shared_ptr<void> get_node_instance() const;
  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface();
};
class NodeFactory {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(NodeFactory)
  virtual ~NodeFactory();
  virtual NodeInstanceWrapper create_node_instance(const rclcpp::NodeOptions& options) = 0;
};
template<class N> class NodeFactoryTemplate : public NodeFactory {
public:
  NodeInstanceWrapper create_node_instance(const rclcpp::NodeOptions& options) override;
};
// a container node; a class of the workspace may derive from it (ros2_canopen's
// DeviceContainer): its constructor serves ~/_container/load_node, unload_node and
// list_nodes (an API row), and these are the members a subclass uses
class ComponentManager : public rclcpp::Node {
public:
  template<class... A> explicit ComponentManager(A&&... args);
  virtual ~ComponentManager();
protected:
  virtual rclcpp::NodeOptions create_node_options(const std::shared_ptr<void> request);
  virtual void add_node_to_executor(uint64_t node_id);
  virtual void remove_node_from_executor(uint64_t node_id);
  std::weak_ptr<rclcpp::Executor> executor_;
  uint64_t unique_id_;
  std::map<uint64_t, NodeInstanceWrapper> node_wrappers_;
  rclcpp::ServiceBase::SharedPtr loadNode_srv_;
  rclcpp::ServiceBase::SharedPtr unloadNode_srv_;
  rclcpp::ServiceBase::SharedPtr listNodes_srv_;
};
}
namespace haros_standin { template<class T> struct component_registration { typedef T type; }; }
// a name of its own per registration (a file may register several components)
#define HAROS_COMPONENT_NAME2(counter) haros_component_registration_##counter
#define HAROS_COMPONENT_NAME(counter) HAROS_COMPONENT_NAME2(counter)
#define RCLCPP_COMPONENTS_REGISTER_NODE(NodeClass) \
  static haros_standin::component_registration<NodeClass> HAROS_COMPONENT_NAME(__COUNTER__);
#endif
