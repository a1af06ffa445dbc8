"""A parameter a launch file sets only through content not known statically (a
``<rosparam>`` whose text is no YAML, or a file not named statically, modelled as
``<name>/?``) has no type the launch gives: it may be a dictionary, a scalar or
nothing. mas_industrial_robotics' atwork_commander_client.launch loads ``$(arg robot)``,
``$(optenv ROBOT !!NO_ROBOT_SET!!)``, into ``robot_name``: unset, the text is a YAML tag
no constructor takes (LAUNCH_YAML), and parameter-type-mismatch said "robot_name is set
as dict (None)" where the node reads a string (survey surveyB). Known keys under the
name still make it a dictionary."""

from __future__ import annotations

import textwrap

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """
    #!/usr/bin/env python
    import rospy
    rospy.init_node('client')
    name = rospy.get_param('~robot_name', 'bot')
    gains = rospy.get_param('~gains', 'none')
    rospy.loginfo(name + gains)
    """
LAUNCH = """
    <launch>
      <arg name="robot" default="$(optenv SURVEYB_NEVER_SET !!NO_ROBOT_SET!!)"/>
      <node pkg="client" type="client.py" name="client">
        <rosparam param="robot_name" subst_value="True">$(arg robot)</rosparam>
        <rosparam param="gains">{p: 1.0}</rosparam>
      </node>
    </launch>
    """


def test_a_name_set_only_through_unknown_content_has_no_launch_type(write_tree):
    root = write_tree({
        "src/client/package.xml": package_xml("client").replace(
            "</package>", "<depend>rospy</depend></package>"),
        "src/client/CMakeLists.txt": ("project(client)\nfind_package(catkin REQUIRED)\n"
                                      "catkin_package()\n"
                                      "catkin_install_python(PROGRAMS scripts/client.py\n"
                                      "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n"),
        "src/client/scripts/client.py": textwrap.dedent(NODE).lstrip(),
        "src/client/launch/client.launch": textwrap.dedent(LAUNCH),
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [client/launch/client.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    config = model.configurations[0]
    types = {p.name: p.launch_type for p in config.parameters}
    assert types["/client/robot_name"] is None
    assert types["/client/gains"] == "dict"
    assert "LAUNCH_YAML" in {d.code for d in config.diagnostics}
    mismatched = sorted(f.entities[0] for f in run_catalogue(model)
                        if f.rule == "parameter-type-mismatch")
    assert mismatched == ["parameter:/client/gains"]
