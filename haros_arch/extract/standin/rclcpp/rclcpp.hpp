// haros_arch stand-in: rclcpp, the ROS 2 C++ client library (declarations only)
#ifndef HAROS_STANDIN_RCLCPP_HPP
#define HAROS_STANDIN_RCLCPP_HPP
#include <array>
#include <chrono>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include <filesystem>
#include <rmw/qos_profiles.h>
#include <rcl/haros_rcl.h>
#include <rclcpp/serialization.hpp>
#include <rclcpp/type_adapter.hpp>
#define RCLCPP_SMART_PTR_ALIASES_ONLY(T) \
  using SharedPtr = std::shared_ptr<T>; using ConstSharedPtr = std::shared_ptr<const T>; \
  using UniquePtr = std::unique_ptr<T>; using WeakPtr = std::weak_ptr<T>;
#define RCLCPP_SMART_PTR_DEFINITIONS(T) RCLCPP_SMART_PTR_ALIASES_ONLY(T) \
  template<class... HarosArgs> static std::shared_ptr<T> make_shared(HarosArgs&&... args); \
  template<class... HarosArgs> static std::unique_ptr<T> make_unique(HarosArgs&&... args);
#define RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(T) RCLCPP_SMART_PTR_DEFINITIONS(T)
#define RCLCPP_SHARED_PTR_DEFINITIONS(T) \
  using SharedPtr = std::shared_ptr<T>; using ConstSharedPtr = std::shared_ptr<const T>;
#define RCLCPP_WEAK_PTR_DEFINITIONS(T) using WeakPtr = std::weak_ptr<T>;
#define RCLCPP_UNIQUE_PTR_DEFINITIONS(T) using UniquePtr = std::unique_ptr<T>;
#define RCLCPP_DISABLE_COPY(T)
#define RCLCPP_PUBLIC
#define RCLCPP_LOCAL
// rclcpp/version.h: the version of the analysed distribution, given as -D flags
// (extract/cpp/versions.py); without them Jazzy's, whose API the stand-ins follow
#ifdef RCLCPP_VERSION_MAJOR
#define HAROS_RCLCPP_VERSION_GIVEN  // the analysed distribution's rclcpp
#endif
#ifndef RCLCPP_VERSION_MAJOR
#define RCLCPP_VERSION_MAJOR (28)
#define RCLCPP_VERSION_MINOR (1)
#define RCLCPP_VERSION_PATCH (14)
#define RCLCPP_VERSION_STR "28.1.14"
#endif
#define RCLCPP_VERSION_GTE(major, minor, patch) ( \
  (major < RCLCPP_VERSION_MAJOR) ? true : (major > RCLCPP_VERSION_MAJOR) ? false : \
  (minor < RCLCPP_VERSION_MINOR) ? true : (minor > RCLCPP_VERSION_MINOR) ? false : \
  (patch <= RCLCPP_VERSION_PATCH))
