"""A standard algorithm of the stand-ins (declared, not defined) called with a lambda:
clang says the template "is used but not defined in this translation unit, and cannot be
defined in any other", but only in a parse with no other error. That error, in the
stand-in, made the parse with the unknown names declared count as bad as the one without
them: bwi_common's logical translator kept ``boost::algorithm::join`` unknown, an error in
a function that calls the ROS API (the node partial). The real library defines it: it is
no error of the code."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <algorithm>
#include <vendor/strings.hpp>
int main(int argc, char** argv) {
  ros::init(argc, argv, "translator");
  ros::NodeHandle nh;
  std::vector<std::string> missing;
  std::string map_file;
  if (!nh.getParam("map_file", map_file)) missing.push_back("map_file");
  if (!missing.empty()) {
    std::string message = "missing: " + vendor::strings::join(missing, ", ");
    ROS_FATAL_STREAM(message);
  }
  std::vector<int> ids = {1, 2};
  std::vector<std::string> names;
  std::transform(ids.begin(), ids.end(), std::back_inserter(names),
                 [](int i) { return std::to_string(i); });
  ros::Publisher pub = nh.advertise<std_msgs::String>("doors", 1);
  ros::spin();
}
"""


def test_a_lambda_given_to_a_standin_template_is_no_error(tmp_path) -> None:
    (tmp_path / "translator.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "translator.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert ("publish", "doors") in [(c.kind, c.name) for c in result.calls]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_NAMES_DECLARED" in codes
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
