// haros_arch stand-in: ros::ServiceServer and ros::ServiceClient
#ifndef HAROS_STANDIN_ROS_SERVICE_SERVER_H
#define HAROS_STANDIN_ROS_SERVICE_SERVER_H
#include <ros/forwards.h>
#include <ros/time.h>
namespace ros {
class ServiceServer {
public:
  ServiceServer();
  void shutdown();
  std::string getService() const;
  // as roscpp declares it: valid handles convert to a non-null void* (so
  // `if (pub)`, `nullptr == pub` and `bool ok = pub;` all compile)
  operator void*() const;
  bool operator<(const ServiceServer& rhs) const;
  bool operator==(const ServiceServer& rhs) const;
  bool operator!=(const ServiceServer& rhs) const;
};
class ServiceClient {
public:
  ServiceClient();
  template<class Service> bool call(Service& service);
  template<class MReq, class MRes> bool call(MReq& req, MRes& res);
  // with the service's md5sum given (a relay's serialized request and response: ``"*"``)
  template<class MReq, class MRes>
  bool call(const MReq& req, MRes& res, const std::string& service_md5sum);
  bool isValid() const;
  bool isPersistent() const;
  bool exists();
  bool waitForExistence(ros::Duration timeout = ros::Duration(-1));
  void shutdown();
  std::string getService();
  // as roscpp declares it: valid handles convert to a non-null void* (so
  // `if (pub)`, `nullptr == pub` and `bool ok = pub;` all compile)
  operator void*() const;
  bool operator<(const ServiceClient& rhs) const;
  bool operator==(const ServiceClient& rhs) const;
  bool operator!=(const ServiceClient& rhs) const;
};
}  // namespace ros
#endif
