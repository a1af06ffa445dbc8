// Status monitor: watches every robot's status.
#include <ros/ros.h>
#include <demo_robot/Status.h>

void onStatus(const demo_robot::Status::ConstPtr& status)
{
  ROS_INFO("robot state: %s", status->state.c_str());
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "monitor");
  ros::NodeHandle nh;
  std::string robot;
  // BUG for the demo: the launch file sets ~robot_name, this reads robot_name
  nh.param<std::string>("robot_name", robot, "robot1");
  ros::Subscriber sub = nh.subscribe("/" + robot + "/status", 10, onStatus);
  ros::spin();
  return 0;
}
