// haros_arch stand-in: urdf's Model and urdfdom's model classes and parser (declarations
// only); every urdf/, urdf_model/ and urdf_parser/ header includes this one
#ifndef HAROS_STANDIN_URDF_MODEL_H
#define HAROS_STANDIN_URDF_MODEL_H
#include <ros/ros.h>
#include <map>
#include <memory>
#include <string>
#include <vector>
namespace urdf {
class Vector3 {
public:
  double x, y, z;
};
class Rotation {
public:
  double x, y, z, w;
  void getRPY(double &roll, double &pitch, double &yaw) const;
};
class Pose {
public:
  Vector3 position;
  Rotation rotation;
};
class Geometry {
public:
  enum { SPHERE, BOX, CYLINDER, MESH } type;
};
class Sphere : public Geometry { public: double radius; };
class Box : public Geometry { public: Vector3 dim; };
class Cylinder : public Geometry { public: double length, radius; };
class Mesh : public Geometry { public: std::string filename; Vector3 scale; };
class Collision {
public:
  Pose origin;
  std::shared_ptr<Geometry> geometry;
  std::string name;
};
class Material;
class Visual {
public:
  Pose origin;
  std::shared_ptr<Geometry> geometry;
  std::string name, material_name;
  std::shared_ptr<Material> material;
};
class JointLimits { public: double lower, upper, effort, velocity; };
class JointDynamics { public: double damping, friction; };
class JointMimic { public: double offset, multiplier; std::string joint_name; };
class JointSafety { public: double soft_upper_limit, soft_lower_limit, k_position, k_velocity; };
class JointCalibration { public: std::shared_ptr<double> rising, falling; double reference_position; };
class Joint {
public:
  enum { UNKNOWN, REVOLUTE, CONTINUOUS, PRISMATIC, FLOATING, PLANAR, FIXED } type;
  std::string name;
  Vector3 axis;
  std::string child_link_name, parent_link_name;
  Pose parent_to_joint_origin_transform;
  std::shared_ptr<JointDynamics> dynamics;
  std::shared_ptr<JointLimits> limits;
  std::shared_ptr<JointMimic> mimic;
  std::shared_ptr<JointSafety> safety;
  std::shared_ptr<JointCalibration> calibration;
};
class Inertial {
public:
  Pose origin;
  double mass, ixx, ixy, ixz, iyy, iyz, izz;
};
class Color { public: float r, g, b, a; };
class Material { public: std::string name, texture_filename; Color color; };
typedef std::shared_ptr<Inertial> InertialSharedPtr;
typedef std::shared_ptr<const Inertial> InertialConstSharedPtr;
typedef std::shared_ptr<Material> MaterialSharedPtr;
class Link;
typedef std::shared_ptr<Link> LinkSharedPtr;
typedef std::shared_ptr<const Link> LinkConstSharedPtr;
typedef std::shared_ptr<Joint> JointSharedPtr;
typedef std::shared_ptr<const Joint> JointConstSharedPtr;
typedef std::shared_ptr<Collision> CollisionSharedPtr;
typedef std::shared_ptr<Geometry> GeometrySharedPtr;
typedef std::shared_ptr<const Geometry> GeometryConstSharedPtr;
typedef std::shared_ptr<Cylinder> CylinderSharedPtr;
typedef std::shared_ptr<Sphere> SphereSharedPtr;
class Link {
public:
  std::string name;
  std::shared_ptr<Inertial> inertial;
  std::shared_ptr<Collision> collision;
  std::vector<std::shared_ptr<Collision> > collision_array;
  std::shared_ptr<Visual> visual;
  std::shared_ptr<Joint> parent_joint;
  std::vector<std::shared_ptr<Joint> > child_joints;
  std::vector<std::shared_ptr<Link> > child_links;
  LinkSharedPtr getParent() const;
};
class ModelInterface {
public:
  std::string name_;
  std::map<std::string, LinkSharedPtr> links_;
  std::map<std::string, JointSharedPtr> joints_;
  LinkConstSharedPtr getRoot() const;
  LinkConstSharedPtr getLink(const std::string &name) const;
  JointConstSharedPtr getJoint(const std::string &name) const;
  const std::string &getName() const;
  void getLinks(std::vector<LinkSharedPtr> &links) const;
};
typedef std::shared_ptr<ModelInterface> ModelInterfaceSharedPtr;
typedef std::shared_ptr<const ModelInterface> ModelInterfaceConstSharedPtr;
ModelInterfaceSharedPtr parseURDF(const std::string &xml_string);
ModelInterfaceSharedPtr parseURDFFile(const std::string &path);
// the ROS package's Model: initParam reads the description from the parameter server
class Model : public ModelInterface {
public:
  bool initFile(const std::string &filename);
  bool initString(const std::string &xmlstring);
  bool initParam(const std::string &param);
  bool initParamWithNodeHandle(const std::string &param,
                               const ros::NodeHandle &nh = ros::NodeHandle());
};
typedef std::shared_ptr<Model> ModelSharedPtr;
}  // namespace urdf
#endif
