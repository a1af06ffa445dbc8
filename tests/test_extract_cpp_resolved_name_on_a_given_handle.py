"""``n.subscribe(n.resolveName("command"), ...)`` on a handle a ROS 1 controller's
``init(robot, n)`` is given (kuka-lwr's lwr_controllers/src/cartesian_impedance_controller.cpp:101,
103, 104): roscpp resolves ``command`` in the handle's namespace, and the call is on that
name. The handle's namespace is not known (the controller manager gives it), so the
name is ``?/command``; the name was the namespace joined to itself,
``?/command/?/command``, a topic nobody else could match."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

CONTROLLER = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <controller_interface/controller.h>
#include <hardware_interface/joint_command_interface.h>
#include <pluginlib/class_list_macros.h>
namespace arm {
class C : public controller_interface::Controller<hardware_interface::EffortJointInterface> {
 public:
  bool init(hardware_interface::EffortJointInterface *robot, ros::NodeHandle &n);
  void update(const ros::Time&, const ros::Duration&) {}
  void cb(const std_msgs::String::ConstPtr&) {}
  ros::Subscriber s_;
  ros::Publisher p_, q_;
};
bool C::init(hardware_interface::EffortJointInterface *robot, ros::NodeHandle &n) {
  s_ = n.subscribe(n.resolveName("command"), 1, &C::cb, this);
  p_ = n.advertise<std_msgs::String>(n.resolveName("status") + "/text", 1);
  q_ = n.advertise<std_msgs::String>("goal", 1);
  return true;
}
}
PLUGINLIB_EXPORT_CLASS(arm::C, controller_interface::ControllerBase)
"""

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
class C {
 public:
  void init(ros::NodeHandle &n);
  void cb(const std_msgs::String::ConstPtr&) {}
  ros::Subscriber s_;
  ros::Publisher p_;
};
void C::init(ros::NodeHandle &n) {
  s_ = n.subscribe(n.resolveName("command"), 1, &C::cb, this);
  p_ = n.advertise<std_msgs::String>(n.resolveName("status") + "/text", 1);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "x");
  ros::NodeHandle nh("arm");
  C c;
  c.init(nh);
  ros::spin();
}
"""


def _topics(tmp_path, text: str) -> list[tuple[str, str]]:
    source = tmp_path / "src" / "c.cpp"
    source.parent.mkdir(parents=True, exist_ok=True)
    source.write_text(text)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    return sorted((c.kind, c.name) for c in result.calls if c.kind in ("subscribe", "publish"))


def test_a_name_resolved_on_a_handle_not_known_is_that_name(tmp_path) -> None:
    assert _topics(tmp_path, CONTROLLER) == [
        ("publish", "?/goal"), ("publish", "?/status/text"), ("subscribe", "?/command")]


def test_a_name_resolved_on_a_handle_given_by_the_caller(tmp_path) -> None:
    # guard: the caller's handle, ``arm``, names both (as before)
    assert _topics(tmp_path, NODE) == [
        ("publish", "arm/status/text"), ("subscribe", "arm/command")]
