"""ROS 1 Gazebo's own ROS interface: gazebo_ros' ``gzserver`` (and ``gazebo``, ``debug``,
``perf``) are shell scripts that run Gazebo's server with ``-s
libgazebo_ros_api_plugin.so``, the system plugin that makes the ``gazebo`` node
(``/gazebo/spawn_urdf_model``, ``/gazebo/model_states``, ``/clock``, ...). The build
stage makes each such script a node with the plugin's sources, so the noetic model has
them; a ``/gazebo`` started by a launch file was of unknown interface (survey Z26)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest
from conftest import package_xml

from haros_arch.pipeline import Options, analyse, read_build_files
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

PLACER = """#!/usr/bin/env python
import rospy
from gazebo_msgs.msg import LinkStates, ModelStates
from gazebo_msgs.srv import SpawnModel
rospy.init_node('placer')
spawn = rospy.ServiceProxy('/gazebo/spawn_urdf_model', SpawnModel)
rospy.Subscriber('/gazebo/link_state', LinkStates, lambda m: None)
rospy.Subscriber('/gazebo/model_states', ModelStates, lambda m: None)
"""

LAUNCH = """<launch>
  <node name="gazebo" pkg="gazebo_ros" type="gzserver" args="-e ode worlds/empty.world"/>
  <node name="placer" pkg="sim_user" type="placer.py"/>
</launch>
"""


def _analysed(write_tree: Any, launch: str = LAUNCH) -> tuple[Any, dict[str, list[str]]]:
    root: Path = write_tree({
        "src/sim_user/package.xml": package_xml("sim_user"),
        "src/sim_user/CMakeLists.txt": "project(sim_user)\n",
        "src/sim_user/scripts/placer.py": PLACER,
        "src/sim_user/launch/sim.launch": launch,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [sim_user/launch/sim.launch]\n",
    })
    os.chmod(root / "src/sim_user/scripts/placer.py", 0o755)
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None, jobs=1))
    found: dict[str, list[str]] = {}
    for finding in run_catalogue(model, project):
        found.setdefault(finding.rule, []).append(finding.message)
    return model.configurations[0], found


def test_gzserver_serves_the_api_plugins_services(write_tree: Any) -> None:
    config, found = _analysed(write_tree)
    gazebo = next(n for n in config.nodes if n.name == "/gazebo")
    assert gazebo.node is not None and gazebo.node.name == "gazebo_ros/gzserver"
    assert gazebo.completeness == "model"
    spawn = next(s for s in config.services if s.name == "/gazebo/spawn_urdf_model")
    assert [link.node.name for link in spawn.servers] == ["/gazebo"]
    assert [link.node.name for link in spawn.clients] == ["/placer"]
    # each server exists only when ~enable_ros_network is true: the model keeps the
    # source's conditions (the caller's ``if (enable_ros_network_)`` and the early
    # ``if (! enable_ros_network_) return;`` of advertiseServices), which the graph
    # decides by the parameter (its default here)
    (server,) = spawn.servers
    assert server.call is not None
    assert server.call.conditions and all(
        c.text.replace(" ", "").lstrip("!") == "enable_ros_network_"
        for c in server.call.conditions)
    assert server.conditions == ()
    states = next(t for t in config.topics if t.name == "/gazebo/model_states")
    assert [link.node.name for link in states.publishers] == ["/gazebo"]
    assert {t.name for t in config.topics} >= {"/clock", "/gazebo/link_states",
                                              "/gazebo/performance_metrics"}
    # a topic the API plugin does not publish: decided now that /gazebo is known (so
    # are the plugin's own command topics, which nothing here publishes)
    assert sorted(m.split(" ")[0] + " " + m.split(" ")[3]
                  for m in found["subscriber-without-publisher"]) == [
        "/gazebo /gazebo/set_link_state", "/gazebo /gazebo/set_model_state",
        "/placer /gazebo/link_state"]
    assert not any("/gazebo" in m for m in found.get(
        "subscriber-without-publisher-undecided", []))


@pytest.mark.parametrize(("setting", "served"), [
    ('<param name="gazebo/enable_ros_network" value="false"/>', False),
    ('<arg name="net"/><param name="gazebo/enable_ros_network" value="$(arg net)"/>', None),
], ids=["disabled", "not-known"])
def test_the_api_plugins_services_follow_enable_ros_network(
        write_tree: Any, setting: str, served: bool | None) -> None:
    # empty_world.launch's enable_ros_network argument sets /gazebo/enable_ros_network
    config, _ = _analysed(write_tree, LAUNCH.replace("<launch>", "<launch>\n  " + setting))
    services = {s.name: s for s in config.services}
    if served is False:  # decided false: the services are not there, /clock still is
        assert not services["/gazebo/spawn_urdf_model"].servers
        assert any(t.name == "/clock" and t.publishers for t in config.topics)
        assert any(d.code == "CONDITION_FALSE" for d in config.diagnostics)
        return
    (server,) = services["/gazebo/spawn_urdf_model"].servers  # not known: conditions
    assert server.conditions and all(
        c.text.replace(" ", "").lstrip("!") == "enable_ros_network_" for c in server.conditions)


UNREAD = """<launch>
  <include file="$(find gazebo_ros)/launch/custom_world.launch"/>
  <param name="robot_description" textfile="$(find sim_user)/robot.urdf"/>
  <node name="spawn" pkg="gazebo_ros" type="spawn_model"
        args="-urdf -param robot_description -model r"/>
  <node name="placer" pkg="sim_user" type="placer.py"/>
