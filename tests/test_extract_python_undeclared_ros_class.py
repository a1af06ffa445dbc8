"""A Python node may build a class of a ROS package its package does not declare
(tiago_tutorials' tts_to_soundplay.py builds sound_play's ``SoundClient()``, which
publishes ``robotsound``; tts' package.xml lists roscpp and rospy only). When the tool
knows the package by a shipped interface model, its class is unseen code as a declared
dependency's is (``PY_CLASS_UNSEEN``), so the node is partial: before, it was complete
with no publisher, and sound_play_node's ``robotsound`` subscription was a false
subscriber-without-publisher warning. A name the tool does not know as a ROS package
(a pip library's class) is no PY_CLASS_UNSEEN (in a ROS 1 node it is PY_MODULE_UNSEEN,
test_extract_python_unread_module_ros1.py)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = """#!/usr/bin/env python
import rospy
import numpy
from sound_play.libsoundplay import SoundClient
from somelib.things import Helper

rospy.init_node('tts_to_soundplay')
client = SoundClient()
helper = Helper()
rospy.spin()
"""


def test_a_class_of_a_known_ros_package_not_declared_is_unseen(write_tree) -> None:
    root = write_tree({
        "src/tts/package.xml": package_xml("tts"),
        "src/tts/scripts/say.py": NODE})
    result = extract_python([str(root / "src/tts/scripts/say.py")],
                            scan([str(root / "src")]), package="tts")
    said = [(d.code, d.location.line, d.message) for d in result.diagnostics
            if d.code == "PY_CLASS_UNSEEN"]
    assert said == [("PY_CLASS_UNSEEN", 8, "sound_play.libsoundplay.SoundClient of ROS "
                     "package sound_play is built here and its code is not read")]
