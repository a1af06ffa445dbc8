"""A topic named by a parameter read on a NodeHandle that a constructor is given by a
caller in another file (m-explore's ``Costmap2DClient(param_nh, subscription_nh, tf)``,
costmap_client.cpp:50-70, built with the private handle in explore.cpp): the call's
``name_param`` is that parameter with the handle the caller passes (``~costmap_topic``),
as the read itself is. It kept the internal mark of "the argument the callers pass"
(a NUL, the constructor's USR, its parameter's index): a name no graph can set."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

HEADER = """#include <ros/ros.h>
#include <nav_msgs/OccupancyGrid.h>
class Client {
 public:
  Client(ros::NodeHandle& param_nh, ros::NodeHandle& subscription_nh);
 private:
  ros::Subscriber sub_;
};
"""

CLIENT = """#include "explore/client.h"
Client::Client(ros::NodeHandle& param_nh, ros::NodeHandle& subscription_nh) {
  std::string topic;
  param_nh.param("costmap_topic", topic, std::string("costmap"));
  sub_ = subscription_nh.subscribe<nav_msgs::OccupancyGrid>(
      topic, 10, [](const nav_msgs::OccupancyGrid::ConstPtr&) {});
}
"""

MAIN = """#include "explore/client.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "explore");
  ros::NodeHandle private_nh("~");
  ros::NodeHandle relative_nh;
  Client client(private_nh, relative_nh);
  ros::spin();
}
"""


def test_a_parameter_named_through_a_handle_of_another_file_is_resolved(tmp_path) -> None:
    package = tmp_path / "src" / "explore"
    (package / "src").mkdir(parents=True)
    (package / "include" / "explore").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>explore</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend></package>\n')
    (package / "include" / "explore" / "client.h").write_text(HEADER)
    (package / "src" / "client.cpp").write_text(CLIENT)
    (package / "src" / "main.cpp").write_text(MAIN)
    src = package / "src"
    batch = extract_cpp_nodes([[str(src / "main.cpp"), str(src / "client.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    calls = batch.results[0].calls
    assert sorted((c.kind, c.name, c.name_param, c.name_default) for c in calls) == [
        ("read", "~costmap_topic", None, None),
        ("subscribe", "?", "~costmap_topic", "costmap")]


def test_the_marks_of_a_handle_no_caller_names_are_unknown() -> None:
    """A plugin's ``initialize(name)`` that reads ``~<name>/plan_topic`` (sbpl_recovery):
    no file of the node calls it (its host does), so the handle's part is ``?``."""
    from haros_arch.extract.cpp.links import _parameter_filled
    from haros_arch.extract.cpp.values import PLACEHOLDER, SEPARATOR

    mark = f"{PLACEHOLDER}c:@S@Recovery@F@initialize#{SEPARATOR}0{PLACEHOLDER}"
    assert _parameter_filled(f"~{mark}/plan_topic", {}) == "~?/plan_topic"
    passed = {"c:@S@Recovery@F@initialize#": {"main.cpp:9": {0: "recovery"}}}
    assert _parameter_filled(f"~{mark}/plan_topic", passed) == "~recovery/plan_topic"