// each message as its generated header (``ros2_interfaces.render``) guards it: the first
// definition met is the one, whichever of the two a unit includes first
namespace rcl_interfaces { namespace msg {
// with the generated messages' set__<field> setters (chained: each returns the message)
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_FLOATINGPOINTRANGE_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_FLOATINGPOINTRANGE_HPP
struct FloatingPointRange { double from_value, to_value, step;
  FloatingPointRange& set__from_value(double v); FloatingPointRange& set__to_value(double v);
  FloatingPointRange& set__step(double v); };
#endif
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_INTEGERRANGE_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_INTEGERRANGE_HPP
struct IntegerRange { int64_t from_value, to_value; uint64_t step;
  IntegerRange& set__from_value(int64_t v); IntegerRange& set__to_value(int64_t v);
  IntegerRange& set__step(uint64_t v); };
#endif
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETERDESCRIPTOR_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETERDESCRIPTOR_HPP
struct ParameterDescriptor {
  std::string name; uint8_t type; std::string description; std::string additional_constraints;
  bool read_only; bool dynamic_typing;
  std::vector<FloatingPointRange> floating_point_range; std::vector<IntegerRange> integer_range;
  ParameterDescriptor& set__name(const std::string& v);
  ParameterDescriptor& set__type(uint8_t v);
  ParameterDescriptor& set__description(const std::string& v);
  ParameterDescriptor& set__additional_constraints(const std::string& v);
  ParameterDescriptor& set__read_only(bool v);
  ParameterDescriptor& set__dynamic_typing(bool v);
  ParameterDescriptor& set__floating_point_range(const std::vector<FloatingPointRange>& v);
  ParameterDescriptor& set__integer_range(const std::vector<IntegerRange>& v);
};
#endif
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_SETPARAMETERSRESULT_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_SETPARAMETERSRESULT_HPP
struct SetParametersResult {
  bool successful; using _successful_type = bool; SetParametersResult& set__successful(const bool& _arg);
  std::string reason; using _reason_type = std::string; SetParametersResult& set__reason(const std::string& _arg);
  RCLCPP_SMART_PTR_ALIASES_ONLY(SetParametersResult)
};
#endif
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_LISTPARAMETERSRESULT_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_LISTPARAMETERSRESULT_HPP
struct ListParametersResult {
  std::vector<std::string> names; using _names_type = std::vector<std::string>; ListParametersResult& set__names(const std::vector<std::string>& _arg);
  std::vector<std::string> prefixes; using _prefixes_type = std::vector<std::string>; ListParametersResult& set__prefixes(const std::vector<std::string>& _arg);
  RCLCPP_SMART_PTR_ALIASES_ONLY(ListParametersResult)
};
#endif
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETERTYPE_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETERTYPE_HPP
struct ParameterType {
  static constexpr uint8_t PARAMETER_NOT_SET = 0, PARAMETER_BOOL = 1, PARAMETER_INTEGER = 2,
    PARAMETER_DOUBLE = 3, PARAMETER_STRING = 4, PARAMETER_BYTE_ARRAY = 5,
    PARAMETER_BOOL_ARRAY = 6, PARAMETER_INTEGER_ARRAY = 7, PARAMETER_DOUBLE_ARRAY = 8,
    PARAMETER_STRING_ARRAY = 9;
};
#endif
} }
namespace builtin_interfaces { namespace msg {
#ifndef HAROS_SYNTH2_BUILTIN_INTERFACES_MSG_TIME_HPP
#define HAROS_SYNTH2_BUILTIN_INTERFACES_MSG_TIME_HPP
struct Time { int32_t sec; uint32_t nanosec; using _sec_type = int32_t; using _nanosec_type = uint32_t;
  Time& set__sec(const int32_t& _arg); Time& set__nanosec(const uint32_t& _arg); RCLCPP_SMART_PTR_ALIASES_ONLY(Time) };
#endif
#ifndef HAROS_SYNTH2_BUILTIN_INTERFACES_MSG_DURATION_HPP
#define HAROS_SYNTH2_BUILTIN_INTERFACES_MSG_DURATION_HPP
struct Duration { int32_t sec; uint32_t nanosec; using _sec_type = int32_t; using _nanosec_type = uint32_t;
  Duration& set__sec(const int32_t& _arg); Duration& set__nanosec(const uint32_t& _arg); RCLCPP_SMART_PTR_ALIASES_ONLY(Duration) };
#endif
} }
// the parameter event messages, as rosidl generates them: rclcpp's headers include them
// (a parameter event callback reads event->changed_parameters without an include)
namespace rcl_interfaces { namespace msg {
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETERVALUE_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETERVALUE_HPP
struct ParameterValue {
  ParameterValue();
  uint8_t type; using _type_type = uint8_t; ParameterValue& set__type(const uint8_t& _arg);
  bool bool_value; using _bool_value_type = bool; ParameterValue& set__bool_value(const bool& _arg);
  int64_t integer_value; using _integer_value_type = int64_t; ParameterValue& set__integer_value(const int64_t& _arg);
  double double_value; using _double_value_type = double; ParameterValue& set__double_value(const double& _arg);
  std::string string_value; using _string_value_type = std::string; ParameterValue& set__string_value(const std::string& _arg);
  std::vector<uint8_t> byte_array_value; using _byte_array_value_type = std::vector<uint8_t>; ParameterValue& set__byte_array_value(const std::vector<uint8_t>& _arg);
  std::vector<bool> bool_array_value; using _bool_array_value_type = std::vector<bool>; ParameterValue& set__bool_array_value(const std::vector<bool>& _arg);
  std::vector<int64_t> integer_array_value; using _integer_array_value_type = std::vector<int64_t>; ParameterValue& set__integer_array_value(const std::vector<int64_t>& _arg);
  std::vector<double> double_array_value; using _double_array_value_type = std::vector<double>; ParameterValue& set__double_array_value(const std::vector<double>& _arg);
  std::vector<std::string> string_array_value; using _string_array_value_type = std::vector<std::string>; ParameterValue& set__string_array_value(const std::vector<std::string>& _arg);
  bool operator==(const ParameterValue& other) const;
  bool operator!=(const ParameterValue& other) const;
  RCLCPP_SMART_PTR_ALIASES_ONLY(ParameterValue)
};
#endif
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETER_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETER_HPP
struct Parameter {
  Parameter();
  std::string name; using _name_type = std::string; Parameter& set__name(const std::string& _arg);
  ParameterValue value; using _value_type = ParameterValue; Parameter& set__value(const ParameterValue& _arg);
  bool operator==(const Parameter& other) const;
  bool operator!=(const Parameter& other) const;
  RCLCPP_SMART_PTR_ALIASES_ONLY(Parameter)
};
#endif
#ifndef HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETEREVENT_HPP
#define HAROS_SYNTH2_RCL_INTERFACES_MSG_PARAMETEREVENT_HPP
struct ParameterEvent {
  ParameterEvent();
  builtin_interfaces::msg::Time stamp; using _stamp_type = builtin_interfaces::msg::Time; ParameterEvent& set__stamp(const builtin_interfaces::msg::Time& _arg);
  std::string node; using _node_type = std::string; ParameterEvent& set__node(const std::string& _arg);
  std::vector<Parameter> new_parameters; using _new_parameters_type = std::vector<Parameter>; ParameterEvent& set__new_parameters(const std::vector<Parameter>& _arg);
  std::vector<Parameter> changed_parameters; using _changed_parameters_type = std::vector<Parameter>; ParameterEvent& set__changed_parameters(const std::vector<Parameter>& _arg);
  std::vector<Parameter> deleted_parameters; using _deleted_parameters_type = std::vector<Parameter>; ParameterEvent& set__deleted_parameters(const std::vector<Parameter>& _arg);
  bool operator==(const ParameterEvent& other) const;
  bool operator!=(const ParameterEvent& other) const;
  RCLCPP_SMART_PTR_ALIASES_ONLY(ParameterEvent)
};
#endif
} }
// rosidl's traits of the messages above, as ros2_interfaces.traits guards them
#include <rosidl_runtime_cpp/traits.hpp>
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_FLOATINGPOINTRANGE
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_FLOATINGPOINTRANGE
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::FloatingPointRange> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_INTEGERRANGE
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_INTEGERRANGE
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::IntegerRange> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETERDESCRIPTOR
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETERDESCRIPTOR
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::ParameterDescriptor> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_SETPARAMETERSRESULT
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_SETPARAMETERSRESULT
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::SetParametersResult> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_LISTPARAMETERSRESULT
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_LISTPARAMETERSRESULT
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::ListParametersResult> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETERTYPE
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETERTYPE
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::ParameterType> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETERVALUE
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETERVALUE
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::ParameterValue> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETER
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETER
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::Parameter> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETEREVENT
#define HAROS_TRAIT_IS_MESSAGE_RCL_INTERFACES_MSG_PARAMETEREVENT
template<> struct rosidl_generator_traits::is_message<rcl_interfaces::msg::ParameterEvent> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_BUILTIN_INTERFACES_MSG_TIME
#define HAROS_TRAIT_IS_MESSAGE_BUILTIN_INTERFACES_MSG_TIME
template<> struct rosidl_generator_traits::is_message<builtin_interfaces::msg::Time> : std::true_type {};
#endif
#ifndef HAROS_TRAIT_IS_MESSAGE_BUILTIN_INTERFACES_MSG_DURATION
#define HAROS_TRAIT_IS_MESSAGE_BUILTIN_INTERFACES_MSG_DURATION
template<> struct rosidl_generator_traits::is_message<builtin_interfaces::msg::Duration> : std::true_type {};
#endif
namespace rclcpp {
void init(int argc, char const* const argv[]);
bool ok(std::shared_ptr<class Context> context = nullptr);
bool shutdown(std::shared_ptr<class Context> context = nullptr, const std::string& reason = "");
void on_shutdown(std::function<void()> callback);
template<class R, class P> bool sleep_for(const std::chrono::duration<R, P>& d);
std::vector<std::string> init_and_remove_ros_arguments(int argc, char const* const argv[]);
std::vector<std::string> remove_ros_arguments(int argc, char const* const argv[]);
enum ParameterType : unsigned char { PARAMETER_NOT_SET, PARAMETER_BOOL, PARAMETER_INTEGER,
  PARAMETER_DOUBLE, PARAMETER_STRING, PARAMETER_BYTE_ARRAY, PARAMETER_BOOL_ARRAY,
  PARAMETER_INTEGER_ARRAY, PARAMETER_DOUBLE_ARRAY, PARAMETER_STRING_ARRAY };
// the value type of get<ParameterType>() / get_value<ParameterType>()
template<ParameterType P> struct haros_parameter_value { using type = std::string; };
template<> struct haros_parameter_value<PARAMETER_BOOL> { using type = bool; };
template<> struct haros_parameter_value<PARAMETER_INTEGER> { using type = int64_t; };
template<> struct haros_parameter_value<PARAMETER_DOUBLE> { using type = double; };
template<> struct haros_parameter_value<PARAMETER_BYTE_ARRAY> {
  using type = std::vector<uint8_t>; };
template<> struct haros_parameter_value<PARAMETER_BOOL_ARRAY> { using type = std::vector<bool>; };
template<> struct haros_parameter_value<PARAMETER_INTEGER_ARRAY> {
  using type = std::vector<int64_t>; };
template<> struct haros_parameter_value<PARAMETER_DOUBLE_ARRAY> {
  using type = std::vector<double>; };
template<> struct haros_parameter_value<PARAMETER_STRING_ARRAY> {
  using type = std::vector<std::string>; };
// the type declare_parameter(name, default) gives for a default of type T: get<T>() of
// its ParameterValue, which for a vector of int or float is the vector of the parameter's
// own type (a member std::vector<int64_t> set from std::vector<int>{16, 18}: spot_ros2)
template<class T> struct haros_declared { using type = T; };
template<> struct haros_declared<std::vector<int>> { using type = std::vector<int64_t>; };
template<> struct haros_declared<std::vector<float>> { using type = std::vector<double>; };
class ParameterValue {
public:
  ParameterValue();
  template<class T> ParameterValue(const T& v);
  ParameterType get_type() const;
  template<class T> T get() const;
  template<ParameterType P> const typename haros_parameter_value<P>::type& get() const;
  bool operator==(const ParameterValue& other) const;
  bool operator!=(const ParameterValue& other) const;
};
// rclcpp/parameter_value.hpp: a value or a type as text (ros2_shared's context macros
// log each parameter with to_string(ParameterValue{member}))
std::string to_string(ParameterType type);
std::string to_string(const ParameterValue& value);
class Parameter {
public:
  Parameter();
  explicit Parameter(const std::string& name);
  template<class T> Parameter(const std::string& name, const T& value);
  const std::string& get_name() const;
  ParameterType get_type() const;
  std::string get_type_name() const;
  ParameterValue get_parameter_value() const;
  template<class T> T get_value() const;
  template<ParameterType P> const typename haros_parameter_value<P>::type& get_value() const;
  bool as_bool() const;
  int64_t as_int() const;
  double as_double() const;
  const std::string& as_string() const;
  const std::vector<uint8_t>& as_byte_array() const;
  const std::vector<bool>& as_bool_array() const;
  const std::vector<int64_t>& as_integer_array() const;
  const std::vector<double>& as_double_array() const;
  const std::vector<std::string>& as_string_array() const;
  std::string value_to_string() const;
  static Parameter from_parameter_msg(const rcl_interfaces::msg::Parameter& parameter);
  rcl_interfaces::msg::Parameter to_parameter_msg() const;
};
class Duration {
public:
  Duration(int32_t seconds, uint32_t nanoseconds);
  template<class R, class P> Duration(const std::chrono::duration<R, P>& d);
  Duration(const builtin_interfaces::msg::Duration& d);
  static Duration from_seconds(double seconds);
  static Duration from_nanoseconds(int64_t ns);
  static Duration max();
  double seconds() const;
  int64_t nanoseconds() const;
  template<class D> D to_chrono() const;
  operator builtin_interfaces::msg::Duration() const;
  bool operator<(const Duration& o) const;
  bool operator>(const Duration& o) const;
  bool operator>=(const Duration& o) const;
  bool operator<=(const Duration& o) const;
  bool operator==(const Duration& o) const;
  bool operator!=(const Duration& o) const;
  Duration operator+(const Duration& o) const;
  Duration operator-(const Duration& o) const;
  Duration operator*(double s) const;
};
class Time {
public:
  Time();
  Time(int32_t seconds, uint32_t nanoseconds);
  explicit Time(int64_t nanoseconds, rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  Time(int32_t seconds, uint32_t nanoseconds, rcl_clock_type_t clock_type);
  rcl_clock_type_t get_clock_type() const;
  Time(const builtin_interfaces::msg::Time& t, rcl_clock_type_t clock_type = RCL_ROS_TIME);
  double seconds() const;
  int64_t nanoseconds() const;
  operator builtin_interfaces::msg::Time() const;
  Duration operator-(const Time& o) const;
  Time operator+(const Duration& d) const;
  Time operator-(const Duration& d) const;
  bool operator<(const Time& o) const;
  bool operator>(const Time& o) const;
  bool operator>=(const Time& o) const;
  bool operator<=(const Time& o) const;
  bool operator==(const Time& o) const;
  bool operator!=(const Time& o) const;
  Time& operator+=(const Duration& d);
  Time& operator-=(const Duration& d);
};
class Clock {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Clock)
  explicit Clock(rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  Time now() const;
  rcl_clock_type_t get_clock_type() const;
  bool sleep_for(Duration d);
  bool sleep_until(Time until);
  bool wait_until_started();
  template<class R, class P> bool wait_until_started(const std::chrono::duration<R, P>& timeout);
  bool started();
};
// rate.hpp: humble's Rate is GenericRate<system_clock>, jazzy's a class of its own
// taking a clock; both declare the smart pointer aliases (``Rate::make_shared(hz)``,
// ``Rate::SharedPtr``: reachy2_core's gazebo_mimic plugin)
class RateBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(RateBase)
  virtual ~RateBase();
  virtual bool sleep() = 0;
  virtual rcl_clock_type_t get_type() const = 0;
  virtual void reset() = 0;
};
class Rate : public RateBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Rate)
  explicit Rate(double rate, Clock::SharedPtr clock = Clock::SharedPtr());
  explicit Rate(const Duration& period, Clock::SharedPtr clock = Clock::SharedPtr());
  template<class R, class P> explicit Rate(const std::chrono::duration<R, P>& period);
  bool sleep() override;
  void reset() override;
  rcl_clock_type_t get_type() const override;
  bool is_steady() const;
  std::chrono::nanoseconds period() const;
};
template<class C = std::chrono::high_resolution_clock> class GenericRate : public RateBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericRate)
  explicit GenericRate(double rate);
  template<class R, class P> explicit GenericRate(const std::chrono::duration<R, P>& period);
  bool sleep() override;
  void reset() override;
  rcl_clock_type_t get_type() const override;
  bool is_steady() const;
  std::chrono::nanoseconds period() const;
};
typedef Rate WallRate;
class Logger {
public:
  enum class Level { Unset = 0, Debug = 10, Info = 20, Warn = 30, Error = 40, Fatal = 50 };
  void set_level(Level level);
  Level get_effective_level() const;
  const char* get_name() const;
  Logger get_child(const std::string& suffix);
};
Logger get_logger(const std::string& name);
// the logging macros take a std::string as the format too (logging.hpp passes the first
// argument through rclcpp::get_c_string of utilities.hpp)
namespace haros {
void log(const Logger& logger, const char* format, ...);
void log(const Logger& logger, const std::string& format, ...);
}
const char* get_c_string(const char* string_in);
const char* get_c_string(const std::string& string_in);
// QoS
// (``Unknown``: what a QoS copied from another endpoint may hold; foxglove_bridge tests
// ``qos.history() == rclcpp::HistoryPolicy::Unknown``)
enum class ReliabilityPolicy { BestEffort, Reliable, SystemDefault, BestAvailable, Unknown };
enum class DurabilityPolicy { Volatile, TransientLocal, SystemDefault, BestAvailable, Unknown };
enum class HistoryPolicy { KeepLast, KeepAll, SystemDefault, Unknown };
enum class LivelinessPolicy { Automatic, ManualByTopic, SystemDefault, BestAvailable, Unknown };
enum class QosPolicyKind { AvoidRosNamespaceConventions, Deadline, Depth, Durability, History,
  Lifespan, Liveliness, LivelinessLeaseDuration, Reliability, Invalid };
