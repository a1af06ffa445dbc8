"""An unqualified name the parse does not know that the C++ standard library declares
(``stringstream``, ``vector``, ``string``) is std's: code that compiles writes it so only
where a ``using namespace std;`` brings it, here from a header the parse lacks.
youbot_driver_ros_interface (db124ec) writes ``stringstream topicName;`` relying on
youbot_driver's headers: the names were declared permissively, and the text written to
the stream was lost (``?`` for every arm topic)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

UNQUALIFIED = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <sstream>
#include <youbot_driver/youbot/YouBotManipulator.hpp>
class Wrapper {
 public:
  void initializeArm(std::string armName);
  ros::NodeHandle node;
  ros::Publisher pub;
};
void Wrapper::initializeArm(std::string armName) {
  stringstream topicName;
  vector<string> names;
  topicName.str("");
  topicName << armName << "/joint_states";
  pub = node.advertise<std_msgs::String>(topicName.str(), 1);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "yb");
  Wrapper w;
  w.initializeArm("arm_1");
  ros::spin();
}
"""


def test_std_names_a_missing_header_brings_unqualified(write_tree) -> None:
    # youbot_driver_ros_interface writes ``stringstream`` and ``vector<string>``
    # unqualified: youbot_driver's headers, missing here, say ``using namespace std``.
    # They were declared permissively, and the stream's text was lost
    root = write_tree({"yb/package.xml": package_xml("yb"), "yb/src/main.cpp": UNQUALIFIED})
    result = extract_cpp([str(root / "yb" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [c.name for c in result.calls if c.kind == "publish"] == ["arm_1/joint_states"]
    declared = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert not any("stringstream" in m or "vector" in m or "string," in m for m in declared)
