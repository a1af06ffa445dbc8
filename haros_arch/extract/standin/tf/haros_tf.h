// haros_arch stand-in: the ROS 1 tf API nodes use (declarations only). Every tf header
// (<tf/transform_listener.h>, <tf/transform_broadcaster.h>, ...) includes this one file.
#ifndef HAROS_STANDIN_TF_H
#define HAROS_STANDIN_TF_H
#include <stdexcept>
#include <string>
#include <vector>
#include <ros/ros.h>
namespace tf {
typedef double tfScalar;
class Vector3 {
public:
  Vector3();
  Vector3(double x, double y, double z);
  double w() const; void setW(double v);
  void setZero(); bool isZero() const; bool fuzzyZero() const;
  double angle(const Vector3& v) const;
  Vector3 rotate(const Vector3& axis, double angle) const;
  Vector3 lerp(const Vector3& v, double t) const;
  Vector3 absolute() const;
  double triple(const Vector3& a, const Vector3& b) const;
  int maxAxis() const; int minAxis() const;
  void setMax(const Vector3& v); void setMin(const Vector3& v);
  Vector3 operator-() const;
  Vector3 operator*(const Vector3& v) const;
  bool operator==(const Vector3& v) const; bool operator!=(const Vector3& v) const;
  double m_floats[4];
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
  Quaternion(const Vector3& axis, double angle);
  Quaternion(double yaw, double pitch, double roll);
  void setX(double v); void setY(double v); void setZ(double v); void setW(double v);
  void setRotation(const Vector3& axis, double angle);
  void setEulerZYX(double yaw, double pitch, double roll);
  double getAngleShortestPath() const;
  double dot(const Quaternion& q) const;
  double length2() const;
  Quaternion slerp(const Quaternion& q, double t) const;
  Quaternion farthest(const Quaternion& q) const;
  Quaternion nearest(const Quaternion& q) const;
  static const Quaternion& getIdentity();
  Quaternion operator+(const Quaternion& q) const;
  Quaternion operator-(const Quaternion& q) const;
  Quaternion operator-() const;
  Quaternion operator*(double s) const;
  Quaternion operator/(double s) const;
  Quaternion& operator+=(const Quaternion& q);
  Quaternion& operator-=(const Quaternion& q);
  Quaternion& operator*=(double s);
  Quaternion& operator/=(double s);
  bool operator==(const Quaternion& q) const; bool operator!=(const Quaternion& q) const;
  double& operator[](int i); double operator[](int i) const;
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
  Matrix3x3(double xx, double xy, double xz, double yx, double yy, double yz,
            double zx, double zy, double zz);
  void setValue(double xx, double xy, double xz, double yx, double yy, double yz,
                double zx, double zy, double zz);
  Vector3 getRow(int i) const;
  Vector3 getColumn(int i) const;
  Vector3& operator[](int i);
  const Vector3& operator[](int i) const;
  void setIdentity();
  static const Matrix3x3& getIdentity();
  void setEulerYPR(double yaw, double pitch, double roll);
  void setEulerZYX(double yaw, double pitch, double roll);
  void getEulerZYX(double& yaw, double& pitch, double& roll, unsigned int solution) const;
  void getRPY(double& roll, double& pitch, double& yaw, unsigned int solution) const;
  void getEulerYPR(double& yaw, double& pitch, double& roll, unsigned int solution) const;
  Matrix3x3 scaled(const Vector3& s) const;
  double determinant() const;
  Matrix3x3 adjoint() const;
  Matrix3x3 absolute() const;
  Matrix3x3 transposeTimes(const Matrix3x3& m) const;
  Matrix3x3 timesTranspose(const Matrix3x3& m) const;
  double tdotx(const Vector3& v) const; double tdoty(const Vector3& v) const;
  double tdotz(const Vector3& v) const;
  void diagonalize(Matrix3x3& rot, double threshold, int max_steps);
  void getOpenGLSubMatrix(double* m) const;
  void setFromOpenGLSubMatrix(const double* m);
  Matrix3x3& operator*=(const Matrix3x3& m);
  bool operator==(const Matrix3x3& m) const;
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
  explicit Transform(const Matrix3x3& b, const Vector3& c = Vector3());
  Vector3 operator()(const Vector3& v) const;
  Vector3 operator*(const Vector3& v) const;
  Quaternion operator*(const Quaternion& q) const;
  Transform& operator*=(const Transform& t);
  void mult(const Transform& a, const Transform& b);
  Transform inverseTimes(const Transform& t) const;
  static const Transform& getIdentity();
  void setFromOpenGLMatrix(const double* m);
  void getOpenGLMatrix(double* m) const;
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
  void setData(const Transform& input);
  StampedTransform(const Transform& input, const ros::Time& timestamp,
                   const std::string& frame_id, const std::string& child_frame_id);
  ros::Time stamp_;
  std::string frame_id_;
  std::string child_frame_id_;
};
template<class T> class Stamped : public T {
public:
  Stamped();
  void setData(const T& input);
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
  static const unsigned int MAX_GRAPH_DEPTH = 100UL;
  static constexpr double DEFAULT_CACHE_TIME = 10.0;  // seconds
  static const int64_t DEFAULT_MAX_EXTRAPOLATION_DISTANCE = 0ULL;
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
  void setExtrapolationLimit(const ros::Duration& distance);
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
Vector3 operator*(double s, const Vector3& v);
Vector3 operator/(const Vector3& a, const Vector3& b);
double tfDot(const Vector3& a, const Vector3& b);
Vector3 tfCross(const Vector3& a, const Vector3& b);
double tfDistance(const Vector3& a, const Vector3& b);
double tfDistance2(const Vector3& a, const Vector3& b);
double tfAngle(const Vector3& a, const Vector3& b);
Vector3 lerp(const Vector3& a, const Vector3& b, double t);
Quaternion operator*(const Quaternion& q, const Vector3& v);
Quaternion operator*(const Vector3& v, const Quaternion& q);
double dot(const Quaternion& a, const Quaternion& b);
double length(const Quaternion& q);
double angle(const Quaternion& a, const Quaternion& b);
double angleShortestPath(const Quaternion& a, const Quaternion& b);
Quaternion inverse(const Quaternion& q);
Quaternion slerp(const Quaternion& a, const Quaternion& b, double t);
Vector3 quatRotate(const Quaternion& rotation, const Vector3& v);
Quaternion shortestArcQuat(const Vector3& a, const Vector3& b);
Quaternion shortestArcQuatNormalize2(Vector3& a, Vector3& b);
Vector3 operator*(const Vector3& v, const Matrix3x3& m);
double tfRadians(double degrees);
double tfDegrees(double radians);
double tfSqrt(double x); double tfFabs(double x); double tfCos(double x);
double tfSin(double x); double tfTan(double x); double tfAcos(double x);
double tfAsin(double x); double tfAtan(double x); double tfAtan2(double y, double x);
double tfNormalizeAngle(double angle);
Quaternion createIdentityQuaternion();
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
template<class A, class B> void vector3MsgToTF(const A& msg, B& v);
template<class A, class B> void pointMsgToTF(const A& msg, B& p);
template<class A, class B> void pointTFToMsg(const A& p, B& msg);
template<class A, class B> void transformMsgToTF(const A& msg, B& t);
template<class A, class B> void transformTFToMsg(const A& t, B& msg);
template<class A, class B> void transformStampedMsgToTF(const A& msg, B& t);
template<class A, class B> void poseStampedMsgToTF(const A& msg, B& pose);
template<class A, class B> void poseStampedTFToMsg(const A& pose, B& msg);
template<class A, class B> void pointStampedMsgToTF(const A& msg, B& p);
template<class A, class B> void pointStampedTFToMsg(const A& p, B& msg);
template<class A, class B> void quaternionStampedMsgToTF(const A& msg, B& q);
template<class A, class B> void quaternionStampedTFToMsg(const A& q, B& msg);
template<class A, class B> void vector3StampedMsgToTF(const A& msg, B& v);
template<class A, class B> void vector3StampedTFToMsg(const A& v, B& msg);
std::string resolve(const std::string& prefix, const std::string& frame_name);
std::string remap(const std::string& frame_id);
std::string getPrefixParam(ros::NodeHandle& nh);
}  // namespace tf
#endif
