"""A class (or function) of another file that reads parameters on the handle its caller
passes makes one call per construction site, each named from that site's handle: each
exists only under the conditions of its own site. ned_ros (v5.6.3)
conveyor_interface_node.cpp:52-62 builds its TtlInterfaceCore on ``nh_ttl`` only ``if
(hardware_version == "ned2" || ...)`` and its CanInterfaceCore on ``nh_can`` only ``if
(hardware_version == "ned" || ...)``: with two sites under different conditions the
calls kept none (the conditions all sites share), so the reads of the class not built in
a configuration were reported as read and never set."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """
#include <ros/ros.h>
#include <string>
class Driver {
 public:
  explicit Driver(ros::NodeHandle& nh);
 private:
  void init(ros::NodeHandle& nh);
  std::string version_;
};
void configure(ros::NodeHandle& nh);
"""

LIBRARY = """
#include "driver.h"
Driver::Driver(ros::NodeHandle& nh) { init(nh); }
void Driver::init(ros::NodeHandle& nh) { nh.getParam("version", version_); }
void configure(ros::NodeHandle& nh) { std::string port; nh.getParam("port", port); }
"""

MAIN = """
#include <memory>
#include "driver.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("~");
  std::string kind;
  nh.getParam("kind", kind);
  std::shared_ptr<Driver> a, b;
  if (kind == "x") {
    ros::NodeHandle nh_a("a");
    a = std::make_shared<Driver>(nh_a);
    configure(nh_a);
  }
  if (kind == "y") {
    ros::NodeHandle nh_b("b");
    b.reset(new Driver(nh_b));
    configure(nh_b);
  }
  for (int i = 0; i < 2; ++i) {
    ros::NodeHandle nh_c("c");
    Driver c(nh_c);
  }
  return 0;
}
"""


def test_each_site_s_calls_keep_that_site_s_conditions(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("p", "catkin"))
    (tmp_path / "src").mkdir()
    (tmp_path / "src/driver.h").write_text(HEADER)
    (tmp_path / "src/driver.cpp").write_text(LIBRARY)
    (tmp_path / "src/main.cpp").write_text(MAIN)
    result = extract_cpp([str(tmp_path / "src/main.cpp"), str(tmp_path / "src/driver.cpp")],
                         scan([str(tmp_path)]), cache_dir=None)
    got = {c.name: [(x.statement, x.text) for x in c.conditions] for c in result.calls}
    assert got == {
        "~kind": [],
        "a/version": [("if", 'kind == "x"')],
        "b/version": [("if", 'kind == "y"')],
        "a/port": [("if", 'kind == "x"')],
        "b/port": [("if", 'kind == "y"')],
        # a loop's turn is no condition of what it builds (``NOT_CARRIED``)
        "c/version": [],
    }
