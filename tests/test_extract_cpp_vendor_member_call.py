"""In ROS 2 code, a call of an API function's name that the parse resolves to a member
of a class declared permissively (its header is missing) is no ROS call left unread:
mqtt_client's ``client_->subscribe(topic, qos)`` on Paho's ``mqtt::async_client`` was
CPP_CALL_MISSED (x4, beside the errors left by its overrides of the vendor's callbacks)
and made the node partial. Such an object can only communicate
through a node it is given, and where the node is given to it the parse says so
(CPP_NODE_TO_UNKNOWN), unless it is given to the vendor whose listener its class derives
(mqtt_client's ``client_->set_callback(*this)``, the class deriving Paho's
``mqtt::callback``): the vendor's code calls the class's overrides, read where they are
defined."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <broker/async_client.h>
#include <other/registry.h>

class Bridge : public rclcpp::Node, public virtual broker::callback {
 public:
  Bridge() : Node("bridge") {
    client_ = std::make_shared<broker::async_client>("tcp://localhost:1883", "id");
    client_->set_callback(*this);
    pub_ = create_publisher<std_msgs::msg::String>("~/out", 10);
  }

  // an override of the vendor's callback: an error left (the declared base has no
  // virtual method), so the unit's call sites are checked
  void connected(const std::string & topic) override;

 private:
  std::shared_ptr<broker::async_client> client_;
  other::registry registry_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

void Bridge::connected(const std::string & topic) {
  client_->subscribe(topic, 1);
  client_->publish(topic + "/state", "up");
}
"""


def _extract(tmp_path, source: str):
    (tmp_path / "package.xml").write_text(package_xml("bridge", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"))
    (tmp_path / "bridge.cpp").write_text(source)
    return extract_cpp([str(tmp_path / "bridge.cpp")], scan([str(tmp_path)]), cache_dir=None)


def test_a_vendor_object_s_subscribe_is_no_missed_call(tmp_path) -> None:
    result = _extract(tmp_path, SOURCE)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~out")]
    assert [d.code for d in result.diagnostics if d.code in (
        "CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL", "CPP_NODE_TO_UNKNOWN")] == []


def test_the_node_given_to_another_vendor_s_object_is_still_said(tmp_path) -> None:
    """``client_->set_callback(*this)`` above hands the object to the vendor whose
    ``callback`` its class derives: a listener registration, whose calls are the class's
    overrides. Handed to a vendor its class derives nothing of, it may be used as the
    node, unseen."""
    result = _extract(tmp_path, SOURCE.replace(
        "client_->subscribe(topic, 1);", "registry_.add(this, topic);"))
    assert [d.code for d in result.diagnostics if d.code in (
        "CPP_CALL_MISSED", "CPP_NODE_TO_UNKNOWN")] == ["CPP_NODE_TO_UNKNOWN"]
    assert [d.code for d in _extract(tmp_path, SOURCE.replace(
        "client_->set_callback(*this);", "other::attach(*this);")).diagnostics
        if d.code == "CPP_NODE_TO_UNKNOWN"] == ["CPP_NODE_TO_UNKNOWN"]
