// haros_arch stand-in: ROS 1 ros_control's controller_interface (declarations only), for a
// workspace that has ros_control installed, not as sources. A controller's ROS calls are
// its own init(hw, controller_nh) / init(hw, root_nh, controller_nh), which the controller
// manager calls with the controller's NodeHandle.
#ifndef HAROS_STANDIN_CONTROLLER_INTERFACE_ROS1_H
#define HAROS_STANDIN_CONTROLLER_INTERFACE_ROS1_H
#include <memory>
#include <string>
#include <vector>
#include <ros/ros.h>
#include <hardware_interface/haros_ros1.h>

namespace controller_interface {
class ControllerBase {
 public:
  ControllerBase() = default;
  virtual ~ControllerBase() = default;
  virtual void starting(const ros::Time& time);
  virtual void update(const ros::Time& time, const ros::Duration& period) = 0;
  virtual void stopping(const ros::Time& time);
  virtual void waiting(const ros::Time& time);
  virtual void aborting(const ros::Time& time);
  bool isInitialized() const;
  bool isRunning() const;
  bool isStopped() const;
  bool isWaiting() const;
  bool isAborted() const;
  typedef std::vector<hardware_interface::InterfaceResources> ClaimedResources;
  enum class ControllerState { CONSTRUCTED, INITIALIZED, RUNNING, STOPPED, WAITING, ABORTED };
};
typedef std::shared_ptr<ControllerBase> ControllerBaseSharedPtr;

template<class T>
class Controller : public virtual ControllerBase {
 public:
  Controller();
  virtual bool init(T* hw, ros::NodeHandle& controller_nh);
  virtual bool init(T* hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh);
};

template<class... T>
class MultiInterfaceController : public virtual ControllerBase {
 public:
  MultiInterfaceController(bool allow_optional_interfaces = false);
  virtual bool init(hardware_interface::RobotHW* robot_hw, ros::NodeHandle& controller_nh);
  virtual bool init(hardware_interface::RobotHW* robot_hw, ros::NodeHandle& root_nh,
                    ros::NodeHandle& controller_nh);
};
}  // namespace controller_interface
#endif
