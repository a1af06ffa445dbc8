// haros_arch stand-in: srdfdom's semantic robot model (declarations only), which MoveIt
// builds every robot model from; read only when the workspace has no srdfdom. No ROS call.
#ifndef HAROS_STANDIN_SRDFDOM_MODEL_H
#define HAROS_STANDIN_SRDFDOM_MODEL_H
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <urdf/model.h>
namespace tinyxml2 {
class XMLElement;
class XMLDocument;
}  // namespace tinyxml2
namespace srdf {
class Model {
public:
  Model();
  bool initXml(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* xml);
  bool initXml(const urdf::ModelInterface& urdf_model, tinyxml2::XMLDocument* xml);
  bool initFile(const urdf::ModelInterface& urdf_model, const std::string& filename);
  bool initString(const urdf::ModelInterface& urdf_model, const std::string& xmlstring);
  struct Group {
    std::string name_;
    std::vector<std::string> joints_;
    std::vector<std::string> links_;
    std::vector<std::pair<std::string, std::string>> chains_;
    std::vector<std::string> subgroups_;
  };
  struct VirtualJoint {
    std::string name_;
    std::string type_;
    std::string parent_frame_;
    std::string child_link_;
  };
  struct EndEffector {
    std::string name_;
    std::string parent_link_;
    std::string parent_group_;
    std::string component_group_;
  };
  struct GroupState {
    std::string name_;
    std::string group_;
    std::map<std::string, std::vector<double>> joint_values_;
  };
  struct PassiveJoint {
    std::string name_;
  };
  struct JointProperty {
    std::string joint_name_;
    std::string property_name_;
    std::string value_;
  };
  struct Sphere {
    double center_x_, center_y_, center_z_, radius_;
  };
  struct LinkSpheres {
    std::string link_;
    std::vector<Sphere> spheres_;
  };
  struct CollisionPair {
    std::string link1_;
    std::string link2_;
    std::string reason_;
  };
  const std::string& getName() const;
  const std::vector<std::string>& getNoDefaultCollisionLinks() const;
  const std::vector<CollisionPair>& getEnabledCollisionPairs() const;
  const std::vector<CollisionPair>& getDisabledCollisionPairs() const;
  const std::vector<Group>& getGroups() const;
  const std::vector<VirtualJoint>& getVirtualJoints() const;
  const std::vector<EndEffector>& getEndEffectors() const;
  const std::vector<GroupState>& getGroupStates() const;
  const std::vector<PassiveJoint>& getPassiveJoints() const;
  const std::vector<LinkSpheres>& getLinkSphereApproximations() const;
  const std::map<std::string, std::vector<JointProperty>>& getJointProperties() const;
  const std::vector<JointProperty>& getJointProperties(const std::string& joint_name) const;
  void clear();
};
typedef std::shared_ptr<Model> ModelSharedPtr;
typedef std::shared_ptr<const Model> ModelConstSharedPtr;
}  // namespace srdf
#endif
