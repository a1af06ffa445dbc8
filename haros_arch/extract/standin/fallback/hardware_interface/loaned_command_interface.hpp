// haros_arch stand-in: the command interface a controller is loaned (declarations only)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_LOANED_COMMAND_INTERFACE_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_LOANED_COMMAND_INTERFACE_HPP
#include <functional>
#include <optional>
#include <string>
#include <hardware_interface/handle.hpp>
namespace hardware_interface {
class LoanedCommandInterface {
public:
  using Deleter = std::function<void(void)>;
  explicit LoanedCommandInterface(CommandInterface& command_interface);
  LoanedCommandInterface(CommandInterface& command_interface, Deleter&& deleter);
  LoanedCommandInterface(CommandInterface::SharedPtr command_interface, Deleter&& deleter);
  LoanedCommandInterface(const LoanedCommandInterface& other) = delete;
  LoanedCommandInterface(LoanedCommandInterface&& other);
  virtual ~LoanedCommandInterface();
  const std::string& get_name() const;
  const std::string& get_interface_name() const;
  const std::string get_full_name() const;
  const std::string& get_prefix_name() const;
  template <typename T> bool set_value(const T& value, unsigned int max_tries = 10);
  double get_value() const;
  template <typename T = double> std::optional<T> get_optional(unsigned int max_tries = 10) const;
  template <typename T> bool get_value(T& value, unsigned int max_tries = 10) const;
  HandleDataType get_data_type() const;
};
}  // namespace hardware_interface
#endif
