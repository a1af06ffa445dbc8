"""An ambiguous call of the unit's own overloads that make no ROS call hides none:
riptide_imu's callback writes ``msg.angular_velocity = toMsg(cd.angularRate())``, its
two ``toMsg`` overloads taking vectornav's ``vn::math::vec4f`` and ``vec3f``, whose
headers are not here: the parse builds both from anything, the call is ambiguous, and
the error in the function that publishes made the node partial (CPP_ERROR_NEAR_CALL,
CPP_NODE_PARTIAL) though either overload only fills a message. An overload that
publishes, or an API call on the error's line, still counts."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <vn/sensors.h>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/vector3.hpp>
#include <geometry_msgs/msg/quaternion.hpp>

using namespace vn::sensors;

class Imu : public rclcpp::Node
{
public:
  Imu() : Node("imu")
  {
    declare_parameter("gain", 1.0);
    pub_ = create_publisher<geometry_msgs::msg::Vector3>("rate", 10);
  }

  static void onPacket(void * self, vn::protocol::uart::Packet & packet, size_t index)
  {
    auto node = reinterpret_cast<Imu *>(self);
    CompositeData cd = cd.parse(packet);
    double gain = node->get_parameter("gain").as_double();
    geometry_msgs::msg::Vector3 msg;
    msg = toMsg(cd.angularRate());
    msg.x *= gain;
    node->pub_->publish(msg);
  }

private:
  static geometry_msgs::msg::Quaternion toMsg(const vn::math::vec4f & q)
  {
    geometry_msgs::msg::Quaternion out;
    out.x = q[0];
    return out;
  }
  static geometry_msgs::msg::Vector3 toMsg(const vn::math::vec3f & v)
  {
    geometry_msgs::msg::Vector3 out;
    out.x = v[0];
    return out;
  }
  HELPER
  rclcpp::Publisher<geometry_msgs::msg::Vector3>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Imu>());
}
"""

LOUD = """geometry_msgs::msg::Vector3 toMsg(const vn::math::vec2f & v)
  {
    geometry_msgs::msg::Vector3 out;
    out.x = v[0] * get_parameter("scale").as_double();
    return out;
  }"""


def _extract(write_tree, helper: str):
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": SOURCE.replace("HELPER", helper)})
    return extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                       cache_dir=None)


def test_an_ambiguous_call_of_quiet_overloads_hides_no_call(write_tree) -> None:
    result = _extract(write_tree, "")
    assert [(c.kind, c.name) for c in result.calls] == [("declare", "gain"), ("publish", "rate")]
    assert "CPP_ERROR_NEAR_CALL" not in [d.code for d in result.diagnostics]


def test_an_overload_that_publishes_still_counts(write_tree) -> None:
    result = _extract(write_tree, LOUD)
    assert "CPP_ERROR_NEAR_CALL" in [d.code for d in result.diagnostics]
