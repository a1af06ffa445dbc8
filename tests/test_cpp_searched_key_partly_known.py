"""``searchParam(key, found)`` writes to ``found`` the name of the parameter it found,
never a parameter's value. With a key whose text is partly known (MoveIt's
kinematics_plugin_loader.cpp:336, ``nh.searchParam(base_param_name +
"/kinematics_solver_timeout", name)`` and then ``nh.getParam(name, timeout)``, line 339)
the read of ``found`` was named ``?`` "by the value of the parameter
``~?/kinematics_solver_timeout``" (the graph would have named it by a number); it reads
the parameter searched for, ``~?/kinematics_solver_timeout``, as a key written whole
does."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <ros/ros.h>
void load(ros::NodeHandle& nh, const std::string& base)
{
  std::string found;
  if (nh.searchParam(KEY, found))
  {
    double timeout;
    if (nh.getParam(found, timeout))
      ROS_INFO("%f", timeout);
  }
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh("~");
  std::string base;
  nh.getParam("base", base);
  load(nh, base);
}
"""


def _reads(write_tree, key: str) -> list[tuple[str, str | None, bool, int]]:
    root = write_tree({
        "p/package.xml": package_xml("p", "catkin"),
        "p/CMakeLists.txt": "project(p)\nfind_package(catkin REQUIRED COMPONENTS roscpp)\n"
                            "add_executable(n src/n.cpp)\n",
        "p/src/n.cpp": SOURCE.replace("KEY", key),
    })
    ws = scan([str(root)])
    package = ws.packages["p"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    return [(c.name, c.name_param, c.searched, c.location.line)
            for c in package.nodes[0].calls if c.kind == "read" and c.location.line == 8]


def test_a_partly_known_key_names_the_read_of_its_result(write_tree) -> None:
    assert _reads(write_tree, 'base + "/kinematics_solver_timeout"') == [
        ("~?/kinematics_solver_timeout", None, True, 8)]


def test_a_key_written_whole_as_before(write_tree) -> None:
    assert _reads(write_tree, '"kinematics_solver_timeout"') == [
        ("~kinematics_solver_timeout", None, True, 8)]
