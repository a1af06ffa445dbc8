"""The address of an object of a type the parse declared permissively is a pointer to
that type, which a template's ``T *`` deduces. RoboRTS' planners (5b45bd37^) read
their protobuf configuration with roborts_common's ``template <class T> bool
ReadProtoFromTextFile(const char *, T *)``, the generated ``GlobalPlannerConfig``
missing: ``&config`` was the permissive address, which deduces no ``T *``, so the call
was an error in the function that makes the node's ROS calls (the node partial, every
global parameter of the configuration undecided)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "planner/global_planner_config.pb.h"

template <class T>
inline bool ReadProtoFromTextFile(const char *file_name, T *proto) { return proto; }

class Planner {
 public:
  bool Init() {
    GlobalPlannerConfig config;
    if (!ReadProtoFromTextFile("config.prototxt", &config)) {
      return false;
    }
    const GlobalPlannerConfig &same = config;
    ReadProtoFromTextFile("again.prototxt", &same);
    nh_.param<std::string>("global_frame", frame_, "map");
    pub_ = nh_.advertise<std_msgs::String>("path", 1);
    return true;
  }
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  std::string frame_;
};

int main(int argc, char **argv) {
  ros::init(argc, argv, "planner");
  Planner planner;
  planner.Init();
  ros::spin();
}
"""


def test_a_declared_object_s_address_is_a_pointer_to_it(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("planner", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "planner.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "global_frame"), ("publish", "path")]
    codes = {d.code for d in result.diagnostics}
    assert "CPP_ERROR_NEAR_CALL" not in codes and "CPP_PARSE_ERROR" not in codes
