// haros_arch stand-in: the ROS package filters (declarations only; ROS 1 noetic-devel and
// ROS 2 ros2 branch side by side), for a workspace that has the package installed, not as
// sources. A FilterChain<T>(data_type) loads, through pluginlib, the classes of base
// filters::FilterBase<data_type> that the parameters its configure(...) reads name:
// ROS 1 the list parameter given (entries {name, type, params}) on the handle given,
// ROS 2 <prefix>.filter1.name / .type, filter2..., each filter's own parameters below
// <prefix>.filterN.params. (API rows: extract/cpp/api.py FILTERS.) Every other header of
// the package stands in as this one.
#ifndef HAROS_STANDIN_FILTERS_H
#define HAROS_STANDIN_FILTERS_H
#include <map>
#include <memory>
#include <string>
#include <vector>
#include <ros/ros.h>

namespace filters {

template <typename T>
class FilterBase {
 public:
  FilterBase();
  virtual ~FilterBase();
  // ROS 1: from a {name, type, params} entry, or a parameter holding one
  bool configure(XmlRpc::XmlRpcValue& config);
  bool configure(const std::string& param_name, ros::NodeHandle node_handle);
  // ROS 2: the chain hands each filter its parameter prefix, name and node interfaces
  template <typename Logging, typename Parameters>
  bool configure(const std::string& param_prefix, const std::string& filter_name,
                 const Logging& node_logger, const Parameters& node_params);
  virtual bool update(const T& data_in, T& data_out) = 0;
  std::string getType();
  const std::string& getName() const;

 protected:
  virtual bool configure() = 0;
  // ROS 1 reads these from the filter's ``params`` entry (no ROS call); ROS 2 declares
  // ``<param_prefix><name>`` on the node's parameters (API row)
  bool getParam(const std::string& name, std::string& value);
  bool getParam(const std::string& name, bool& value);
  bool getParam(const std::string& name, double& value);
  bool getParam(const std::string& name, int& value);
  bool getParam(const std::string& name, unsigned int& value);
  bool getParam(const std::string& name, size_t& value);
  bool getParam(const std::string& name, std::vector<double>& value);
  bool getParam(const std::string& name, std::vector<std::string>& value);
  bool getParam(const std::string& name, XmlRpc::XmlRpcValue& value);
  std::string filter_name_;
  std::string filter_type_;
  bool configured_;
  std::map<std::string, XmlRpc::XmlRpcValue> params_;  // ROS 1
  // ROS 2: the chain gives each filter ``<prefix>.filterN.params.``, which the getParam
  // rows write as ``?.`` and the graph fills per filter; a filter naming parameters or
  // chains of its own with it (laser_filters' LaserArrayFilter: ``param_prefix_ +
  // "range_filter_chain"``) gets the same mark (const: read as its initialiser)
  const std::string param_prefix_ = "?.";
#ifdef HAROS_STANDIN_RCLCPP_HPP
  // ROS 2 (rclcpp is in the precompiled stand-ins; not included here, which would make
  // every unit that includes this header ROS 2 code)
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr params_interface_;
  rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr logging_interface_;
#endif
};

template <typename T>
class MultiChannelFilterBase : public FilterBase<T> {
 public:
  MultiChannelFilterBase();
  bool configure(unsigned int number_of_channels, XmlRpc::XmlRpcValue& config);
  bool configure(unsigned int number_of_channels, const std::string& param_name,
                 ros::NodeHandle node_handle);
  template <typename Logging, typename Parameters>
  bool configure(size_t number_of_channels, const std::string& param_prefix,
                 const std::string& filter_name, const Logging& node_logger,
                 const Parameters& node_params);
  virtual bool update(const std::vector<T>& data_in, std::vector<T>& data_out) = 0;
  virtual bool update(const T& data_in, T& data_out);

 protected:
  unsigned int number_of_channels_;
};

template <typename T>
class FilterChain {
 public:
  explicit FilterChain(std::string data_type);
  ~FilterChain();
  // ROS 1
  bool configure(std::string param_name, ros::NodeHandle node = ros::NodeHandle());
  bool configure(XmlRpc::XmlRpcValue& config, const std::string& filter_ns);
  // ROS 2 (node logging and parameters interfaces)
  template <typename Logging, typename Parameters>
  bool configure(const std::string& param_prefix, const Logging& node_logger,
                 const Parameters& node_params);
  bool update(const T& data_in, T& data_out);
  bool clear();
  size_t get_length() const;
  std::vector<std::shared_ptr<FilterBase<T>>> getFilters() const;
};

template <typename T>
class MultiChannelFilterChain {
 public:
  explicit MultiChannelFilterChain(std::string data_type);
  ~MultiChannelFilterChain();
  bool configure(unsigned int size, std::string param_name,
                 ros::NodeHandle node = ros::NodeHandle());
  bool configure(unsigned int size, XmlRpc::XmlRpcValue& config);
  template <typename Logging, typename Parameters>
  bool configure(size_t size, const std::string& param_prefix, const Logging& node_logger,
                 const Parameters& node_params);
  bool update(const std::vector<T>& data_in, std::vector<T>& data_out);
  bool clear();
};

}  // namespace filters
#endif
