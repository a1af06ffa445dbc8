"""What MoveIt's CurrentStateMonitor (noetic, current_state_monitor.cpp) uses beside its
joint_states subscription, which every MoveIt node that monitors the robot's state runs
(move_group among them): tf2's ``BufferCore::_addTransformsChangedListener`` /
``_removeTransformsChangedListener`` (geometry2 noetic-devel tf2/buffer_core.h:260-261),
``std::quoted`` (<iomanip>) and ``boost::condition_variable::wait_for``. The listener's
error in ``startStateMonitor``, which subscribes, made move_group partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <iomanip>
#include <memory>
#include <string>
#include <boost/thread/mutex.hpp>
#include <boost/thread/condition_variable.hpp>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/buffer.h>

struct Monitor {
  void cb(const sensor_msgs::JointState::ConstPtr& msg);
  void tfCallback();
  virtual void start(const std::string& topic) {
    sub_ = nh_.subscribe(topic, 25, &Monitor::cb, this);
    auto connection = buffer_->_addTransformsChangedListener([this] { tfCallback(); });
    buffer_->_removeTransformsChangedListener(connection);
    ROS_ERROR_STREAM("no group " << std::quoted(topic) << "!");
  }
  virtual bool wait(double seconds) {
    boost::mutex::scoped_lock lock(mutex_);
    condition_.wait_for(lock, std::chrono::nanoseconds(static_cast<long>(seconds * 1e9)));
    return condition_.wait_for(lock, std::chrono::milliseconds(5), [] { return true; });
  }
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  std::shared_ptr<tf2_ros::Buffer> buffer_;
  boost::mutex mutex_;
  boost::condition_variable condition_;
};
"""


def test_the_state_monitors_tf_listener_and_waits_parse(tmp_path) -> None:
    source = tmp_path / "monitor.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "?")]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []


SHARED = """
#include <ros/ros.h>
#include <memory>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

struct Deleter {
  explicit Deleter(tf2_ros::TransformListener* listener);
  void operator()(tf2_ros::Buffer* buffer) const;
};
struct Model { int* part(); };

std::shared_ptr<tf2_ros::Buffer> shared(std::shared_ptr<Model> owner) {
  std::shared_ptr<tf2_ros::Buffer> buffer;
  tf2_ros::Buffer* raw = new tf2_ros::Buffer();
  buffer.reset(raw, Deleter(new tf2_ros::TransformListener(*raw)));
  std::shared_ptr<int> alias(owner, owner->part());
  ros::NodeHandle nh;
  nh.advertise<std_msgs::String>("alive", 1);
  return buffer;
}
"""


def test_shared_ptrs_reset_with_a_deleter_and_aliasing_parse(tmp_path) -> None:
    # MoveIt's common_objects.cpp: getSharedTF() resets its buffer with a deleter that
    # also deletes the listener, getSharedRobotModel() makes an aliasing shared_ptr
    source = tmp_path / "objects.cpp"
    source.write_text(SHARED.replace("#include <memory>", "#include <memory>\n"
                                     "#include <std_msgs/String.h>"))
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert ("publish", "alive") in [(c.kind, c.name) for c in result.calls]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
