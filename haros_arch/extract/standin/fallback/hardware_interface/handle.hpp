// haros_arch stand-in: ros2_control's state and command interfaces (handles; declarations
// only). The Humble API (a handle on a double, set_value returning nothing) and the Jazzy
// one (typed values, get_optional, set_value returning whether it was set) are both here.
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_HANDLE_HPP
#define HAROS_STANDIN_HARDWARE_INTERFACE_HANDLE_HPP
#include <functional>
#include <memory>
#include <optional>
#include <shared_mutex>
#include <string>
#include <hardware_interface/hardware_info.hpp>
namespace hardware_interface {
class Handle {
public:
  Handle(const std::string& prefix_name, const std::string& interface_name, double* value_ptr);
  explicit Handle(const std::string& prefix_name, const std::string& interface_name,
                  const std::string& data_type = "double",
                  const std::string& initial_value = "");
  explicit Handle(const InterfaceDescription& interface_description);
  explicit Handle(const std::string& interface_name);
  explicit Handle(const char* interface_name);
  Handle(const Handle& other);
  Handle(Handle&& other);
  Handle& operator=(const Handle& other);
  Handle& operator=(Handle&& other);
  virtual ~Handle();
  const std::string& get_name() const;
  const std::string& get_interface_name() const;
  const std::string get_full_name() const;
  const std::string& get_prefix_name() const;
  double get_value() const;
  template <typename T = double> std::optional<T> get_optional() const;
  template <typename T> bool get_value(T& value, bool wait_for_lock) const;
  template <typename T> bool set_value(const T& value);
  template <typename T> bool set_value(const T& value, bool wait_for_lock);
  std::shared_mutex& get_mutex() const;
  HandleDataType get_data_type() const;
  bool is_castable_to_double() const;
  bool is_valid() const;
protected:
  std::string prefix_name_;
  std::string interface_name_;
  std::string handle_name_;
  double* value_ptr_;
};
class StateInterface : public Handle {
public:
  explicit StateInterface(const InterfaceDescription& interface_description);
  StateInterface(const StateInterface& other);
  StateInterface(StateInterface&& other);
  using Handle::Handle;
  using SharedPtr = std::shared_ptr<StateInterface>;
  using ConstSharedPtr = std::shared_ptr<const StateInterface>;
};
class CommandInterface : public Handle {
public:
  explicit CommandInterface(const InterfaceDescription& interface_description);
  CommandInterface(const CommandInterface& other) = delete;
  CommandInterface(CommandInterface&& other);
  using Handle::Handle;
  void set_on_set_command_limiter(std::function<double(double, bool&)> on_set_command_limiter);
  template <typename T> bool set_limited_value(const T& value);
  const bool& is_limited() const;
  using SharedPtr = std::shared_ptr<CommandInterface>;
};
}  // namespace hardware_interface
#endif
