"""A name built with ``test ? a : b`` where the test is whether a string is empty: the
side each value picks, through the call sites of the function that builds it (in its
file and in the node's other files), and through a wrapper called with its default."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp, extract_cpp_nodes
from haros_arch.workspace import Workspace, scan

LIMITER = r"""
#include <ros/ros.h>
#include <string>
class Limiter {
 public:
  void init(const ros::NodeHandle& nh, const std::string& field = std::string()) {
    std::string prefix = !field.empty() ? field + "/" : "";
    double m;
    nh.param(prefix + "max", m, 1.0);
  }
};
class Plain {
 public:
  void init(const ros::NodeHandle& nh, const std::string& field = "") {
    double m;
    nh.param(field + "min", m, 0.0);
  }
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle pnh("~");
  Limiter attitude, yaw;
  attitude.init(pnh);
  yaw.init(pnh, "yaw");
  Plain low;
  low.init(pnh);
  return 0;
}
"""


def test_an_emptiness_test_picks_the_side_of_each_call_sites_value(tmp_path: Path) -> None:
    """hector_quadrotor's limiters: ``init(nh)`` leaves ``field`` empty, so the read is
    ``~max``, not ``~/max`` (the longest side) nor ``~?max``; a wrapper called with its
    name's default makes its call (it made none)."""
    source = tmp_path / "n.cpp"
    source.write_text(LIMITER)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert sorted({c.name for c in result.calls}) == ["~max", "~min", "~yaw/max"]


PORT_H = """#include <ros/ros.h>
#include <string>
class Port {
 public:
  void init(ros::NodeHandle& nh, const std::string& node, const std::string& handle);
};
"""

PORT = """#include "robot/port.h"
void Port::init(ros::NodeHandle& nh, const std::string& node, const std::string& handle) {
  std::string name = node + ((handle.length() > 0) ? "/" + handle : "");
  int baud;
  nh.getParam(name + "/serialBaud", baud);
  std::string other = node + (handle.empty() ? "" : "/" + handle);
  nh.getParam(other + "/serialParity", baud);
}
"""

GPS = """#include "robot/port.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "gps");
  ros::NodeHandle nh;
  Port a, b;
  a.init(nh, ros::this_node::getName(), "primaryPort");
  b.init(nh, ros::this_node::getName(), "");
  ros::spin();
}
"""


def test_an_emptiness_test_of_a_string_another_file_passes(tmp_path: Path) -> None:
    """autorally's serial ports: ``nodeName + (handle.empty() ? "" : "/" + handle)`` in
    the library's file, the handles passed by the node's main file: one read per value,
    ``~serialBaud`` and ``~primaryPort/serialBaud`` (it was ``~?/serialBaud``)."""
    package = tmp_path / "src" / "robot"
    (package / "src").mkdir(parents=True)
    (package / "include" / "robot").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>robot</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend></package>\n')
    (package / "include" / "robot" / "port.h").write_text(PORT_H)
    (package / "src" / "port.cpp").write_text(PORT)
    (package / "src" / "gps.cpp").write_text(GPS)
    src = package / "src"
    batch = extract_cpp_nodes([[str(src / "gps.cpp"), str(src / "port.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    names = sorted({c.name for c in batch.results[0].calls})
    assert names == ["~primaryPort/serialBaud", "~primaryPort/serialParity",
                     "~serialBaud", "~serialParity"]
