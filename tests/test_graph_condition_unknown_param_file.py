"""A parameter read's default decides a condition only where nothing may set the
parameter: a launch parameter whose name is not known statically that may be it (a
``<rosparam command="load">`` of a file not read, ROS 1 mavros'
``$(find mavros)/launch/px4_config.yaml`` where mavros is not installed here, which
sets ``landing_target/listen_lt``) leaves the read's value unknown, so the call under
the condition stays, undecided, instead of a CONDITION_FALSE. Without such a file the
default decides it as before."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

NODE = r"""
#include <ros/ros.h>
#include <std_msgs/Empty.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "lt");
  ros::NodeHandle nh("~");
  bool listen = false;
  nh.param("target/listen", listen, false);
  ros::Publisher pub;
  if (listen) {
    pub = nh.advertise<std_msgs::Empty>("raw", 1);
  }
  ros::spin();
}
"""

LAUNCH = """<launch>
  <node pkg="lt" type="lt" name="lt">
    <param name="rate" value="1"/>
    {load}
  </node>
</launch>
"""


def _raw(write_tree, load: str):
    root = write_tree({
        "lt/package.xml": package_xml("lt", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"),
        "lt/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(lt)\n"
                             "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
                             "catkin_package()\nadd_executable(lt src/lt.cpp)\n",
        "lt/src/lt.cpp": NODE,
        "lt/launch/lt.launch": LAUNCH.format(load=load),
    })
    project = Project("p", os.path.join(str(root), "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["lt/launch/lt.launch"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    raw = [link for link in config.links if link.resource.name == "/lt/raw"]
    said = [d.message for d in config.diagnostics if d.code == "CONDITION_FALSE"]
    return raw, said


def test_a_parameter_file_not_read_may_set_the_tested_parameter(write_tree):
    raw, said = _raw(write_tree, '<rosparam command="load" '
                                 'file="$(find not_here)/launch/config.yaml"/>')
    assert len(raw) == 1 and raw[0].conditions, said
    assert not any("/lt/raw" in message for message in said)


def test_without_one_the_default_decides(write_tree):
    raw, said = _raw(write_tree, "")
    assert raw == []
    assert any("/lt/raw" in message for message in said)
