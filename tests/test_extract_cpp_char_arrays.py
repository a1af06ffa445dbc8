"""Topic names kept in C character arrays: a ``constexpr char kTopic[] = "..."`` constant
(the const is on the elements: cartographer_ros' node_constants.h, ROS 2 demos'
``DEFAULT_TOPIC_NAME``) is its literal; an array a call fills through a pointer
(``snprintf(topic, size, "analog_output%02d", i)``: phidgets) is not its initializer,
but what the call prints (``analog_output?``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

CONSTANTS = """
namespace carto {
constexpr char kSubmapListTopic[] = "submap_list";
constexpr int kLatestOnlyPublisherQueueSize = 1;
}
"""

NODE = """
#include <cstdio>
#include <cstring>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "carto/node_constants.h"
namespace carto {
const char kLocal[] = "local_topic";
char kChanged[] = "before";
void rename(char * name) { name[0] = 'x'; }
void log(const char * format, ...);
void run(int i) {
  ros::NodeHandle nh;
  auto a = nh.advertise<std_msgs::String>(kSubmapListTopic, kLatestOnlyPublisherQueueSize);
  auto b = nh.advertise<std_msgs::String>(kLocal, 1);
  char topicname[] = "analog_output00";
  snprintf(topicname, sizeof(topicname), "analog_output%02d", i);
  auto c = nh.advertise<std_msgs::String>(topicname, 1);
  char kept[] = "kept_name";
  log("advertising %s", kept);  // a printf-like variadic reads it
  auto d = nh.advertise<std_msgs::String>(kept, std::strlen(kept));
  rename(kChanged);
  auto e = nh.advertise<std_msgs::String>(kChanged, 1);
}
}
"""


def test_names_in_char_arrays(write_tree) -> None:
    root = write_tree({
        "carto/package.xml": package_xml("carto"),
        "carto/include/carto/node_constants.h": CONSTANTS,
        "carto/src/node.cc": NODE,
    })
    result = extract_cpp([str(root / "carto" / "src" / "node.cc")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.name, c.queue_size) for c in result.calls if c.kind == "publish"] == [
        # what snprintf prints into the array: its format, ``?`` for ``%02d`` of ``i``
        ("submap_list", 1), ("local_topic", 1), ("analog_output?", 1), ("kept_name", None),
        ("?", 1)]
