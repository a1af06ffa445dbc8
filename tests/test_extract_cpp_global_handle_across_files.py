"""A global node handle that one file of a node defines and sets in ``main`` and that
another file of the node uses through ``extern`` (OpenMower's mower_logic: ``ros::
NodeHandle* n;`` and ``n = new ros::NodeHandle();`` in mower_logic.cpp, ``extern ros::
NodeHandle* n;`` in AreaRecordingBehavior.cpp, whose service clients and publishers were
``/?/mower_map_service/add_mowing_area``): the other file's calls are in the namespace
main gives the handle, as for a handle member whose constructors are in another file."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#include <ros/ros.h>
#include <std_msgs/String.h>
extern ros::NodeHandle* n;
extern ros::NodeHandle* priv;
extern ros::NodeHandle* either;
extern ros::NodeHandle* never;
void start_recording();
"""

MAIN = """#include "rec/shared.h"
ros::NodeHandle* n;
ros::NodeHandle* priv;
ros::NodeHandle* either;
ros::NodeHandle* never;
int main(int argc, char** argv) {
  ros::init(argc, argv, "logic");
  n = new ros::NodeHandle();
  priv = new ros::NodeHandle("~");
  either = new ros::NodeHandle("a");
  if (argc > 2) { either = new ros::NodeHandle("b"); }
  ros::Publisher mine = n->advertise<std_msgs::String>("here", 1);
  start_recording();
  ros::spin();
}
"""

BEHAVIOR = """#include "rec/shared.h"
void start_recording() {
  ros::Publisher a = n->advertise<std_msgs::String>("area_recorder/progress", 10);
  ros::Publisher b = priv->advertise<std_msgs::String>("status", 10);
  ros::Publisher c = either->advertise<std_msgs::String>("which", 10);
  ros::Publisher d = never->advertise<std_msgs::String>("unset", 10);
}
"""


def test_an_extern_handle_takes_the_namespace_main_gives_it(tmp_path: Path) -> None:
    package = tmp_path / "src" / "rec"
    (package / "src").mkdir(parents=True)
    (package / "include" / "rec").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("rec"))
    (package / "include" / "rec" / "shared.h").write_text(HEADER)
    (package / "src" / "main.cpp").write_text(MAIN)
    (package / "src" / "behavior.cpp").write_text(BEHAVIOR)
    src = package / "src"
    batch = extract_cpp_nodes([[str(src / "main.cpp"), str(src / "behavior.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    result = batch.results[0]
    assert sorted((c.name, c.handle_namespace) for c in result.calls
                  if c.kind == "publish") == [
        ("?/unset", "?"),  # written by no file of the node: unknown, as before
        ("?/which", "?"),  # written twice in main: not one namespace
        ("area_recorder/progress", None),
        ("here", None),
        ("~status", "~"),
    ]
