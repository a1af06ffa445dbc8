"""A counting loop up to an integer parameter that no launch file sets runs as many
turns as the default the node reads it with. mavros_controllers (8b3fff0)'s
trajectory_publisher reads ``nh_private_.param<int>("number_of_primitives",
num_primitives_, 7)`` and advertises ``"trajectory_publisher/primitiveset" +
std::to_string(i)`` for ``i`` from 0 below it; trajectory_publisher.launch sets nothing,
so ROS makes primitiveset0 to primitiveset6. The graph kept one publisher
``primitiveset?`` and said the name was "the elements of the list parameter
~number_of_primitives, which the configuration does not set". A count read with no
default (``getParam``) still keeps its ``?``, and the diagnostic names a loop's counter,
not a list; a count another node may set keeps it too."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

CODE = """
#include <ros/ros.h>
#include <nav_msgs/Path.h>
#include <string>
#include <vector>
int main(int argc, char **argv) {
  ros::init(argc, argv, "traj");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  int primitives;
  pnh.param<int>("number_of_primitives", primitives, 3);
  std::vector<ros::Publisher> pubs;
  for (int i = 0; i < primitives; i++)
    pubs.push_back(nh.advertise<nav_msgs::Path>("primitiveset" + std::to_string(i), 1));
  int extra;
  pnh.getParam("extra", extra);
  for (int k = 0; k < extra; k++)
    pubs.push_back(nh.advertise<nav_msgs::Path>("extra" + std::to_string(k), 1));
  int none;
  pnh.param("none", none, -1);
  for (int j = 0; j < none; j++)
    pubs.push_back(nh.advertise<nav_msgs::Path>("none" + std::to_string(j), 1));
  ros::spin();
}
"""


def _analysed(write_tree, params: str):
    root = write_tree({
        "src/tp/package.xml": package_xml("tp"),
        "src/tp/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(tp)\n"
                                 "find_package(catkin REQUIRED COMPONENTS roscpp)\n"
                                 "catkin_package()\nadd_executable(traj src/traj.cpp)\n",
        "src/tp/src/traj.cpp": CODE,
        "src/tp/launch/traj.launch": '<launch>\n  <node pkg="tp" type="traj" name="traj">'
                                     f'{params}</node>\n</launch>\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [tp/launch/traj.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def _published(model) -> list[str]:
    return sorted(link.resource.name for link in model.configurations[0].links
                  if link.kind == "publish" and link.node.name == "/traj")


def test_an_unset_count_runs_the_turns_of_its_default(write_tree) -> None:
    model = _analysed(write_tree, "")
    assert _published(model) == ["/extra?", "/primitiveset0", "/primitiveset1",
                                 "/primitiveset2"]
    messages = [d.message for d in model.configurations[0].diagnostics
                if d.code == "NAME_PARAM_UNSET"]
    assert len(messages) == 1
    assert "counter of the loop up to the parameter ~extra" in messages[0]
    assert "list" not in messages[0]


def test_a_count_the_launch_file_sets_wins_over_the_default(write_tree) -> None:
    model = _analysed(write_tree, '<param name="number_of_primitives" value="1"/>'
                                  '<param name="extra" value="2"/>')
    assert _published(model) == ["/extra0", "/extra1", "/primitiveset0"]
