// haros_arch stand-in: ROS 1 gazebo_ros_control's GazeboRosControlPlugin (noetic-devel,
// declarations only), the base of the ros_control Gazebo plugins that robots build of
// their own (baxter_gazebo's BaxterGazeboRosControlPlugin). Read only when the workspace
// has no gazebo_ros_control/gazebo_ros_control_plugin.h (headers.FALLBACK). Its Load
// makes what the gazebo_ros_control row of robot.gazebo_plugins describes (the manager's
// services, the description read), which robot.attach gives to a plugin that includes
// this header; here it only declares what a derived class uses: the model's handle and
// the controller manager. Members of Gazebo's own types (the model, the update
// connection) are left out, as the Gazebo stand-in leaves those types to the parse.
#ifndef HAROS_STANDIN_GAZEBO_ROS_CONTROL_PLUGIN_H
#define HAROS_STANDIN_GAZEBO_ROS_CONTROL_PLUGIN_H
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>
#include <ros/ros.h>
#include <gazebo/gazebo.hh>
#include <controller_manager/controller_manager.h>

namespace gazebo_ros_control
{
class GazeboRosControlPlugin : public gazebo::ModelPlugin
{
public:
  virtual ~GazeboRosControlPlugin();
  // Load(physics::ModelPtr, sdf::ElementPtr): a template, Gazebo's model type not
  // being declared here
  template <class M, class S> void Load(M parent, S sdf);
  void Update();
  virtual void Reset();
  std::string getURDF(std::string param_name) const;
  bool parseTransmissionsFromURDF(const std::string &urdf_string);

protected:
  ros::NodeHandle model_nh_;
  std::string robot_namespace_;
  std::string robot_description_;
  std::string robot_hw_sim_type_str_;
  boost::shared_ptr<controller_manager::ControllerManager> controller_manager_;
  ros::Duration control_period_;
  ros::Time last_update_sim_time_ros_;
  ros::Time last_write_sim_time_ros_;
  bool e_stop_active_, last_e_stop_active_;
  ros::Subscriber e_stop_sub_;
};
}  // namespace gazebo_ros_control
#endif
