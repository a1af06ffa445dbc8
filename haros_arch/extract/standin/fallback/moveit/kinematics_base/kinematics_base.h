// haros_arch stand-in: ROS 1 MoveIt's kinematics plugin base (moveit_core's
// kinematics_base.h, noetic API; declarations only), for a workspace whose kinematics
// plugins (IKFast solvers generated for a robot) build on an installed moveit_core. The
// base makes no ROS call in what it declares here: it stores what initialize / setValues
// are given (the group, frames, discretisation) in the protected members plugins read.
// Left out on purpose: the protected lookupParam<T>(name, value, default), whose reads
// (~<group>/<name>, ~<name>, robot_description_kinematics/<group>/<name>,
// robot_description_kinematics/<name>) no row describes: a plugin calling it keeps an
// error there, and its node stays partial rather than reading nothing.
#ifndef HAROS_STANDIN_MOVEIT_KINEMATICS_BASE_H
#define HAROS_STANDIN_MOVEIT_KINEMATICS_BASE_H
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/ros.h>
#include <geometry_msgs/Pose.h>
#include <moveit_msgs/MoveItErrorCodes.h>

namespace moveit {
namespace core {
class JointModelGroup;
class RobotState;
class RobotModel;
using RobotModelPtr = std::shared_ptr<RobotModel>;
using RobotModelConstPtr = std::shared_ptr<const RobotModel>;
}  // namespace core
}  // namespace moveit

namespace kinematics {

namespace DiscretizationMethods {
enum DiscretizationMethod {
  NO_DISCRETIZATION = 1,
  ALL_DISCRETIZED,
  SOME_DISCRETIZED,
  ALL_RANDOM_SAMPLED,
  SOME_RANDOM_SAMPLED
};
}  // namespace DiscretizationMethods
using DiscretizationMethod = DiscretizationMethods::DiscretizationMethod;

namespace KinematicErrors {
enum KinematicError {
  OK = 1,
  UNSUPORTED_DISCRETIZATION_REQUESTED,
  DISCRETIZATION_NOT_INITIALIZED,
  MULTIPLE_TIPS_NOT_SUPPORTED,
  EMPTY_TIP_POSES,
  IK_SEED_OUTSIDE_LIMITS,
  SOLVER_NOT_ACTIVE,
  NO_SOLUTION
};
}  // namespace KinematicErrors
using KinematicError = KinematicErrors::KinematicError;

struct KinematicsQueryOptions {
  KinematicsQueryOptions();
  bool lock_redundant_joints;
  bool return_approximate_solution;
  DiscretizationMethod discretization_method;
};

struct KinematicsResult {
  KinematicError kinematic_error;
  double solution_percentage;
};

class KinematicsBase {
 public:
  static const double DEFAULT_SEARCH_DISCRETIZATION;
  static const double DEFAULT_TIMEOUT;
  using IKCallbackFn = boost::function<void(const geometry_msgs::Pose &,
                                            const std::vector<double> &,
                                            moveit_msgs::MoveItErrorCodes &)>;

  KinematicsBase();
  virtual ~KinematicsBase();

