// haros_arch stand-in: ros::param
#ifndef HAROS_STANDIN_ROS_PARAM_H
#define HAROS_STANDIN_ROS_PARAM_H
#include <ros/forwards.h>
namespace ros { namespace param {
void set(const std::string& key, const XmlRpc::XmlRpcValue& v);
void set(const std::string& key, const std::string& s);
void set(const std::string& key, const char* s);
void set(const std::string& key, double d);
void set(const std::string& key, int i);
void set(const std::string& key, bool b);
template<class T> void set(const std::string& key, const std::vector<T>& vec);
bool get(const std::string& key, std::string& s);
bool get(const std::string& key, double& d);
bool get(const std::string& key, float& f);
bool get(const std::string& key, int& i);
bool get(const std::string& key, bool& b);
bool get(const std::string& key, XmlRpc::XmlRpcValue& v);
template<class T> bool get(const std::string& key, std::vector<T>& vec);
bool getCached(const std::string& key, std::string& s);
bool getCached(const std::string& key, double& d);
bool getCached(const std::string& key, float& f);
bool getCached(const std::string& key, int& i);
bool getCached(const std::string& key, bool& b);
bool getCached(const std::string& key, XmlRpc::XmlRpcValue& v);
bool has(const std::string& key);
bool del(const std::string& key);
bool search(const std::string& key, std::string& result);
bool search(const std::string& ns, const std::string& key, std::string& result);
bool getParamNames(std::vector<std::string>& keys);
template<typename T> bool param(const std::string& name, T& value, const T& default_val);
template<typename T, typename D> bool param(const std::string& name, T& value, const D& default_val);
template<typename T> T param(const std::string& name, const T& default_val);
} }  // namespace ros::param
#endif
