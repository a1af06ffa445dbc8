"""A catkin program written to be read by both the shell and Python (FlexBE's
``bin/start_behavior``: ``#!/bin/bash``, then the shell's lines inside a Python string
that ends with ``python "${BASH_SOURCE[0]}" $*``): the shell runs the file again under
Python, so it is a Python node whose calls are read, not a program of unknown interface
(``NODE_NOT_READ``). A shell script that runs another file under Python stays a script
of its own."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.cmake.nodes import is_python
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

POLYGLOT = """#!/bin/bash
if "true" : '''\\'
then
python${ROS_PYTHON_VERSION:-} "${BASH_SOURCE[0]}" $*
exit
fi
'''
import rospy
from std_msgs.msg import String

if __name__ == '__main__':
    rospy.init_node('talker')
    pub = rospy.Publisher('chatter', String, queue_size=10)
    rospy.spin()
"""

SHELL = """#!/bin/sh
# starts the real program
exec python3 "$(dirname "$0")/../scripts/other.py" "$@"
"""


def test_a_shell_script_run_again_under_python_is_python(tmp_path) -> None:
    texts = {
        "polyglot": POLYGLOT,
        "rerun_sh": '#!/bin/sh\n""":"\nexec python3 "$0" "$@"\n"""\nimport rospy\n',
        "env_bash": '#!/usr/bin/env bash\n""":"\nexec /usr/bin/env python3 $0 "$@"\n"""\n',
        "shell": SHELL,
        "plain": "#!/bin/bash\necho python $0\n",
    }
    found = {}
    for name, text in texts.items():
        (tmp_path / name).write_text(text)
        found[name] = is_python(str(tmp_path / name))
    assert found == {"polyglot": True, "rerun_sh": True, "env_bash": True,
                     "shell": False, "plain": False}


def test_a_polyglot_program_is_a_python_node(write_tree) -> None:
    root = write_tree({
        "src/talk/package.xml": package_xml("talk"),
        "src/talk/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.0.2)\nproject(talk)\n"
            "find_package(catkin REQUIRED)\ncatkin_package()\n"
            "install(PROGRAMS bin/talker\n"
            "        DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n"),
        "src/talk/bin/talker": POLYGLOT,
        "src/talk/launch/talk.launch": (
            '<launch>\n  <node name="talker" pkg="talk" type="talker"/>\n</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [talk/launch/talk.launch]\n",
    })
    os.chmod(root / "src/talk/bin/talker", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    assert not [d for d in model.diagnostics if d.code == "NODE_NOT_READ"]
    (node,) = model.configuration("c").nodes
    assert node.completeness == "complete"
    assert [(link.KIND, link.rosname.full) for link in node.links] == [
        ("publish", "/chatter")]
