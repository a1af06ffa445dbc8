"""A node class built by a variable declared without an initialiser whose construction
the parse drops, and a base class a constructor leaves to C++.

ethzasl_msf's sensor managers: ``main()`` declares ``PoseSensorManager manager;``;
the class overrides pure virtual methods with types built from boost::fusion, which the
parse does not have, so it is abstract to clang and the variable keeps no construction.
C++ runs the default constructor all the same: ``PoseSensorManager(ros::NodeHandle pnh =
ros::NodeHandle("~/pose_sensor"))``, which serves ``initialize_msf_scale`` on ``pnh``
and makes the sensor handlers with ``new`` (their subscriptions), and, left to C++, its
base's ``MSF_SensorManagerROS(ros::NodeHandle pnh = ros::NodeHandle("~core"))``. The
handlers' subscriptions were left out (no construction of the manager reached them) and
the names on both ``pnh`` were ``?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

MANAGER = """\
#pragma once
#include <string>
#include <boost/shared_ptr.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
namespace core {
template <int N> struct Vector {};
template <typename State>
class Manager {
 public:
  Manager(ros::NodeHandle pnh = ros::NodeHandle("~core")) {
    pnh.param("rate", rate_, 1.0);
    ros::NodeHandle nh("msf_core");
    pub_ = nh.advertise<std_msgs::String>("state_out", 10);
  }
  virtual ~Manager() {}
  virtual void correct(const Vector<State::size>& delta) = 0;
  double rate_;
  ros::Publisher pub_;
};
}  // namespace core
namespace up {
class ImuHandler {
 public:
  explicit ImuHandler(const std::string& ns) {
    ros::NodeHandle nh(ns);
    sub_ = nh.subscribe("imu_state_input", 10, &ImuHandler::cb, this);
  }
  void cb(const std_msgs::String::ConstPtr&) {}
  ros::Subscriber sub_;
};
struct State { static const int size = 3; };
struct Traits {};  // the size a library computes: unknown to the parse
class PoseManager : public core::Manager<State> {
 public:
  PoseManager(ros::NodeHandle pnh = ros::NodeHandle("~/pose_sensor")) {
    srv_ = pnh.advertiseService("init", &PoseManager::cb, this);
    imu_.reset(new ImuHandler("msf_core"));
  }
  // no override to clang (its type is in error): the class is abstract to the parse
  void correct(const core::Vector<Traits::size>& delta) override {}
  bool cb(std_srvs::Empty::Request&, std_srvs::Empty::Response&) { return true; }
  boost::shared_ptr<ImuHandler> imu_;
  ros::ServiceServer srv_;
};
}  // namespace up
"""
MAIN = """\
#include <up/manager.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "pose_sensor");
  up::PoseManager manager;
  ros::spin();
}
"""
# a second file of the executable: the node's names are then read across its files
OTHER = """\
#include <ros/ros.h>
int helper() { return 1; }
"""
MANIFEST = package_xml("up").replace(
    "</package>", "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
    "<depend>std_msgs</depend><depend>std_srvs</depend></package>")


def _calls(write_tree, files: dict[str, str]) -> set[tuple[str, str]]:
    root = write_tree({"up/package.xml": MANIFEST,
                       **{f"up/{name}": text for name, text in files.items()}})
    sources = [str(root / "up" / name) for name in files if name.endswith(".cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None)
    return {(call.kind, call.name) for call in result.calls}


def test_a_dropped_default_construction_runs_the_constructor_and_its_base(
        write_tree) -> None:
    calls = _calls(write_tree, {"include/up/manager.h": MANAGER, "src/main.cpp": MAIN,
                                "src/helper.cpp": OTHER})
    assert ("subscribe", "msf_core/imu_state_input") in calls  # the handler it makes
    assert ("server", "~pose_sensor/init") in calls  # its own default argument
    assert ("read", "~core/rate") in calls  # the base's default argument
    assert ("publish", "msf_core/state_out") in calls
    assert not any("?" in name for _, name in calls)


def test_a_base_left_to_cxx_takes_its_default_argument(write_tree) -> None:
    # one file, the construction kept: only the base's handle was unknown
    kept = MANAGER.replace("const core::Vector<Traits::size>&", "const core::Vector<3>&")
    calls = _calls(write_tree, {"include/up/manager.h": kept, "src/main.cpp": MAIN})
    assert ("read", "~core/rate") in calls
    assert ("server", "~pose_sensor/init") in calls
    assert ("subscribe", "msf_core/imu_state_input") in calls


def test_a_base_constructed_as_written_keeps_its_argument(write_tree) -> None:
    written = MANAGER.replace(
        'PoseManager(ros::NodeHandle pnh = ros::NodeHandle("~/pose_sensor")) {',
        'PoseManager(ros::NodeHandle pnh = ros::NodeHandle("~/pose_sensor"))\n'
        '  : core::Manager<State>(ros::NodeHandle("~given")) {').replace(
        "const core::Vector<Traits::size>&", "const core::Vector<3>&")
    calls = _calls(write_tree, {"include/up/manager.h": written, "src/main.cpp": MAIN})
    assert ("read", "~given/rate") in calls
    assert ("read", "~core/rate") not in calls