struct QoSInitialization {
  QoSInitialization(rmw_qos_history_policy_t history, size_t depth);
  static QoSInitialization from_rmw(const rmw_qos_profile_t& profile);
};
struct KeepLast : QoSInitialization { explicit KeepLast(size_t depth); };
struct KeepAll : QoSInitialization { KeepAll(); };
class QoS {
public:
  QoS(const QoSInitialization& init, const rmw_qos_profile_t& profile = rmw_qos_profile_default);
  QoS(size_t history_depth);
  rmw_qos_profile_t& get_rmw_qos_profile();
  const rmw_qos_profile_t& get_rmw_qos_profile() const;
  QoS& liveliness(rmw_qos_liveliness_policy_t l);
  QoS& liveliness(LivelinessPolicy l);
  QoS& liveliness_lease_duration(rmw_time_t d);
  QoS& liveliness_lease_duration(const Duration& d);
  QoS& deadline(rmw_time_t d);
  QoS& deadline(const Duration& d);
  QoS& lifespan(rmw_time_t d);
  QoS& lifespan(const Duration& d);
  QoS& avoid_ros_namespace_conventions(bool v);
  HistoryPolicy history() const;
  ReliabilityPolicy reliability() const;
  DurabilityPolicy durability() const;
  LivelinessPolicy liveliness() const;
  Duration deadline() const;
  Duration lifespan() const;
  Duration liveliness_lease_duration() const;
  bool avoid_ros_namespace_conventions() const;
  bool operator==(const QoS& o) const;
  bool operator!=(const QoS& o) const;
  QoS& keep_last(size_t depth);
  QoS& keep_all();
  QoS& reliable();
  QoS& best_effort();
  QoS& reliability(rmw_qos_reliability_policy_t r);
  QoS& reliability(ReliabilityPolicy r);
  QoS& durability_volatile();
  QoS& transient_local();
  QoS& durability(rmw_qos_durability_policy_t d);
  QoS& durability(DurabilityPolicy d);
  QoS& history(rmw_qos_history_policy_t h);
  QoS& history(HistoryPolicy h);
  template<class R, class P> QoS& deadline(const std::chrono::duration<R, P>& d);
  template<class R, class P> QoS& lifespan(const std::chrono::duration<R, P>& d);
  size_t depth() const;
};
class SensorDataQoS : public QoS { public: explicit SensorDataQoS(const QoSInitialization& i = KeepLast(5)); };
class ParametersQoS : public QoS { public: explicit ParametersQoS(const QoSInitialization& i = KeepLast(1000)); };
class ParameterEventsQoS : public QoS { public: explicit ParameterEventsQoS(const QoSInitialization& i = KeepLast(1000)); };
class ServicesQoS : public QoS { public: explicit ServicesQoS(const QoSInitialization& i = KeepLast(10)); };
class RosoutQoS : public QoS { public: explicit RosoutQoS(const QoSInitialization& i = KeepLast(1000)); };
class SystemDefaultsQoS : public QoS { public: explicit SystemDefaultsQoS(const QoSInitialization& i = KeepLast(10)); };
class ClockQoS : public QoS { public: explicit ClockQoS(const QoSInitialization& i = KeepLast(1)); };
// rclcpp/node_interfaces/node_graph_interface.hpp: an endpoint of a topic as the graph
// tells it (topic_tools' relay takes the type and QoS of its input's publishers)
enum class EndpointType { Invalid = 0, Publisher, Subscription };
class TopicEndpointInfo {
public:
  std::string& node_name();
  const std::string& node_name() const;
  std::string& node_namespace();
  const std::string& node_namespace() const;
  std::string& topic_type();
  const std::string& topic_type() const;
  EndpointType& endpoint_type();
  const EndpointType& endpoint_type() const;
  std::array<uint8_t, 24>& endpoint_gid();
  const std::array<uint8_t, 24>& endpoint_gid() const;
  QoS& qos_profile();
  const QoS& qos_profile() const;
};
// entities
class CallbackGroup { public: RCLCPP_SMART_PTR_DEFINITIONS(CallbackGroup) };
enum class CallbackGroupType { MutuallyExclusive, Reentrant };
// QoS events: one info type with the fields of each rmw event status
struct QOSEventInfo {
  int32_t total_count; int32_t total_count_change; int32_t alive_count;
  int32_t not_alive_count; int32_t alive_count_change; int32_t not_alive_count_change;
  int last_policy_kind; size_t current_count; int32_t current_count_change;
};
using QOSDeadlineOfferedInfo = QOSEventInfo;
using QOSDeadlineRequestedInfo = QOSEventInfo;
using QOSLivelinessChangedInfo = QOSEventInfo;
using QOSLivelinessLostInfo = QOSEventInfo;
using QOSMessageLostInfo = QOSEventInfo;
using QOSOfferedIncompatibleQoSInfo = QOSEventInfo;
using QOSRequestedIncompatibleQoSInfo = QOSEventInfo;
using IncompatibleTypeInfo = QOSEventInfo;
using MatchedInfo = QOSEventInfo;
// rclcpp/event_handler.hpp: the callback types of PublisherEventCallbacks and
// SubscriptionEventCallbacks
using QOSDeadlineOfferedCallbackType = std::function<void(QOSDeadlineOfferedInfo&)>;
using QOSDeadlineRequestedCallbackType = std::function<void(QOSDeadlineRequestedInfo&)>;
using QOSLivelinessChangedCallbackType = std::function<void(QOSLivelinessChangedInfo&)>;
using QOSLivelinessLostCallbackType = std::function<void(QOSLivelinessLostInfo&)>;
using QOSMessageLostCallbackType = std::function<void(QOSMessageLostInfo&)>;
using QOSOfferedIncompatibleQoSCallbackType = std::function<void(QOSOfferedIncompatibleQoSInfo&)>;
using QOSRequestedIncompatibleQoSCallbackType =
    std::function<void(QOSRequestedIncompatibleQoSInfo&)>;
