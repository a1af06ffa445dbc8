"""Names and queue sizes a node takes from functions that return a constant: a free or
inline function without parameters (a library header's ``inline std::string
imu_topic() { return "imu/data"; }``, a file's ``static int depth() { return 7; }``) as
a class's static getter already was, and an integer getter as a string one; and a depth
the parse does not know (``rclcpp::QoS(topicQueueSize_)`` of a member set from a
parameter, a function's result) is unknown, not the default profile's 10."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """
    #include <string>
    namespace sensing {
    class RangeSource {
     public:
      static std::string topic() { return "ranges"; }
      static int depth() { return 5; }
    };
    inline std::string imu_topic() { return "imu/data"; }
    }  // namespace sensing
    """

NODE = """
    #include <memory>
    #include <string>
    #include <rclcpp/rclcpp.hpp>
    #include <sensor_msgs/msg/imu.hpp>
    #include <sensor_msgs/msg/range.hpp>
    #include "pkg/sensing.hpp"

    static int local_depth() { return 7; }
    static std::string local_topic() { return "local"; }
    size_t depth_of(int robot);

    class Ranger : public rclcpp::Node {
     public:
      Ranger() : rclcpp::Node("ranger") {
        ranges_ = create_publisher<sensor_msgs::msg::Range>(
            sensing::RangeSource::topic(), sensing::RangeSource::depth());
        local_ = create_publisher<sensor_msgs::msg::Range>(local_topic(), local_depth());
        imu_ = create_subscription<sensor_msgs::msg::Imu>(
            sensing::imu_topic(), 10, [](sensor_msgs::msg::Imu::SharedPtr) {});
        queue_ = declare_parameter("queue", 3);
        other_ = create_publisher<sensor_msgs::msg::Range>("other", rclcpp::QoS(queue_));
        far_ = create_publisher<sensor_msgs::msg::Range>("far", depth_of(2));
      }

     private:
      int queue_;
      rclcpp::Publisher<sensor_msgs::msg::Range>::SharedPtr ranges_, local_, other_, far_;
      rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr imu_;
    };

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Ranger>());
    }
    """


def test_constant_getters_name_calls_and_unknown_depths_stay_unknown(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>sensor_msgs</depend></package>"),
        "pkg/include/pkg/sensing.hpp": HEADER,
        "pkg/src/node.cpp": NODE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    found = {(c.kind, c.name): (c.queue_size, (c.qos or {}).get("depth"))
             for c in result.calls if c.kind in ("publish", "subscribe")}
    assert found == {("publish", "ranges"): (5, 5), ("publish", "local"): (7, 7),
                     ("subscribe", "imu/data"): (10, 10),
                     ("publish", "other"): (None, None), ("publish", "far"): (None, None)}
