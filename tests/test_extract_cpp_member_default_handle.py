"""A handle member given its namespace by a default member initialiser and set by no
constructor: ``ros::NodeHandle pnh_{"~"};`` (Tier IV's ROS 1 Autoware: shift_decider,
vehicle_cmd_gate, autoware_state_monitor, ... publish on ``pnh_`` / ``private_nh_``),
``ros::NodeHandle pnh_ = ros::NodeHandle("~");``. Names through it are private; they
were taken as the default handle's (relative), so ``~output/shift_cmd`` was
``output/shift_cmd``. A constructor's initialiser list still overrides it."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
class Gate {
public:
  Gate() {
    brace_ = pnh_.advertise<std_msgs::String>("output/brace", 1);
    assigned_ = pnh2_.advertise<std_msgs::String>("output/assigned", 1);
    child_ = sub_.advertise<std_msgs::String>("output/child", 1);
    plain_ = nh_.advertise<std_msgs::String>("output/plain", 1);
    pnh_.param("update_rate", rate_, 10.0);
  }
  ros::NodeHandle nh_{""};
  ros::NodeHandle pnh_{"~"};
  ros::NodeHandle pnh2_ = ros::NodeHandle("~");
  ros::NodeHandle sub_{"ns"};
  ros::Publisher brace_, assigned_, child_, plain_;
  double rate_;
};
class Overridden {
public:
  Overridden() : pnh_("other") { pub_ = pnh_.advertise<std_msgs::String>("out", 1); }
  ros::NodeHandle pnh_{"~"};
  ros::Publisher pub_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "gate");
  Gate gate;
  Overridden other;
  ros::spin();
}
"""


def test_a_default_member_initialiser_gives_the_handle_its_namespace(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("gate").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "gate.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    names = sorted((c.kind, c.name) for c in result.calls)
    assert names == [
        ("publish", "ns/output/child"), ("publish", "other/out"),
        ("publish", "output/plain"), ("publish", "~output/assigned"),
        ("publish", "~output/brace"), ("read", "~update_rate")], names