using IncompatibleTypeCallbackType = std::function<void(IncompatibleTypeInfo&)>;
using PublisherMatchedCallbackType = std::function<void(MatchedInfo&)>;
using SubscriptionMatchedCallbackType = std::function<void(MatchedInfo&)>;
struct PublisherEventCallbacks {
  std::function<void(QOSDeadlineOfferedInfo&)> deadline_callback;
  std::function<void(QOSLivelinessLostInfo&)> liveliness_callback;
  std::function<void(QOSOfferedIncompatibleQoSInfo&)> incompatible_qos_callback;
  std::function<void(IncompatibleTypeInfo&)> incompatible_type_callback;
  std::function<void(MatchedInfo&)> matched_callback;
};
struct SubscriptionEventCallbacks {
  std::function<void(QOSDeadlineRequestedInfo&)> deadline_callback;
  std::function<void(QOSLivelinessChangedInfo&)> liveliness_callback;
  std::function<void(QOSRequestedIncompatibleQoSInfo&)> incompatible_qos_callback;
  std::function<void(QOSMessageLostInfo&)> message_lost_callback;
  std::function<void(IncompatibleTypeInfo&)> incompatible_type_callback;
  std::function<void(MatchedInfo&)> matched_callback;
};
enum class IntraProcessSetting { Enable, Disable, NodeDefault };
enum class TopicStatisticsState { Enable, Disable, NodeDefault };
using QosCallbackResult = rcl_interfaces::msg::SetParametersResult;
using QosCallback = std::function<QosCallbackResult(const class QoS&)>;
class QosOverridingOptions {
public:
  QosOverridingOptions();
  QosOverridingOptions(std::initializer_list<QosPolicyKind> policy_kinds,
                       QosCallback validation_callback = nullptr, std::string id = "");
  static QosOverridingOptions with_default_policies(QosCallback validation_callback = nullptr,
                                                    std::string id = "");
  const std::string& get_id() const;
};
namespace detail {
struct TopicStatisticsOptions {
  TopicStatisticsState state; std::string publish_topic;
  std::chrono::milliseconds publish_period;
};
struct ContentFilterOptions {
  std::string filter_expression; std::vector<std::string> expression_parameters;
};
// a client's future with its request's id (rclcpp/client.hpp), which a wrapper's own
// future may derive from (Autoware's agnocast_wrapper::Client)
template<class FutureT> struct FutureAndRequestId {
  FutureT future; int64_t request_id;
  FutureAndRequestId(FutureT impl, int64_t id);
  operator FutureT&(); FutureT share() noexcept;
  decltype(std::declval<FutureT>().get()) get();
  bool valid() const noexcept; void wait() const;
  template<class R, class P> std::future_status wait_for(
      const std::chrono::duration<R, P>& timeout) const;
  template<class C, class D> std::future_status wait_until(
      const std::chrono::time_point<C, D>& deadline) const;
};
}
// rclcpp/subscription_content_filter_options.hpp names it in rclcpp itself
using detail::ContentFilterOptions;
struct PublisherOptionsBase {
  std::shared_ptr<CallbackGroup> callback_group;
  IntraProcessSetting use_intra_process_comm;
  PublisherEventCallbacks event_callbacks;
  bool use_default_callbacks;
  QosOverridingOptions qos_overriding_options;
  rmw_unique_network_flow_endpoints_requirement_t require_unique_network_flow_endpoints;
};
struct SubscriptionOptionsBase {
  std::shared_ptr<CallbackGroup> callback_group;
  IntraProcessSetting use_intra_process_comm;
  SubscriptionEventCallbacks event_callbacks;
  bool use_default_callbacks;
  bool ignore_local_publications;
  detail::TopicStatisticsOptions topic_stats_options;
  QosOverridingOptions qos_overriding_options;
  detail::ContentFilterOptions content_filter_options;
  rmw_unique_network_flow_endpoints_requirement_t require_unique_network_flow_endpoints;
};
template<class A = void> struct PublisherOptionsWithAllocator : PublisherOptionsBase {
  PublisherOptionsWithAllocator();
  PublisherOptionsWithAllocator(const PublisherOptionsBase& base);
  std::shared_ptr<A> allocator;
};
template<class A = void> struct SubscriptionOptionsWithAllocator : SubscriptionOptionsBase {
  SubscriptionOptionsWithAllocator();
  SubscriptionOptionsWithAllocator(const SubscriptionOptionsBase& base);
  std::shared_ptr<A> allocator;
};
using PublisherOptions = PublisherOptionsWithAllocator<std::allocator<void>>;
using SubscriptionOptions = SubscriptionOptionsWithAllocator<std::allocator<void>>;
// rclcpp/network_flow_endpoint.hpp
class NetworkFlowEndpoint {
public:
  const std::string& transport_protocol() const;
  const std::string& internet_protocol() const;
  uint16_t transport_port() const;
  uint32_t flow_label() const;
  uint8_t dscp() const;
  const std::string& internet_address() const;
  bool operator==(const NetworkFlowEndpoint& other) const;
  bool operator!=(const NetworkFlowEndpoint& other) const;
};
class PublisherBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(PublisherBase)
  const char* get_topic_name() const;
  std::vector<NetworkFlowEndpoint> get_network_flow_endpoints() const;
  template<class R = long, class P = std::milli>
  bool wait_for_all_acked(std::chrono::duration<R, P> timeout = std::chrono::duration<R, P>(-1)) const;
  size_t get_subscription_count() const;
  size_t get_intra_process_subscription_count() const;
  const rmw_gid_t& get_gid() const;
};
// the allocator's default is rclcpp's, so a workspace wrapper's
// ``shared_ptr<Publisher<M, std::allocator<void>>>`` is a ``Publisher<M>::SharedPtr``
template<class M, class A = std::allocator<void>> class Publisher : public PublisherBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Publisher)
  using PublishedType = M;
  using ROSMessageType = M;  // (an adapted type's ROS message: not followed here)
  void publish(const M& msg);
  void publish(std::unique_ptr<M> msg);
  void publish(const SerializedMessage& msg);
  template<class T> void publish(const T& msg);  // an adapted type's custom type
  bool assert_liveliness() const;
  rclcpp::QoS get_actual_qos() const;
  bool can_loan_messages() const;
  struct LoanedMessage { M& get(); bool is_valid() const; };
  LoanedMessage borrow_loaned_message();
  void publish(LoanedMessage&& loaned);
};
class MessageInfo;
class SubscriptionBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SubscriptionBase)
  const char* get_topic_name() const;
  size_t get_publisher_count() const;
  rclcpp::QoS get_actual_qos() const;
  std::vector<NetworkFlowEndpoint> get_network_flow_endpoints() const;
  std::shared_ptr<void> create_message();
  bool take_type_erased(void* message, MessageInfo& message_info);
  // an events executor's listeners (rclcpp since humble)
  void set_on_new_message_callback(std::function<void(size_t)> callback);
  void clear_on_new_message_callback();
  void set_on_new_intra_process_message_callback(std::function<void(size_t)> callback);
  void clear_on_new_intra_process_message_callback();
  void handle_message(std::shared_ptr<void>& message, const MessageInfo& message_info);
};
// rclcpp/message_info.hpp: what a subscription callback's second parameter can be
class MessageInfo {
public:
  MessageInfo();
  template<class I> MessageInfo(const I& rmw_message_info);
  const struct rmw_message_info_s& get_rmw_message_info() const;
};
// rclcpp/message_memory_strategy.hpp, strategies/message_pool_memory_strategy.hpp: how a
// subscription allocates its messages, create_subscription's fifth argument
// (aws-deepracer's servo_node hands it a MessagePoolMemoryStrategy)
namespace message_memory_strategy {
template<class M, class A = std::allocator<void>> class MessageMemoryStrategy {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(MessageMemoryStrategy)
  virtual ~MessageMemoryStrategy();
  static SharedPtr create_default();
};
}
namespace strategies { namespace message_pool_memory_strategy {
template<class M, size_t Size, class E = void> class MessagePoolMemoryStrategy
    : public message_memory_strategy::MessageMemoryStrategy<M> {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(MessagePoolMemoryStrategy)
  MessagePoolMemoryStrategy();
};
} }
template<class M, class A = std::allocator<void>> class Subscription : public SubscriptionBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Subscription)
  bool take(M& message_out, MessageInfo& message_info_out);
  bool is_cft_enabled() const;
  void set_content_filter(const std::string& expression,
                          const std::vector<std::string>& parameters = {});
  detail::ContentFilterOptions get_content_filter() const;
  rclcpp::QoS get_actual_qos() const;
};
class GenericPublisher : public PublisherBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericPublisher)
  void publish(const SerializedMessage& msg);
};
class GenericSubscription : public SubscriptionBase { public: RCLCPP_SMART_PTR_DEFINITIONS(GenericSubscription) };
class ServiceBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ServiceBase)
  const char* get_service_name() const;
  void set_on_new_request_callback(std::function<void(size_t)> callback);
  void clear_on_new_request_callback();
};
template<class S> class Service : public ServiceBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Service)
  using SharedRequest = std::shared_ptr<typename S::Request>;
  using SharedResponse = std::shared_ptr<typename S::Response>;
  // the callback types of rclcpp's AnyServiceCallback, as code names them
  using CallbackType = std::function<void(const SharedRequest, SharedResponse)>;
  using CallbackWithHeaderType =
      std::function<void(const std::shared_ptr<rmw_request_id_t>, const SharedRequest,
                         SharedResponse)>;
  void send_response(rmw_request_id_t& header, typename S::Response& response);
  void configure_introspection(std::shared_ptr<Clock> clock, const QoS& qos,
                               rcl_service_introspection_state_t state);
};
class ClientBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ClientBase)
  bool service_is_ready() const;
  template<class R = long, class P = std::ratio<1>>
  bool wait_for_service(std::chrono::duration<R, P> timeout = std::chrono::duration<R, P>(-1));
  const char* get_service_name() const;
  void set_on_new_response_callback(std::function<void(size_t)> callback);
  void clear_on_new_response_callback();
};
template<class S> class Client : public ClientBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Client)
  using SharedRequest = std::shared_ptr<typename S::Request>;
  using SharedResponse = std::shared_ptr<typename S::Response>;
  using SharedFuture = std::shared_future<SharedResponse>;
  using SharedFutureWithRequest = std::shared_future<std::pair<SharedRequest, SharedResponse>>;
  using CallbackType = std::function<void(SharedFuture)>;
  using CallbackWithRequestType = std::function<void(SharedFutureWithRequest)>;
  struct FutureAndRequestId : std::future<SharedResponse> { std::shared_future<SharedResponse> future; long request_id; };
  using SharedFutureAndRequestId = FutureAndRequestId;
  FutureAndRequestId async_send_request(SharedRequest request);
  template<class F> FutureAndRequestId async_send_request(SharedRequest request, F&& callback);
  bool remove_pending_request(long request_id);
  bool remove_pending_request(const FutureAndRequestId& future);
  size_t prune_pending_requests();
  template<class A = std::allocator<long>>
  size_t prune_requests_older_than(std::chrono::time_point<std::chrono::system_clock> time_point,
                                   std::vector<long, A>* pruned_requests = nullptr);
  void configure_introspection(std::shared_ptr<Clock> clock, const QoS& qos,
                               rcl_service_introspection_state_t state);
};
class TimerBase {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(TimerBase)
  void cancel();
  void reset();
  bool is_canceled();
  std::shared_ptr<void> call();
  void execute_callback(const std::shared_ptr<void>& data);
  std::shared_ptr<const rcl_timer_t> get_timer_handle();
  std::chrono::nanoseconds time_until_trigger();
  bool is_ready();
};
// the folder of the process's log files (rclcpp/logging.hpp)
std::filesystem::path get_logging_directory();
template<class F, class = void> class GenericTimer : public TimerBase {
public: RCLCPP_SMART_PTR_DEFINITIONS(GenericTimer) };
template<class F> class WallTimer : public TimerBase { public: RCLCPP_SMART_PTR_DEFINITIONS(WallTimer) };
class NodeOptions {
public:
  NodeOptions();
  NodeOptions& use_intra_process_comms(bool v);
  NodeOptions& allow_undeclared_parameters(bool v);
  NodeOptions& automatically_declare_parameters_from_overrides(bool v);
  NodeOptions& parameter_overrides(const std::vector<Parameter>& p);
  NodeOptions& append_parameter_override(const std::string& name, const ParameterValue& v);
  NodeOptions& arguments(const std::vector<std::string>& a);
  NodeOptions& start_parameter_services(bool v);
  NodeOptions& start_parameter_event_publisher(bool v);
  NodeOptions& enable_logger_service(bool v);
  NodeOptions& enable_topic_statistics(bool v);
  NodeOptions& enable_rosout(bool v);
  NodeOptions& use_global_arguments(bool v);
  NodeOptions& context(std::shared_ptr<class Context> c);
  const std::vector<std::string>& arguments() const;
  const std::vector<Parameter>& parameter_overrides() const;
  bool use_intra_process_comms() const;
};
class Event;
// rclcpp/expand_topic_or_service_name.hpp
std::string expand_topic_or_service_name(const std::string& name, const std::string& node_name,
    const std::string& namespace_, bool is_service = false);
