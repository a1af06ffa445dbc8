"""A count or a flag of the parameter reads that found nothing, tested to fail: each read
it gathers is required, although its result is an operand of ``!`` (depthai_examples'
``badParams += !pnh.getParam("x", x);`` then ``if (badParams > 0) throw ..``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

COUNTS = r"""
#include <ros/ros.h>
#include <stdexcept>
#include <string>
void counted(ros::NodeHandle& pnh) {
  int badParams = 0, rate;
  std::string mode;
  badParams += !pnh.getParam("count_rate", rate);
  badParams += !pnh.getParam("count_mode", mode);
  if (badParams > 0) {
    throw std::runtime_error("missing parameters");
  }
  pnh.getParam("count_after", mode);
}
bool flagged(ros::NodeHandle& pnh) {
  bool ok = true;
  double a, b;
  ok &= pnh.getParam("flag_a", a);
  ok = ok && pnh.getParam("flag_b", b);
  if (!ok) {
    ROS_FATAL("missing");
    return false;
  }
  return true;
}
void incremented(ros::NodeHandle& pnh) {
  int missing = 0;
  double c;
  if (!pnh.getParam("inc_c", c)) {
    ROS_ERROR("no c");
    ++missing;
  }
  if (missing != 0) exit(1);
}
void warned(ros::NodeHandle& pnh) {
  int badParams = 0, rate;
  badParams += !pnh.getParam("warn_rate", rate);
  if (badParams > 0) {
    ROS_WARN("using defaults");
  }
  int left = 0;
  left += pnh.getParam("found_rate", rate);
  if (left == 0) {
    throw std::runtime_error("a success count: not about absence");
  }
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "counts");
  ros::NodeHandle pnh("~");
  counted(pnh);
  flagged(pnh);
  incremented(pnh);
  warned(pnh);
}
"""


def _reads(tmp_path) -> dict[str, tuple[bool, bool]]:
    source = tmp_path / "n.cpp"
    source.write_text(COUNTS)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    return {c.name: (c.tested, c.has_default) for c in result.calls if c.kind == "read"}


def test_reads_a_failed_count_gathers_are_required_when_it_fails(tmp_path):
    reads = _reads(tmp_path)
    # ``badParams += !read`` then ``if (badParams > 0) throw``: required, no default
    assert reads["~count_rate"] == (False, False)
    assert reads["~count_mode"] == (False, False)
    # ``ok &= read``, ``ok = ok && read``, ``if (!ok) { ROS_FATAL; return false; }``
    assert reads["~flag_a"] == (False, False)
    assert reads["~flag_b"] == (False, False)
    # ``if (!read) ++missing;`` then ``if (missing != 0) exit(1);``
    assert reads["~inc_c"] == (False, False)


def test_a_count_whose_test_does_not_fail_leaves_the_reads_handled(tmp_path):
    reads = _reads(tmp_path)
    # a warning is no failure: the absence is handled
    assert reads["~warn_rate"][0] is True
    # a count of reads that succeeded says nothing about one absence
    assert reads["~found_rate"][0] is False
    assert reads["~count_after"][0] is False
