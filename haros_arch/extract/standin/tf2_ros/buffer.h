// haros_arch stand-in: tf2_ros buffers, broadcasters and listeners (declarations only)
#ifndef HAROS_STANDIN_TF2_ROS_H
#define HAROS_STANDIN_TF2_ROS_H
#include <string>
#include <vector>
#include <memory>
#include <chrono>
#include <boost/shared_ptr.hpp>
#include <ros/time.h>
namespace haros_standin {
// A message whose type the stand-ins cannot name (its package's headers are synthesised
// for each workspace): it converts to whatever it initialises, is assigned to or is
// passed as. One conversion function template only: a second one to M& made copying or
// assigning it to a message ambiguous (both yield M, and M's operator=(const M&) could
// take either), where the real function's result is that message.
struct any_message {
  template<class M> operator M() const;
};
// geometry_msgs' TransformStamped, which tf2_ros' lookupTransform and tf2_eigen's
// eigenToTransform return: its fields, for `auto t = buffer.lookupTransform(...);
// t.transform.translation.x`, each converting like the message it is
struct any_vector3 : any_message { double x, y, z; };
struct any_quaternion : any_message { double x, y, z, w; };
struct any_transform : any_message { any_vector3 translation; any_quaternion rotation; };
struct any_time : any_message {  // both builtin_interfaces' Time and ros::Time
  int sec; unsigned int nanosec, nsec;
  double toSec() const;
};
struct any_header : any_message { unsigned int seq; any_time stamp; std::string frame_id; };
struct any_transform_stamped : any_message {
  any_header header;
  std::string child_frame_id;
  any_transform transform;
};
}
namespace tf2 {
class TransformException : public std::runtime_error { public: explicit TransformException(const std::string& s); };
class LookupException : public TransformException { public: using TransformException::TransformException; };
class ConnectivityException : public TransformException { public: using TransformException::TransformException; };
class ExtrapolationException : public TransformException { public: using TransformException::TransformException; };
class InvalidArgumentException : public TransformException { public: using TransformException::TransformException; };
class TimeoutException : public TransformException { public: using TransformException::TransformException; };
using Duration = std::chrono::nanoseconds;
using TimePoint = std::chrono::time_point<std::chrono::system_clock, Duration>;
// tf2's ``TimePoint(Duration::zero())``, a time point as any other (swri_transform_util's
// ``GetTransform(target, source, tf2::TimePointZero, transform)`` takes a TimePoint)
extern const TimePoint TimePointZero;
typedef double tf2Scalar;
class Quaternion {
public:
  Quaternion();
  Quaternion(double x, double y, double z, double w);
  Quaternion(const class Vector3& axis, double angle);
  Quaternion(double yaw, double pitch, double roll);
  void setRPY(double roll, double pitch, double yaw);
  void setEuler(double yaw, double pitch, double roll);
  void setRotation(const class Vector3& axis, double angle);
  double x() const; double y() const; double z() const; double w() const;
  double getX() const; double getY() const; double getZ() const; double getW() const;
  void setX(double v); void setY(double v); void setZ(double v); void setW(double v);
  void setValue(double x, double y, double z, double w);
  // tf2's QuadWord converts to its array of four: ``q[0]`` is x
  double operator[](int i) const; double& operator[](int i);
  double getAngle() const;
  double getAngleShortestPath() const;
  class Vector3 getAxis() const;
  double dot(const Quaternion& q) const;
  double length() const; double length2() const;
  double angle(const Quaternion& q) const;
  double angleShortestPath(const Quaternion& q) const;
  Quaternion slerp(const Quaternion& q, double t) const;
  static const Quaternion& getIdentity();
  Quaternion operator+(const Quaternion& q) const;
  Quaternion operator-(const Quaternion& q) const;
  Quaternion operator-() const;
  Quaternion operator*(double s) const;
  Quaternion operator/(double s) const;
  Quaternion& operator*=(const Quaternion& q);
  Quaternion& operator*=(double s);
  bool operator==(const Quaternion& q) const; bool operator!=(const Quaternion& q) const;
  Quaternion normalized() const;
  Quaternion& normalize();
  Quaternion inverse() const;
  Quaternion operator*(const Quaternion& q) const;
};
class Vector3 {
public:
  Vector3(); Vector3(double x, double y, double z);
  double x() const; double y() const; double z() const; double w() const;
  double getX() const; double getY() const; double getZ() const;
  void setX(double v); void setY(double v); void setZ(double v); void setW(double v);
  void setValue(double x, double y, double z);
  double length() const; double length2() const;
  Vector3 operator+(const Vector3& v) const; Vector3 operator-(const Vector3& v) const;
  Vector3 operator*(double s) const;
  double operator[](int i) const; double& operator[](int i);
  double dot(const Vector3& v) const; Vector3 cross(const Vector3& v) const;
  double distance(const Vector3& v) const; double distance2(const Vector3& v) const;
  double angle(const Vector3& v) const;
  Vector3& normalize(); Vector3 normalized() const;
  Vector3 rotate(const Vector3& axis, double angle) const;
  Vector3 absolute() const;
  void setZero(); bool isZero() const; bool fuzzyZero() const;
  Vector3 operator-() const; Vector3 operator/(double s) const;
  Vector3& operator+=(const Vector3& v); Vector3& operator-=(const Vector3& v);
  Vector3& operator*=(double s); Vector3& operator/=(double s);
  bool operator==(const Vector3& v) const; bool operator!=(const Vector3& v) const;
};
class Matrix3x3 {
public:
  Matrix3x3(); explicit Matrix3x3(const Quaternion& q);
  Matrix3x3(double xx, double xy, double xz, double yx, double yy, double yz,
            double zx, double zy, double zz);
  void setValue(double xx, double xy, double xz, double yx, double yy, double yz,
                double zx, double zy, double zz);
  Vector3 getRow(int i) const; Vector3 getColumn(int i) const;
  Vector3& operator[](int i);
  void setIdentity(); static const Matrix3x3& getIdentity();
  void setRotation(const Quaternion& q);
  void setEulerYPR(double yaw, double pitch, double roll);
  Matrix3x3 transpose() const; Matrix3x3 inverse() const;
  double determinant() const;
  Vector3 operator*(const Vector3& v) const;
  Matrix3x3 operator*(const Matrix3x3& m) const;
  Matrix3x3& operator*=(const Matrix3x3& m);
  void getRPY(double& roll, double& pitch, double& yaw, unsigned int solution = 1) const;
  void getEulerYPR(double& yaw, double& pitch, double& roll, unsigned int solution = 1) const;
  void getRotation(Quaternion& q) const;
  void setRPY(double roll, double pitch, double yaw);
  const Vector3& operator[](int i) const;
};
class Transform {
public:
  Transform(); Transform(const Quaternion& q, const Vector3& v = Vector3());
  void setOrigin(const Vector3& v); void setRotation(const Quaternion& q);
  void setIdentity();
  Vector3& getOrigin(); const Vector3& getOrigin() const;
  Quaternion getRotation() const;
  Matrix3x3& getBasis(); const Matrix3x3& getBasis() const;
  Transform inverse() const;
  Transform inverseTimes(const Transform& t) const;
  Transform operator*(const Transform& t) const;
  Transform& operator*=(const Transform& t);
  Quaternion operator*(const Quaternion& q) const;
  void mult(const Transform& a, const Transform& b);
  void setBasis(const Matrix3x3& basis);
  Vector3 operator*(const Vector3& v) const;
  static const Transform& getIdentity();
};
// a stamped datum: ROS 2's tf2 stamps it with its own TimePoint, ROS 1's with ros::Time
// (a unit that has included rclcpp is ROS 2's: robot_localization's
// ``pose.stamp_ = tf2::timeFromSec(...)``; but the precompiled stand-ins include rclcpp
// in every unit, so a unit of a ROS 1 distribution, whose roscpp version the flags give
// and not rclcpp's, is ROS 1's: neonavigation's ``tf2::Stamped<tf2::Transform>(t,
// odom->header.stamp, frame)``)
#if defined(HAROS_STANDIN_RCLCPP_HPP) && !(defined(HAROS_ROSCPP_VERSION_GIVEN) && \
                                           !defined(HAROS_RCLCPP_VERSION_GIVEN))
