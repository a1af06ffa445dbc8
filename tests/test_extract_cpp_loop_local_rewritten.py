"""A string variable declared in a loop's body, read, then written again in the same
turn: the read takes the value the declaration gives, as each turn makes the variable
anew (the later write reaches no read of a later turn). realsense-ros reads its stream
options so, ``std::string param_name(_stream_name[s] + "_width"); _pnh.param(param_name,
...); param_name = _stream_name[s] + "_height"; ...`` in a loop over its streams: the
first read was ``~?`` (any parameter, global too) where it is ``~?_width``. A variable
declared outside the loop keeps what a later write of the turn before may give."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <string>
#include <vector>
int main(int argc, char** argv) {
  ros::init(argc, argv, "camera");
  ros::NodeHandle pnh("~");
  std::vector<std::string> streams;
  pnh.getParam("streams", streams);
  int value = 0;
  std::string outside = "first";
  for (const std::string& stream : streams) {
    std::string name(stream + "_width");
    pnh.param(name, value, 640);
    name = stream + "_height";
    pnh.param(name, value, 480);
    pnh.param(outside, value, 0);
    outside = "second";
  }
  ros::spin();
}
"""


def test_a_variable_of_the_loop_s_body_read_before_its_next_write(write_tree) -> None:
    root = write_tree({"cam/package.xml": package_xml("cam", "catkin").replace(
                           "</package>", "<depend>roscpp</depend></package>"),
                       "cam/src/camera.cpp": SOURCE})
    result = extract_cpp([str(root / "cam" / "src" / "camera.cpp")], scan([str(root)]),
                         cache_dir=None)
    reads = sorted((c.location.line, c.name) for c in result.calls if c.kind == "read")
    assert reads[0] == (8, "~streams")
    assert (13, "~?_width") in reads and (15, "~?_height") in reads
    # ``outside`` may hold either: not the first value alone
    assert [name for line, name in reads if line == 16] == ["~?"]
