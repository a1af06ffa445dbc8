"""ROS 1 messages and services may be named in lowercase (LIO-SAM's ``msg/cloud_info.msg``
and ``srv/save_map.srv``): their generated headers ``<pkg/cloud_info.h>`` and
``<pkg/save_map.h>`` are synthesised from the package's definitions, as a capitalised
one is, not replaced by an empty stand-in that leaves the types unknown."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include "slam/cloud_info.h"
#include <slam/save_map.h>
#include <slam/helpers.h>

class Mapper {
public:
  Mapper() {
    sub_ = nh_.subscribe<slam::cloud_info>("feature/cloud_info", 1, &Mapper::onCloud, this);
    pub_ = nh_.advertise<slam::cloud_info>("mapping/slam_info", 1);
    srv_ = nh_.advertiseService("save_map", &Mapper::save, this);
  }
  void onCloud(const slam::cloud_infoConstPtr& msg) {
    if (msg->startRingIndex.size() > helpers::limit()) pub_.publish(*msg);
  }
  bool save(slam::save_mapRequest& req, slam::save_mapResponse& res) {
    res.success = req.resolution > 0;
    return true;
  }
private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  ros::Publisher pub_;
  ros::ServiceServer srv_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "mapper");
  Mapper mapper;
  ros::spin();
  return 0;
}
"""


def _tree(write_tree):
    return write_tree({
        "slam/package.xml": package_xml("slam", "catkin"),
        "slam/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(slam)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs message_generation)\n"
            "add_message_files(DIRECTORY msg FILES cloud_info.msg)\n"
            "add_service_files(DIRECTORY srv FILES save_map.srv)\n"
            "generate_messages(DEPENDENCIES std_msgs)\ncatkin_package()\n"
            "add_executable(mapper src/mapper.cpp)\n"),
        "slam/msg/cloud_info.msg": "Header header\nint32[] startRingIndex\n",
        "slam/srv/save_map.srv": "float32 resolution\n---\nbool success\n",
        "slam/include/slam/helpers.h": (
            "namespace helpers { inline unsigned limit() { return 0; } }\n"),
        "slam/src/mapper.cpp": SOURCE})


def test_lowercase_message_and_service_headers_are_synthesised(write_tree) -> None:
    root = _tree(write_tree)
    result = extract_cpp([str(root / "slam" / "src" / "mapper.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    calls = [(c.kind, c.name, c.type) for c in result.calls]
    assert ("subscribe", "feature/cloud_info", "slam/cloud_info") in calls
    assert ("publish", "mapping/slam_info", "slam/cloud_info") in calls
    assert ("server", "save_map", "slam/save_map") in calls
    codes = [d.code for d in result.diagnostics]
    assert "CPP_INCLUDE_MISSING" not in codes
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes


def test_a_lowercase_header_that_is_no_message_stays_the_package_s(write_tree) -> None:
    """``<slam/helpers.h>`` is the package's own header: no definition by that name, so
    it is read from the package, not taken for a message."""
    root = _tree(write_tree)
    result = extract_cpp([str(root / "slam" / "src" / "mapper.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert not [d for d in result.diagnostics if "helpers" in d.message]
