// haros_arch stand-in: gazebo_ros (ROS 2 gazebo_ros_pkgs) Node, the rclcpp node a
// Gazebo classic plugin gets from Node::Get(sdf): named by the <plugin>'s name, in its
// <ros><namespace>, with its <ros><remapping> rules (robot.attach gives the plugin's
// instance those). Read only when the workspace has no gazebo_ros/node.hpp
// (headers.FALLBACK); gazebo_ros' other headers are not stood in for.
#ifndef HAROS_STANDIN_GAZEBO_ROS_NODE_HPP
#define HAROS_STANDIN_GAZEBO_ROS_NODE_HPP
#include <memory>
#include <string>
#include <gazebo/gazebo.hh>
#include <rclcpp/rclcpp.hpp>

namespace gazebo_ros
{
// gazebo_ros/qos.hpp: the <qos> overrides of a plugin's topics, over a default QoS
class QoS
{
public:
  QoS();
  explicit QoS(sdf::ElementPtr _sdf);
  rclcpp::QoS get_publisher_qos(const std::string _topic,
                                rclcpp::QoS _default = rclcpp::QoS(10)) const;
  rclcpp::QoS get_subscription_qos(const std::string _topic,
                                   rclcpp::QoS _default = rclcpp::QoS(10)) const;
};

class Node : public rclcpp::Node
{
public:
  typedef std::shared_ptr<Node> SharedPtr;
  static SharedPtr Get(sdf::ElementPtr _sdf);
  static SharedPtr Get(sdf::ElementPtr _sdf, const std::string &_node_name);
  static SharedPtr Get();
  // the QoS overrides of the plugin's <ros><qos> (gazebo_ros/node.hpp)
  const QoS &get_qos() const &;
  QoS get_qos() &&;
};
}  // namespace gazebo_ros
#endif
