"""gencpp writes three headers per service: ``<pkg/Srv.h>``, ``<pkg/SrvRequest.h>`` and
``<pkg/SrvResponse.h>``. A unit that includes only a part's header (mrs_uav_managers'
tracker.h: ``#include <mrs_msgs/ReferenceSrvRequest.h>``, ``<std_srvs/TriggerRequest.h>``)
got an empty stand-in for an unknown message, its fields errors."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
#include <p/ThingRequest.h>
#include <p/ThingResponse.h>
#include <std_srvs/TriggerRequest.h>
#include <std_srvs/TriggerResponse.h>
bool serve(p::ThingRequest& req, p::ThingResponse& res) {
  res.ok = req.a > 0;
  return true;
}
bool trigger(std_srvs::TriggerRequest& req, std_srvs::TriggerResponse& res) {
  res.success = true;
  res.message = "done";
  return true;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "server");
  ros::NodeHandle nh;
  ros::ServiceServer a = nh.advertiseService("thing", serve);
  ros::ServiceServer b = nh.advertiseService("trigger", trigger);
  ros::spin();
}
"""


def test_a_service_part_header_is_the_service_s(write_tree) -> None:
    root = write_tree({
        "p/package.xml": package_xml("p", "catkin"),
        "p/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(p)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp message_generation)\n"
            "add_service_files(DIRECTORY srv/parts FILES Thing.srv)\ncatkin_package()\n"
            "add_executable(server src/server.cpp)\n"),
        "p/srv/parts/Thing.srv": "int32 a\n---\nbool ok\n",
        "p/src/server.cpp": SOURCE})
    result = extract_cpp([str(root / "p" / "src" / "server.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("server", "thing", "p/Thing"), ("server", "trigger", "std_srvs/Trigger")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_MESSAGE_UNKNOWN" not in codes and "CPP_PARSE_ERROR" not in codes, [
        d.message for d in result.diagnostics]
