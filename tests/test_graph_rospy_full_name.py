"""rospy's ``get_name()`` is the node's fully qualified name (``/robot/gnode``): at the
start of a name, followed by ``/``, it is the private namespace (``~status``), and
anywhere else the graph puts the instance's name in its place (``"/" +
rospy.get_name() + "/x"``, ``"/debug" + rospy.get_name()``, ``rospy.get_name() +
"_status"``), which the launch file gives; those names were ``/?/x``, ``/debug?`` and
``?_status``. rospy makes names canonical (no ``//``). A text method of the name
(``split``) stays unknown."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

CODE = ("#!/usr/bin/env python\nimport rospy\nfrom std_msgs.msg import String\n"
        "rospy.init_node('gn')\n"
        "rospy.Publisher(rospy.get_name() + '/status', String, queue_size=1)\n"
        "rospy.Publisher('/' + rospy.get_name() + '/x', String, queue_size=1)\n"
        "rospy.Publisher('/debug' + rospy.get_name(), String, queue_size=1)\n"
        "rospy.Publisher(rospy.get_name() + '_status', String, queue_size=1)\n"
        "me = rospy.get_name()\n"
        "rospy.Subscriber('/relay%s/in' % me, String, print)\n"
        "rospy.Subscriber(rospy.get_name().split('/')[-1] + '/last', String, print)\n")


def test_rospy_get_name_inside_a_name_is_the_instance_name(write_tree) -> None:
    root = write_tree({
        "src/gn/package.xml": package_xml("gn"),
        "src/gn/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(gn)\n"
                                 "find_package(catkin REQUIRED COMPONENTS rospy)\n"
                                 "catkin_package()\n"
                                 "catkin_install_python(PROGRAMS scripts/gn.py "
                                 "DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        "src/gn/scripts/gn.py": CODE,
        "src/gn/launch/gn.launch": "<launch><group ns=\"robot\">"
                                   "<node pkg=\"gn\" type=\"gn.py\" name=\"gnode\"/>"
                                   "</group></launch>\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [gn/launch/gn.launch]\n",
    })
    os.chmod(root / "src/gn/scripts/gn.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    calls = [(c.name, c.name_full) for p in model.packages for n in p.nodes
             for c in n.calls]
    assert calls == [("~status", False), ("/?/x", True), ("/debug?", True),
                     ("?_status", True), ("/relay?/in", True), ("?/last", False)]
    links = sorted(link.resource.name for link in model.configurations[0].links)
    assert links == ["/debug/robot/gnode", "/relay/robot/gnode/in", "/robot/gnode/status",
                     "/robot/gnode/x", "/robot/gnode_status", "?/last"]