namespace node_interfaces {
class NodeBaseInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeBaseInterface)
  const char* get_name() const; const char* get_namespace() const;
  const char* get_fully_qualified_name() const; std::shared_ptr<class Context> get_context();
  std::string resolve_topic_or_service_name(const std::string& name, bool is_service,
      bool only_expand = false) const;
  template<class... A> std::shared_ptr<CallbackGroup> create_callback_group(A&&... args);
  std::shared_ptr<CallbackGroup> get_default_callback_group();
  std::atomic_bool& get_associated_with_executor_atomic(); };
class NodeTopicsInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeTopicsInterface)
  std::string resolve_topic_name(const std::string& name, bool only_expand = false) const; };
// rclcpp's parameter API on the node's parameters interface (api.RCLCPP_INTERFACES)
struct OnSetParametersCallbackHandle;
class NodeParametersInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeParametersInterface)
  // the callback type of the parameter-set callbacks (foxy's name, kept as an alias)
  using OnParametersSetCallbackType = std::function<rcl_interfaces::msg::SetParametersResult(
      const std::vector<rclcpp::Parameter>&)>;
  using OnSetParametersCallbackType = OnParametersSetCallbackType;  // (rclcpp 28's name)
  template<class C> std::shared_ptr<OnSetParametersCallbackHandle>
      add_on_set_parameters_callback(C callback);
  void remove_on_set_parameters_callback(const OnSetParametersCallbackHandle* handler);
  const rclcpp::ParameterValue& declare_parameter(const std::string& name,
      const rclcpp::ParameterValue& default_value = rclcpp::ParameterValue(),
      const rcl_interfaces::msg::ParameterDescriptor& descriptor =
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false);
  const rclcpp::ParameterValue& declare_parameter(const std::string& name,
      rclcpp::ParameterType type, const rcl_interfaces::msg::ParameterDescriptor& descriptor =
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false);
  void undeclare_parameter(const std::string& name);
  bool has_parameter(const std::string& name) const;
  rclcpp::Parameter get_parameter(const std::string& name) const;
  bool get_parameter(const std::string& name, rclcpp::Parameter& parameter) const;
  std::vector<rclcpp::Parameter> get_parameters(const std::vector<std::string>& names) const;
  bool get_parameters_by_prefix(const std::string& prefix,
      std::map<std::string, rclcpp::Parameter>& parameters) const;
  std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
      const std::vector<rclcpp::Parameter>& parameters);
  rcl_interfaces::msg::SetParametersResult set_parameters_atomically(
      const std::vector<rclcpp::Parameter>& parameters);
  const std::map<std::string, rclcpp::ParameterValue>& get_parameter_overrides() const; };
class NodeLoggingInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeLoggingInterface)
  rclcpp::Logger get_logger() const; const char* get_logger_name() const; };
class NodeClockInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeClockInterface)
  std::shared_ptr<rclcpp::Clock> get_clock();
  std::shared_ptr<const rclcpp::Clock> get_clock() const; };
class NodeGraphInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeGraphInterface)
  std::map<std::string, std::vector<std::string>> get_topic_names_and_types(
      bool no_demangle = false) const;
  std::map<std::string, std::vector<std::string>> get_service_names_and_types() const;
  std::vector<std::string> get_node_names() const;
  size_t count_publishers(const std::string& topic) const;
  size_t count_subscribers(const std::string& topic) const;
  std::vector<rclcpp::TopicEndpointInfo> get_publishers_info_by_topic(
      const std::string& topic_name, bool no_mangle = false) const;
  std::vector<rclcpp::TopicEndpointInfo> get_subscriptions_info_by_topic(
      const std::string& topic_name, bool no_mangle = false) const;
  std::shared_ptr<rclcpp::Event> get_graph_event();
  void wait_for_graph_change(std::shared_ptr<rclcpp::Event> event,
                             std::chrono::nanoseconds timeout); };
class NodeServicesInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeServicesInterface) };
class NodeTimersInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeTimersInterface)
  void add_timer(rclcpp::TimerBase::SharedPtr timer,
                 rclcpp::CallbackGroup::SharedPtr callback_group); };
class NodeWaitablesInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeWaitablesInterface) };
struct OnSetParametersCallbackHandle { RCLCPP_SMART_PTR_DEFINITIONS(OnSetParametersCallbackHandle)
  using OnSetParametersCallbackType = NodeParametersInterface::OnParametersSetCallbackType;
  using OnParametersSetCallbackType = OnSetParametersCallbackType; };
struct PreSetParametersCallbackHandle { RCLCPP_SMART_PTR_DEFINITIONS(PreSetParametersCallbackHandle) };
struct PostSetParametersCallbackHandle { RCLCPP_SMART_PTR_DEFINITIONS(PostSetParametersCallbackHandle) };
class NodeTimeSourceInterface { public: RCLCPP_SMART_PTR_DEFINITIONS(NodeTimeSourceInterface) };
#if RCLCPP_VERSION_GTE(21, 0, 0)
// rclcpp/node_interfaces/node_interfaces.hpp (Iron and later): the interfaces of a
// node-like (a node, a lifecycle node, another NodeInterfaces) gathered in one value that
// a node converts to implicitly; its getters name every standard interface (the real
// class has those of its arguments only, which a unit that compiles never goes beyond)
template<class... InterfaceTs> class NodeInterfaces { public:
  template<class NodeT> NodeInterfaces(NodeT& node);  // NOLINT: implicit, as rclcpp's
  template<class NodeT> NodeInterfaces(std::shared_ptr<NodeT> node);
  explicit NodeInterfaces(std::shared_ptr<InterfaceTs>... interfaces);
  template<class InterfaceT> std::shared_ptr<InterfaceT> get();
  std::shared_ptr<NodeBaseInterface> get_node_base_interface();
  std::shared_ptr<NodeClockInterface> get_node_clock_interface();
  std::shared_ptr<NodeGraphInterface> get_node_graph_interface();
  std::shared_ptr<NodeLoggingInterface> get_node_logging_interface();
  std::shared_ptr<NodeParametersInterface> get_node_parameters_interface();
  std::shared_ptr<NodeServicesInterface> get_node_services_interface();
  std::shared_ptr<NodeTimeSourceInterface> get_node_time_source_interface();
  std::shared_ptr<NodeTimersInterface> get_node_timers_interface();
  std::shared_ptr<NodeTopicsInterface> get_node_topics_interface();
  std::shared_ptr<NodeWaitablesInterface> get_node_waitables_interface(); };
