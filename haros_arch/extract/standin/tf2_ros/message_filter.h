// haros_arch stand-in
#pragma once
#include <string>
#include <vector>
#include <tf2_ros/buffer.h>

#include <message_filters/subscriber.h>

namespace tf2_ros {
// what every MessageFilter gives whatever its message type (ROS 1 and ROS 2): a class
// that keeps filters of several types in one container
class MessageFilterBase {
public:
  virtual ~MessageFilterBase();
  virtual void clear();
  virtual void setTargetFrame(const std::string& frame);
  virtual void setTargetFrames(const std::vector<std::string>& frames);
  template<class D> void setTolerance(const D& tolerance);
};
// Filters messages until their frames can be transformed; no graph primitive of its own.
// ROS 2's is a template on the buffer type too (tf2_ros::Buffer by default).
template<class M, class BufferT = void> class MessageFilter
    : public MessageFilterBase, public message_filters::SimpleFilter<M> {
public:
  template<class... A> MessageFilter(A&&... args);
  template<class C> message_filters::Connection registerCallback(const C& callback);
  template<class C> void registerFailureCallback(const C& callback);
  template<class C, class T> message_filters::Connection registerCallback(C callback, T* object);
  template<class F> void connectInput(F& filter);
  void setTargetFrame(const std::string& frame) override;
  void setTargetFrames(const std::vector<std::string>& frames) override;
  template<class D> void setTolerance(const D& tolerance);
  void setQueueSize(uint32_t size);
  uint32_t getQueueSize();
  std::string getTargetFramesString();  // ROS 1: the frames joined, for logging
  void clear() override;
  template<class P> void add(const P& message);
};
}  // namespace tf2_ros
