"""A node class whose base is a specialisation of a class template deriving from
rclcpp::Node (perception_pcl's ``class Filter : public PCLNode<PointCloud2>``,
``template<typename T> class PCLNode : public rclcpp::Node``). ``this`` handed to
message_filters' ``subscribe(this, "input", qos)`` (pcl_ros filter.cpp:123,
project_inliers.cpp:115) was not seen as the node: the names came out as
``?/input``, ``?/indices``, ``?/model`` (CPP_DYNAMIC_NAME) instead of relative names."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <message_filters/subscriber.h>
#include <sensor_msgs/msg/point_cloud2.hpp>
template<class T> class Base : public rclcpp::Node {
public:
  explicit Base(const std::string & name) : rclcpp::Node(name) {}
  message_filters::Subscriber<T> input_;
};
class Filter : public Base<sensor_msgs::msg::PointCloud2> {
public:
  Filter() : Base<sensor_msgs::msg::PointCloud2>("filter") {
    auto qos = rclcpp::SensorDataQoS().keep_last(3).get_rmw_qos_profile();
    input_.subscribe(this, "input", qos);
  }
};
"""


def test_this_of_a_class_derived_from_a_node_class_template_is_the_node(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls if c.kind == "subscribe"] == [
        ("subscribe", "input")]
    assert "CPP_DYNAMIC_NAME" not in [d.code for d in result.diagnostics]
