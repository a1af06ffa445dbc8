"""The stand-ins declare the APIs whose absence made a unit's first parse fail and cost it
a second parse with the unknown names declared permissively (bench/README "Stand-in
gaps"): message_filters' SubscriberBase (a class in ROS 1 and from Rolling's release on,
a template on the node type in ROS 2 before) and Connection, tf2_ros' MessageFilterBase,
ROS 2 laser_geometry, dynamic_reconfigure's service and messages, rclcpp's
ParameterCallbackHandle, std algorithms and type traits, libuuid, nanoflann and
BehaviorTree.CPP. Each unit here parses once, without errors, and its calls are found."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

ROS1_FILTERS = """\
#include <ros/ros.h>
#include <message_filters/subscriber.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/buffer.h>
#include <laser_geometry/laser_geometry.h>
#include <sensor_msgs/LaserScan.h>
#include <boost/shared_ptr.hpp>
#include <vector>
class Layer {
 public:
  void onInitialize() {
    boost::shared_ptr<message_filters::Subscriber<sensor_msgs::LaserScan> > sub(
        new message_filters::Subscriber<sensor_msgs::LaserScan>(nh_, "scan", 50));
    boost::shared_ptr<tf2_ros::MessageFilter<sensor_msgs::LaserScan> > filter(
        new tf2_ros::MessageFilter<sensor_msgs::LaserScan>(*sub, *tf_, "map", 50, nh_));
    filter->registerCallback(boost::bind(&Layer::onScan, this, _1));
    subscribers_.push_back(sub);
    notifiers_.push_back(filter);
    notifiers_.back()->setTargetFrame("odom");
    pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan_out", 1);
  }
  void deactivate() {
    for (auto& s : subscribers_) s->unsubscribe();
  }
  void onScan(const sensor_msgs::LaserScanConstPtr& scan);
 private:
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  tf2_ros::Buffer* tf_;
  laser_geometry::LaserProjection projector_;
  std::vector<boost::shared_ptr<message_filters::SubscriberBase> > subscribers_;
  std::vector<boost::shared_ptr<tf2_ros::MessageFilterBase> > notifiers_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "layer");
  Layer layer;
  layer.onInitialize();
}
"""

ROS2_FILTERS = """\
#include <memory>
#include <vector>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "message_filters/subscriber.hpp"
#include "tf2_ros/message_filter.hpp"
#include "tf2_ros/buffer.hpp"
#include "laser_geometry/laser_geometry.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "sensor_msgs/msg/point_cloud2.hpp"
class Layer : public rclcpp_lifecycle::LifecycleNode {
 public:
  Layer() : rclcpp_lifecycle::LifecycleNode("layer") {
#if RCLCPP_VERSION_GTE(29, 6, 0)
    auto sub = std::make_shared<message_filters::Subscriber<sensor_msgs::msg::LaserScan>>(
      shared_from_this(), "scan", rclcpp::SensorDataQoS());
#else
    auto sub = std::make_shared<message_filters::Subscriber<sensor_msgs::msg::LaserScan,
        rclcpp_lifecycle::LifecycleNode>>(
      shared_from_this(), "scan", rmw_qos_profile_sensor_data);
#endif
    auto filter = std::make_shared<tf2_ros::MessageFilter<sensor_msgs::msg::LaserScan>>(
      *sub, *tf_, "map", 50, get_node_logging_interface(), get_node_clock_interface());
    connection_ = filter->registerCallback(
      std::bind(&Layer::onScan, this, std::placeholders::_1));
    subscribers_.push_back(sub);
    notifiers_.push_back(filter);
    notifiers_.back()->setTolerance(rclcpp::Duration::from_seconds(0.1));
    pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("cloud", 1);
  }
  ~Layer() {connection_.disconnect();}
  void onScan(sensor_msgs::msg::LaserScan::ConstSharedPtr scan) {
    sensor_msgs::msg::PointCloud2 cloud;
    projector_.transformLaserScanToPointCloud("map", *scan, cloud, *tf_);
    projector_.projectLaser(*scan, cloud);
    for (auto & s : subscribers_) {s->unsubscribe();}
  }
 private:
  std::shared_ptr<tf2_ros::Buffer> tf_;
  laser_geometry::LaserProjection projector_;
  message_filters::Connection connection_;
#if RCLCPP_VERSION_GTE(29, 6, 0)
  std::vector<std::shared_ptr<message_filters::SubscriberBase>> subscribers_;
#else
  std::vector<std::shared_ptr<message_filters::SubscriberBase<rclcpp_lifecycle::LifecycleNode>>>
  subscribers_;
#endif
  std::vector<std::shared_ptr<tf2_ros::MessageFilterBase>> notifiers_;
  rclcpp_lifecycle::LifecyclePublisher<sensor_msgs::msg::PointCloud2>::SharedPtr pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Layer>();
  rclcpp::spin(node->get_node_base_interface());
}
"""

LIBRARIES = """\
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include <uuid/uuid.h>
#include <nanoflann.hpp>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/float32.hpp"
#if SIZE_MAX == UINT64_MAX
#define BITS 64
#else
#error Unsupported bitness
#endif
struct Cloud {
  std::vector<double> xs;
  size_t kdtree_get_point_count() const {return xs.size();}
  double kdtree_get_pt(const size_t i, const size_t) const {return xs[i];}
  template<class B> bool kdtree_get_bbox(B &) const {return false;}
};
typedef nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 1, unsigned int> tree_t;
template<class T, class = std::enable_if_t<std::is_trivially_copyable<T>::value &&
  std::is_nothrow_swappable<T>::value && (std::alignment_of<T>::value > 0)>>