  virtual bool getPositionIK(const geometry_msgs::Pose &ik_pose,
                             const std::vector<double> &ik_seed_state,
                             std::vector<double> &solution,
                             moveit_msgs::MoveItErrorCodes &error_code,
                             const KinematicsQueryOptions &options = KinematicsQueryOptions())
      const = 0;
  virtual bool getPositionIK(const std::vector<geometry_msgs::Pose> &ik_poses,
                             const std::vector<double> &ik_seed_state,
                             std::vector<std::vector<double> > &solutions,
                             KinematicsResult &result,
                             const KinematicsQueryOptions &options) const;
  virtual bool searchPositionIK(const geometry_msgs::Pose &ik_pose,
                                const std::vector<double> &ik_seed_state, double timeout,
                                std::vector<double> &solution,
                                moveit_msgs::MoveItErrorCodes &error_code,
                                const KinematicsQueryOptions &options = KinematicsQueryOptions())
      const = 0;
  virtual bool searchPositionIK(const geometry_msgs::Pose &ik_pose,
                                const std::vector<double> &ik_seed_state, double timeout,
                                const std::vector<double> &consistency_limits,
                                std::vector<double> &solution,
                                moveit_msgs::MoveItErrorCodes &error_code,
                                const KinematicsQueryOptions &options = KinematicsQueryOptions())
      const = 0;
  virtual bool searchPositionIK(const geometry_msgs::Pose &ik_pose,
                                const std::vector<double> &ik_seed_state, double timeout,
                                std::vector<double> &solution,
                                const IKCallbackFn &solution_callback,
                                moveit_msgs::MoveItErrorCodes &error_code,
                                const KinematicsQueryOptions &options = KinematicsQueryOptions())
      const = 0;
  virtual bool searchPositionIK(const geometry_msgs::Pose &ik_pose,
                                const std::vector<double> &ik_seed_state, double timeout,
                                const std::vector<double> &consistency_limits,
                                std::vector<double> &solution,
                                const IKCallbackFn &solution_callback,
                                moveit_msgs::MoveItErrorCodes &error_code,
                                const KinematicsQueryOptions &options = KinematicsQueryOptions())
      const = 0;
  virtual bool searchPositionIK(const std::vector<geometry_msgs::Pose> &ik_poses,
                                const std::vector<double> &ik_seed_state, double timeout,
                                const std::vector<double> &consistency_limits,
                                std::vector<double> &solution,
                                const IKCallbackFn &solution_callback,
                                moveit_msgs::MoveItErrorCodes &error_code,
                                const KinematicsQueryOptions &options = KinematicsQueryOptions(),
                                const moveit::core::RobotState *context_state = nullptr) const;
  virtual bool getPositionFK(const std::vector<std::string> &link_names,
                             const std::vector<double> &joint_angles,
                             std::vector<geometry_msgs::Pose> &poses) const = 0;

  // store the group, frames and discretisation in the members below (no ROS call)
  virtual void setValues(const std::string &robot_description, const std::string &group_name,
                         const std::string &base_frame, const std::string &tip_frame,
                         double search_discretization);
  virtual void setValues(const std::string &robot_description, const std::string &group_name,
                         const std::string &base_frame,
                         const std::vector<std::string> &tip_frames,
                         double search_discretization);
  virtual bool initialize(const std::string &robot_description, const std::string &group_name,
                          const std::string &base_frame, const std::string &tip_frame,
                          double search_discretization);
  virtual bool initialize(const std::string &robot_description, const std::string &group_name,
                          const std::string &base_frame,
                          const std::vector<std::string> &tip_frames,
                          double search_discretization);
  virtual bool initialize(const moveit::core::RobotModel &robot_model,
                          const std::string &group_name, const std::string &base_frame,
                          const std::vector<std::string> &tip_frames,
                          double search_discretization);

  virtual const std::string &getGroupName() const;
  virtual const std::string &getBaseFrame() const;
  virtual const std::string &getTipFrame() const;
  virtual const std::vector<std::string> &getTipFrames() const;
  virtual bool setRedundantJoints(const std::vector<unsigned int> &redundant_joint_indices);
  bool setRedundantJoints(const std::vector<std::string> &redundant_joint_names);
  virtual void getRedundantJoints(std::vector<unsigned int> &redundant_joint_indices) const;
  virtual const std::vector<std::string> &getJointNames() const = 0;
  virtual const std::vector<std::string> &getLinkNames() const = 0;
  virtual bool supportsGroup(const moveit::core::JointModelGroup *jmg,
                             std::string *error_text_out = nullptr) const;
  void setSearchDiscretization(double sd);
  void setSearchDiscretization(const std::map<int, double> &discretization);
  double getSearchDiscretization(int joint_index = 0) const;
  std::vector<DiscretizationMethod> getSupportedDiscretizationMethods() const;
  void setDefaultTimeout(double timeout);
  double getDefaultTimeout() const;

 protected:
  moveit::core::RobotModelConstPtr robot_model_;
  std::string robot_description_;
  std::string group_name_;
  std::string base_frame_;
  std::vector<std::string> tip_frames_;
  std::string tip_frame_;  // kept for the IKFast plugins of before tip_frames_
  double search_discretization_;
  double default_timeout_;
  std::vector<unsigned int> redundant_joint_indices_;
  std::map<int, double> redundant_joint_discretization_;
  std::vector<DiscretizationMethod> supported_methods_;
  void storeValues(const moveit::core::RobotModel &robot_model, const std::string &group_name,
                   const std::string &base_frame, const std::vector<std::string> &tip_frames,
                   double search_discretization);
};

using KinematicsBasePtr = std::shared_ptr<KinematicsBase>;
using KinematicsBaseConstPtr = std::shared_ptr<const KinematicsBase>;

}  // namespace kinematics
#endif
