"""A thread runs its function with the arguments it is given: ``threading.Thread(
target=self._spin)`` is walked as the call ``self._spin()`` where the thread is made, so
the method sees the attributes its object was given (svea's interfaces start their
subscribers in ``Thread(target=self._init_and_spin_ros, args=()).start()``, named by the
vehicle name their constructor took: walked only as an entry, the object's attributes
were unknown and every name ``?lli/remote``). The same for ``threading.Timer``,
``multiprocessing.Process`` and ``_thread.start_new_thread``, with their ``args`` and
``kwargs``; a function not known statically (a lambda) is not followed."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = """\
import threading
import multiprocessing
import _thread
from threading import Thread
import rospy
from std_msgs.msg import String


class Interface(object):
    def __init__(self, vehicle_name=''):
        sub = vehicle_name + '/' if vehicle_name else ''
        self._remote = '{}lli/remote'.format(sub)

    def start(self):
        Thread(target=self._spin, args=()).start()
        return self

    def _spin(self):
        self._listen()

    def _listen(self):
        rospy.Subscriber(self._remote, String, self.cb)

    def cb(self, msg):
        pass


def advertise(topic, size=1, latch=False):
    rospy.Publisher(topic, String, queue_size=size, latch=latch)


def later(prefix):
    rospy.Publisher(prefix + '/later', String, queue_size=1)


def main():
    rospy.init_node('car')
    Interface('veh0').start()
    Interface().start()
    threading.Thread(target=advertise, args=('status',), kwargs={'size': 5}).start()
    t = threading.Timer(1.0, later, ['timer'])
    t.start()
    multiprocessing.Process(None, advertise, None, ('process',)).start()
    _thread.start_new_thread(advertise, ('raw', 7))
    threading.Thread(target=lambda: None).start()


main()
"""


def test_a_thread_runs_its_target_with_its_arguments(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"),
                         "pkg/scripts/car.py": NODE})
    result = extract_python([str(folder / "pkg" / "scripts" / "car.py")],
                            scan([str(folder)]), package="pkg")
    made = sorted((call.kind, call.name, call.queue_size) for call in result.calls)
    assert made == [
        ("publish", "process", 1),
        ("publish", "raw", 7),
        ("publish", "status", 5),
        ("publish", "timer/later", 1),
        ("subscribe", "lli/remote", None),
        ("subscribe", "veh0/lli/remote", None),
    ]
