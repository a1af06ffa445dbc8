// haros_arch stand-in: dynamic_reconfigure's server (advertises ~set_parameters and the
// ~parameter_descriptions / ~parameter_updates topics; see the API table)
#pragma once
#include <boost/function.hpp>
#include <boost/thread.hpp>
#include <ros/ros.h>

namespace dynamic_reconfigure {
template<class ConfigType> class Server {
public:
  typedef boost::function<void(ConfigType&, uint32_t level)> CallbackType;
  Server(const ros::NodeHandle& nh = ros::NodeHandle("~"));
  Server(boost::recursive_mutex& mutex, const ros::NodeHandle& nh = ros::NodeHandle("~"));
  void setCallback(const CallbackType& callback);
  void clearCallback();
  void updateConfig(const ConfigType& config);
  void getConfigMax(ConfigType& config);
  void getConfigMin(ConfigType& config);
  void getConfigDefault(ConfigType& config);
  void setConfigMax(const ConfigType& config);
  void setConfigMin(const ConfigType& config);
  void setConfigDefault(const ConfigType& config);
};
}  // namespace dynamic_reconfigure
