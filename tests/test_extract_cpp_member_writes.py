"""A node handle member set once outside its class's constructor list takes that value,
as depth_image_proc's disparity nodelet (ROS 1 image_pipeline) sets
``right_nh_.reset(new ros::NodeHandle(nh, "right"))`` in ``onInit`` and subscribes
``camera_info`` on ``*right_nh_`` in its connection callback: ``right/camera_info``,
not ``?/camera_info``. The value is read where it is written (a local handle of that
method); a member the file's functions set to different values, or to a parameter of a
method no call of the file makes, is unknown, not the default handle."""

from __future__ import annotations

from pathlib import Path

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODELET = """
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <boost/shared_ptr.hpp>
#include <message_filters/subscriber.h>
#include <sensor_msgs/CameraInfo.h>
#include <std_msgs/String.h>

namespace demo {
class Disparity : public nodelet::Nodelet {
  ros::NodeHandlePtr right_nh_;
  ros::NodeHandle left_nh_;
  ros::NodeHandle sub_nh_;
  boost::shared_ptr<ros::NodeHandle> either_nh_;
  ros::NodeHandle host_nh_;
  message_filters::Subscriber<sensor_msgs::CameraInfo> sub_info_;
  ros::Publisher a_, b_, c_, d_, e_;
  void onInit() override;
  void connectCb();
  void setup(ros::NodeHandle& pnh);
  void other();
  void initialize(std::string name);
};

void Disparity::onInit() {
  ros::NodeHandle& nh = getNodeHandle();
  right_nh_.reset(new ros::NodeHandle(nh, "right"));
  ros::NodeHandle left(nh, "left");
  left_nh_ = left;
  either_nh_.reset(new ros::NodeHandle(nh, "one"));
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  setup(pnh);
}

void Disparity::setup(ros::NodeHandle& pnh) {
  sub_nh_ = ros::NodeHandle(pnh, "sub");
}

void Disparity::other() {
  either_nh_.reset(new ros::NodeHandle(getNodeHandle(), "two"));
}

void Disparity::initialize(std::string name) {
  host_nh_ = ros::NodeHandle("~/" + name);
}

void Disparity::connectCb() {
  sub_info_.subscribe(*right_nh_, "camera_info", 1);
  a_ = right_nh_->advertise<std_msgs::String>("right_out", 1);
  b_ = left_nh_.advertise<std_msgs::String>("left_out", 1);
  c_ = sub_nh_.advertise<std_msgs::String>("sub_out", 1);
  d_ = either_nh_->advertise<std_msgs::String>("either_out", 1);
  e_ = host_nh_.advertise<std_msgs::String>("host_out", 1);
}
}  // namespace demo

PLUGINLIB_EXPORT_CLASS(demo::Disparity, nodelet::Nodelet)
"""

NODE = """
#include <ros/ros.h>
#include <boost/shared_ptr.hpp>
#include <std_msgs/String.h>

int main(int argc, char ** argv) {
  ros::init(argc, argv, "talker");
  boost::shared_ptr<ros::NodeHandle> nh;
  nh.reset(new ros::NodeHandle("ns"));
  ros::Publisher p = nh->advertise<std_msgs::String>("chatter", 1);
  ros::spin();
}
"""


def _calls(root: Path, name: str, text: str) -> dict[str, str]:
    """The name of each call by its last part."""
    (root / "demo" / "src").mkdir(parents=True, exist_ok=True)
    (root / "demo" / "package.xml").write_text(package_xml("demo"))
    (root / "demo" / "src" / name).write_text(text)
    result = extract_cpp([str(root / "demo" / "src" / name)], scan([str(root)]),
                         cache_dir=None)
    return {c.name.rpartition("/")[2]: c.name for c in result.calls}


