// Velocity controller: slows down near obstacles.
#include <ros/ros.h>
#include <geometry_msgs/Twist.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Empty.h>

static const char* const CMD_TOPIC = "cmd_vel";

ros::Publisher cmd_pub;
double max_speed = 0.5;

void onScan(const sensor_msgs::LaserScan::ConstPtr& scan)
{
  geometry_msgs::Twist cmd;
  cmd.linear.x = max_speed;
  for (float range : scan->ranges)
  {
    if (range < 0.3f)
      cmd.linear.x = 0.0;
  }
  cmd_pub.publish(cmd);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "controller");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  pnh.param("max_speed", max_speed, 0.5);
  cmd_pub = nh.advertise<geometry_msgs::Twist>(CMD_TOPIC, 10);
  ros::Subscriber scan_sub = nh.subscribe("scan", 5, onScan);
  bool use_reset = false;
  pnh.getParam("use_reset", use_reset);
  if (use_reset || ros::service::exists("driver/reset", false))
  {
    ros::ServiceClient reset = nh.serviceClient<std_srvs::Empty>("driver/reset");
    std_srvs::Empty call;
    reset.call(call);
  }
  ros::spin();
  return 0;
}
