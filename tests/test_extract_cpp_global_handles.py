"""A global node handle that ``main`` sets once (ublox_gps: ``boost::shared_ptr<
ros::NodeHandle> nh;`` in node.h, ``nh.reset(new ros::NodeHandle("~"))`` in main) has
that handle's namespace in every function of the unit: its 19 topics were ``?/fix``..."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <ros/ros.h>
#include <boost/shared_ptr.hpp>
boost::shared_ptr<ros::NodeHandle> nh;
boost::shared_ptr<ros::NodeHandle> made;
boost::shared_ptr<ros::NodeHandle> twice;
"""

NODE = """
#include <std_msgs/String.h>
#include <boost/make_shared.hpp>
#include "ub/node.h"
namespace ub {
template <typename T> void publish(const T & m) {
  static ros::Publisher p = nh->advertise<T>("fix", 1);
  p.publish(m);
}
void other() {
  ros::Publisher q = made->advertise<std_msgs::String>("status", 1);
  ros::Publisher r = twice->advertise<std_msgs::String>("either", 1);
}
}
int main(int argc, char ** argv) {
  ros::init(argc, argv, "ublox_gps");
  nh.reset(new ros::NodeHandle("~"));
  made = boost::make_shared<ros::NodeHandle>("gps");
  twice.reset(new ros::NodeHandle("a"));
  if (argc > 2) { twice.reset(new ros::NodeHandle("b")); }
  ub::publish(std_msgs::String());
  ub::other();
}
"""


def test_a_global_handle_main_sets_once(write_tree) -> None:
    root = write_tree({
        "ub/package.xml": package_xml("ub"),
        "ub/include/ub/node.h": HEADER,
        "ub/src/node.cpp": NODE,
    })
    result = extract_cpp([str(root / "ub" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "?/either"), ("publish", "gps/status"), ("publish", "~fix")]


NESTED = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "ub/node.h"
namespace app { namespace setup {
void start() { nh.reset(new ros::NodeHandle("~")); }
} }
namespace app {
void run() { ros::Publisher p = nh->advertise<std_msgs::String>("out", 1); }
}
int main(int argc, char ** argv) {
  ros::init(argc, argv, "nested");
  app::setup::start();
  app::run();
}
"""


def test_the_write_may_be_in_a_function_of_a_namespace(write_tree) -> None:
    """The main file's functions are looked for in its namespaces, nested too."""
    root = write_tree({
        "ub/package.xml": package_xml("ub"),
        "ub/include/ub/node.h": HEADER,
        "ub/src/node.cpp": NESTED,
    })
    result = extract_cpp([str(root / "ub" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~out")]
