"""A class nested in a vendor's class template, named through a type alias of one of its
specialisations, and a member of that class: ethzasl_icp_mapping's mapper (4d50c6f^)
includes libpointmatcher's PointMatcher.h, which the workspace does not have, and
libpointmatcher_ros' aliases.h says ``typedef PointMatcher<float> PM;``; its constructor's
initialiser ``Ticp(PM::TransformationParameters::Identity(4, 4))`` (mapper.cpp:99) was
clang's "no member named 'Identity' in 'PointMatcher<float>::TransformationParameters'":
a third wave of errors (the template, the class nested in it, the member of that), after
the parses a unit gets, so the constructor, which makes the node's ROS calls, was an
error near them, the node partial, and the launch file's ``cloudTopic``, which the mapper
never reads, undecided. The names written after an alias of an unknown template are now
declared in the template from the first parse, for ``typedef`` and ``using`` alike; a
``PM::X`` of two parts is still left to clang's errors."""

from __future__ import annotations

import textwrap

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

UNCLEAN = ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")

ALIASES = {
    "typedef": "typedef PointMatcher<float> PM;",
    "using": "using PM = PointMatcher<float>;",
}

HEADER = """\
#ifndef ALIASES_H
#define ALIASES_H
#include "pointmatcher/PointMatcher.h"
{alias}
typedef PM::TransformationParameters TP;
#endif
"""

NODE = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "aliases.h"

class Mapper {
 public:
  explicit Mapper(ros::NodeHandle& pn)
      : Ticp(PM::TransformationParameters::Identity(4, 4)),
        minOverlap(pn.param<double>("minOverlap", 0.5)) {
    mapPub = pn.advertise<std_msgs::String>("point_map", 2, true);
    cloudSub = pn.subscribe("cloud_in", 2, &Mapper::gotCloud, this);
  }
  void gotCloud(const std_msgs::String::ConstPtr& msg) {
    TP T(PM::TransformationParameters::Identity(4, 4));
  }

 private:
  PM::TransformationParameters Ticp;
  double minOverlap;
  ros::Publisher mapPub;
  ros::Subscriber cloudSub;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "mapper");
  ros::NodeHandle pn("~");
  Mapper mapper(pn);
  ros::spin();
  return 0;
}
"""


@pytest.mark.parametrize("kind", sorted(ALIASES))
def test_a_member_of_a_class_nested_in_an_aliased_unknown_template(tmp_path, kind) -> None:
    (tmp_path / "package.xml").write_text(package_xml("mapping").replace(
        "</package>", "<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend>"
                      "<depend>std_msgs</depend></package>"))
    (tmp_path / "aliases.h").write_text(HEADER.format(alias=ALIASES[kind]))
    source = tmp_path / "mapper.cpp"
    source.write_text(textwrap.dedent(NODE))
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(d.code, d.message) for d in result.diagnostics if d.code in UNCLEAN] == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("read", "~minOverlap", "double"),
        ("publish", "~point_map", "std_msgs/String"),
        ("subscribe", "~cloud_in", "std_msgs/String"),
    ]
