// haros_arch stand-in: the ROS 1 tf API nodes use (declarations only). Every tf header
// (<tf/transform_listener.h>, <tf/transform_broadcaster.h>, ...) includes this one file.
#ifndef HAROS_STANDIN_TF_H
#define HAROS_STANDIN_TF_H
#include <stdexcept>
#include <string>
#include <vector>
#include <ros/ros.h>
namespace tf {
class Vector3 {
public:
  Vector3();
  Vector3(double x, double y, double z);
  double x() const; double y() const; double z() const;
  void setX(double v); void setY(double v); void setZ(double v);
  double length() const;
};
class Quaternion {
public:
  Quaternion();
  Quaternion(double x, double y, double z, double w);
  void setRPY(double roll, double pitch, double yaw);
  double x() const; double y() const; double z() const; double w() const;
};
class Matrix3x3 {
public:
  explicit Matrix3x3(const Quaternion& q);
  void getRPY(double& roll, double& pitch, double& yaw) const;
};
typedef Vector3 Point;
class Transform {
public:
  Transform();
  Transform(const Quaternion& q, const Vector3& c = Vector3());
  Vector3& getOrigin();
  const Vector3& getOrigin() const;
  Quaternion getRotation() const;
  void setOrigin(const Vector3& origin);
  void setRotation(const Quaternion& q);
  void setIdentity();
  Transform inverse() const;
  Transform operator*(const Transform& t) const;
};
typedef Transform Pose;
class StampedTransform : public Transform {
public:
  StampedTransform();
  StampedTransform(const Transform& input, const ros::Time& timestamp,
                   const std::string& frame_id, const std::string& child_frame_id);
  ros::Time stamp_;
  std::string frame_id_;
  std::string child_frame_id_;
};
template<class T> class Stamped : public T {
public:
  Stamped();
  Stamped(const T& input, const ros::Time& timestamp, const std::string& frame_id);
  ros::Time stamp_;
  std::string frame_id_;
};
class TransformException : public std::runtime_error {
public:
  explicit TransformException(const std::string& what);
};
class LookupException : public TransformException { public: using TransformException::TransformException; };
class ConnectivityException : public TransformException { public: using TransformException::TransformException; };
class ExtrapolationException : public TransformException { public: using TransformException::TransformException; };
class Transformer {
public:
  template<class... A> void lookupTransform(A&&... args) const;
  template<class... A> bool waitForTransform(A&&... args) const;
  template<class... A> bool canTransform(A&&... args) const;
  template<class... A> void transformPoint(A&&... args) const;
  template<class... A> void transformPose(A&&... args) const;
  template<class... A> void transformVector(A&&... args) const;
  template<class... A> void transformQuaternion(A&&... args) const;
  bool frameExists(const std::string& frame) const;
  std::string allFramesAsString() const;
};
class TransformListener : public Transformer {
public:
  TransformListener();
  template<class... A> explicit TransformListener(A&&... args);
  std::string resolve(const std::string& frame_name);
};
class TransformBroadcaster {
public:
  TransformBroadcaster();
  template<class M> void sendTransform(const M& transform);
};
Quaternion createQuaternionFromRPY(double roll, double pitch, double yaw);
Quaternion createQuaternionFromYaw(double yaw);
template<class M> M createQuaternionMsgFromYaw(double yaw);
double getYaw(const Quaternion& q);
template<class M> double getYaw(const M& q);
template<class A, class B> void poseMsgToTF(const A& msg, B& pose);
template<class A, class B> void poseTFToMsg(const A& pose, B& msg);
template<class A, class B> void quaternionMsgToTF(const A& msg, B& q);
template<class A, class B> void quaternionTFToMsg(const A& q, B& msg);
template<class A, class B> void transformStampedTFToMsg(const A& t, B& msg);
template<class A, class B> void vector3TFToMsg(const A& v, B& msg);
std::string resolve(const std::string& prefix, const std::string& frame_name);
std::string remap(const std::string& frame_id);
}  // namespace tf
#endif
