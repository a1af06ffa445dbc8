"""A Python program that asks a class for its subclasses and builds what it gets
(kalman_robot's supervisor: ``[cls() for cls in all_inherited_classes(Module)]``, each
module opening its topics and reading its parameters in ``configure``) runs classes
chosen when it runs: ``PY_DYNAMIC_CLASSES`` at the call, and the node is partial, so the
parameters the launch file gives it are not "set but never read" for sure (the tool
said the supervisor was complete: 44 remap-unused and 15 parameter-set-not-read
warnings, false)."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import Workspace, scan

SUPERVISOR = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import String


class Module(object):
    def configure(self):
        pass


class Arm(Module):
    def configure(self):
        self.rate = rospy.get_param('~' + self.__class__.__name__.lower() + '_rate')


def all_inherited_classes(cls):
    return cls.__subclasses__() + [
        g for s in cls.__subclasses__() for g in all_inherited_classes(s)]


if __name__ == '__main__':
    rospy.init_node('supervisor')
    modules = [module_class() for module_class in all_inherited_classes(Module)]
    for module in modules:
        module.configure()
    rospy.spin()
"""
PLAIN = """#!/usr/bin/env python3
import rospy
rospy.init_node('plain')
rospy.spin()
"""


def test_a_program_that_builds_its_subclasses_is_said(tmp_path) -> None:
    source = tmp_path / "supervisor.py"
    source.write_text(SUPERVISOR)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    said = [(d.location.line, d.message) for d in result.diagnostics
            if d.code == "PY_DYNAMIC_CLASSES"]
    assert said == [(17, "cls.__subclasses__() lists classes at run time, which the "
                         "program may build; their code is not followed")]
    plain = tmp_path / "plain.py"
    plain.write_text(PLAIN)
    result = extract_python([str(plain)], Workspace(root=str(tmp_path)), package="p")
    assert [d for d in result.diagnostics if d.code == "PY_DYNAMIC_CLASSES"] == []


def test_the_node_is_partial_and_its_parameters_undecided(write_tree) -> None:
    root = write_tree({
        "src/sup/package.xml": package_xml("sup"),
        "src/sup/CMakeLists.txt": "project(sup)\n",
        "src/sup/scripts/supervisor.py": SUPERVISOR,
        "src/sup/launch/sup.launch": (
            '<launch>\n  <node name="supervisor" pkg="sup" type="supervisor.py">\n'
            '    <param name="arm_rate" value="5"/>\n  </node>\n</launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [sup/launch/sup.launch]\n",
    })
    os.chmod(root / "src/sup/scripts/supervisor.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (node,) = model.configuration("c").nodes
    assert node.completeness == "partial"
    rules = {f.rule for f in run_catalogue(model)}
    assert "parameter-set-not-read" not in rules


FACTORY = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import Float64
{imports}

class Generator(object):
    LABEL = ''

    def sample(self, t):
        raise NotImplementedError()

    @staticmethod
    def create(name):
        for gen in Generator.__subclasses__():
            if gen.LABEL == name:
                return gen()


class Line(Generator):
    LABEL = 'line'

    def sample(self, t):
        return 2.0 * t


class Spiral(Line):
    LABEL = 'spiral'

    def sample(self, t):
        return helper(t) * t


def helper(t):
    {helper}


if __name__ == '__main__':
    rospy.init_node('planner')
    generator = Generator.create(rospy.get_param('~generator', 'line'))
    pub = rospy.Publisher('setpoint', Float64, queue_size=1)
    rospy.spin()
"""


def factory_said(tmp_path, imports: str = "", helper: str = "return 1.0",
                 extra: dict[str, str] | None = None) -> list[str]:
    (tmp_path / "package.xml").write_text(package_xml("p"))
    source = tmp_path / "planner.py"
    source.write_text(FACTORY.format(imports=imports, helper=helper))
    for name, text in (extra or {}).items():
        (tmp_path / name).write_text(text)
    result = extract_python([str(source)], scan([str(tmp_path)], {}), package="p")
    return [d.message for d in result.diagnostics if d.code == "PY_DYNAMIC_CLASSES"]


def test_subclasses_of_a_named_class_that_make_no_ros_call_are_no_loss(tmp_path) -> None:
    """uuv_simulator's path generators: ``PathGenerator.__subclasses__()`` of a class the
    program reads, every subclass seen (a subclass of a subclass too) and none of them,
    nor what they call, making a ROS call: nothing of the graph is left unread."""
    assert factory_said(tmp_path) == []
    # a subclass in another module the program imports, read: plain too
    assert factory_said(tmp_path, imports="import shapes", extra={"shapes.py": (
        "import planner\n\nclass Circle(planner.Generator):\n    LABEL = 'circle'\n")}) == []
    # a module that imports by a name at run time (tf_quaternion's transformations.py,
    # ``__import__(module_name)`` of '_transformations'): the walk judges that import
    # itself (PY_DYNAMIC_IMPORT where the name is not known)
    assert factory_said(tmp_path, imports="import shapes", extra={"shapes.py": (
        "import planner\n\ndef load(name):\n    return __import__(name)\n\n"
        "class Circle(planner.Generator):\n    LABEL = 'circle'\n")}) == []


def test_a_subclass_that_may_make_a_ros_call_keeps_it_said(tmp_path) -> None:
    # what a subclass's method calls publishes (uuv_simulator's thrusters: their base's
    # __init__ makes a publisher)
    assert factory_said(tmp_path, helper="rospy.Publisher('x', Float64).publish(t)") == [
        "Generator.__subclasses__() lists classes at run time, which the program may "
        "build; their code is not followed"]
    # a subclass in another module of the program, of a base not read
    assert factory_said(tmp_path, imports="import shapes", extra={"shapes.py": (
        "import planner\nfrom somewhere import Mixin\n\n"
        "class Circle(planner.Generator, Mixin):\n    LABEL = 'circle'\n")}) != []
