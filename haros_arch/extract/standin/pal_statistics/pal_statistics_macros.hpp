// haros_arch stand-in: PAL Robotics' pal_statistics for ROS 2 (declarations only; every
// header of the library stands in as this one, headers.UMBRELLAS). Its registry, made
// for a node and a topic T, publishes pal_statistics_msgs' Statistics on T/full,
// StatisticsNames on T/names and StatisticsValues on T/values; the extractor knows
// getOrCreateRegistry / getRegistry(node, topic) as those calls (api.py), and the macros
// below expand to them as the library's do.
#ifndef HAROS_STANDIN_PAL_STATISTICS_MACROS_HPP
#define HAROS_STANDIN_PAL_STATISTICS_MACROS_HPP
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

constexpr char DEFAULT_STATISTICS_TOPIC[] = "pal_statistics";

namespace pal_statistics {
typedef unsigned int IdType;
class StatisticsRegistry;

class RegistrationsRAII {
public:
  RegistrationsRAII();
  bool remove(const std::string& name);
  bool remove(IdType id);
  void removeAll();
  bool enable(const std::string& name);
  bool enable(IdType id);
  bool enableAll();
  bool disable(const std::string& name);
  bool disable(IdType id);
  bool disableAll();
};

class StatisticsRegistry : public std::enable_shared_from_this<StatisticsRegistry> {
public:
  virtual ~StatisticsRegistry();
  IdType registerVariable(const std::string& name, const double* variable,
                          RegistrationsRAII* bookkeeping = nullptr, bool enabled = true);
  IdType registerFunction(const std::string& name, const std::function<double()>& funct,
                          RegistrationsRAII* bookkeeping = nullptr, bool enabled = true);
  void unregisterVariable(const std::string& name, RegistrationsRAII* bookkeeping = nullptr);
  void unregisterVariable(IdType id, RegistrationsRAII* bookkeeping = nullptr);
  void publish();
  bool publishAsync();
  void startPublishThread();
  void stopPublisherThread();
  bool enable(const IdType& id);
  bool disable(const IdType& id);
  template<typename T> void publishCustomStatistic(const std::string& name, T value);
};

// a variable (or a function) read at each publication
template<typename T>
IdType customRegister(StatisticsRegistry& registry, const std::string& name, const T* variable,
                      RegistrationsRAII* bookkeeping = nullptr, bool enabled = true);
template<typename T>
IdType customRegister(StatisticsRegistry& registry, const std::string& name,
                      const std::function<T()>& funct, RegistrationsRAII* bookkeeping = nullptr,
                      bool enabled = true);

// the registry of a node's topic, under a key: made (with its publishers) on first use
std::shared_ptr<StatisticsRegistry> getOrCreateRegistry(
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr parameters_interface,
  rclcpp::node_interfaces::NodeTopicsInterface::SharedPtr topics_interface,
  const rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr& logging_interface,
  const rclcpp::node_interfaces::NodeClockInterface::SharedPtr& clock_interface,
  const std::string& topic, const std::string& registry_key);
template<typename NodeT>
std::shared_ptr<StatisticsRegistry> getOrCreateRegistry(
  const NodeT& node, const std::string& topic, const std::string& custom_key);
template<typename NodeT>
std::string getUniqueRegistryKey(const NodeT& node, const std::string& topic);
// the registry kept under a key (no publisher of its own: nullptr when none was made)
std::shared_ptr<StatisticsRegistry> getRegistry(const std::string& registry_key);
// the registry of a node's topic, made on first use (the older API)
template<typename NodeT>
std::shared_ptr<StatisticsRegistry> getRegistry(const NodeT& node, const std::string& topic);
std::shared_ptr<StatisticsRegistry> getRegistry(
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr parameters_interface,
  rclcpp::node_interfaces::NodeTopicsInterface::SharedPtr topics_interface,
  const rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr& logging_interface,
  const rclcpp::node_interfaces::NodeClockInterface::SharedPtr& clock_interface,
  const std::string& node_namespace, const std::string& topic);
void deleteRegistry(const std::string& registry_key);
void clearAllRegistries();
}  // namespace pal_statistics

