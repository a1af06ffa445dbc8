"""Eigen's comma initialiser on a vendor's vector type whose header is missing
(LIO-SAM's imuPreintegration.cpp:218-225, ``(gtsam::Vector(6) << 1e-2, ...).finished()``
in the constructor that subscribes and advertises): ``<<`` on a permissively declared
class was ambiguous (built-in shift or the standard library's stream output, each through
a conversion) and the comma gave a ``double`` whose ``.finished()`` was an error, so the
node was partial. A stream on the left keeps the standard library's operator."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <iostream>
#include <gtsam/geometry/Pose3.h>
class Fuser {
public:
  Fuser() {
    pub_ = nh_.advertise<std_msgs::String>("fused", 10);
    noise_ = gtsam::noiseModel::Diagonal::Sigmas(
        (gtsam::Vector(6) << 1e-2, 1e-2, 1e-2, 1, 1, 1).finished());
    bias_ = (gtsam::Vector(6) << 1, 1, 1, 1, 1, 1).finished();
    std::cout << "pose " << p_ << std::endl;
    double d = p_.x() * 2.0;
  }
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  gtsam::noiseModel::Diagonal::shared_ptr noise_;
  gtsam::Vector bias_;
  gtsam::Pose3 p_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "fuser");
  Fuser fuser;
  ros::spin();
}
"""


def test_a_comma_initialiser_on_a_vendor_vector_is_no_error(write_tree) -> None:
    root = write_tree({
        "fuse/package.xml": package_xml("fuse", "catkin"),
        "fuse/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(fuse)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp)\ncatkin_package()\n"
            "add_executable(fuser src/fuser.cpp)\n"),
        "fuse/src/fuser.cpp": SOURCE})
    result = extract_cpp([str(root / "fuse" / "src" / "fuser.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "fused")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
    assert "CPP_NAMES_DECLARED" in codes
