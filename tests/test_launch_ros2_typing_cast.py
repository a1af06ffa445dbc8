"""``typing.cast(T, value)`` in a Python launch file: Python returns ``value``
unchanged (the type is for checkers only). rm_engineer's bringup launch files cast
``xacro.process_file(...)`` to a DOM document before ``toxml()``: that was a call not
interpreted, so the robot description became a value said unsupported rather than the
output of the xacro command it stands for."""

from __future__ import annotations

from test_launch_ros2_python import run


def test_typing_cast_gives_its_value(write_tree):
    for imported, called in (("from typing import cast, Optional", "cast"),
                             ("import typing", "typing.cast")):
        model, _ = run(write_tree, f"""
{imported}
import xacro
from xml.dom.minidom import Document

def load_xacro(path, mappings=None):
    doc = {called}(Document, xacro.process_file(path, mappings=mappings or {{}}))
    return doc.toxml()

def generate_launch_description():
    name = {called}(str, 'state_' + 'publisher')
    description = {{'robot_description': load_xacro('/robot.urdf.xacro')}}
    return LaunchDescription([Node(package='robot_state_publisher',
                                   executable='robot_state_publisher', name=name,
                                   parameters=[description])])
""")
        assert [n.name for n in model.nodes] == ["/state_publisher"], called
        assert not any(d.code in ("LAUNCH_PY_UNSUPPORTED", "LAUNCH_UNSUPPORTED")
                       for d in model.diagnostics), [d.message for d in model.diagnostics]
        unknown = [d.message for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
        assert any("xacro /robot.urdf.xacro" in m for m in unknown), unknown
