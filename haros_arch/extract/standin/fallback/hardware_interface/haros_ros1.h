// haros_arch stand-in: ROS 1 ros_control's hardware_interface (declarations only), for a
// workspace that has ros_control installed, not as sources: a robot's RobotHW and the
// handles and interfaces its controllers claim. They make no ROS call of their own
// (a RobotHW's init(root_nh, robot_hw_nh) is the workspace's code); controllers get them
// with ``robot_hw->get<hardware_interface::PositionJointInterface>()`` (franka_ros).
#ifndef HAROS_STANDIN_HARDWARE_INTERFACE_ROS1_H
#define HAROS_STANDIN_HARDWARE_INTERFACE_ROS1_H
#include <list>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>
#include <ros/ros.h>

namespace hardware_interface {
class HardwareInterfaceException : public std::exception {
 public:
  explicit HardwareInterfaceException(const std::string& message);
  const char* what() const noexcept override;
};

class HardwareInterface {
 public:
  virtual ~HardwareInterface();
  void claim(const std::string& resource);
  void clearClaims();
  std::set<std::string> getClaims() const;
};

class ResourceManagerBase {
 public:
  virtual ~ResourceManagerBase();
};
struct DontClaimResources {};
struct ClaimResources {};
template<class ResourceHandle>
class ResourceManager : public ResourceManagerBase {
 public:
  typedef ResourceHandle ResourceHandleType;
  std::vector<std::string> getNames() const;
  void registerHandle(const ResourceHandle& handle);
  ResourceHandle getHandle(const std::string& name);
};
template<class ResourceHandle, class ClaimPolicy = DontClaimResources>
class HardwareResourceManager : public HardwareInterface, public ResourceManager<ResourceHandle> {
 public:
  typedef ResourceManager<ResourceHandle> ResourceManagerType;
  ResourceHandle getHandle(const std::string& name);
};

struct InterfaceResources {
  InterfaceResources();
  InterfaceResources(const std::string& hw_iface, const std::set<std::string>& res);
  std::string hardware_interface;
  std::set<std::string> resources;
};
struct ControllerInfo {
  std::string name;
  std::string type;
  std::vector<InterfaceResources> claimed_resources;
};

class InterfaceManager {
 public:
  template<class T> void registerInterface(T* iface);
  void registerInterfaceManager(InterfaceManager* iface_man);
  template<class T> T* get();
  std::vector<std::string> getNames() const;
  std::vector<std::string> getInterfaceResources(std::string iface_type) const;
};

class RobotHW : public InterfaceManager {
 public:
  virtual ~RobotHW();
  virtual bool init(ros::NodeHandle& root_nh, ros::NodeHandle& robot_hw_nh);
  virtual bool checkForConflict(const std::list<ControllerInfo>& info) const;
  virtual bool prepareSwitch(const std::list<ControllerInfo>& start_list,
                             const std::list<ControllerInfo>& stop_list);
  virtual void doSwitch(const std::list<ControllerInfo>& start_list,
                        const std::list<ControllerInfo>& stop_list);
  enum class SwitchState { DONE, ONGOING, ERROR };
  virtual SwitchState switchResult() const;
  virtual SwitchState switchResult(const ControllerInfo& controller) const;
  virtual void read(const ros::Time& time, const ros::Duration& period);
  virtual void write(const ros::Time& time, const ros::Duration& period);
};
typedef std::shared_ptr<RobotHW> RobotHWSharedPtr;

class JointStateHandle {
 public:
  JointStateHandle();
  JointStateHandle(const std::string& name, const double* pos, const double* vel,
                   const double* eff);
  JointStateHandle(const std::string& name, const double* pos, const double* vel,
                   const double* eff, const double* absolute_pos, const double* torque_sensor);
  std::string getName() const;
  double getPosition() const;
  double getVelocity() const;
  double getEffort() const;
  double getAbsolutePosition() const;
  double getTorqueSensor() const;
  const double* getPositionPtr() const;
  const double* getVelocityPtr() const;
  const double* getEffortPtr() const;
  bool hasAbsolutePosition() const;
  bool hasTorqueSensor() const;
};
class JointStateInterface : public HardwareResourceManager<JointStateHandle> {};

class JointHandle : public JointStateHandle {
 public:
  JointHandle();
  JointHandle(const JointStateHandle& js, double* cmd);
  void setCommand(double command);
  double getCommand() const;
  const double* getCommandPtr() const;
};
class JointCommandInterface : public HardwareResourceManager<JointHandle, ClaimResources> {};
class EffortJointInterface : public JointCommandInterface {};
class VelocityJointInterface : public JointCommandInterface {};
class PositionJointInterface : public JointCommandInterface {};

class PosVelJointHandle : public JointStateHandle {
 public:
  PosVelJointHandle();
  PosVelJointHandle(const JointStateHandle& js, double* cmd_pos, double* cmd_vel);
  void setCommand(double cmd_pos, double cmd_vel);
  void setCommandPosition(double cmd_pos);
  void setCommandVelocity(double cmd_vel);
  double getCommandPosition() const;
  double getCommandVelocity() const;
};
class PosVelJointInterface : public HardwareResourceManager<PosVelJointHandle, ClaimResources> {};
class PosVelAccJointHandle : public PosVelJointHandle {
 public:
  PosVelAccJointHandle();
  PosVelAccJointHandle(const JointStateHandle& js, double* cmd_pos, double* cmd_vel,
                       double* cmd_acc);
  void setCommand(double cmd_pos, double cmd_vel, double cmd_acc);
  void setCommandAcceleration(double cmd_acc);
  double getCommandAcceleration() const;
};
class PosVelAccJointInterface
    : public HardwareResourceManager<PosVelAccJointHandle, ClaimResources> {};

enum class JointCommandModes { BEGIN = -1, MODE_POSITION = 0, MODE_VELOCITY = 1,
                               MODE_EFFORT = 2, NOMODE = 3, EMERGENCY_STOP = 4,
                               SWITCHING = 5, ERROR = 6 };
class JointModeHandle {
 public:
  JointModeHandle();
  JointModeHandle(std::string name, JointCommandModes* mode);
  std::string getName() const;
  void setMode(JointCommandModes mode);
  int getMode() const;
  const int* getModePtr() const;
};
class JointModeInterface : public HardwareResourceManager<JointModeHandle, ClaimResources> {};

class ActuatorStateHandle {
 public:
  ActuatorStateHandle();
  ActuatorStateHandle(const std::string& name, const double* pos, const double* vel,
                      const double* eff);
  std::string getName() const;
  double getPosition() const;
  double getVelocity() const;
  double getEffort() const;
};
class ActuatorStateInterface : public HardwareResourceManager<ActuatorStateHandle> {};
class ActuatorHandle : public ActuatorStateHandle {
 public:
  ActuatorHandle();
  ActuatorHandle(const ActuatorStateHandle& as, double* cmd);
  void setCommand(double command);
  double getCommand() const;
};
class ActuatorCommandInterface : public HardwareResourceManager<ActuatorHandle, ClaimResources> {};
class EffortActuatorInterface : public ActuatorCommandInterface {};
class VelocityActuatorInterface : public ActuatorCommandInterface {};
class PositionActuatorInterface : public ActuatorCommandInterface {};

class ImuSensorHandle {
 public:
  struct Data {
    Data();
    std::string name;
    std::string frame_id;
    double* orientation;
    double* orientation_covariance;
    double* angular_velocity;
    double* angular_velocity_covariance;
    double* linear_acceleration;
    double* linear_acceleration_covariance;
  };
  ImuSensorHandle(const Data& data = {});
  ImuSensorHandle(const std::string& name, const std::string& frame_id,
                  const double* orientation, const double* orientation_covariance,
                  const double* angular_velocity, const double* angular_velocity_covariance,
                  const double* linear_acceleration,
                  const double* linear_acceleration_covariance);
  std::string getName() const;
  std::string getFrameId() const;
  const double* getOrientation() const;
  const double* getOrientationCovariance() const;
  const double* getAngularVelocity() const;
  const double* getAngularVelocityCovariance() const;
  const double* getLinearAcceleration() const;
  const double* getLinearAccelerationCovariance() const;
};
class ImuSensorInterface : public HardwareResourceManager<ImuSensorHandle> {};

class ForceTorqueSensorHandle {
 public:
  ForceTorqueSensorHandle();
  ForceTorqueSensorHandle(const std::string& name, const std::string& frame_id,
                          const double* force, const double* torque);
  std::string getName() const;
  std::string getFrameId() const;
  const double* getForce() const;
  const double* getTorque() const;
};
class ForceTorqueSensorInterface : public HardwareResourceManager<ForceTorqueSensorHandle> {};
}  // namespace hardware_interface
#endif
