"""What made ublox's ROS 2 driver ``partial`` with no ROS call hidden:

- the grep for API call sites took asio's ``resolver.resolve(query)`` for ROS 1's
  ``tf::TransformListener::resolve``: a ROS 2 unit cannot call an API of ROS 1 only, so
  those names are no call site there (and the error in that function, a vendor type's,
  is no error near a call);
- the stand-ins lacked ``std::basic_ios::fill`` (``filename.fill('0')``) and tf2's
  ``Quaternion`` subscript (``orientation[0]``, QuadWord's conversion to its array), so
  functions that publish had errors in them.

And, once the node was complete, a read in a wrapper that handles the parameter's
absence itself (``getRosUint(node, key, u, default_val)``: ``if (!getRosUint(node, key,
u)) u = default_val;``) is ``tested`` at each call of it: no read-not-set warning; the
three-argument one returns whether the parameter is there, so its callers' own tests
decide."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <sstream>
#include <stdexcept>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <tf2/LinearMath/Quaternion.h>
#include <asio/ip/tcp.hpp>
template <typename U>
bool getUint(rclcpp::Node* node, const std::string& key, U& u) {
  rclcpp::Parameter parameter;
  if (!node->get_parameter(key, parameter)) {
    return false;
  }
  u = parameter.get_value<U>();
  return true;
}
template <typename U, typename V>
void getUint(rclcpp::Node* node, const std::string& key, U& u, V fallback) {
  if (!getUint(node, key, u)) {
    u = fallback;
  }
}
class Gps : public rclcpp::Node {
public:
  Gps() : rclcpp::Node("gps") {
    unsigned sig = 0, plain = 0, checked = 0;
    getUint(this, "sig_cfg", sig, 1);
    getUint(this, "plain", plain);
    if (!getUint(this, "checked", checked)) {
      throw std::runtime_error("checked must be set");
    }
    pub_ = create_publisher<std_msgs::msg::String>("heading", 1);
  }
  void connect(const std::string& host) {
    asio::ip::tcp::resolver resolver(io_);
    auto endpoint = resolver.resolve(asio::ip::tcp::resolver::query(host, "80"));
    throw std::runtime_error("no " + endpoint->host_name());
  }
  void heading(double yaw) {
    double offset = declare_parameter("offset", 0.0);
    tf2::Quaternion orientation;
    orientation.setRPY(0, 0, yaw + offset);
    std::stringstream text;
    text.width(4); text.fill('0');
    text << orientation[2];
    std_msgs::msg::String msg;
    msg.data = text.str();
    pub_->publish(msg);
  }
  asio::io_service io_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_a_ros2_unit_is_not_partial_for_a_ros1_name_or_a_standin_gap(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("gps", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend>"
                      "<depend>tf2</depend></package>"))
    source = tmp_path / "gps.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    hiding = [d.message for d in result.diagnostics
              if d.code in ("CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL")]
    assert hiding == [], hiding
    reads = {c.name: c.tested for c in result.calls if c.kind == "read"}
    assert reads == {"sig_cfg": True, "plain": False, "checked": True}, reads
