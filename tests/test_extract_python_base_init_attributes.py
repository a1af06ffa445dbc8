"""An object built by a class whose ``__init__`` calls its base's (``super().__init__(...)``,
``super(Cls, self).__init__(...)``, ``Base.__init__(self, ...)``) has the attributes the
base's ``__init__`` gives it from the call's arguments, in their place among the
subclass's own assignments. svea's ``SVEAPurePursuit(..., vehicle_name='veh0')`` hands the
name to ``SVEAManager.__init__``, which builds the actuation interface with it: its topics
were ``?lli/remote``, now ``veh0/lli/remote``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = """\
import rospy
from std_msgs.msg import String


class Actuation(object):
    def __init__(self, vehicle_name=''):
        sub = vehicle_name + '/' if vehicle_name else ''
        self.topic = '{}lli/remote'.format(sub)

    def start(self):
        rospy.Subscriber(self.topic, String, self.cb)

    def cb(self, msg):
        pass


class Manager(object):
    def __init__(self, actuation=Actuation, vehicle_name=''):
        self.actuation = actuation(vehicle_name)
        self.label = 'base'

    def start(self):
        self.actuation.start()
        rospy.Publisher(self.label, String, queue_size=1)


class Explicit(Manager):
    def __init__(self, vehicle_name=''):
        Manager.__init__(self, vehicle_name=vehicle_name)


class Plain(Manager):
    def __init__(self, name):
        super().__init__(Actuation, name)
        self.label = name + '/label'


class Old(Manager):
    def __init__(self, name):
        self.label = 'before'
        super(Old, self).__init__(vehicle_name=name)


def main():
    rospy.init_node('car')
    Explicit(vehicle_name='veh0').start()
    Plain('veh1').start()
    Old('veh2').start()


main()
"""


def test_a_base_init_gives_attributes_from_its_arguments(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/car.py": NODE})
    result = extract_python([str(folder / "pkg" / "scripts" / "car.py")],
                            scan([str(folder)]), package="pkg")
    made = sorted((call.kind, call.name) for call in result.calls)
    assert made == [
        # Explicit's, and Old's (the base's assignment is the later; one call made
        # twice at one place, with one name, is one call)
        ("publish", "base"),
        ("publish", "veh1/label"),  # Plain's own assignment after the base's
        ("subscribe", "veh0/lli/remote"),
        ("subscribe", "veh1/lli/remote"),
        ("subscribe", "veh2/lli/remote"),
    ]
