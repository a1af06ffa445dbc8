// haros_arch stand-in: ros::service
#ifndef HAROS_STANDIN_ROS_SERVICE_H
#define HAROS_STANDIN_ROS_SERVICE_H
#include <ros/forwards.h>
#include <ros/time.h>
#include <ros/service_server.h>
namespace ros { namespace service {
template<class Service> bool call(const std::string& service_name, Service& service);
template<class MReq, class MRes>
bool call(const std::string& service_name, MReq& req, MRes& res);
bool exists(const std::string& service_name, bool print_failure_reason);
bool waitForService(const std::string& service_name, ros::Duration timeout = ros::Duration(-1));
bool waitForService(const std::string& service_name, int32_t timeout);
template<class Service>
ServiceClient createClient(const std::string& service_name, bool persistent = false,
                           const M_string& header_values = M_string());
} }  // namespace ros::service
#endif