#endif
}
using OnSetParametersCallbackHandle = node_interfaces::OnSetParametersCallbackHandle;
// the node: its primitives are what the extractor's API table lists; its publishers of
// the class ``PublisherT`` (a lifecycle node's are LifecyclePublishers, managed entities)
#define HAROS_RCLCPP_NODE_API(NodeT) HAROS_RCLCPP_NODE_API_OF(NodeT, rclcpp::Publisher)
#define HAROS_RCLCPP_NODE_API_OF(NodeT, PublisherT) \
  const char* get_name() const; \
  const rclcpp::NodeOptions& get_node_options() const; \
  rcl_interfaces::msg::ListParametersResult list_parameters( \
      const std::vector<std::string>& prefixes, uint64_t depth) const; \
  const char* get_namespace() const; \
  const char* get_fully_qualified_name() const; \
  const std::string& get_effective_namespace() const; \
  rclcpp::Logger get_logger() const; \
  rclcpp::Clock::SharedPtr get_clock(); \
  rclcpp::Clock::ConstSharedPtr get_clock() const; \
  rclcpp::Time now() const; \
  std::shared_ptr<NodeT> shared_from_this(); \
  rclcpp::CallbackGroup::SharedPtr create_callback_group(rclcpp::CallbackGroupType t, bool automatically_add = true); \
  template<class M, class A = void> std::shared_ptr<PublisherT<M>> create_publisher( \
      const std::string& topic, const rclcpp::QoS& qos, \
      const rclcpp::PublisherOptions& options = rclcpp::PublisherOptions()); \
  template<class M, class C> std::shared_ptr<rclcpp::Subscription<M>> create_subscription( \
      const std::string& topic, const rclcpp::QoS& qos, C&& callback, \
      const rclcpp::SubscriptionOptions& options = rclcpp::SubscriptionOptions(), \
      std::shared_ptr<rclcpp::message_memory_strategy::MessageMemoryStrategy<M>> \
          msg_mem_strat = nullptr); \
  std::shared_ptr<rclcpp::GenericPublisher> create_generic_publisher(const std::string& topic, \
      const std::string& type, const rclcpp::QoS& qos, \
      const rclcpp::PublisherOptions& options = rclcpp::PublisherOptions()); \
  template<class C> std::shared_ptr<rclcpp::GenericSubscription> create_generic_subscription( \
      const std::string& topic, const std::string& type, const rclcpp::QoS& qos, C&& callback, \
      const rclcpp::SubscriptionOptions& options = rclcpp::SubscriptionOptions()); \
  template<class S, class C> std::shared_ptr<rclcpp::Service<S>> create_service( \
      const std::string& name, C&& callback, \
      const rmw_qos_profile_t& qos = rmw_qos_profile_services_default, \
      rclcpp::CallbackGroup::SharedPtr group = nullptr); \
  template<class S> std::shared_ptr<rclcpp::Client<S>> create_client(const std::string& name, \
      const rmw_qos_profile_t& qos = rmw_qos_profile_services_default, \
      rclcpp::CallbackGroup::SharedPtr group = nullptr); \
  template<class S, class C> std::shared_ptr<rclcpp::Service<S>> create_service( \
      const std::string& name, C&& callback, const rclcpp::QoS& qos, \
      rclcpp::CallbackGroup::SharedPtr group = nullptr); \
  template<class S> std::shared_ptr<rclcpp::Client<S>> create_client(const std::string& name, \
      const rclcpp::QoS& qos, rclcpp::CallbackGroup::SharedPtr group = nullptr); \
  template<class R, class P, class C> rclcpp::TimerBase::SharedPtr create_wall_timer( \
      std::chrono::duration<R, P> period, C callback, \
      rclcpp::CallbackGroup::SharedPtr group = nullptr); \
  template<class R, class P, class C> rclcpp::TimerBase::SharedPtr create_timer( \
      std::chrono::duration<R, P> period, C callback, \
      rclcpp::CallbackGroup::SharedPtr group = nullptr); \
  const rclcpp::ParameterValue& declare_parameter(const std::string& name, \
      const rclcpp::ParameterValue& default_value = rclcpp::ParameterValue(), \
      const rcl_interfaces::msg::ParameterDescriptor& descriptor = \
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false); \
  template<class T> auto declare_parameter(const std::string& name, const T& default_value, \
      const rcl_interfaces::msg::ParameterDescriptor& descriptor = \
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false) \
      -> typename std::enable_if<!__is_array(T), \
                                 typename rclcpp::haros_declared<T>::type>::type; \
  /* a character array (a wrapper's declare_parameter<T> of a string literal): its value \
     is a string, as ParameterValue(const char*) and get<T>() make it */ \
  template<class T> auto declare_parameter(const std::string& name, const T& default_value, \
      const rcl_interfaces::msg::ParameterDescriptor& descriptor = \
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false) \
      -> typename std::enable_if<__is_array(T), const std::string&>::type; \
  template<class T> T declare_parameter(const std::string& name, \
      const rcl_interfaces::msg::ParameterDescriptor& descriptor = \
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false); \
  const rclcpp::ParameterValue& declare_parameter(const std::string& name, \
      rclcpp::ParameterType type, const rcl_interfaces::msg::ParameterDescriptor& descriptor = \
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false); \
  std::string declare_parameter(const std::string& name, const char* default_value, \
      const rcl_interfaces::msg::ParameterDescriptor& descriptor = \
          rcl_interfaces::msg::ParameterDescriptor(), bool ignore_override = false); \
  template<class T> std::vector<T> declare_parameters(const std::string& ns, \
      const std::map<std::string, T>& parameters, bool ignore_overrides = false); \
  void undeclare_parameter(const std::string& name); \
  bool has_parameter(const std::string& name) const; \
  rclcpp::Parameter get_parameter(const std::string& name) const; \
  template<class T> bool get_parameter(const std::string& name, T& value) const; \
  template<class T> bool get_parameter_or(const std::string& name, T& value, \
      const T& alternative) const; \
  template<class T> T get_parameter_or(const std::string& name, const T& alternative) const; \
  std::vector<rclcpp::Parameter> get_parameters(const std::vector<std::string>& names) const; \
  template<class T> bool get_parameters(const std::string& prefix, \
      std::map<std::string, T>& values) const; \
  rcl_interfaces::msg::SetParametersResult set_parameter(const rclcpp::Parameter& p); \
  std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters( \
      const std::vector<rclcpp::Parameter>& p); \
  rcl_interfaces::msg::SetParametersResult set_parameters_atomically( \
      const std::vector<rclcpp::Parameter>& p); \
  rcl_interfaces::msg::ParameterDescriptor describe_parameter(const std::string& name) const; \
  std::vector<rcl_interfaces::msg::ParameterDescriptor> describe_parameters( \
      const std::vector<std::string>& names) const; \
  std::vector<uint8_t> get_parameter_types(const std::vector<std::string>& names) const; \
  template<class C> rclcpp::OnSetParametersCallbackHandle::SharedPtr \
      add_on_set_parameters_callback(C callback); \
  template<class C> rclcpp::node_interfaces::PreSetParametersCallbackHandle::SharedPtr \
      add_pre_set_parameters_callback(C callback); \
  template<class C> rclcpp::node_interfaces::PostSetParametersCallbackHandle::SharedPtr \
      add_post_set_parameters_callback(C callback); \
  template<class H> void remove_on_set_parameters_callback(H handler); \
  template<class H> void remove_pre_set_parameters_callback(H handler); \
  template<class H> void remove_post_set_parameters_callback(H handler); \
  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface(); \
  rclcpp::node_interfaces::NodeTopicsInterface::SharedPtr get_node_topics_interface(); \
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr get_node_parameters_interface(); \
  rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr get_node_logging_interface(); \
  rclcpp::node_interfaces::NodeClockInterface::SharedPtr get_node_clock_interface(); \
  rclcpp::node_interfaces::NodeGraphInterface::SharedPtr get_node_graph_interface(); \
  rclcpp::node_interfaces::NodeServicesInterface::SharedPtr get_node_services_interface(); \
  rclcpp::node_interfaces::NodeTimersInterface::SharedPtr get_node_timers_interface(); \
  rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr get_node_waitables_interface(); \
  size_t count_publishers(const std::string& topic) const; \
  size_t count_subscribers(const std::string& topic) const; \
  std::vector<rclcpp::TopicEndpointInfo> get_publishers_info_by_topic( \
      const std::string& topic_name, bool no_mangle = false) const; \
  std::vector<rclcpp::TopicEndpointInfo> get_subscriptions_info_by_topic( \
      const std::string& topic_name, bool no_mangle = false) const; \
  std::map<std::string, std::vector<std::string>> get_topic_names_and_types() const; \
  std::map<std::string, std::vector<std::string>> get_service_names_and_types() const; \
  std::vector<std::string> get_node_names() const; \
  std::shared_ptr<rclcpp::Event> get_graph_event(); \
  void wait_for_graph_change(std::shared_ptr<rclcpp::Event> event, \
                             std::chrono::nanoseconds timeout); \
  using OnSetParametersCallbackHandle = rclcpp::node_interfaces::OnSetParametersCallbackHandle; \
  using OnParametersSetCallbackType = \
      rclcpp::node_interfaces::NodeParametersInterface::OnParametersSetCallbackType; \
  OnParametersSetCallbackType set_on_parameters_set_callback( \
      OnParametersSetCallbackType callback); \
  using PreSetParametersCallbackHandle = \
      rclcpp::node_interfaces::PreSetParametersCallbackHandle; \
  using PostSetParametersCallbackHandle = \
      rclcpp::node_interfaces::PostSetParametersCallbackHandle;
class Node : public std::enable_shared_from_this<Node> {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Node)
  explicit Node(const std::string& node_name, const NodeOptions& options = NodeOptions());
  Node(const std::string& node_name, const std::string& namespace_,
       const NodeOptions& options = NodeOptions());
  virtual ~Node();
  HAROS_RCLCPP_NODE_API(Node)
  Node::SharedPtr create_sub_node(const std::string& sub_namespace);
};
enum class FutureReturnCode { SUCCESS, INTERRUPTED, TIMEOUT };
class PreShutdownCallbackHandle {};
class Context { public: RCLCPP_SMART_PTR_DEFINITIONS(Context) bool is_valid() const;
  std::shared_ptr<rcl_context_t> get_rcl_context();
  template<class C> PreShutdownCallbackHandle add_pre_shutdown_callback(C callback);
  bool remove_pre_shutdown_callback(const PreShutdownCallbackHandle& handle);
  template<class C> void add_on_shutdown_callback(C callback);
  template<class C> C on_shutdown(C callback);  // the callback passed back
  bool shutdown(const std::string& reason); };
