// haros_arch stand-in: ros2_control's semantic components, state interfaces read as one
// message (declarations only; headers.FALLBACK)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENT_INTERFACE_HPP
#define HAROS_STANDIN_SEMANTIC_COMPONENT_INTERFACE_HPP
#include <array>
#include <functional>
#include <string>
#include <vector>
#include <hardware_interface/loaned_state_interface.hpp>
namespace semantic_components {
template <typename MessageReturnType>
class SemanticComponentInterface {
public:
  SemanticComponentInterface(const std::string& name,
                             const std::vector<std::string>& interface_names);
  explicit SemanticComponentInterface(const std::string& name, std::size_t size = 0);
  virtual ~SemanticComponentInterface();
  bool assign_loaned_state_interfaces(
      std::vector<hardware_interface::LoanedStateInterface>& state_interfaces);
  void release_interfaces();
  virtual std::vector<std::string> get_state_interface_names();
  bool get_values(std::vector<double>& values) const;
  bool get_values_as_message(MessageReturnType& message);
protected:
  std::string name_;
  std::vector<std::string> interface_names_;
  std::vector<std::reference_wrapper<hardware_interface::LoanedStateInterface>> state_interfaces_;
};
}  // namespace semantic_components
#endif
