"""What a helper returns through an ``if`` / ``else``: the Python reader read only
straight-line helper bodies, so a helper that names a topic on two paths (dt-core's
DTROS ``get_namespace`` sets a local under an ``if`` before it returns) gave ``?``. The
paths are now read as the reader's own ``if`` reads them: an ``if`` the evaluator
decides takes its path; one it cannot decide gives each path's value under its
condition (``Alternatives``: one call per value, as for a local an ``if`` sets), a
value when the paths agree, and ``?`` where a path does what is not followed."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

SOURCE = """import rospy
from std_msgs.msg import String

def topic_of(kind):
    if kind == 'front':
        return 'camera/front'
    return 'camera/rear'

def chosen():
    if rospy.get_param('~rear', False):
        return 'rear/image'
    else:
        return 'front/image'

def prefixed(name, level):
    prefix = '/robot'
    if level > 1:
        prefix = '/robot/arm'
    return prefix + '/' + name

def agreeing():
    if rospy.get_param('~a', 0):
        return 'status'
    return 'status'

def looping(names):
    for name in names:
        if name:
            return name
    return 'none'

def main():
    rospy.init_node('n')
    rospy.Publisher(topic_of('front'), String, queue_size=1)
    image = chosen()
    rospy.Subscriber(image, String, print)
    rospy.Publisher(prefixed('state', 2), String, queue_size=1)
    rospy.Publisher(agreeing(), String, queue_size=1)
    rospy.Publisher(looping(['x']), String, queue_size=1)
    rospy.Subscriber('/robot/' + chosen(), String, print)
"""


def _calls(tmp_path):
    source = tmp_path / "n.py"
    source.write_text(SOURCE)
    found = extract_python([str(source)], scan([str(tmp_path)]))
    return [(c.kind, c.name, tuple(f"{x.statement} {x.text}" for x in c.conditions))
            for c in found.calls if c.kind in ("publish", "subscribe")]


def test_a_helper_returns_through_its_paths(tmp_path) -> None:
    assert _calls(tmp_path) == [
        ("publish", "camera/front", ()),  # a test the evaluator decides
        ("subscribe", "rear/image", ("if rospy.get_param('~rear', False)",)),
        ("subscribe", "front/image", ("else rospy.get_param('~rear', False)",)),
        ("publish", "/robot/arm/state", ()),
        ("publish", "status", ()),  # both paths give it
        ("publish", "?", ()),  # a loop is not followed
        # the helper called in the argument itself: one call per value too
        ("subscribe", "/robot/rear/image", ("if rospy.get_param('~rear', False)",)),
        ("subscribe", "/robot/front/image", ("else rospy.get_param('~rear', False)",)),
    ]
