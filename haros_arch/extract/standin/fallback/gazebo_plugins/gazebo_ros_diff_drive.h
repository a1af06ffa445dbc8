// haros_arch stand-in: ROS 1 gazebo_plugins' differential drive plugin class
// (gazebo_plugins/gazebo_ros_diff_drive.h, kinetic to noetic), which packages build a
// copy of its source against (HusqvarnaResearch/hrp's am_gazebo_controller_2wd compiles
// its own gazebo_ros_diff_drive.cpp with this header). Read only when the workspace has
// no such header (headers.FALLBACK). Declarations only: the class, its methods and the
// members its source uses, so that a copy's out-of-line definitions parse and their ROS
// calls (the command subscriber, the odometry and joint state publishers, made on the
// GazeboRos helper's handle) are read there. gazebo_plugins' own plugin, loaded from
// libgazebo_ros_diff_drive.so, is a row of robot/gazebo_plugins.py instead.
#ifndef HAROS_STANDIN_GAZEBO_PLUGINS_GAZEBO_ROS_DIFF_DRIVE_H
#define HAROS_STANDIN_GAZEBO_PLUGINS_GAZEBO_ROS_DIFF_DRIVE_H
#include <map>
#include <string>
#include <vector>
#include <boost/bind.hpp>
#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <gazebo/gazebo.hh>
#include <gazebo_plugins/gazebo_ros_utils.h>
#include <geometry_msgs/Pose2D.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/advertise_options.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sdf/sdf.hh>
#include <sensor_msgs/JointState.h>
#include <tf/transform_broadcaster.h>
#include <tf/transform_listener.h>

namespace gazebo
{
class Joint;
class Entity;

// the Gazebo types the class's members are declared with, as Gazebo 7 to 11 declare
// them (gazebo/physics/PhysicsTypes.hh, common/CommonTypes.hh, common/Time.hh): boost
// pointers to classes declared here and left to the parse, which defines a class used
// complete permissively (a copy's ``parent->GetWorld()``); the simulation time its
// members hold is written out
namespace physics
{
class Model;
class Joint;
typedef boost::shared_ptr<Model> ModelPtr;
typedef boost::shared_ptr<Joint> JointPtr;
}  // namespace physics
namespace event
{
class Connection;
typedef boost::shared_ptr<Connection> ConnectionPtr;
}  // namespace event
namespace common
{
class Time
{
public:
  Time();
  Time(double _time);
  Time(int _sec, int _nsec);
  static const Time &GetWallTime();
  double Double() const;
  float Float() const;
  Time operator+(const Time &_time) const;
  Time operator-(const Time &_time) const;
  Time &operator+=(const Time &_time);
  Time &operator-=(const Time &_time);
  bool operator==(const Time &_time) const;
  bool operator!=(const Time &_time) const;
  bool operator<(const Time &_time) const;
  bool operator<=(const Time &_time) const;
  bool operator>(const Time &_time) const;
  bool operator>=(const Time &_time) const;
  int sec;
  int nsec;
};
}  // namespace common

class GazeboRosDiffDrive : public ModelPlugin
{
  enum OdomSource
  {
    ENCODER = 0,
    WORLD = 1,
  };

public:
  GazeboRosDiffDrive();
  ~GazeboRosDiffDrive();
  void Load(physics::ModelPtr _parent, sdf::ElementPtr _sdf);
  void Reset();

protected:
  virtual void UpdateChild();
  virtual void FiniChild();

private:
  void publishOdometry(double step_time);
  void getWheelVelocities();
  void publishWheelTF();
  void publishWheelJointState();
  void UpdateOdometryEncoder();
  void QueueThread();
  void cmdVelCallback(const geometry_msgs::Twist::ConstPtr &cmd_msg);

  GazeboRosPtr gazebo_ros_;
  physics::ModelPtr parent;
  event::ConnectionPtr update_connection_;
  double wheel_separation_;
  double wheel_diameter_;
  double wheel_torque;
  double wheel_speed_[2];
  double wheel_accel;
  double wheel_speed_instr_[2];
  std::vector<physics::JointPtr> joints_;
  ros::Publisher odometry_publisher_;
  ros::Subscriber cmd_vel_subscriber_;
  boost::shared_ptr<tf::TransformBroadcaster> transform_broadcaster_;
  sensor_msgs::JointState joint_state_;
  ros::Publisher joint_state_publisher_;
  nav_msgs::Odometry odom_;
  std::string tf_prefix_;
  boost::mutex lock;
  std::string robot_namespace_;
  std::string command_topic_;
  std::string odometry_topic_;
  std::string odometry_frame_;
  std::string robot_base_frame_;
  bool publish_tf_;
  ros::CallbackQueue queue_;
  boost::thread callback_queue_thread_;
  double x_;
  double rot_;
  bool alive_;
  double update_rate_;
  double update_period_;
  common::Time last_update_time_;
  OdomSource odom_source_;
  geometry_msgs::Pose2D pose_encoder_;
  common::Time last_odom_update_;
  bool publishWheelTF_;
  bool publishOdomTF_;
  bool publishWheelJointState_;
};
}  // namespace gazebo
#endif
