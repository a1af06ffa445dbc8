"""A Python program of the client library that makes no node in the code read, yet
builds a class of its own whose base is a class of a Python package the workspace does
not hold and its package.xml does not name (pepper_robot 60d4e08's camera.py:
``PepperCam('pepper_camera')``, a ``NaoqiCam`` of naoqi_sensors_py, whose module is
``naoqi_sensors``; dt-core's nodes, ``DTROS`` of duckietown): that base makes the node
and reads its parameters, unseen, so the node is partial (``PY_NODE_UNSEEN``) and the
launch file's parameters for it are not "set but never read". A program that makes its
node itself takes such a base for a library."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

MANIFEST = """<?xml version="1.0"?>
<package format="2">
  <name>p</name><version>0.0.1</version><description>d</description>
  <maintainer email="a@b.c">a</maintainer><license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
  <exec_depend>rospy</exec_depend>
  <exec_depend>naoqi_sensors_py</exec_depend>
</package>
"""

CAMERA = """
import rospy
from naoqi_sensors.naoqi_camera import NaoqiCam

class PepperCam(NaoqiCam):
    def __init__(self, node_name='pepper_camera'):
        NaoqiCam.__init__(self, node_name)

if __name__ == "__main__":
    camera = PepperCam('pepper_camera')
    camera.start()
    rospy.spin()
"""

OWN_NODE = """
import rospy
from torch.nn import Module

class Net(Module):
    def __init__(self):
        super().__init__()

rospy.init_node('detector')
net = Net()
pub = rospy.Publisher('detections', rospy.AnyMsg, queue_size=1)
rospy.spin()
"""


def _result(tmp_path, text: str):
    package = tmp_path / "src" / "p"
    (package / "scripts").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    (package / "CMakeLists.txt").write_text("project(p)\nfind_package(catkin REQUIRED)\n")
    source = package / "scripts" / "n.py"
    source.write_text(text)
    return extract_python([str(source)], scan([str(tmp_path / "src")]), package="p")


def test_a_base_of_an_unheld_package_that_makes_the_node_is_unseen_code(tmp_path):
    result = _result(tmp_path, CAMERA)
    (said,) = [d for d in result.diagnostics if d.code == "PY_NODE_UNSEEN"]
    assert "naoqi_sensors.naoqi_camera.NaoqiCam of naoqi_sensors" in said.message
    assert said.location.line == CAMERA.splitlines().index(
        "    camera = PepperCam('pepper_camera')") + 1


def test_a_program_that_makes_its_node_takes_such_a_base_for_a_library(tmp_path):
    result = _result(tmp_path, OWN_NODE)
    assert "PY_NODE_UNSEEN" not in [d.code for d in result.diagnostics]
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "detections")]
