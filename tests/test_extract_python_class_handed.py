"""A class of the workspace handed, as a value, to code that builds it out of the walk's
sight: nova's python_control2 (MonashNovaRover, Jazzy) has each node write
``PythonControl(node).with_hardware("arm", QCMDHardware)``; the builder keeps the class
in a DeferredConstructor, which runs ``self.cls.__init__(instance, ...)`` once the node
spins, and the hardware class declares ``hardware.<name>.can_id`` and its other
parameters. Nothing built it in the code walked, so the node was complete without those
reads: 184 parameters of its YAML files said set and never read, all false. The class
now counts as built, its methods walked as those of a class the program builds (the
name its builder gives it left ``?``); a class given to ``isinstance`` is not."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

LIBRARY = '''class Deferred:
    def __init__(self, cls):
        self.cls = cls
        self.name = None

    def build(self, node):
        made = object.__new__(self.cls)
        self.cls.__init__(made, node, self.name)
        return made


class Builder:
    @classmethod
    def make(cls, node):
        return cls(node)

    def __init__(self, node):
        self.node = node
        self.parts = []

    def with_part(self, name, part):
        deferred = Deferred(part)
        deferred.name = name
        self.parts.append(deferred)
        return self

    def spin(self):
        for part in self.parts:
            part.build(self.node)
'''

PARTS = '''class Motor:
    def __init__(self, node, name):
        self.node = node
        node.declare_parameter(f"hardware.{name}.can_id", 0)


class Checked:
    def __init__(self, node):
        node.declare_parameter("checked", 0)
'''

NODE = '''import rclpy
from rclpy.node import Node
from ctl import Builder
from ctl.parts import Checked, Motor


def main():
    rclpy.init()
    node = Node('scraper')
    if isinstance(node, Checked):
        return
    Builder.make(node).with_part('arm', Motor).spin()
'''


def run(folder: Path):
    ws = scan([str(folder)])
    return extract_python([str(folder / "pkg" / "scripts" / "scraper.py")], ws,
                          package="pkg")


def test_a_class_handed_to_a_builder_is_walked_as_built(write_tree) -> None:
    folder = write_tree({"ctl/package.xml": package_xml("ctl", "ament_python"),
                         "ctl/ctl/__init__.py": LIBRARY,
                         "ctl/ctl/parts.py": PARTS,
                         "pkg/package.xml": package_xml("pkg", "ament_python"),
                         "pkg/scripts/scraper.py": NODE})
    result = run(folder)
    assert [(c.kind, c.name) for c in result.calls] == [("declare", "hardware.?.can_id")]