namespace memory_strategy { class MemoryStrategy { public: RCLCPP_SMART_PTR_DEFINITIONS(MemoryStrategy) }; }
struct ExecutorOptions {
  ExecutorOptions();
  std::shared_ptr<memory_strategy::MemoryStrategy> memory_strategy;
  std::shared_ptr<Context> context;
  size_t max_conditions;
};
namespace executors {
class Executor {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Executor)
  explicit Executor(const ExecutorOptions& options = ExecutorOptions());
  virtual ~Executor();
  void add_node(std::shared_ptr<Node> node, bool notify = true);
  template<class N> void add_node(std::shared_ptr<N> node, bool notify = true);
  void remove_node(std::shared_ptr<Node> node, bool notify = true);
  template<class N> void remove_node(std::shared_ptr<N> node, bool notify = true);
  void add_callback_group(std::shared_ptr<CallbackGroup> group,
                          std::shared_ptr<node_interfaces::NodeBaseInterface> node,
                          bool notify = true);
  virtual void spin();
  void spin_some(std::chrono::nanoseconds max_duration = std::chrono::nanoseconds(0));
  void spin_all(std::chrono::nanoseconds max_duration);
  void spin_once(std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  template<class N> void spin_node_some(std::shared_ptr<N> node);
  template<class N, class R = long, class P = std::ratio<1>> void spin_node_once(
      std::shared_ptr<N> node, std::chrono::duration<R, P> timeout = std::chrono::duration<R, P>(-1));
  template<class F, class R = long, class P = std::milli> FutureReturnCode
  spin_until_future_complete(const F& future,
                             std::chrono::duration<R, P> timeout = std::chrono::duration<R, P>(-1));
  void cancel();
  bool is_spinning();
};
class SingleThreadedExecutor : public Executor {
public:
  explicit SingleThreadedExecutor(const ExecutorOptions& options = ExecutorOptions());
};
class MultiThreadedExecutor : public Executor {
public:
  explicit MultiThreadedExecutor(const ExecutorOptions& options = ExecutorOptions(),
                                 size_t number_of_threads = 0, bool yield_before_execute = false,
                                 std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  size_t get_number_of_threads();
};
class EventsExecutor : public Executor {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(EventsExecutor)
  explicit EventsExecutor(const ExecutorOptions& options = ExecutorOptions());
};
class StaticSingleThreadedExecutor : public Executor { public: StaticSingleThreadedExecutor(); };
}
// Iron and Jazzy declare the events executor in rclcpp/experimental (later releases
// in rclcpp::executors): bitbots_main's nodes spin on
// ``rclcpp::experimental::executors::EventsExecutor``
namespace experimental { namespace executors { using rclcpp::executors::EventsExecutor; } }
using executors::Executor;
std::ostream& operator<<(std::ostream& os, const FutureReturnCode& code);
std::string to_string(const FutureReturnCode& code);
namespace executor { using FutureReturnCode = rclcpp::FutureReturnCode; }
template<class N> void spin(std::shared_ptr<N> node);
// rclcpp/copy_all_parameter_values.hpp: declares on ``destination`` the parameters
// ``source`` has, with their values (names known only at run time: no API row)
template<class S, class D> void copy_all_parameter_values(
    const S& source, const D& destination, const bool override_existing_params = false);
template<class N> void spin_some(std::shared_ptr<N> node);
// rclcpp's spin takes a Node::SharedPtr, which a std::unique_ptr converts to
template<class N, class D> void spin(std::unique_ptr<N, D>&& node);
template<class N, class D> void spin_some(std::unique_ptr<N, D>&& node);
template<class N, class F> FutureReturnCode spin_until_future_complete(std::shared_ptr<N> node,
                                                                       const F& future);
template<class N, class F, class R, class P> FutureReturnCode spin_until_future_complete(
    std::shared_ptr<N> node, const F& future, std::chrono::duration<R, P> timeout);
namespace contexts {
class DefaultContext : public Context { public: RCLCPP_SMART_PTR_DEFINITIONS(DefaultContext) };
DefaultContext::SharedPtr get_global_default_context();
}
class TimeSource {
public:
  TimeSource();
  template<class N> explicit TimeSource(std::shared_ptr<N> node);
  template<class N> void attachNode(std::shared_ptr<N> node);
  void detachNode();
  void attachClock(std::shared_ptr<Clock> clock);
};
class Event { public: RCLCPP_SMART_PTR_DEFINITIONS(Event) };
class SyncParametersClient {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SyncParametersClient)
  template<class... A> explicit SyncParametersClient(A&&... args);
  template<class R = long, class P = std::ratio<1>>
  bool wait_for_service(std::chrono::duration<R, P> timeout = std::chrono::duration<R, P>(-1));
  std::vector<Parameter> get_parameters(const std::vector<std::string>& names);
  std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
      const std::vector<Parameter>& parameters);
  template<class T> T get_parameter(const std::string& name, const T& default_value);
  bool has_parameter(const std::string& name);
  struct ListParametersResult { std::vector<std::string> names; std::vector<std::string> prefixes; };
  ListParametersResult list_parameters(const std::vector<std::string>& prefixes, uint64_t depth);
  template<class C> std::shared_ptr<void> on_parameter_event(C&& callback);
  template<class C, class... O> std::shared_ptr<void> on_parameter_event(
      C&& callback, const QoS& qos, const O&... options);
  template<class N, class C> static std::shared_ptr<void> on_parameter_event(N node,
                                                                             C&& callback);
  void delete_parameters(const std::vector<std::string>& names);
};
class AsyncParametersClient {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(AsyncParametersClient)
  template<class... A> explicit AsyncParametersClient(A&&... args);
  template<class R = long, class P = std::ratio<1>>
  bool wait_for_service(std::chrono::duration<R, P> timeout = std::chrono::duration<R, P>(-1));
  bool service_is_ready() const;
  template<class C = std::nullptr_t> std::shared_future<std::vector<Parameter>> get_parameters(
      const std::vector<std::string>& names, C callback = nullptr);
  template<class C = std::nullptr_t>
  std::shared_future<std::vector<rcl_interfaces::msg::SetParametersResult>> set_parameters(
      const std::vector<Parameter>& parameters, C callback = nullptr);
  template<class C = std::nullptr_t>
  std::shared_future<rcl_interfaces::msg::SetParametersResult> set_parameters_atomically(
      const std::vector<Parameter>& parameters, C callback = nullptr);
  std::shared_future<std::vector<rcl_interfaces::msg::SetParametersResult>> delete_parameters(
      const std::vector<std::string>& parameters_names);
  template<class C = std::nullptr_t>
  std::shared_future<SyncParametersClient::ListParametersResult> list_parameters(
      const std::vector<std::string>& prefixes, uint64_t depth, C callback = nullptr);
  template<class C> std::shared_ptr<void> on_parameter_event(C&& callback);
  template<class C, class... O> std::shared_ptr<void> on_parameter_event(
      C&& callback, const QoS& qos, const O&... options);
  template<class N, class C> static std::shared_ptr<void> on_parameter_event(N node,
                                                                             C&& callback);
};
// what ParameterEventHandler's add_*_callback give, kept to remove the callback later
struct ParameterCallbackHandle {
  RCLCPP_SMART_PTR_DEFINITIONS(ParameterCallbackHandle)
  using ParameterCallbackType = std::function<void(const Parameter&)>;
  std::string parameter_name;
  std::string node_name;
  ParameterCallbackType callback;
};
struct ParameterEventCallbackHandle {
  RCLCPP_SMART_PTR_DEFINITIONS(ParameterEventCallbackHandle)
  using ParameterEventCallbackType =
      std::function<void(const rcl_interfaces::msg::ParameterEvent&)>;
  ParameterEventCallbackType callback;
};
class ParameterEventHandler {
public:
  template<class N> explicit ParameterEventHandler(N node);
  template<class C> ParameterCallbackHandle::SharedPtr add_parameter_callback(
      const std::string& name, C cb, const std::string& node_name = "");
  template<class C> ParameterEventCallbackHandle::SharedPtr add_parameter_event_callback(C cb);
  void remove_parameter_callback(ParameterCallbackHandle::SharedPtr handle);
  void remove_parameter_event_callback(ParameterEventCallbackHandle::SharedPtr handle);
  static bool get_parameter_from_event(const rcl_interfaces::msg::ParameterEvent& event,
      Parameter& parameter, const std::string& parameter_name, const std::string& node_name = "");
  static Parameter get_parameter_from_event(const rcl_interfaces::msg::ParameterEvent& event,
      const std::string& parameter_name, const std::string& node_name = "");
  static std::vector<Parameter> get_parameters_from_event(
      const rcl_interfaces::msg::ParameterEvent& event);
};
// rclcpp/parameter_events_filter.hpp: the parameters of an event of the names and kinds
// asked (metavision_driver's onParameterEvent); a filter of a message, no ROS call
class ParameterEventsFilter {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ParameterEventsFilter)
  enum class EventType { NEW, DELETED, CHANGED };
  using EventPair = std::pair<EventType, rcl_interfaces::msg::Parameter*>;
  ParameterEventsFilter(std::shared_ptr<const rcl_interfaces::msg::ParameterEvent> event,
                        const std::vector<std::string>& names,
                        const std::vector<EventType>& types);
  const std::vector<EventPair>& get_events() const;
};
// rclcpp/guard_condition.hpp, wait_result_kind.hpp, wait_result.hpp, wait_set_template.hpp
// and wait_set.hpp: a wait set over the node's entities (waits, takes; makes no ROS name)
class GuardCondition {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GuardCondition)
  explicit GuardCondition(std::shared_ptr<Context> context = nullptr);
  void trigger();
};
class Waitable { public: RCLCPP_SMART_PTR_DEFINITIONS(Waitable) };
struct SubscriptionWaitSetMask {
  bool include_subscription = true;
  bool include_events = true;
  bool include_intra_process_waitable = true;
};
enum WaitResultKind { Ready, Timeout, Empty };
template<class W> class WaitResult {
public:
  WaitResultKind kind() const;
  const W& get_wait_set() const;
  W& get_wait_set();
};
namespace wait_set_policies {
struct SequentialSynchronization {};
struct ThreadSafeSynchronization {};
struct haros_entries {
  struct SubscriptionEntry {
    SubscriptionEntry(std::shared_ptr<SubscriptionBase> subscription = nullptr,
                      const SubscriptionWaitSetMask& mask = {});
    std::shared_ptr<SubscriptionBase> subscription;
    SubscriptionWaitSetMask mask;
  };
  struct WaitableEntry {
    WaitableEntry(std::shared_ptr<Waitable> waitable = nullptr,
                  std::shared_ptr<void> associated_entity = nullptr);
    std::shared_ptr<Waitable> waitable;
    std::shared_ptr<void> associated_entity;
  };
};
struct DynamicStorage : haros_entries {
  using SubscriptionsIterable = std::vector<SubscriptionEntry>;
  using GuardConditionsIterable = std::vector<std::shared_ptr<GuardCondition>>;
  using TimersIterable = std::vector<std::shared_ptr<TimerBase>>;
  using ClientsIterable = std::vector<std::shared_ptr<ClientBase>>;
  using ServicesIterable = std::vector<std::shared_ptr<ServiceBase>>;
  using WaitablesIterable = std::vector<WaitableEntry>;
};
template<size_t S, size_t G, size_t T, size_t C, size_t V, size_t W>
struct StaticStorage : haros_entries {
  using SubscriptionsIterable = std::array<SubscriptionEntry, S>;
  using GuardConditionsIterable = std::array<std::shared_ptr<GuardCondition>, G>;
  using TimersIterable = std::array<std::shared_ptr<TimerBase>, T>;
  using ClientsIterable = std::array<std::shared_ptr<ClientBase>, C>;
  using ServicesIterable = std::array<std::shared_ptr<ServiceBase>, V>;
  using WaitablesIterable = std::array<WaitableEntry, W>;
};
}  // namespace wait_set_policies
template<class Sync, class Storage> class WaitSetTemplate {
public:
  RCLCPP_SMART_PTR_DEFINITIONS(WaitSetTemplate)
  using SubscriptionEntry = typename Storage::SubscriptionEntry;
  using WaitableEntry = typename Storage::WaitableEntry;
  explicit WaitSetTemplate(
    const typename Storage::SubscriptionsIterable& subscriptions = {},
    const typename Storage::GuardConditionsIterable& guard_conditions = {},
    const typename Storage::TimersIterable& timers = {},
    const typename Storage::ClientsIterable& clients = {},
    const typename Storage::ServicesIterable& services = {},
    const typename Storage::WaitablesIterable& waitables = {},
    std::shared_ptr<Context> context = nullptr);
  const rcl_wait_set_t& get_rcl_wait_set() const;
  void add_subscription(std::shared_ptr<SubscriptionBase> subscription,
                        SubscriptionWaitSetMask mask = {});
  void remove_subscription(std::shared_ptr<SubscriptionBase> subscription,
                           SubscriptionWaitSetMask mask = {});
  void add_guard_condition(std::shared_ptr<GuardCondition> guard_condition);
  void remove_guard_condition(std::shared_ptr<GuardCondition> guard_condition);
  void add_timer(std::shared_ptr<TimerBase> timer);
  void remove_timer(std::shared_ptr<TimerBase> timer);
  void add_client(std::shared_ptr<ClientBase> client);
  void remove_client(std::shared_ptr<ClientBase> client);
  void add_service(std::shared_ptr<ServiceBase> service);
  void remove_service(std::shared_ptr<ServiceBase> service);
  void add_waitable(std::shared_ptr<Waitable> waitable,
                    std::shared_ptr<void> associated_entity = nullptr);
  void remove_waitable(std::shared_ptr<Waitable> waitable);
  void prune_deleted_entities();
  template<class R = long, class P = std::nano>
  WaitResult<WaitSetTemplate> wait(std::chrono::duration<R, P> time_to_wait =
                                   std::chrono::duration<R, P>(-1));
};
using WaitSet = WaitSetTemplate<wait_set_policies::SequentialSynchronization,
                                wait_set_policies::DynamicStorage>;
