"""A finding about installed packages' own files only (a launch file of an installed
package read from its model, a parameter file it loads, a node it starts) is true of
any system that includes those files and not the workspace's to change: gazebo_ros'
client waits for the physics services only the server has, mavros' apm_config.yaml sets
parameters of plugins its own list turns off. Such matches are counted in one info per
rule and configuration (``<rule>-upstream``), not reported one by one; a match that
also involves the workspace (its node publishing to the modelled server) stays."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue

TALKER = """\
import rospy
from std_msgs.msg import String
rospy.init_node('mover')
pub = rospy.Publisher('/gazebo/set_model_state', String, queue_size=1)
rospy.spin()
"""


def _findings(write_tree, mover: bool):
    node = '  <node name="mover" pkg="app" type="mover.py"/>\n' if mover else ""
    root = write_tree({
        "src/app/package.xml": package_xml("app"),
        "src/app/CMakeLists.txt": ("cmake_minimum_required(VERSION 3.0)\nproject(app)\n"
                                   "find_package(catkin REQUIRED)\ncatkin_package()\n"
                                   "catkin_install_python(PROGRAMS scripts/mover.py "
                                   "DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n"),
        "src/app/scripts/mover.py": TALKER,
        "src/app/launch/sim.launch": (
            "<launch>\n"
            "  <include file=\"$(find gazebo_ros)/launch/empty_world.launch\"/>\n"
            f"{node}</launch>\n"),
        "project.yaml": ("project: p\nworkspace: src\ndistro: noetic\n"
                         "configurations:\n  c: [app/launch/sim.launch]\n"),
    })
    project = load(str(root / "project.yaml"))
    model = analyse(project, {}, Options(cache_dir=None, jobs=1))
    return run_catalogue(model, project)


def test_findings_about_installed_packages_files_only_are_counted_not_reported(write_tree):
    found = _findings(write_tree, mover=False)
    upstream = [f for f in found if (f.location.file or "").startswith("github:")]
    # gzclient's two physics clients have no server in its process: one info says so
    assert [(f.rule, f.severity) for f in upstream if f.severity != "info"] == []
    counted = {f.rule: f for f in found if f.rule.endswith("-upstream")}
    assert "client-without-server-upstream" in counted
    info = counted["client-without-server-upstream"]
    assert info.severity == "info"
    assert info.message.startswith("2 finding(s) about installed packages' own launch")
    assert "github:ros-simulation/gazebo_ros_pkgs" in info.message
    assert "set_physics_properties" in info.message


def test_a_finding_that_involves_the_workspace_stays(write_tree):
    found = _findings(write_tree, mover=True)
    mismatch = [f for f in found if f.rule == "topic-type-mismatch"]
    assert len(mismatch) == 1 and mismatch[0].severity == "error"
    assert "/gazebo/set_model_state" in mismatch[0].message
    assert mismatch[0].location.file == "app/scripts/mover.py"
