"""GUI toolkits a ROS 1 node imports by a module name that no rosdep key gives:
squirrel_robotino's robotino_hardware_test/src/dialog_client/dialog.py:7 imports ``wx``
(wxPython, rosdep's ``python-wxtools``) and builds ``wx.App()`` and
``wx.MessageDialog(...)`` in its service callbacks. pip_libraries.yaml lists keys'
names (``wxtools``, ``pyqt5``), so ``wx`` was taken for a ROS package whose code is not
read (PY_MODULE_UNSEEN, the node partial), as was Qt's ``PyQt5``."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = """#!/usr/bin/env python
import rospy
{imports}
from std_srvs.srv import Trigger, TriggerResponse


def confirm(req):
    {call}
    return TriggerResponse(True, 'ok')


rospy.init_node('dialog')
rospy.Service('confirm', Trigger, confirm)
rospy.spin()
"""


def _said(write_tree, imports: str, call: str) -> tuple[list[str], list[tuple[str, str]]]:
    root = write_tree({
        "src/dialog/package.xml": package_xml("dialog"),
        "src/dialog/CMakeLists.txt": "project(dialog)\n",
        "src/dialog/scripts/dialog.py": NODE.format(imports=imports, call=call),
    })
    source = root / "src/dialog/scripts/dialog.py"
    result = extract_python([str(source)], scan([str(root / "src")]), package="dialog")
    return ([d.message for d in result.diagnostics if d.code == "PY_MODULE_UNSEEN"],
            sorted((c.kind, c.name) for c in result.calls))


@pytest.mark.parametrize(("imports", "call"), [
    ("import wx", "app = wx.App(); wx.MessageDialog(None, 'sure?', 'Confirm', wx.OK)"),
    ("from PyQt5.QtWidgets import QApplication, QMessageBox",
     "QMessageBox.question(None, 'Confirm', 'sure?')"),
])
def test_a_gui_toolkit_makes_no_ros_call(write_tree, imports: str, call: str) -> None:
    unseen, calls = _said(write_tree, imports, call)
    assert unseen == []
    assert ("server", "confirm") in calls


def test_a_ros_package_of_another_name_is_still_unseen(write_tree) -> None:
    # the guard: a module no list knows may be ROS code
    unseen, _ = _said(write_tree, "import wxtools_helper", "wxtools_helper.ask('sure?')")
    assert len(unseen) == 1
