"""xmlrpcpp's headers by their bare names: xmlrpcpp exports its ``include/xmlrpcpp``
folder as well as ``include``, so ROS 1 code writes ``#include <XmlRpcValue.h>``
(cob_bms_driver), ``<XmlRpc.h>`` (cob_scan_unifier) and ``<XmlRpcException.h>``. They
stand in as the ``xmlrpcpp/`` headers do (roscpp's XmlRpcValue and XmlRpcException),
not as empty headers said missing (CPP_INCLUDE_MISSING, three of them in cob_driver)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <XmlRpc.h>
#include <XmlRpcValue.h>
#include <XmlRpcException.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "bms");
  ros::NodeHandle nh("~");
  XmlRpc::XmlRpcValue topics;
  try {
    nh.getParam("topics", topics);
    for (int i = 0; i < topics.size(); ++i) {
      std::string name = static_cast<std::string>(topics[i]);
    }
  } catch (XmlRpc::XmlRpcException& e) {
    ROS_ERROR("bad topics: %s", e.getMessage().c_str());
  }
  ros::Publisher pub = nh.advertise<std_msgs::Float64>("voltage", 1);
  ros::spin();
}
"""


def test_bare_xmlrpcpp_headers_stand_in_as_roscpps(tmp_path) -> None:
    (tmp_path / "bms.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "bms.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls if c.kind == "publish"] == [
        ("publish", "~voltage")]
    assert [d.code for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED")] == []
