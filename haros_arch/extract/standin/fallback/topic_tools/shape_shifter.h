// haros_arch stand-in: ROS 1 topic_tools' ShapeShifter (noetic-devel
// topic_tools/shape_shifter.h), roscpp's message of any type: what a relay, a mux, a
// logger of topics found at run time subscribes to (subt's bridge_logger:
// ``n.subscribe(name, 1000, callback)`` with a ``boost::function<void(const
// ShapeShifter::ConstPtr&)>``) and what it republishes (``msg->advertise(nh, topic, 1)``).
// Read only when the workspace has no such header (headers.FALLBACK). Its type is
// ``topic_tools/ShapeShifter``, which the checks take as any type (query.access).
#ifndef HAROS_STANDIN_TOPIC_TOOLS_SHAPE_SHIFTER_H
#define HAROS_STANDIN_TOPIC_TOOLS_SHAPE_SHIFTER_H
#include <string>
#include <boost/shared_ptr.hpp>
#include <ros/ros.h>

namespace topic_tools
{
class ShapeShifter
{
public:
  typedef boost::shared_ptr<ShapeShifter> Ptr;
  typedef boost::shared_ptr<ShapeShifter const> ConstPtr;
  static bool uses_old_API_;
  ShapeShifter();
  virtual ~ShapeShifter();
  std::string const &getDataType() const;
  std::string const &getMD5Sum() const;
  std::string const &getMessageDefinition() const;
  void morph(const std::string &md5sum, const std::string &datatype,
             const std::string &msg_def, const std::string &latching);
  ros::Publisher advertise(ros::NodeHandle &nh, const std::string &topic,
                           uint32_t queue_size_, bool latch = false,
                           const ros::SubscriberStatusCallback &connect_cb =
                               ros::SubscriberStatusCallback()) const;
  template <class M> boost::shared_ptr<M> instantiate() const;
  template <typename Stream> void write(Stream &stream) const;
  template <typename Stream> void read(Stream &stream);
  uint32_t size() const;
};
}  // namespace topic_tools
#endif
