"""A copy of gazebo_plugins' differential drive source built against the package's
installed header (HusqvarnaResearch/hrp's am_gazebo_controller_2wd compiles its own
gazebo_ros_diff_drive.cpp with ``#include <gazebo_plugins/gazebo_ros_diff_drive.h>``).
gazebo_plugins is not in the workspace and the header had no fallback stand-in: every
out-of-line definition of the class was an error and its ROS calls were missed
(``CPP_CALL_MISSED``). glibc's ``isnanf``, which the copy tests, was undeclared too. Its
members' Gazebo types are declared there (a model, a joint: classes the parse then
defines permissively where the code uses them complete, in Gazebo's namespaces)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = r"""
#include <algorithm>
#include <cmath>
#include <gazebo_plugins/gazebo_ros_diff_drive.h>

namespace gazebo
{
GazeboRosDiffDrive::GazeboRosDiffDrive() {}
GazeboRosDiffDrive::~GazeboRosDiffDrive() {}

void GazeboRosDiffDrive::Load(physics::ModelPtr _parent, sdf::ElementPtr _sdf)
{
  this->parent = _parent;
  gazebo_ros_ = GazeboRosPtr(new GazeboRos(_parent, _sdf, "DiffDrive"));
  gazebo_ros_->isInitialized();
  joints_.resize(2);
  joints_[0] = gazebo_ros_->getJoint(parent, "leftJoint", "left_joint");
  joints_[0]->SetParam("max_force", 0, wheel_torque);
  last_update_time_ = parent->GetWorld()->SimTime();
  gazebo_ros_->getParameter<std::string>(command_topic_, "commandTopic", "cmd_vel");
  gazebo_ros_->getParameter<std::string>(odometry_topic_, "odometryTopic", "odom");
  gazebo_ros_->getParameterBoolean(publishWheelJointState_, "publishWheelJointState", false);
  if (this->publishWheelJointState_)
  {
    joint_state_publisher_ =
        gazebo_ros_->node()->advertise<sensor_msgs::JointState>("joint_states", 1000);
  }
  ros::SubscribeOptions so = ros::SubscribeOptions::create<geometry_msgs::Twist>(
      command_topic_, 1, boost::bind(&GazeboRosDiffDrive::cmdVelCallback, this, _1),
      ros::VoidPtr(), &queue_);
  cmd_vel_subscriber_ = gazebo_ros_->node()->subscribe(so);
  odometry_publisher_ = gazebo_ros_->node()->advertise<nav_msgs::Odometry>(odometry_topic_, 1);
  this->callback_queue_thread_ = boost::thread(boost::bind(&GazeboRosDiffDrive::QueueThread, this));
}

void GazeboRosDiffDrive::Reset() { x_ = 0; rot_ = 0; }

void GazeboRosDiffDrive::cmdVelCallback(const geometry_msgs::Twist::ConstPtr &cmd_msg)
{
  boost::mutex::scoped_lock scoped_lock(lock);
  x_ = cmd_msg->linear.x;
  rot_ = cmd_msg->angular.z;
}

void GazeboRosDiffDrive::UpdateOdometryEncoder()
{
  double w = wheel_speed_[0];
  if (fabs(w) < 0.002 || isnanf(w)) { w = 0; }
  pose_encoder_.x += w;
}

void GazeboRosDiffDrive::QueueThread()
{
  while (alive_ && gazebo_ros_->node()->ok()) { queue_.callAvailable(ros::WallDuration(0.01)); }
}

void GazeboRosDiffDrive::UpdateChild()
{
  common::Time current_time = parent->GetWorld()->SimTime();
  if ((current_time - last_update_time_).Double() > update_period_) { UpdateOdometryEncoder(); }
  last_update_time_ += common::Time(update_period_);
}
void GazeboRosDiffDrive::FiniChild() { alive_ = false; queue_.clear(); queue_.disable(); }

GZ_REGISTER_MODEL_PLUGIN(GazeboRosDiffDrive)
}
"""


def test_the_copy_s_calls_are_read(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("drive"))
    source = tmp_path / "diff_drive.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
    assert sorted((c.kind, c.type) for c in result.calls
                  if c.kind in ("publish", "subscribe")) == [
        ("publish", "nav_msgs/Odometry"), ("publish", "sensor_msgs/JointState"),
        ("subscribe", "geometry_msgs/Twist")]
