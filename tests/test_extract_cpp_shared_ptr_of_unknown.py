"""A ``std::shared_ptr`` built from what a function of a missing header returns
(vrpn_client_ros' ``connection_ = std::shared_ptr<vrpn_Connection>(
vrpn_get_connection_by_name(host_.c_str()))``, vrpn's headers not found): the function is
declared permissively, its value converts to any type, and the stand-in's constructors
were all reachable that way, ambiguously. The parse error made the constructor around it
a place where a ROS call may be missing (the node partial) and the tracker handle it
stores unknown: vrpn_client_node's parameters read as ``?/frame_id``."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """#include <ros/ros.h>
#include <memory>
#include <string>
#include <vendor_connection.h>

class Tracker {
public:
  Tracker(std::shared_ptr<vendor_Connection> connection, ros::NodeHandle nh)
  {
    std::string frame_id;
    nh.param<std::string>("frame_id", frame_id, "world");
  }
};

class Client {
public:
  Client(ros::NodeHandle nh, ros::NodeHandle private_nh)
  {
    output_nh_ = private_nh;
    std::string host = "localhost";
    connection_ = std::shared_ptr<vendor_Connection>(vendor_connect(host.c_str()));
    other_.reset(vendor_connect(host.c_str()));
    tracker_ = std::make_shared<Tracker>(connection_, output_nh_);
  }
private:
  ros::NodeHandle output_nh_;
  std::shared_ptr<vendor_Connection> connection_, other_;
  std::shared_ptr<Tracker> tracker_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "client");
  ros::NodeHandle nh, private_nh("~");
  Client client(nh, private_nh);
  ros::spin();
}
"""


def test_a_shared_ptr_of_a_permissive_value_is_no_parse_error(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/src/node.cpp": NODE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    errors = [d.message for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == []
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~frame_id")]
