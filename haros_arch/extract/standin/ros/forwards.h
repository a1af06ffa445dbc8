// haros_arch stand-in: roscpp forward declarations and common types
#ifndef HAROS_STANDIN_ROS_FORWARDS_H
#define HAROS_STANDIN_ROS_FORWARDS_H
#include <ros/common.h>  // as roscpp's forwards.h: the version macros
#include <stdint.h>
#include <map>
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
#include <boost/bind/bind.hpp>
#include <boost/thread.hpp>
#include <ros/message_forward.h>  // reached through roscpp's message traits
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
  TransportHints& maxDatagramSize(int size);
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
// as xmlrpcpp/XmlRpcValue.h declares it (the members nodes use)
class XmlRpcValue {
public:
  enum Type { TypeInvalid, TypeBoolean, TypeInt, TypeDouble, TypeString, TypeDateTime,
              TypeBase64, TypeArray, TypeStruct };
  typedef std::vector<char> BinaryData;
  typedef std::vector<XmlRpcValue> ValueArray;
  typedef std::map<std::string, XmlRpcValue> ValueStruct;
  typedef ValueStruct::iterator iterator;
  typedef ValueStruct::const_iterator const_iterator;
  XmlRpcValue();
  XmlRpcValue(bool value);
  XmlRpcValue(int value);
  XmlRpcValue(double value);
  XmlRpcValue(const std::string& value);
  XmlRpcValue(const char* value);
  XmlRpcValue(struct tm* value);
  XmlRpcValue(void* value, int nBytes);
  // a value parsed from XML text at *offset (range_sensor_layer's default topic list)
  XmlRpcValue(const std::string& xml, int* offset);
  XmlRpcValue(const XmlRpcValue& rhs);
  ~XmlRpcValue();
  void clear();
  XmlRpcValue& operator=(const XmlRpcValue& rhs);
  XmlRpcValue& operator=(const int& rhs);
  XmlRpcValue& operator=(const double& rhs);
  XmlRpcValue& operator=(const char* rhs);
  bool operator==(const XmlRpcValue& other) const;
  bool operator!=(const XmlRpcValue& other) const;
  operator bool&();
  operator int&();
  operator double&();
  operator std::string&();
  operator BinaryData&();
  operator struct tm&();
  const XmlRpcValue& operator[](int i) const;
  XmlRpcValue& operator[](int i);
  XmlRpcValue& operator[](const std::string& k);
  XmlRpcValue& operator[](const char* k);
  // of a const value too, as noetic's xmlrpcpp has them (a const reference's members:
  // fuse's ``config["name"]``)
  XmlRpcValue& operator[](const std::string& k) const;
  XmlRpcValue& operator[](const char* k) const;
  iterator begin();
  iterator end();
  const_iterator begin() const;
  const_iterator end() const;
  bool valid() const;
  Type const& getType() const;
  int size() const;
  void setSize(int size);
  bool hasMember(const std::string& name) const;
  std::string toXml() const;
  std::ostream& write(std::ostream& os) const;
protected:
  // what subclasses set directly (costmap_2d's SuperValue::setStruct / setArray)
  Type _type;
  union {
    bool asBool;
    int asInt;
    double asDouble;
    struct tm* asTime;
    std::string* asString;
    BinaryData* asBinary;
    ValueArray* asArray;
    ValueStruct* asStruct;
  } _value;
};
// as xmlrpcpp/XmlRpcException.h declares it (what converting a value of another type
// throws: neonavigation's ``catch (XmlRpc::XmlRpcException& e)``)
class XmlRpcException {
public:
  XmlRpcException(const std::string& message, int code = -1);
  const std::string& getMessage() const;
  int getCode() const;
};
}  // namespace XmlRpc
#endif
