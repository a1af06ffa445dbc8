// haros_arch stand-in: ROS 1 resource_retriever (declarations only), for a workspace
// that has the package installed, not as sources. Its Retriever reads a package://,
// file:// or http:// URL into memory (curl; roslib's ros::package::getPath): it makes
// no ROS call, so a node that builds one (a URDF mesh loader) is not partial for it.
#ifndef HAROS_STANDIN_RESOURCE_RETRIEVER_H
#define HAROS_STANDIN_RESOURCE_RETRIEVER_H
#include <stdexcept>
#include <string>
#include <stdint.h>
#include <boost/shared_array.hpp>

namespace resource_retriever {
class Exception : public std::runtime_error {
 public:
  Exception(const std::string& file, const std::string& error_msg);
};

struct MemoryResource {
  MemoryResource();
  boost::shared_array<uint8_t> data;
  uint32_t size;
};

class Retriever {
 public:
  Retriever();
  ~Retriever();
  MemoryResource get(const std::string& url);
};
}  // namespace resource_retriever
#endif