using ThreadSafeWaitSet = WaitSetTemplate<wait_set_policies::ThreadSafeSynchronization,
                                          wait_set_policies::DynamicStorage>;
template<size_t S, size_t G, size_t T, size_t C, size_t V, size_t W>
using StaticWaitSet = WaitSetTemplate<wait_set_policies::SequentialSynchronization,
                                      wait_set_policies::StaticStorage<S, G, T, C, V, W>>;
// rclcpp/create_publisher.hpp, create_subscription.hpp: the free functions on a node
template<class M, class A = std::allocator<void>, class P = rclcpp::Publisher<M>, class N,
         class... R>
std::shared_ptr<P> create_publisher(N&& node, const std::string& topic_name,
                                    const rclcpp::QoS& qos, R&&... rest);
template<class M, class C, class A = std::allocator<void>, class... T, class N, class... R>
std::shared_ptr<rclcpp::Subscription<M>> create_subscription(
    N&& node, const std::string& topic_name, const rclcpp::QoS& qos, C&& callback,
    R&&... rest);
template<class M, class C, class A = std::allocator<void>, class... T>
std::shared_ptr<rclcpp::Subscription<M>> create_subscription(
    std::shared_ptr<node_interfaces::NodeParametersInterface> parameters,
    std::shared_ptr<node_interfaces::NodeTopicsInterface> topics,
    const std::string& topic_name, const rclcpp::QoS& qos, C&& callback,
    const SubscriptionOptionsWithAllocator<A>& options = SubscriptionOptionsWithAllocator<A>());
// rclcpp/create_service.hpp, create_client.hpp: on node interfaces (nav2's ServiceServer)
template<class S, class B, class V, class C, class... R>
std::shared_ptr<rclcpp::Service<S>> create_service(
    B&& node_base, V&& node_services, const std::string& service_name, C&& callback,
    R&&... rest);
template<class S, class B, class G, class V, class... R>
std::shared_ptr<rclcpp::Client<S>> create_client(
    B&& node_base, G&& node_graph, V&& node_services, const std::string& service_name,
    R&&... rest);
class UnsupportedEventTypeException : public std::runtime_error {
public:
  explicit UnsupportedEventTypeException(const std::string& what);
};
// rclcpp/create_timer.hpp: a timer on a node (or its interfaces) and a clock
template<class... A> TimerBase::SharedPtr create_timer(A&&... args);
template<class... A> TimerBase::SharedPtr create_wall_timer(A&&... args);
// rclcpp/parameter_value.hpp
class ParameterTypeException : public std::runtime_error {
public:
  ParameterTypeException(ParameterType expected, ParameterType actual);
};
// rclcpp/exceptions/exceptions.hpp
namespace exceptions {
class RCLErrorBase { public: std::string message; std::string file; size_t line; };
class RCLError : public RCLErrorBase, public std::runtime_error {
public: template<class... A> explicit RCLError(A&&... args); };
class RCLBadAlloc : public RCLErrorBase, public std::bad_alloc {
public: template<class... A> explicit RCLBadAlloc(A&&... args); };
class RCLInvalidArgument : public RCLErrorBase, public std::invalid_argument {
public: template<class... A> explicit RCLInvalidArgument(A&&... args); };
template<class... A> void throw_from_rcl_error(A&&... args);
#define HAROS_RCLCPP_EXCEPTION(name, base) \
  class name : public base { public: template<class... A> explicit name(A&&... args); };
HAROS_RCLCPP_EXCEPTION(InvalidNodeError, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(NameValidationError, std::invalid_argument)
HAROS_RCLCPP_EXCEPTION(InvalidNodeNameError, NameValidationError)
HAROS_RCLCPP_EXCEPTION(InvalidNamespaceError, NameValidationError)
HAROS_RCLCPP_EXCEPTION(InvalidTopicNameError, NameValidationError)
HAROS_RCLCPP_EXCEPTION(InvalidServiceNameError, NameValidationError)
HAROS_RCLCPP_EXCEPTION(UnimplementedError, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(InvalidEventError, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(EventNotRegisteredError, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(InvalidParametersException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(InvalidParameterValueException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(InvalidParameterTypeException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(UninitializedStaticallyTypedParameterException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(ParameterAlreadyDeclaredException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(ParameterNotDeclaredException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(ParameterImmutableException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(ParameterModifiedInCallbackException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(ParameterUninitializedException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(InvalidQosOverridesException, std::runtime_error)
HAROS_RCLCPP_EXCEPTION(QoSCheckCompatibleException, std::runtime_error)
#undef HAROS_RCLCPP_EXCEPTION
}  // namespace exceptions
}  // namespace rclcpp
// rclcpp/parameter.hpp adds these to std
namespace std {
string to_string(const rclcpp::Parameter& param);
string to_string(const vector<rclcpp::Parameter>& parameters);
}  // namespace std
#define HAROS_RCLCPP_LOG(logger, ...) ::rclcpp::haros::log(logger, __VA_ARGS__)
#define HAROS_RCLCPP_STREAM(logger, args) do { std::stringstream haros_ss; haros_ss << args; } while (0)
// rclcpp/logging.hpp: every severity with every variant (the real header generates the
// same set); the arguments that are not the message are dropped
#define RCLCPP_DEBUG(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_ONCE(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_EXPRESSION(logger, expression, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_FUNCTION(logger, function, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_SKIPFIRST(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_SKIPFIRST_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_STREAM(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_DEBUG_STREAM_ONCE(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_DEBUG_STREAM_EXPRESSION(logger, expression, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_DEBUG_STREAM_FUNCTION(logger, function, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_DEBUG_STREAM_SKIPFIRST(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_DEBUG_STREAM_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_DEBUG_STREAM_SKIPFIRST_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_INFO(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_ONCE(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_EXPRESSION(logger, expression, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_FUNCTION(logger, function, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_SKIPFIRST(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_SKIPFIRST_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_STREAM(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_INFO_STREAM_ONCE(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_INFO_STREAM_EXPRESSION(logger, expression, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_INFO_STREAM_FUNCTION(logger, function, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_INFO_STREAM_SKIPFIRST(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_INFO_STREAM_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_INFO_STREAM_SKIPFIRST_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_WARN(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_ONCE(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_EXPRESSION(logger, expression, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_FUNCTION(logger, function, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_SKIPFIRST(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_SKIPFIRST_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_STREAM(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_WARN_STREAM_ONCE(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_WARN_STREAM_EXPRESSION(logger, expression, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_WARN_STREAM_FUNCTION(logger, function, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_WARN_STREAM_SKIPFIRST(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_WARN_STREAM_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_WARN_STREAM_SKIPFIRST_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_ERROR(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_ONCE(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_EXPRESSION(logger, expression, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_FUNCTION(logger, function, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_SKIPFIRST(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_SKIPFIRST_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_STREAM(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_ERROR_STREAM_ONCE(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_ERROR_STREAM_EXPRESSION(logger, expression, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_ERROR_STREAM_FUNCTION(logger, function, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_ERROR_STREAM_SKIPFIRST(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_ERROR_STREAM_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_ERROR_STREAM_SKIPFIRST_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_FATAL(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_ONCE(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_EXPRESSION(logger, expression, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_FUNCTION(logger, function, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_SKIPFIRST(logger, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_SKIPFIRST_THROTTLE(logger, clock, duration, ...) HAROS_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_STREAM(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_FATAL_STREAM_ONCE(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_FATAL_STREAM_EXPRESSION(logger, expression, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_FATAL_STREAM_FUNCTION(logger, function, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_FATAL_STREAM_SKIPFIRST(logger, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_FATAL_STREAM_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#define RCLCPP_FATAL_STREAM_SKIPFIRST_THROTTLE(logger, clock, duration, args) HAROS_RCLCPP_STREAM(logger, args)
#endif
