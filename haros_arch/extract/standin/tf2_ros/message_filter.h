// haros_arch stand-in
#pragma once
#include <string>
#include <vector>
#include <tf2_ros/buffer.h>

namespace tf2_ros {
// Filters messages until their frames can be transformed; no graph primitive of its own.
template<class M> class MessageFilter {
public:
  template<class... A> MessageFilter(A&&... args);
  template<class C> void registerCallback(const C& callback);
  template<class C> void registerFailureCallback(const C& callback);
  template<class C, class T> void registerCallback(C callback, T* object);
  template<class F> void connectInput(F& filter);
  void setTargetFrame(const std::string& frame);
  void setTargetFrames(const std::vector<std::string>& frames);
  template<class D> void setTolerance(const D& tolerance);
  void setQueueSize(uint32_t size);
  void clear();
  template<class P> void add(const P& message);
};
}  // namespace tf2_ros
