"""``del`` in a Python launch file as Python runs it. Only ``del os.environ[key]`` and
``del d[key]`` were read (surveyU, ab99f74a); ``del name``, ``del obj.attr`` and ``del
items[i]`` were said not interpreted (LAUNCH_PY_UNSUPPORTED) and left the value in place:
a list of nodes from which the file deletes one still started it. Now a name is unbound
in its scope (a read after it is Python's NameError, given to a ``try`` that catches
it), an attribute is removed from the object or class, an item or slice from a list (an
index out of range is IndexError, to a ``try`` as the dict's KeyError is)."""

from __future__ import annotations

from test_launch_ros2_python import run


def _names(model) -> list[str]:
    return [n.name for n in model.nodes]


def _unsupported(model) -> list[str]:
    return [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]


def test_del_of_list_items_names_and_attributes(write_tree):
    model, _ = run(write_tree, """
class Robot:
    kind = 'rover'

    def __init__(self):
        self.name = 'first'
        self.spare = 'spare'

def generate_launch_description():
    names = ['a', 'b', 'c', 'd', 'e']
    del names[1]
    del names[-1], names[0:1]
    robot = Robot()
    del robot.spare
    kind = 'none'
    extra = 'x'
    del extra
    try:
        names.append(extra)
    except NameError:
        names.append('unbound')
    try:
        del names[7]
    except IndexError:
        names.append('out_of_range')
    (first, second) = ('f', 's')
    del (first, second)
    try:
        del first
    except UnboundLocalError:
        names.append('local')
    return LaunchDescription([Node(package='p', executable='e', name=n + '_' + robot.name)
                              for n in names])
""")
    assert _unsupported(model) == [], _unsupported(model)
    assert _names(model) == ["/c_first", "/d_first", "/unbound_first", "/out_of_range_first",
                             "/local_first"], _names(model)


def test_del_of_a_global_and_of_a_class_attribute(write_tree):
    model, _ = run(write_tree, """
RATE = '10'

class Robot:
    def __init__(self):
        self.spare = 'spare'

class Config:
    topic = 'scan'

def forget():
    global RATE
    del RATE

def generate_launch_description():
    forget()
    del Config.topic
    try:
        rate = RATE
    except NameError:
        rate = 'unset'
    robot = Robot()
    del robot.spare
    return LaunchDescription([Node(package='p', executable='e', name=rate + '_' + Config.topic),
                              Node(package='p', executable='e', name=robot.spare)])
""")
    # read after del, the attributes are not known ('?'), not the values they had
    assert _names(model) == ["/unset_?", "/?"], (_names(model), _unsupported(model))
    assert _unsupported(model) == ["Config.topic is not set as read here",
                                   "Robot.spare is not set as read here"], _unsupported(model)


def test_what_python_raises_without_a_try_is_said(write_tree):
    model, _ = run(write_tree, """
def generate_launch_description():
    nodes = ['a']
    del nodes[3]
    del never_bound
    return LaunchDescription([Node(package='p', executable='e', name=n) for n in nodes])
""")
    said = _unsupported(model)
    assert any("del nodes[3] fails" in m and "out of range" in m for m in said), said
    assert any("del never_bound fails" in m and "UnboundLocalError" in m for m in said), said
