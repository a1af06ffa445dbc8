"""``ros::service::call<S>`` bound with ``std::bind`` (or ``boost::bind``) to its name and
request, and run by the function object (ros_canopen's robot_layer.cpp: ``boost::thread
call(std::bind(ros::service::call<SwitchController>, "controller_manager/
switch_controller", srv))``) is a client of that service where it is bound: the node's
interface was partial without it (pilz_robots 79695c1)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

NODE = """\
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <functional>
#include <thread>

void stop() {
  std_srvs::Trigger srv;
  std::thread call(std::bind(ros::service::call<std_srvs::Trigger>, "manager/stop", srv));
  call.detach();
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "layer");
  ros::NodeHandle nh;
  stop();
  ros::spin();
}
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(layer)
find_package(catkin REQUIRED COMPONENTS roscpp std_srvs)
catkin_package()
add_executable(layer src/layer.cpp)
"""


def test_a_bound_service_call_is_a_client(write_tree):
    root = write_tree({
        "src/layer/package.xml": package_xml("layer"),
        "src/layer/CMakeLists.txt": CMAKE,
        "src/layer/src/layer.cpp": NODE,
        "src/layer/launch/layer.launch": (
            '<launch><group ns="robot"><node pkg="layer" type="layer" name="layer"/>'
            '</group></launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [layer/launch/layer.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (node,) = model.nodes
    assert [(c.kind, c.name, c.type) for c in node.calls] == [
        ("client", "manager/stop", "std_srvs/Trigger")]
    (config,) = model.configurations
    (instance,) = config.nodes
    assert [(link.kind, link.rosname.full) for link in instance.links] == [
        ("client", "/robot/manager/stop")]
