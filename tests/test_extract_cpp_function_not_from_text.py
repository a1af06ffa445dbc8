"""``std::function``'s converting constructor takes only what can be called, as
libstdc++'s (``_Requires<_Callable<F>>``): mrs_lib's ``SubscribeHandler<M>(options, topic,
args...)`` beside ``SubscribeHandler<M>(options, timeout_callback, args...)`` (a
``std::function``) was ambiguous for ``SubscribeHandler<M>(opts, "odometry_in", &C::cb,
this)`` when a string literal converted to the function too, an error beside each manager's
ROS calls (mrs_uav_managers)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <functional>
#include <string>
struct Options { ros::NodeHandle nh; };
template <class M> class Handler {
public:
  typedef std::function<void(const std::string&, const ros::Time&)> timeout_t;
  Handler() {}
  template <class... T> Handler(const Options& o, const std::string& topic, T... args) {}
  template <class... T> Handler(const Options& o, const timeout_t& timeout, T... args) {}
};
class Manager {
public:
  void init() {
    Options opts;
    pub_ = nh_.advertise<std_msgs::String>("status", 10);
    odom_ = Handler<std_msgs::String>(opts, "odometry_in", &Manager::callback, this);
    name_ = Handler<std_msgs::String>(opts, std::string("name_in"));
    timed_ = Handler<std_msgs::String>(opts, [](const std::string&, const ros::Time&) {});
    int rate = 3;
    std::function<void()> f = [rate]() {};
  }
  void callback(const std_msgs::String::ConstPtr&) {}
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  Handler<std_msgs::String> odom_, name_, timed_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "manager");
  Manager manager;
  manager.init();
  ros::spin();
}
"""


def test_text_does_not_convert_to_a_std_function(write_tree) -> None:
    root = write_tree({
        "mgr/package.xml": package_xml("mgr", "catkin"),
        "mgr/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(mgr)\n"
            "find_package(catkin REQUIRED COMPONENTS roscpp)\ncatkin_package()\n"
            "add_executable(manager src/manager.cpp)\n"),
        "mgr/src/manager.cpp": SOURCE})
    result = extract_cpp([str(root / "mgr" / "src" / "manager.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes, [
        d.message for d in result.diagnostics]
