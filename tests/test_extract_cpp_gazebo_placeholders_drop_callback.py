"""Two stand-in gaps that made nodes partial in orca2 7bab8eb (clydemcqueen's ROS 2 AUV):
- Gazebo classic's headers bring boost's placeholders into the global namespace (its
  transport/Node.hh itself writes ``boost::bind(_fp, _obj, _1)``; boost/bind.hpp puts
  ``_1`` there), so a plugin writes ``boost::bind(&Plugin::OnUpdate, this, _1)`` with
  no ``using`` (orca_gazebo/src/thruster_plugin.cpp:184): "'_1' does not refer to a
  value" in Load, which makes the plugin's publishers and subscriptions.
- message_filters' ``ExactTime`` policy, which a ``Synchronizer`` derives from, has
  ``registerDropCallback`` (orca_filter/src/fp_node.cpp:227): "no member named
  'registerDropCallback'" in the node's constructor."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

PLUGIN = """#include <memory>
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo_ros/node.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
namespace gazebo
{
class ThrusterPlugin : public ModelPlugin
{
public:
  void Load(physics::ModelPtr model, sdf::ElementPtr sdf) override
  {
    node_ = gazebo_ros::Node::Get(sdf);
    update_connection_ = event::Events::ConnectWorldUpdateBegin(
      boost::bind(&ThrusterPlugin::OnUpdate, this, _1));
    pub_ = node_->create_publisher<std_msgs::msg::Float64>("effort", 10);
  }
  void OnUpdate(const common::UpdateInfo & info) {}
private:
  gazebo_ros::Node::SharedPtr node_;
  event::ConnectionPtr update_connection_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
GZ_REGISTER_MODEL_PLUGIN(ThrusterPlugin)
}
"""

NODE = """#include <functional>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <message_filters/subscriber.h>
#include <message_filters/synchronizer.h>
#include <message_filters/sync_policies/exact_time.h>
#include <geometry_msgs/msg/pose_stamped.hpp>
#include <sensor_msgs/msg/imu.hpp>
using Policy = message_filters::sync_policies::ExactTime<geometry_msgs::msg::PoseStamped,
                                                          sensor_msgs::msg::Imu>;
using Sync = message_filters::Synchronizer<Policy>;
class FPNode : public rclcpp::Node
{
public:
  FPNode() : Node("fp_node")
  {
    pose_sub_.subscribe(this, "pose");
    imu_sub_.subscribe(this, "imu");
    using namespace std::placeholders;
    sync_.reset(new Sync(Policy(10), pose_sub_, imu_sub_));
    sync_->registerCallback(std::bind(&FPNode::callback, this, _1, _2));
    sync_->registerDropCallback(std::bind(&FPNode::dropped, this, _1, _2));
    pub_ = create_publisher<geometry_msgs::msg::PoseStamped>("fp", 10);
  }
private:
  void callback(const geometry_msgs::msg::PoseStamped::ConstSharedPtr & pose,
                const sensor_msgs::msg::Imu::ConstSharedPtr & imu) {}
  void dropped(const geometry_msgs::msg::PoseStamped::ConstSharedPtr & pose,
               const sensor_msgs::msg::Imu::ConstSharedPtr & imu) {}
  message_filters::Subscriber<geometry_msgs::msg::PoseStamped> pose_sub_;
  message_filters::Subscriber<sensor_msgs::msg::Imu> imu_sub_;
  std::shared_ptr<Sync> sync_;
  rclcpp::Publisher<geometry_msgs::msg::PoseStamped>::SharedPtr pub_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<FPNode>());
  return 0;
}
"""


def _extract(write_tree, path: str, source: str):
    root = write_tree({"orca/package.xml": package_xml("orca").replace(
                           "</package>", "<depend>rclcpp</depend><depend>gazebo_ros</depend>"
                           "<depend>message_filters</depend></package>"),
                       path: source})
    return extract_cpp([str(root / path)], scan([str(root)]), cache_dir=None)


def _near(result):
    return [d for d in result.diagnostics
            if d.code in ("CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")]


def test_gazebo_plugin_binds_with_boost_global_placeholder(write_tree) -> None:
    result = _extract(write_tree, "orca/src/thruster_plugin.cpp", PLUGIN)
    assert [c.name for c in result.calls if c.kind == "publish"] == ["effort"]
    assert not _near(result), _near(result)


def test_exact_time_synchronizer_drop_callback(write_tree) -> None:
    result = _extract(write_tree, "orca/src/fp_node.cpp", NODE)
    assert sorted(c.name for c in result.calls if c.kind == "subscribe") == ["imu", "pose"]
    assert [c.name for c in result.calls if c.kind == "publish"] == ["fp"]
    assert not _near(result), _near(result)