typedef TimePoint haros_stamp_type;
#else
typedef ros::Time haros_stamp_type;
#endif
template<class T> class Stamped : public T {
public:
  Stamped(); Stamped(const T& input, const haros_stamp_type& stamp, const std::string& frame_id);
  void setData(const T& input);
  haros_stamp_type stamp_; std::string frame_id_;
};
double angle(const Quaternion& a, const Quaternion& b);
Vector3 quatRotate(const Quaternion& rotation, const Vector3& v);
Quaternion slerp(const Quaternion& a, const Quaternion& b, double t);
Vector3 lerp(const Vector3& a, const Vector3& b, double t);
// tf2/utils.h: a quaternion's (or a message's) yaw, pitch and roll
template<class A> void getEulerYPR(const A& a, double& yaw, double& pitch, double& roll);
Quaternion inverse(const Quaternion& q);
double dot(const Quaternion& a, const Quaternion& b);
Quaternion shortestArcQuat(const Vector3& a, const Vector3& b);
Quaternion operator*(const Quaternion& q, const Vector3& v);
Vector3 operator*(double s, const Vector3& v);
double tf2Dot(const Vector3& a, const Vector3& b);
Vector3 tf2Cross(const Vector3& a, const Vector3& b);
double tf2Distance(const Vector3& a, const Vector3& b);
template<class A, class B> void fromMsg(const A& a, B& b);
// tf2_geometry_msgs: a LinearMath quaternion or vector becomes its geometry_msgs message,
// whose header this stand-in does not include: the message's fields, and it converts to
// the message type
struct QuaternionMsg {
  double x, y, z, w;
  template<class M> operator M() const;
};
struct Vector3Msg {
  double x, y, z;
  template<class M> operator M() const;
};
QuaternionMsg toMsg(const Quaternion& q);
Vector3Msg toMsg(const Vector3& v);
// a transform becomes geometry_msgs' Transform, a stamped one TransformStamped
// (robot_localization's ``trans_msg.transform = tf2::toMsg(tf2::Transform::getIdentity())``)
haros_standin::any_transform toMsg(const Transform& t);
template<class T> haros_standin::any_transform_stamped toMsg(const Stamped<T>& t);
template<class A> A toMsg(const A& a);
template<class A, class B> B& toMsg(const A& a, B& b);
template<class T> void convert(const T& a, T& b);
template<class A, class B> void convert(const A& a, B& b);
double getYaw(const Quaternion& q);
template<class A> double getYaw(const A& a);
// tf2/time.h (its types: before Stamped)
Duration durationFromSec(double t_sec);
TimePoint timeFromSec(double t_sec);
double durationToSec(const Duration& input);
double timeToSec(const TimePoint& timepoint);
std::string displayTimePoint(const TimePoint& stamp);
// tf2/convert.h: a datum transformed by a transform, both any message or tf2 type
template<class In, class Out, class T> void doTransform(const In& in, Out& out, const T& transform);
template<class T> T transformToMsg(const T& t);
// tf2_geometry_msgs: a covariance in another frame
template<class C, class T> C transformCovariance(const C& cov_in, const T& transform);
class BufferCore {
public:
  static const int DEFAULT_CACHE_TIME = 10;
  template<class... A> explicit BufferCore(A&&... args);
  void clear();
  std::string allFramesAsString() const;
  std::string allFramesAsYAML() const;
  void getFrameStrings(std::vector<std::string>& ids) const;
  bool _frameExists(const std::string& frame_id_str) const;
  // the frames between two, at two times, through a fixed frame (tf2_monitor's
  // ``_chainAsVector(b, t0, a, t0, b, chain)``)
  template<class T> void _chainAsVector(const std::string& target_frame, const T& target_time,
      const std::string& source_frame, const T& source_time, const std::string& fixed_frame,
      std::vector<std::string>& output) const;
  // ROS 1 tf2: a callback run whenever transforms change, and its removal by the
  // boost::signals2::connection the first returns (MoveIt's CurrentStateMonitor)
  template<class F> haros_standin::any_message _addTransformsChangedListener(F callback);
  template<class C> void _removeTransformsChangedListener(const C& connection);
  // what a Buffer looks up, on the core itself (a ``tf2::BufferCore`` member)
  template<class S, class T, class... A> haros_standin::any_transform_stamped lookupTransform(
      const std::string& target, const S& source, const T& time, const A&... more) const;
  template<class S, class T, class... A> bool canTransform(const std::string& target,
      const S& source, const T& time, const A&... more) const;
};
}
// ROS 2's tf2_ros: a tf2 time or duration as a builtin_interfaces message and back
namespace builtin_interfaces { namespace msg { struct Time; struct Duration; } }
namespace tf2_ros {
builtin_interfaces::msg::Time toMsg(const tf2::TimePoint& t);
builtin_interfaces::msg::Duration toMsg(const tf2::Duration& d);
tf2::TimePoint fromMsg(const builtin_interfaces::msg::Time& time_msg);
tf2::Duration fromMsg(const builtin_interfaces::msg::Duration& duration_msg);
double timeToSec(const builtin_interfaces::msg::Time& time_msg);
}  // namespace tf2_ros
namespace tf2_ros {
class Buffer : public tf2::BufferCore {
public:
  typedef std::shared_ptr<Buffer> SharedPtr;
  typedef std::shared_ptr<const Buffer> ConstSharedPtr;
  typedef std::unique_ptr<Buffer> UniquePtr;
  template<class... A> explicit Buffer(A&&... args);
  // (target, source, time, ...) and the advanced form (target, target_time, source,
  // source_time, fixed_frame, timeout): its second argument a time (hdl_localization);
  // every argument read only (taken as const: the frame variables a call names keep
  // their one write, ``ReadCall.variable``)
  template<class S, class T, class... A> haros_standin::any_transform_stamped lookupTransform(
      const std::string& target, const S& source, const T& time, const A&... more) const;
  template<class S, class T, class... A> bool canTransform(const std::string& target,
      const S& source, const T& time, const A&... more) const;
  template<class M, class... A> M& transform(const M& in, M& out, const std::string& target, A&&... more) const;
  template<class M, class... A> M transform(const M& in, const std::string& target, A&&... more) const;
  void setUsingDedicatedThread(bool v);
  template<class M> bool setTransform(const M& transform, const std::string& authority,
                                      bool is_static = false);
  template<class I> void setCreateTimerInterface(I i);
};
class TransformListener {
public:
  template<class... A> explicit TransformListener(Buffer& buffer, A&&... args);
  // on a plain tf2::BufferCore (nav2_util's BaseFootprintPublisherListener)
  template<class... A> explicit TransformListener(tf2::BufferCore& buffer, A&&... args);
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
