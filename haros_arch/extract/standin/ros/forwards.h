// haros_arch stand-in: roscpp forward declarations and common types
#ifndef HAROS_STANDIN_ROS_FORWARDS_H
#define HAROS_STANDIN_ROS_FORWARDS_H
#include <stdint.h>
#include <map>
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
#include <boost/bind/bind.hpp>
#include <boost/thread.hpp>
namespace ros {
typedef std::map<std::string, std::string> M_string;
typedef std::vector<std::string> V_string;
class NodeHandle;
typedef boost::shared_ptr<NodeHandle> NodeHandlePtr;
class Publisher;
class Subscriber;
class ServiceServer;
class ServiceClient;
class Timer;
class CallbackQueueInterface;
class SingleSubscriberPublisher {
public:
  template<class M> void publish(const M& message) const;
  std::string getTopic() const;
  std::string getSubscriberName() const;
};
typedef boost::function<void(const SingleSubscriberPublisher&)> SubscriberStatusCallback;
typedef std::vector<Publisher> V_Publisher;
typedef std::vector<Subscriber> V_Subscriber;
typedef std::vector<ServiceServer> V_ServiceServer;
typedef std::vector<ServiceClient> V_ServiceClient;
class TransportHints {
public:
  TransportHints();
  TransportHints& tcpNoDelay(bool nodelay = true);
  TransportHints& udp();
  TransportHints& tcp();
  TransportHints& unreliable();
  TransportHints& reliable();
};
typedef boost::shared_ptr<void const> VoidConstPtr;
typedef boost::shared_ptr<void> VoidPtr;
class Exception {
public:
  explicit Exception(const std::string& what);
  const char* what() const;
};
class InvalidNameException : public Exception {
public:
  explicit InvalidNameException(const std::string& what);
};
}  // namespace ros
namespace XmlRpc {
class XmlRpcValue {
public:
  enum Type { TypeInvalid, TypeBoolean, TypeInt, TypeDouble, TypeString, TypeDateTime,
              TypeBase64, TypeArray, TypeStruct };
  XmlRpcValue();
  Type getType() const;
  int size() const;
  bool valid() const;
  bool hasMember(const std::string& name) const;
  XmlRpcValue& operator[](int i);
  XmlRpcValue& operator[](const std::string& k);
  operator bool&();
  operator int&();
  operator double&();
  operator std::string&();
};
}  // namespace XmlRpc
#endif
