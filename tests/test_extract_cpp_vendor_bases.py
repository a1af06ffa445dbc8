"""A pointer to one vendor class given where a pointer to another is wanted (motoman's
``init(&default_tcp_connection_)``: a TcpClient for a SmplMsgConnection, both of
industrial_core, not in the workspace), read from the error or, for an overloaded
function, from its candidates' notes: the declared classes derive so, and the function
that calls the ROS API there parses."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "vendor/tcp_client.h"
#include "vendor/connection.h"
using vendor::tcp::TcpClient;
using vendor::conn::Connection;
class Relay {
 public:
  bool init(Connection * connection) {
    pub_ = nh_.advertise<std_msgs::String>("state", 1);
    return connection != nullptr;
  }
  bool init(Connection * connection, int retries);  // an overload: the call is resolved
  bool start() {                                       // among candidates, whose notes
    serial_.open("/dev/ttyS0");                        // say which conversion fails
    return init(&serial_);
  }
  bool restart() {
    Connection * c = &client_;
    sub_ = nh_.subscribe<std_msgs::String>("in", 1, &Relay::onIn, this);
    c = &other_;
    return init(c);
  }
  void onIn(const std_msgs::String::ConstPtr &);
  TcpClient client_;
  vendor::serial::SerialClient serial_;
  vendor::udp::UdpClient other_;
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "relay");
  Relay relay;
  relay.start();
  relay.restart();
}
"""


def test_a_vendor_class_given_for_another_derives_from_it(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("relay").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "relay.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "state"), ("subscribe", "in")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_NAMES_DECLARED" in codes
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
