"""roscpp's ``AsyncSpinner(thread_count, queue)``, a spinner of a callback queue of the
node's own: PX4-Avoidance's global planner builds two in its constructor (beside its
timers); the stand-in had only ``AsyncSpinner(thread_count)``, a clang error in a function
that calls the ROS API, and the node partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <ros/callback_queue.h>
#include <std_msgs/String.h>
class Planner {
 public:
  explicit Planner(ros::NodeHandle& nh) {
    pub_ = nh.advertise<std_msgs::String>("plan", 1);
    spinner_.reset(new ros::AsyncSpinner(1, &queue_));
    if (spinner_->canStart()) spinner_->start();
  }
  ros::CallbackQueue queue_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
  ros::Publisher pub_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "planner");
  ros::NodeHandle nh("~");
  Planner planner(nh);
  ros::spin();
}
"""


def test_an_async_spinner_of_the_node_s_own_queue(tmp_path) -> None:
    (tmp_path / "planner.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "planner.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~plan")]
    assert [str(d) for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
