"""A handle-holding member first set to a null pointer and then assigned in the
constructor's body is the handle it is assigned (Kimera-VIO-ROS's
RosDataProviderInterface: ``it_(nullptr)`` in the initialiser list, then ``it_ =
VIO::make_unique<image_transport::ImageTransport>(nh_)``): the null pointer holds nothing
the node's calls are made on. And a library's own ``make_unique`` / ``make_shared``, its
header not in the workspace, makes its template argument from its arguments as the
standard's does, so the image transport made from ``nh_`` is in ``nh_``'s namespace, not
an unknown one (``?/left_cam/image_raw``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <memory>
#include <ros/ros.h>
#include <image_transport/image_transport.h>
#include <sensor_msgs/Image.h>
#include <vio_lib/utils.h>

class Provider {
 public:
  Provider() : nh_(), pnh_("~"), it_(nullptr), it3_(NULL) {
    it_ = std::make_unique<image_transport::ImageTransport>(nh_);
    sub_ = it_->subscribe("left_cam/image_raw", 1, &Provider::cb, this);
    it2_ = VIO::make_unique<image_transport::ImageTransport>(nh_);
    sub2_ = it2_->subscribe("right_cam/image_raw", 1, &Provider::cb, this);
    it3_ = new image_transport::ImageTransport(pnh_);
    sub3_ = it3_->subscribe("depth", 1, &Provider::cb, this);
  }
  void cb(const sensor_msgs::ImageConstPtr& m) {}
 private:
  ros::NodeHandle nh_, pnh_;
  std::unique_ptr<image_transport::ImageTransport> it_;
  std::unique_ptr<image_transport::ImageTransport> it2_;
  image_transport::ImageTransport* it3_;
  image_transport::Subscriber sub_, sub2_, sub3_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Provider p;
  ros::spin();
}
"""


def test_member_null_in_initialiser_then_assigned(write_tree) -> None:
    xml = package_xml("pkg", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>image_transport</depend>"
        "<depend>sensor_msgs</depend><depend>vio_lib</depend></package>")
    root = write_tree({"pkg/package.xml": xml, "pkg/src/n.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "n.cpp")], scan([str(root)]),
                         cache_dir=None)
    found = sorted((c.name, c.location.line) for c in result.calls if c.kind == "subscribe")
    assert found == [("left_cam/image_raw", 11), ("right_cam/image_raw", 13),
                     ("~depth", 15)]


HEADER = """\
#include <memory>
#include <ros/ros.h>
#include <image_transport/image_transport.h>
#include <sensor_msgs/Image.h>
class Base {
 public:
  Base();
  virtual ~Base();
  void cb(const sensor_msgs::ImageConstPtr& m) {}
 protected:
  ros::NodeHandle nh_;
  std::unique_ptr<image_transport::ImageTransport> it_;
  image_transport::ImageTransport* raw_;
  image_transport::Publisher debug_;
};
class Online : public Base {
 public:
  Online();
 private:
  image_transport::Subscriber sub_, sub2_;
};
"""

BASE = """\
#include "pkg/base.h"
#include <vio_lib/utils.h>
Base::Base() : nh_("cam"), it_(nullptr), raw_(nullptr) {
  it_ = VIO::make_unique<image_transport::ImageTransport>(nh_);
  raw_ = new image_transport::ImageTransport(nh_);
  debug_ = it_->advertise("debug", 1);
}
Base::~Base() {}
"""

ONLINE = """\
#include "pkg/base.h"
Online::Online() : Base() {
  sub_ = it_->subscribe("left/image_raw", 1, &Base::cb, (Base*)this);
  sub2_ = raw_->subscribe("right/image_raw", 1, &Base::cb, (Base*)this);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  Online o;
  ros::spin();
}
"""


def test_pointer_to_a_handle_set_by_a_constructor_of_another_file(write_tree) -> None:
    xml = package_xml("pkg", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>image_transport</depend>"
        "<depend>sensor_msgs</depend><depend>vio_lib</depend></package>")
    root = write_tree({"pkg/package.xml": xml, "pkg/include/pkg/base.h": HEADER,
                       "pkg/src/base.cpp": BASE, "pkg/src/online.cpp": ONLINE})
    result = extract_cpp([str(root / "pkg" / "src" / "base.cpp"),
                          str(root / "pkg" / "src" / "online.cpp")], scan([str(root)]),
                         cache_dir=None)
    found = sorted((c.kind, c.name) for c in result.calls)
    assert found == [("publish", "cam/debug"), ("subscribe", "cam/left/image_raw"),
                     ("subscribe", "cam/right/image_raw")]
