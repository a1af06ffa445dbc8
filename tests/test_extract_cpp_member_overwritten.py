"""A handle member's write that a later statement of the same block replaces, with
nothing between them that may read the member, is never seen: tuw_multi_robot's fake
pose nodelet (``tuw_multi_robot_ctrl``) sets ``nh_ = getPrivateNodeHandle();`` then
``nh_ = getNodeHandle();`` in ``onInit`` and advertises ``pose`` on it: ``pose`` in the
nodelet's namespace, not ``?/pose`` (the two writes disagreed) nor ``~pose`` (the first
write of the initialisation method). A write that a statement reads before the next
one (the member named, or a method of the class called, which may read it) stays one
of the member's values."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODELET = """
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <std_msgs/String.h>

namespace demo {
void inspect(const void* object);

class Fake : public nodelet::Nodelet {
  ros::NodeHandle nh_;
  ros::NodeHandle early_nh_;
  ros::NodeHandle helped_nh_;
  ros::NodeHandle this_nh_;
  ros::Publisher a_, b_, c_, d_, e_;
  int count_ = 0;
  void helper() { c_ = helped_nh_.advertise<std_msgs::String>("helper_out", 1); }
  void onInit() override {
    nh_ = getPrivateNodeHandle();
    count_ = 1;
    nh_ = getNodeHandle();
    a_ = nh_.advertise<std_msgs::String>("pose", 1);
    early_nh_ = getPrivateNodeHandle();
    b_ = early_nh_.advertise<std_msgs::String>("early", 1);
    early_nh_ = getNodeHandle();
    helped_nh_ = getPrivateNodeHandle();
    helper();
    helped_nh_ = getNodeHandle();
    this_nh_ = getPrivateNodeHandle();
    this->count_ = 2;  // (a write of another member: no read of this_nh_)
    inspect(this);
    this_nh_ = getNodeHandle();
    d_ = this_nh_.advertise<std_msgs::String>("this_out", 1);
  }
};
}  // namespace demo
PLUGINLIB_EXPORT_CLASS(demo::Fake, nodelet::Nodelet)
"""


def _calls(root: Path) -> dict[str, str]:
    """The name of each call by its last part."""
    (root / "demo" / "src").mkdir(parents=True)
    (root / "demo" / "package.xml").write_text(package_xml("demo"))
    (root / "demo" / "src" / "fake.cpp").write_text(NODELET)
    result = extract_cpp([str(root / "demo" / "src" / "fake.cpp")], scan([str(root)]),
                         cache_dir=None)
    return {c.name.rpartition("/")[2]: c.name for c in result.calls}


def test_a_handle_write_replaced_unread_is_not_one_of_its_values(tmp_path: Path) -> None:
    assert _calls(tmp_path) == {
        "pose": "pose",  # the first write replaced, a plain member's write between
        "early": "?/early",  # read between the two writes: either value
        "helper_out": "?/helper_out",  # a method of the class called between
        "this_out": "?/this_out",  # ``this`` passed between: it may read any member
    }
