// Motor driver: takes velocity commands, publishes odometry and its status.
#include <string>

#include <ros/ros.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <std_srvs/Empty.h>
#include <demo_robot/Status.h>
#include <demo_robot/DockAction.h>
#include <actionlib/server/simple_action_server.h>

class Driver
{
public:
  Driver() : private_nh_("~"), dock_server_(nh_, "dock", false)
  {
    private_nh_.param<std::string>("port", port_, "/dev/ttyACM0");
    nh_.getParam("wheel_radius", wheel_radius_);
    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 50);
    status_pub_ = nh_.advertise<demo_robot::Status>("status", 1, true);
    // BUG for the demo: the controller publishes geometry_msgs/Twist on cmd_vel
    cmd_sub_ = nh_.subscribe("cmd_vel", 1, &Driver::onCommand, this);
    reset_srv_ = private_nh_.advertiseService("reset", &Driver::onReset, this);
    dock_server_.start();
  }

private:
  void onCommand(const geometry_msgs::TwistStamped::ConstPtr& cmd)
  {
    nav_msgs::Odometry odom;
    odom.twist.twist = cmd->twist;
    odom_pub_.publish(odom);
  }

  bool onReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&)
  {
    demo_robot::Status status;
    status.state = "reset";
    status_pub_.publish(status);
    return true;
  }

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  ros::Publisher odom_pub_;
  ros::Publisher status_pub_;
  ros::Subscriber cmd_sub_;
  ros::ServiceServer reset_srv_;
  actionlib::SimpleActionServer<demo_robot::DockAction> dock_server_;
  std::string port_;
  double wheel_radius_ = 0.1;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "driver");
  Driver driver;
  ros::spin();
  return 0;
}
