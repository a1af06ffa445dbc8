// haros_arch stand-in: tf2_ros buffers, broadcasters and listeners (declarations only)
#ifndef HAROS_STANDIN_TF2_ROS_H
#define HAROS_STANDIN_TF2_ROS_H
#include <string>
#include <vector>
#include <memory>
#include <boost/shared_ptr.hpp>
#include <ros/time.h>
namespace haros_standin {
struct any_message {
  template<class M> operator M() const;
  template<class M> operator M&() const;
};
}
namespace tf2 {
class TransformException : public std::runtime_error { public: explicit TransformException(const std::string& s); };
class LookupException : public TransformException { public: using TransformException::TransformException; };
class ConnectivityException : public TransformException { public: using TransformException::TransformException; };
class ExtrapolationException : public TransformException { public: using TransformException::TransformException; };
class InvalidArgumentException : public TransformException { public: using TransformException::TransformException; };
struct TimePointZero_t {};
extern const TimePointZero_t TimePointZero;
class Quaternion {
public:
  Quaternion();
  Quaternion(double x, double y, double z, double w);
  void setRPY(double roll, double pitch, double yaw);
  double x() const; double y() const; double z() const; double w() const;
  Quaternion normalized() const;
};
class Vector3 { public: Vector3(); Vector3(double x, double y, double z); double x() const; double y() const; double z() const; };
class Transform { public: Transform(); void setOrigin(const Vector3& v); void setRotation(const Quaternion& q); };
template<class A, class B> void fromMsg(const A& a, B& b);
template<class A> A toMsg(const A& a);
template<class A, class B> B& toMsg(const A& a, B& b);
template<class T> void convert(const T& a, T& b);
template<class A, class B> void convert(const A& a, B& b);
double getYaw(const Quaternion& q);
template<class A> double getYaw(const A& a);
}
namespace tf2_ros {
class Buffer {
public:
  template<class... A> explicit Buffer(A&&... args);
  template<class T, class... A> haros_standin::any_message lookupTransform(
      const std::string& target, const std::string& source, const T& time, A&&... more) const;
  template<class T, class... A> bool canTransform(const std::string& target,
      const std::string& source, const T& time, A&&... more) const;
  template<class M, class... A> M& transform(const M& in, M& out, const std::string& target, A&&... more) const;
  template<class M, class... A> M transform(const M& in, const std::string& target, A&&... more) const;
  void setUsingDedicatedThread(bool v);
  template<class I> void setCreateTimerInterface(I i);
};
class TransformListener {
public:
  template<class... A> explicit TransformListener(Buffer& buffer, A&&... args);
};
class TransformBroadcaster {
public:
  TransformBroadcaster();
  template<class N> explicit TransformBroadcaster(N&& node);
  template<class N, class Q> TransformBroadcaster(N&& node, const Q& qos);
  template<class M> void sendTransform(const M& transform);
};
class StaticTransformBroadcaster {
public:
  StaticTransformBroadcaster();
  template<class N> explicit StaticTransformBroadcaster(N&& node);
  template<class N, class Q> StaticTransformBroadcaster(N&& node, const Q& qos);
  template<class M> void sendTransform(const M& transform);
};
class CreateTimerROS { public: template<class... A> CreateTimerROS(A&&... args); };
}
#endif