@pytest.fixture(scope="module")
def nodelet(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    return _calls(tmp_path_factory.mktemp("nodelet"), "disparity.cpp", NODELET)


@pytest.mark.parametrize("name", [
    "right/camera_info",  # reset(new NodeHandle(nh, "right")) in onInit, ``*right_nh_``
    "right/right_out",  # the same member through ``right_nh_->``
    "left/left_out",  # a local handle of onInit, assigned: read in onInit
    "~sub/sub_out",  # ``= ros::NodeHandle(pnh, "sub")`` in a method onInit calls
    "?/either_out",  # set to ``one`` in onInit and to ``two`` in other(): unknown
    "?/host_out",  # from a parameter of a method no call here makes: its host's value
])
def test_a_handle_member_set_outside_the_constructor(nodelet: dict[str, str],
                                                      name: str) -> None:
    assert nodelet[name.rpartition("/")[2]] == name


def test_a_local_handle_pointer_reset_once(tmp_path: Path) -> None:
    assert _calls(tmp_path, "talker.cpp", NODE) == {"chatter": "ns/chatter"}


LIFELONG = """
#include <rclcpp/rclcpp.hpp>
class Lifelong : public rclcpp::Node {
 public:
  Lifelong() : rclcpp::Node("lifelong") {}
  void on_configure();
 private:
  bool use_tree_;
};

void Lifelong::on_configure() {
  use_tree_ = false;
  if (!this->has_parameter("use_tree")) {
    this->declare_parameter("use_tree", use_tree_);
  }
  use_tree_ = this->get_parameter("use_tree").as_bool();
}
"""


def test_a_builtin_member_set_by_an_init_method_with_equals(tmp_path: Path) -> None:
    """slam_toolbox's LifelongSlamToolbox::on_configure: ``use_tree_ = false;`` (a
    builtin's ``=``, not an ``operator=`` call) is the value its declaration gives, as
    its later read into it follows the declaration."""
    root = tmp_path
    (root / "demo" / "src").mkdir(parents=True)
    (root / "demo" / "package.xml").write_text(package_xml("demo", "ament_cmake").replace(
        "<export>", "<depend>rclcpp</depend><export>"))
    (root / "demo" / "src" / "lifelong.cpp").write_text(LIFELONG)
    result = extract_cpp([str(root / "demo" / "src" / "lifelong.cpp")], scan([str(root)]),
                         cache_dir=None)
    declared = [c for c in result.calls if c.kind == "declare"]
    assert [(c.name, c.has_default, c.default) for c in declared] == [
        ("use_tree", True, False)]


UNRESOLVED_FIELD = """
#include <ros/ros.h>
#include <pkg/SetDatum.h>

class Localiser {
 public:
  Localiser() : nh_("~") {
    pkg::SetDatum::Request request;
    request.geo_pose.position.latitude = 1.0;  // a field of a message known by name
    nh_.param("frequency", frequency_, frequency_);
  }
 private:
  ros::NodeHandle nh_;
  double frequency_ = 30.0;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "localiser");
  Localiser localiser;
  ros::spin();
}
"""


def test_a_write_to_a_member_the_parse_cannot_resolve_is_no_crash(write_tree) -> None:
    # robot_localization's navsat_transform (noetic): ``request.geo_pose.position.
    # latitude = datum_lat`` on a service of a message package not in the tree, in the
    # constructor whose writes a member's value is looked for: ``None == field``
    root = write_tree({"pkg/package.xml": package_xml("pkg"),
                       "pkg/srv/SetDatum.srv": "geographic_msgs/GeoPose geo_pose\n---\n",
                       "pkg/src/node.cpp": UNRESOLVED_FIELD})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~frequency")]


TWO_WRITES_ONE_NAMESPACE = """
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <sensor_msgs/LaserScan.h>

namespace demo {
class Scanner : public nodelet::Nodelet {
  ros::NodeHandle nh_, private_nh_;
  ros::Publisher pub_;
  void onInit() override {
    private_nh_ = getPrivateNodeHandle();
    bool concurrent = false;
    private_nh_.param("concurrency", concurrent, false);
    if (concurrent) {
      nh_ = getMTNodeHandle();
    } else {
      nh_ = getNodeHandle();
    }
    pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 10);
  }
};
}  // namespace demo
PLUGINLIB_EXPORT_CLASS(demo::Scanner, nodelet::Nodelet)
"""


def test_writes_that_differ_as_text_but_name_one_namespace_agree(write_tree) -> None:
    # pointcloud_to_laserscan's nodelet: nh_ is getMTNodeHandle() or getNodeHandle()
    root = write_tree({"pkg/package.xml": package_xml("pkg"),
                       "pkg/src/node.cpp": TWO_WRITES_ONE_NAMESPACE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~concurrency"), ("publish", "scan")]


STRUCT = """
#include <ros/ros.h>
#include <std_msgs/String.h>

struct Context { ros::NodeHandle* nh; int rate; };
struct Owner { ros::NodeHandle own; };

int main(int argc, char** argv) {
  ros::init(argc, argv, "ctx");
  ros::NodeHandle pnh("~");
  Context ctx{&pnh, 10};
  ctx.nh->hasParam("through_pointer");
  Context copy = {&pnh, 5};
  ros::Publisher out = copy.nh->advertise<std_msgs::String>("pointer_out", 1);
  Owner owner;
  owner.own.hasParam("value_member");
  ros::spin();
}
"""


def test_a_pointer_member_nothing_seen_sets_is_not_the_default_handle(tmp_path: Path
                                                                      ) -> None:
    """A handle *value* member that nothing sets is the default handle (``Owner::own``);
    a *pointer* to a handle that no constructor and no assignment of the unit sets points
    to one set where the extraction does not look (an aggregate's ``{&pnh, 10}``, a copy
    of the struct): its namespace is unknown, ``?/through_pointer``, not the node's
    namespace (which made ``/through_pointer`` of a private parameter)."""
    assert _calls(tmp_path, "ctx.cpp", STRUCT) == {
        "through_pointer": "?/through_pointer", "pointer_out": "?/pointer_out",
        "value_member": "value_member"}
