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
  double getX() const; double getY() const; double getZ() const;
  void setX(double v); void setY(double v); void setZ(double v);
  void setValue(double x, double y, double z);
  double length() const;
  double length2() const;
  double distance(const Vector3& v) const;
  double distance2(const Vector3& v) const;
  double dot(const Vector3& v) const;
  Vector3 cross(const Vector3& v) const;
  Vector3& normalize();
  Vector3 normalized() const;
  Vector3 operator+(const Vector3& v) const;
  Vector3 operator-(const Vector3& v) const;
  Vector3 operator*(double s) const;
  Vector3 operator/(double s) const;
  Vector3& operator+=(const Vector3& v);
  Vector3& operator-=(const Vector3& v);
  Vector3& operator*=(double s);
  Vector3& operator/=(double s);
  double& operator[](int i);
  double operator[](int i) const;
};
class Quaternion {
public:
  Quaternion();
  Quaternion(double x, double y, double z, double w);
  void setRPY(double roll, double pitch, double yaw);
  void setEuler(double yaw, double pitch, double roll);
  double x() const; double y() const; double z() const; double w() const;
  double getX() const; double getY() const; double getZ() const; double getW() const;
  void setValue(double x, double y, double z, double w);
  double angle(const Quaternion& q) const;
  double angleShortestPath(const Quaternion& q) const;
  double getAngle() const;
  Vector3 getAxis() const;
  Quaternion& normalize();
  Quaternion normalized() const;
  Quaternion inverse() const;
  double length() const;
  Quaternion operator*(const Quaternion& q) const;
  Quaternion& operator*=(const Quaternion& q);
};
class Matrix3x3 {
public:
  Matrix3x3();
  explicit Matrix3x3(const Quaternion& q);
  void getRPY(double& roll, double& pitch, double& yaw) const;
  void getEulerYPR(double& yaw, double& pitch, double& roll) const;
  void setRPY(double roll, double pitch, double yaw);
  void setRotation(const Quaternion& q);
  void getRotation(Quaternion& q) const;
  Matrix3x3 inverse() const;
  Matrix3x3 transpose() const;
  Vector3 operator*(const Vector3& v) const;
  Matrix3x3 operator*(const Matrix3x3& m) const;
};
typedef Vector3 Point;
class Transform {
public:
  Transform();
  Transform(const Quaternion& q, const Vector3& c = Vector3());
  Vector3& getOrigin();
  const Vector3& getOrigin() const;
  Quaternion getRotation() const;
  Matrix3x3& getBasis();
  const Matrix3x3& getBasis() const;
  void setBasis(const Matrix3x3& basis);
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
  bool setTransform(const StampedTransform& transform,
                    const std::string& authority = "default_authority");
  void chainAsVector(const std::string& target_frame, ros::Time target_time,
                     const std::string& source_frame, ros::Time source_time,
                     const std::string& fixed_frame, std::vector<std::string>& output) const;
  void getFrameStrings(std::vector<std::string>& ids) const;
  int getLatestCommonTime(const std::string& source_frame, const std::string& target_frame,
                          ros::Time& time, std::string* error_string) const;
  std::string getTFPrefix() const;
  void clear();
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
// a geometry_msgs::Quaternion (tf/transform_datatypes.h), whose header this stand-in
// does not include: the message's fields, and it converts to the message type
struct QuaternionMsg {
  double x, y, z, w;
  template<class M> operator M() const;
};
QuaternionMsg createQuaternionMsgFromYaw(double yaw);
QuaternionMsg createQuaternionMsgFromRollPitchYaw(double roll, double pitch, double yaw);
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
std::string getPrefixParam(ros::NodeHandle& nh);
}  // namespace tf
#endif