</launch>
"""


def test_gazebo_from_an_unread_gazebo_ros_launch_file_is_its_gzserver(
        write_tree: Any) -> None:
    # gazebo_ros installed, not in the workspace: a launch file of it that its model does
    # not hold is not read; the /gazebo that stands for its gazebo node runs gzserver, as
    # gazebo_ros' world files start it
    write_tree({"src/sim_user/robot.urdf": (
        "<robot name='r'><link name='base'/><gazebo>"
        "<plugin name='imu' filename='libgazebo_ros_imu.so'/></gazebo></robot>\n")})
    config, found = _analysed(write_tree, UNREAD)
    gazebo = next(n for n in config.nodes if n.name == "/gazebo")
    assert gazebo.node is not None and gazebo.node.name == "gazebo_ros/gzserver"
    assert gazebo.is_complete
    spawn = next(s for s in config.services if s.name == "/gazebo/spawn_urdf_model")
    assert [link.node.name for link in spawn.servers] == ["/gazebo"]
    assert sorted(link.node.name for link in spawn.clients) == ["/placer", "/spawn"]
    assert any(d.code == "GAZEBO_NOT_STARTED" for d in config.diagnostics)
    # what the include may start besides is not known: an absence stays undecided
    assert "subscriber-without-publisher" not in found
    # the rules about code leave the model's calls out (/clock), not those of the
    # description's plugins (the IMU's default topic)
    assert [m for m in found["global-names"] if m.startswith("/gazebo ")] == [
        "/gazebo uses the global name /default_imu for a publish call",
        "/gazebo uses the global name /default_imu for a server call"]


def test_the_build_stage_makes_a_gzserver_script_a_node_of_its_system_plugins(
        write_tree: Any) -> None:
    root: Path = write_tree({
        "src/sim/package.xml": package_xml("sim"),
        "src/sim/CMakeLists.txt": """
            project(sim)
            add_library(sim_api_plugin src/api.cpp)
            add_library(sim_model_plugin src/model.cpp)
            install(PROGRAMS scripts/server scripts/client scripts/plain
                    DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
            """,
        "src/sim/src/api.cpp": """
            #include <gazebo/common/Plugin.hh>
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            namespace gazebo {
            class SimApi : public SystemPlugin {
             public:
              void Load(int argc, char** argv) {
                ros::init(argc, argv, "sim");
                ros::NodeHandle nh("~");
                pub_ = nh.advertise<std_msgs::String>("status", 1);
              }
              ros::Publisher pub_;
            };
            GZ_REGISTER_SYSTEM_PLUGIN(SimApi)
            }
            """,
        "src/sim/src/model.cpp": """
            #include <gazebo/common/Plugin.hh>
            namespace gazebo {
            class SimModel : public ModelPlugin {
             public:
              void Load(physics::ModelPtr, sdf::ElementPtr) {}
            };
            GZ_REGISTER_MODEL_PLUGIN(SimModel)
            }
            """,
        # the server with the package's system plugin (a model plugin given by -s is
        # not one); the client runs no server; plain names no plugin of the package
        "src/sim/scripts/server": "#!/bin/sh\n# gzserver -s libnot_this.so\n"
                                  "gzserver $@ -s `catkin_find libsim_api_plugin.so` "
                                  "-s libsim_model_plugin.so\n",
        "src/sim/scripts/client": "#!/bin/sh\ngzclient $@ -g libsim_api_plugin.so\n",
        "src/sim/scripts/plain": "#!/bin/sh\ngzserver $@ -s libother_plugin.so\n",
    })
    workspace = scan([str(root / "src")], {})
    package = workspace.packages["sim"]
    read_build_files(package, workspace)
    nodes = {n.executable: n for n in package.nodes}
    assert sorted(nodes) == ["server", "sim_api_plugin", "sim_model_plugin"]
    server = nodes["server"]
    assert (server.kind, server.language, server.sources) == (
        "executable", "cpp", ["sim/src/api.cpp"])