T keep(T v) {return v;}
template<size_t... I> size_t count(std::index_sequence<I...>) {return sizeof...(I);}
class Ring : public rclcpp::Node {
 public:
  Ring() : rclcpp::Node("ring") {
    tree_ = new tree_t(1, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree_->buildIndex();
    uuid_t id;
    uuid_generate(id);
    char text[37];
    uuid_unparse(id, text);
    if (std::string(text).ends_with("0")) {buffer_.resize(count(std::make_index_sequence<3>{}));}
    buffer_.push_back(keep(UINT64_C(0xe17a1465)));
    pub_ = create_publisher<std_msgs::msg::Float32>("ring", 10);
    events_ = std::make_shared<rclcpp::ParameterEventHandler>(this);
    handle_ = events_->add_parameter_callback(
      "resolution", [](const rclcpp::Parameter &) {}, "map_server");
  }
  void push(float v) {
    std::rotate(buffer_.begin(), buffer_.begin() + 1, buffer_.end());
    buffer_.back() = v;
    unsigned int index;
    double distance;
    tree_->knnSearch(&cloud_.xs[0], 1, &index, &distance);
    int dx = static_cast<int>(index) - 3, dy = 4;
    buffer_.push_back(std::sqrt(dx * dx + dy * dy));
  }
 private:
  Cloud cloud_;
  tree_t * tree_;
  std::vector<float> buffer_;
  rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr pub_;
  std::shared_ptr<rclcpp::ParameterEventHandler> events_;
  std::shared_ptr<rclcpp::ParameterCallbackHandle> handle_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Ring>());
}
"""

BEHAVIOR_TREE = """\
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "behaviortree_cpp/bt_factory.h"
#include "behaviortree_cpp/action_node.h"
#include "behaviortree_cpp/condition_node.h"
#include "behaviortree_cpp/decorator_node.h"
#include "behaviortree_cpp/control_node.h"
#include "behaviortree_cpp/loggers/groot2_publisher.h"
class Say : public BT::SyncActionNode {
 public:
  Say(const std::string & name, const BT::NodeConfig & config)
  : BT::SyncActionNode(name, config) {
    node_ = config.blackboard->get<rclcpp::Node::SharedPtr>("node");
    pub_ = node_->create_publisher<std_msgs::msg::String>("said", 10);
  }
  static BT::PortsList providedPorts() {
    return {BT::InputPort<std::string>("text"), BT::OutputPort<int>("length")};
  }
  BT::NodeStatus tick() override {
    auto text = getInput<std::string>("text");
    if (!text) {return BT::NodeStatus::FAILURE;}
    setOutput("length", static_cast<int>(text.value().size()));
    return BT::NodeStatus::SUCCESS;
  }
 private:
  rclcpp::Node::SharedPtr node_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Wait : public BT::StatefulActionNode {
 public:
  using BT::StatefulActionNode::StatefulActionNode;
  BT::NodeStatus onStart() override {return BT::NodeStatus::RUNNING;}
  BT::NodeStatus onRunning() override {return BT::NodeStatus::SUCCESS;}
  void onHalted() override {}
};
class Ready : public BT::ConditionNode {
 public:
  Ready(const std::string & name, const BT::NodeConfiguration & config)
  : BT::ConditionNode(name, config) {}
  BT::NodeStatus tick() override {return BT::NodeStatus::SUCCESS;}
};
class Twice : public BT::DecoratorNode {
 public:
  Twice(const std::string & name, const BT::NodeConfig & config)
  : BT::DecoratorNode(name, config) {}
  BT::NodeStatus tick() override {return child_node_->executeTick();}
};
class First : public BT::ControlNode {
 public:
  First(const std::string & name, const BT::NodeConfig & config)
  : BT::ControlNode(name, config) {}
  BT::NodeStatus tick() override {return children_nodes_[0]->executeTick();}
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("teller");
  auto status = node->create_publisher<std_msgs::msg::String>("status", 1);
  BT::BehaviorTreeFactory factory;
  factory.registerNodeType<Say>("Say");
  factory.registerNodeType<Wait>("Wait");
  factory.registerNodeType<Ready>("Ready");
  factory.registerNodeType<Twice>("Twice");
  factory.registerNodeType<First>("First");
  auto blackboard = BT::Blackboard::create();
  blackboard->set<rclcpp::Node::SharedPtr>("node", node);
  BT::Tree tree = factory.createTreeFromFile("tree.xml", blackboard);
  BT::Groot2Publisher groot(tree);
  while (rclcpp::ok() && tree.tickOnce() == BT::NodeStatus::RUNNING) {
    tree.sleep(std::chrono::milliseconds(10));
  }
  tree.haltTree();
}
"""


def _extract(tmp_path, text: str, distro: str | None = None) -> CppResult:
    (tmp_path / "package.xml").write_text(package_xml("gaps"))
    source = tmp_path / "node.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None, distro=distro)


def _unparsed(result: CppResult) -> list[tuple[str, str]]:
    return [(d.code, d.message) for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_NAMES_DECLARED", "CPP_INCLUDE_MISSING")]


def test_ros1_filter_bases_and_laser_projection(tmp_path) -> None:
    result = _extract(tmp_path, ROS1_FILTERS, "noetic")
    assert _unparsed(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "scan", "sensor_msgs/LaserScan"),
        ("publish", "scan_out", "sensor_msgs/LaserScan")]


@pytest.mark.parametrize("distro", ["humble", "jazzy", "rolling"])
def test_ros2_filter_bases_connection_and_laser_projection(tmp_path, distro: str) -> None:
    """Jazzy's SubscriberBase is a template on the node type, Rolling's a class."""
    result = _extract(tmp_path, ROS2_FILTERS, distro)
    assert _unparsed(result) == []
    # the lifecycle node's own services and transition events aside
    assert [(c.kind, c.name, c.type) for c in result.calls if not c.name.startswith("~")] == [
        ("subscribe", "scan", "sensor_msgs/msg/LaserScan"),
        ("publish", "cloud", "sensor_msgs/msg/PointCloud2")]


def test_std_algorithms_traits_uuid_and_nanoflann(tmp_path) -> None:
    result = _extract(tmp_path, LIBRARIES, "jazzy")
    assert _unparsed(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "ring", "std_msgs/msg/Float32"),
        ("subscribe", "/parameter_events", "rcl_interfaces/msg/ParameterEvent")]


def test_behavior_tree_nodes_factory_and_blackboard(tmp_path) -> None:
    result = _extract(tmp_path, BEHAVIOR_TREE, "jazzy")
    assert _unparsed(result) == []
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "said", "std_msgs/msg/String"),
        ("publish", "status", "std_msgs/msg/String")]


RECONFIGURE_CLIENT = """\
#include <ros/ros.h>
#include <dynamic_reconfigure/Reconfigure.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "slow");
  ros::NodeHandle planner("move_base/planner");
  ros::ServiceClient client =
      planner.serviceClient<dynamic_reconfigure::Reconfigure>("set_parameters", true);
  dynamic_reconfigure::Reconfigure request;
  dynamic_reconfigure::DoubleParameter speed;
  speed.name = "max_vel_x";
  speed.value = 0.25;
  request.request.config.doubles.push_back(speed);
  client.call(request);
}
"""


def test_dynamic_reconfigure_service_of_another_node(tmp_path) -> None:
    """move_slow_and_clear sets the planner's parameters through its set_parameters
    service: dynamic_reconfigure's Reconfigure and Config's parameter messages."""
    result = _extract(tmp_path, RECONFIGURE_CLIENT, "noetic")
    assert _unparsed(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("client", "move_base/planner/set_parameters", "dynamic_reconfigure/Reconfigure")]
