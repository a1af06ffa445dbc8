// haros_arch stand-in: ROS 1 ros_control's controller_manager::ControllerManager
// (declarations only), for a workspace that has controller_manager installed, not as
// sources. A robot's hardware node builds one with its RobotHW and a handle; its
// constructor serves controller_manager/{list_controllers, list_controller_types,
// load_controller, unload_controller, switch_controller, reload_controller_libraries}
// in that handle's namespace (api.LIBRARIES), and the controllers the spawners name are
// loaded into that node. The hardware is taken as void*: the workspace may have
// hardware_interface's headers or not (a RobotHW declared permissively).
#ifndef HAROS_STANDIN_CONTROLLER_MANAGER_H
#define HAROS_STANDIN_CONTROLLER_MANAGER_H
#include <string>
#include <vector>
#include <ros/ros.h>

namespace controller_manager {
class ControllerManager {
 public:
  ControllerManager(void* robot_hw, const ros::NodeHandle& nh = ros::NodeHandle());
  virtual ~ControllerManager();
  void update(const ros::Time& time, const ros::Duration& period,
              bool reset_controllers = false);
  bool loadController(const std::string& name);
  bool unloadController(const std::string& name);
  bool switchController(const std::vector<std::string>& start_controllers,
                        const std::vector<std::string>& stop_controllers,
                        const int strictness, bool start_asap = false,
                        double timeout = 0.0);
};
}  // namespace controller_manager
#endif
