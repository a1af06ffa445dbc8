// haros_arch stand-in: the state interface a controller is loaned (declarations only)
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_LOANED_STATE_INTERFACE_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_LOANED_STATE_INTERFACE_HPP
#include <functional>
#include <optional>
#include <string>
#include <hardware_interface/handle.hpp>
namespace hardware_interface {
class LoanedStateInterface {
public:
  using Deleter = std::function<void(void)>;
  explicit LoanedStateInterface(const StateInterface& state_interface);
  LoanedStateInterface(const StateInterface& state_interface, Deleter&& deleter);
  LoanedStateInterface(StateInterface::ConstSharedPtr state_interface, Deleter&& deleter);
  LoanedStateInterface(const LoanedStateInterface& other) = delete;
  LoanedStateInterface(LoanedStateInterface&& other);
  virtual ~LoanedStateInterface();
  const std::string& get_name() const;
  const std::string& get_interface_name() const;
  const std::string get_full_name() const;
  const std::string& get_prefix_name() const;
  double get_value() const;
  template <typename T = double> std::optional<T> get_optional(unsigned int max_tries = 10) const;
  template <typename T> bool get_value(T& value, unsigned int max_tries = 10) const;
  HandleDataType get_data_type() const;
};
}  // namespace hardware_interface
#endif
