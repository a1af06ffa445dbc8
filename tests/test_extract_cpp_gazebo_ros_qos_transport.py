"""A ROS 2 Gazebo classic plugin that takes a topic's QoS from its ``gazebo_ros::Node``
(``ros_node_->get_qos().get_publisher_qos(topic)``: the node's ``<qos>`` overrides over
a default of ``rclcpp::QoS(10)``) and talks to Gazebo's own transport through
``transport::NodePtr`` made by ``boost::make_shared<transport::Node>()``. In Gazebo
classic, transport's pointers are ``boost::shared_ptr`` (gazebo/transport/
TransportTypes.hh), and gazebo_ros' ``Node`` has ``get_qos()`` (node.hpp), whose
``QoS`` getters default their second argument. The stand-ins had the pointers as
``std::shared_ptr``, no ``get_qos`` and no defaults: "no viable overloaded '='" and
"no member named 'get_qos'" in the plugin's Load, which calls the ROS API, and the
plugin was partial (drone_autonomous_landing_on_ugv cdfdd52,
ros2_px4_gazebo_uwb.cpp:98, 206)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <memory>
#include <string>
#include <boost/make_shared.hpp>
#include <gazebo/common/Plugin.hh>
#include <gazebo/transport/transport.hh>
#include <gazebo_ros/node.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
namespace gazebo
{
class RangePlugin : public ModelPlugin
{
public:
  void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) override;
private:
  gazebo_ros::Node::SharedPtr ros_node_;
  transport::NodePtr gazebo_node_{nullptr};
  transport::SubscriberPtr anchor_sub_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr range_pub_;
  std::string topic_{"range"};
  void OnAnchor(ConstPoseStampedPtr &_msg);
};
GZ_REGISTER_MODEL_PLUGIN(RangePlugin)
void RangePlugin::Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
{
  ros_node_ = gazebo_ros::Node::Get(_sdf);
  gazebo_node_ = boost::make_shared<transport::Node>();
  gazebo_node_->Init(_model->GetWorld()->Name());
  anchor_sub_ = gazebo_node_->Subscribe("~/anchors", &RangePlugin::OnAnchor, this);
  const gazebo_ros::QoS & qos = ros_node_->get_qos();
  range_pub_ = ros_node_->create_publisher<std_msgs::msg::Float64>(
      topic_, qos.get_publisher_qos(topic_));
  auto other = ros_node_->create_publisher<std_msgs::msg::Float64>(
      "other", ros_node_->get_qos().get_publisher_qos("other", rclcpp::QoS(1)));
}
void RangePlugin::OnAnchor(ConstPoseStampedPtr &_msg) {}
}
"""


def test_gazebo_ros_node_qos_and_transport_pointers(write_tree) -> None:
    root = write_tree({"uwb/package.xml": package_xml("uwb").replace(
                           "</package>", "<depend>rclcpp</depend><depend>gazebo_ros</depend>"
                           "</package>"),
                       "uwb/src/range_plugin.cpp": SOURCE})
    result = extract_cpp([str(root / "uwb" / "src" / "range_plugin.cpp")],
                         scan([str(root)]), cache_dir=None)
    assert sorted(c.name for c in result.calls if c.kind == "publish") == ["other", "range"]
    near = [d for d in result.diagnostics
            if d.code in ("CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")]
    assert not near, near
