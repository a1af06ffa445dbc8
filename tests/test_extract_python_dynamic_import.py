"""A Python program that imports a module by a name it computes at run time runs code
the tool does not read (FlexBE's onboard engine imports each behavior it is sent,
``__import__("tmp_%d" % msg.behavior_checksum)``, and runs its state machine, which reads
the engine's ``~log_enabled``): ``PY_DYNAMIC_IMPORT`` at the call, and the node is
partial, so its launch parameters are not "set but never read" for sure. A module of
messages, a name known here, a package asked only where it is
(``__import__(pkg).__path__``, FlexBE's behavior library), or the module of a class
(``t.__module__``, carla's ros_compatibility) is no such import."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import Workspace

ENGINE = """#!/usr/bin/env python3
import importlib
import rospy
from std_msgs.msg import String


class Engine(object):
    def __init__(self):
        self._sub = rospy.Subscriber('start', String, self._start)
        self.be = None

    def _start(self, msg):
        package = __import__("tmp_%s" % msg.data, fromlist=["tmp"])
        self.be = package.Behavior()
        self.be.run()


def plugin(name):
    return importlib.import_module(name)


def interface_of(type_name, interface_type):
    package, interface, name = type_name.split('/')
    module = importlib.import_module(package + '.' + interface_type)
    return getattr(module, name)


def ask_of(type_name, kind):
    return importlib.import_module(type_name.split('/')[0] + '.' + kind)


def request_of(service_type):
    module = ".".join(service_type.__module__.split(".")[:-1])
    made = __import__(module, fromlist=[service_type.__name__ + "Request"])
    return getattr(made, service_type.__name__ + "Request")()


if __name__ == '__main__':
    rospy.init_node('engine')
    Engine()
    plugin(rospy.get_param('~plugin', 'x'))
    types = importlib.import_module(rospy.get_param('~pkg', 'y') + '.msg')
    known = __import__('os')
    where = __import__(rospy.get_param('~behaviors', 'z')).__path__[-1]
    request = request_of(String)
    topic_type = interface_of(rospy.get_param('~topic_type', 'a/msg/B'), 'msg')
    service_type = interface_of(rospy.get_param('~service_type', 'a/srv/B'), 'srv')
    anything = ask_of(rospy.get_param('~what', 'a/b'), rospy.get_param('~kind', 'msg'))
    rospy.spin()
"""


def test_an_import_by_computed_name_is_said(tmp_path) -> None:
    source = tmp_path / "engine.py"
    source.write_text(ENGINE)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    said = sorted((d.location.line, d.message) for d in result.diagnostics
                  if d.code == "PY_DYNAMIC_IMPORT")
    assert said == [
        (13, "__import__ imports a module whose name is computed at run time (tmp_?); "
             "its code is not read"),
        (19, "importlib.import_module imports a module whose name is computed at run "
             "time (?); its code is not read"),
        # (joy_teleop's get_interface_type: every call gives 'msg', 'srv' or 'action'; not
        # ask_of, which is given a parameter's value)
        (29, "importlib.import_module imports a module whose name is computed at run "
             "time (?.?); its code is not read")]


def test_the_importing_node_is_partial(write_tree) -> None:
    root = write_tree({
        "src/engine/package.xml": package_xml("engine"),
        "src/engine/CMakeLists.txt": "project(engine)\n",
        "src/engine/scripts/engine.py": ENGINE,
        "src/engine/launch/engine.launch": (
            '<launch>\n  <node name="engine" pkg="engine" type="engine.py">\n'
            '    <param name="log_enabled" value="true"/>\n  </node>\n</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [engine/launch/engine.launch]\n",
    })
    os.chmod(root / "src/engine/scripts/engine.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (node,) = model.configuration("c").nodes
    assert node.completeness == "partial"
    rules = {f.rule for f in run_catalogue(model)}
    assert "parameter-set-not-read" not in rules
    assert "parameter-set-not-read-undecided" in rules
