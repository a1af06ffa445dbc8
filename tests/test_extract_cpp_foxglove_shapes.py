"""Two shapes of foxglove_bridge's ROS 2 node that cost it its calls: a vendor type whose
header is missing, named in lowercase by an alias declaration (``using ConnectionHandle
= websocketpp::connection_hdl;``), and rclcpp's generic publishers and subscriptions with
their options, a QoS policy ``Unknown`` and ``AsyncParametersClient::delete_parameters``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ALIASED = """\
#include <map>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <websock/common/connection_hdl.hpp>
namespace bridge {
using ConnectionHandle = websock::connection_hdl;
typedef websock::server_t Server;
using Clients = std::map<ConnectionHandle, int, std::owner_less<>>;
class Bridge : public rclcpp::Node {
public:
  Bridge() : Node("bridge") {
    port_ = declare_parameter("port", 8765);
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }
private:
  void on_open(ConnectionHandle handle);
  Clients clients_;
  Server server_;
  int port_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace bridge
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<bridge::Bridge>());
}
"""
GENERIC = """\
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
class Bridge : public rclcpp::Node {
public:
  Bridge() : Node("bridge") {
    rclcpp::QoS qos(10);
    if (qos.history() == rclcpp::HistoryPolicy::Unknown) {
      qos.history(rclcpp::HistoryPolicy::SystemDefault);
    }
    rclcpp::SubscriptionOptions subscription_options;
    sub_ = create_generic_subscription(
      "chatter", "std_msgs/msg/String", qos,
      [](std::shared_ptr<const rclcpp::SerializedMessage>) {}, subscription_options);
    rclcpp::PublisherOptions publisher_options;
    pub_ = create_generic_publisher("echo", "std_msgs/msg/String", qos, publisher_options);
  }
  void forget(std::shared_ptr<rclcpp::AsyncParametersClient> client) {
    auto deleted = client->delete_parameters({"gain"});
    declare_parameter("forgotten", true);
  }
  rclcpp::GenericSubscription::SharedPtr sub_;
  rclcpp::GenericPublisher::SharedPtr pub_;
};
"""


def _extract(write_tree, source: str):
    root = write_tree({
        "bridge/package.xml": package_xml("bridge", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "bridge/src/bridge.cpp": source})
    return extract_cpp([str(root / "bridge" / "src" / "bridge.cpp")],
                       scan([str(root)], {"ROS_VERSION": "2"}), cache_dir=None,
                       distro="jazzy")


def test_a_lowercase_vendor_name_an_alias_declares_is_a_type(write_tree) -> None:
    result = _extract(write_tree, ALIASED)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "port"), ("publish", "status")]
    assert "CPP_ERROR_NEAR_CALL" not in {d.code for d in result.diagnostics}


def test_generic_endpoints_with_options_and_parameter_deletion(write_tree) -> None:
    result = _extract(write_tree, GENERIC)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "chatter", "std_msgs/msg/String"),
        ("publish", "echo", "std_msgs/msg/String"),
        ("declare", "forgotten", "bool")]
    assert not {"CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED"} & {
        d.code for d in result.diagnostics}
