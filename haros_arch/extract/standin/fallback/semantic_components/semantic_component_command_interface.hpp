// haros_arch stand-in: ros2_control's semantic command components (declarations only)
#ifndef HAROS_STANDIN_SEMANTIC_COMPONENT_COMMAND_INTERFACE_HPP
#define HAROS_STANDIN_SEMANTIC_COMPONENT_COMMAND_INTERFACE_HPP
#include <functional>
#include <string>
#include <vector>
#include <hardware_interface/loaned_command_interface.hpp>
namespace semantic_components {
template <typename MessageInputType>
class SemanticComponentCommandInterface {
public:
  SemanticComponentCommandInterface(const std::string& name,
                                    const std::vector<std::string>& interface_names);
  virtual ~SemanticComponentCommandInterface();
  bool assign_loaned_command_interfaces(
      std::vector<hardware_interface::LoanedCommandInterface>& command_interfaces);
  void release_interfaces();
  const std::vector<std::string>& get_command_interface_names() const;
  bool set_values(const std::vector<double>& values);
  virtual bool set_values_from_message(const MessageInputType& message) = 0;
protected:
  std::string name_;
  std::vector<std::string> interface_names_;
  std::vector<std::reference_wrapper<hardware_interface::LoanedCommandInterface>>
      command_interfaces_;
};
}  // namespace semantic_components
#endif