// The macros, by their number of arguments (the library picks an overload the same way)
#define HAROS_PALSTATS_ARG3(a, b, c, ...) c
#define HAROS_PALSTATS_ARG4(a, b, c, d, ...) d
#define HAROS_PALSTATS_ARG5(a, b, c, d, e, ...) e
#define HAROS_PALSTATS_ARG6(a, b, c, d, e, f, ...) f

#define HAROS_PALSTATS_INIT_2(NODE, TOPIC) pal_statistics::getOrCreateRegistry( \
    NODE, TOPIC, NODE->get_node_topics_interface()->resolve_topic_name(TOPIC))
#define HAROS_PALSTATS_INIT_3(NODE, TOPIC, KEY) pal_statistics::getOrCreateRegistry(NODE, TOPIC, KEY)
#define INITIALIZE_REGISTRY(...) HAROS_PALSTATS_ARG4(__VA_ARGS__, HAROS_PALSTATS_INIT_3, \
    HAROS_PALSTATS_INIT_2, unused)(__VA_ARGS__)

#define HAROS_PALSTATS_DELETE_1(KEY) pal_statistics::deleteRegistry(KEY)
#define HAROS_PALSTATS_DELETE_2(NODE, TOPIC) \
  pal_statistics::deleteRegistry(pal_statistics::getUniqueRegistryKey(NODE, TOPIC))
#define DELETE_REGISTRY(...) HAROS_PALSTATS_ARG3(__VA_ARGS__, HAROS_PALSTATS_DELETE_2, \
    HAROS_PALSTATS_DELETE_1, unused)(__VA_ARGS__)
#define CLEAR_ALL_REGISTRIES() pal_statistics::clearAllRegistries()

// an entity registered in the registry kept under a key (arguments after the entity:
// bookkeeping, enabled)
#define REGISTER_ENTITY(KEY, ID, ...) \
  if (pal_statistics::getRegistry(KEY) != nullptr) { \
    pal_statistics::customRegister(*pal_statistics::getRegistry(KEY), ID, __VA_ARGS__); \
  }
#define UNREGISTER_ENTITY(KEY, ...) \
  if (pal_statistics::getRegistry(KEY) != nullptr) { \
    pal_statistics::getRegistry(KEY)->unregisterVariable(__VA_ARGS__); \
  }

// the older API, on a node's topic: REGISTER_VARIABLE(NODE, TOPIC, ID, VARIABLE[, BOOKKEEPING])
#define REGISTER_VARIABLE(NODE, TOPIC, ID, ...) \
  pal_statistics::customRegister(*pal_statistics::getRegistry(NODE, TOPIC), ID, __VA_ARGS__);
#define REGISTER_VARIABLE_SIMPLE(NODE, TOPIC, VARIABLE, BOOKKEEPING) \
  pal_statistics::customRegister(*pal_statistics::getRegistry(NODE, TOPIC), #VARIABLE, VARIABLE, \
                                 BOOKKEEPING);
#define UNREGISTER_VARIABLE(NODE, TOPIC, ...) \
  pal_statistics::getRegistry(NODE, TOPIC)->unregisterVariable(__VA_ARGS__);

// publishing, on the registry of a key or of a node's topic
#define PUBLISH_STATISTICS(...) pal_statistics::getRegistry(__VA_ARGS__)->publish();
#define PUBLISH_ASYNC_STATISTICS(...) pal_statistics::getRegistry(__VA_ARGS__)->publishAsync();
#define START_PUBLISH_THREAD(...) pal_statistics::getRegistry(__VA_ARGS__)->startPublishThread();
#define STOP_PUBLISHER_THREAD(...) pal_statistics::getRegistry(__VA_ARGS__)->stopPublisherThread();
#define PUBLISH_CUSTOM_STATISTIC(NODE, TOPIC, ID, VALUE) \
  pal_statistics::getRegistry(NODE, TOPIC)->publishCustomStatistic(ID, VALUE)
#endif
