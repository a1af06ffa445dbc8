"""A for loop over a known, short sequence is unrolled: one call per item, made for sure
(no condition) unless the body can leave the loop early (``break``, ``return``, ``raise``:
then each with the loop's condition); longer or unknown sequences keep '?'. A list
changed in place before the loop (``append``, ``extend``, ``insert``, an item set) is
the list it then is, or unknown."""

from __future__ import annotations

from haros_arch.extract.python import PythonResult, extract_python
from haros_arch.workspace import Workspace

HEAD = ("import rclpy\nfrom rclpy.node import Node\nfrom sensor_msgs.msg import Image\n"
        "class Cam(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('cam')\n")


def run(tmp_path, body: str) -> PythonResult:
    source = tmp_path / "node.py"
    source.write_text(HEAD + body)
    return extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")


def names(result: PythonResult) -> list[tuple[str, tuple[str, ...]]]:
    return [(c.name, tuple(x.text for x in c.conditions)) for c in result.calls]


def test_list_of_strings(tmp_path) -> None:
    result = run(tmp_path,
                 "        for side in ['left', 'right']:\n"
                 "            self.create_publisher(Image, f'{side}/image', 10)\n")
    assert names(result) == [("left/image", ()), ("right/image", ())]
    assert [d.code for d in result.diagnostics] == []
    assert {c.location.line for c in result.calls} == {8}


def test_range_with_literal_bounds(tmp_path) -> None:
    result = run(tmp_path,
                 "        for i in range(1, 4):\n"
                 "            self.create_publisher(Image, 'camera%d/image' % i, 10)\n")
    assert [n for n, _ in names(result)] == ["camera1/image", "camera2/image",
                                             "camera3/image"]


def test_sequence_from_an_attribute_and_tuple_targets(tmp_path) -> None:
    result = run(tmp_path,
                 "        self.sides = ('front', 'back')\n"
                 "        for i, side in enumerate(self.sides):\n"
                 "            self.create_subscription(Image, f'{side}/image_{i}', None, 1)\n"
                 "        for name, depth in [('a', 1), ('b', 5)]:\n"
                 "            self.create_publisher(Image, name, depth)\n")
    got = [(c.kind, c.name, c.queue_size) for c in result.calls]
    assert got == [("subscribe", "front/image_0", 1), ("subscribe", "back/image_1", 1),
                   ("publish", "a", 1), ("publish", "b", 5)]


def test_nested_loops(tmp_path) -> None:
    result = run(tmp_path,
                 "        for robot in ['r1', 'r2']:\n"
                 "            for side in ['left', 'right']:\n"
                 "                self.create_publisher(Image, f'{robot}/{side}', 10)\n")
    assert [n for n, _ in names(result)] == ["r1/left", "r1/right", "r2/left", "r2/right"]
    assert all(c == () for _, c in names(result))


def test_a_body_that_can_leave_early_keeps_the_loop_condition(tmp_path) -> None:
    result = run(tmp_path,
                 "        for side in ['a', 'b']:\n"
                 "            if side == self.stop:\n"
                 "                break\n"
                 "            self.create_publisher(Image, side + '/x', 10)\n"
                 "        for side in ['c']:\n"
                 "            for inner in range(2):\n"
                 "                break\n"
                 "            self.create_publisher(Image, side + '/y', 10)\n"
                 "        for side in ['d']:\n"
                 "            for inner in range(2):\n"
                 "                return\n"
                 "            self.create_publisher(Image, side + '/z', 10)\n")
    assert names(result) == [
        # (after ``if side == self.stop: break``: under its else)
        ("a/x", ("side in ['a', 'b']", "side == self.stop")),
        ("b/x", ("side in ['a', 'b']", "side == self.stop")),
        ("c/y", ()),  # the inner loop's break is its own
        ("d/z", ("side in ['d']",))]  # a return leaves every loop


def test_a_list_changed_in_place_is_what_it_became(tmp_path) -> None:
    """``self.sides.append('right')`` before the loop: the loop runs over both (the
    second was missed, a definite publisher left out); a list whose item is set, or
    changed by a method we do not follow, is unknown: one call named '?'."""
    result = run(tmp_path,
                 "        self.sides = ['left']\n"
                 "        self.sides.append('right')\n"
                 "        more = ['x']\n"
                 "        more.extend(['y'])\n"
                 "        more.insert(0, 'w')\n"
                 "        for side in self.sides:\n"
                 "            self.create_publisher(Image, side + '/image', 10)\n"
                 "        for m in more:\n"
                 "            self.create_publisher(Image, m, 10)\n"
                 "        names = ['p', 'q']\n"
                 "        names[0] = 'z'\n"
                 "        for n in names:\n"
                 "            self.create_publisher(Image, n + '/n', 10)\n"
                 "        kept = ['k']\n"
                 "        kept.sort()\n"
                 "        for k in kept:\n"
                 "            self.create_publisher(Image, k + '/k', 10)\n")
    assert [n for n, _ in names(result)] == [
        "left/image", "right/image", "w", "x", "y", "?/n", "?/k"]


def test_long_or_unknown_sequences_keep_unknown(tmp_path) -> None:
    result = run(tmp_path,
                 "        for i in range(257):\n"
                 "            self.create_publisher(Image, f'big{i}', 10)\n"
                 "        for t in self.get_topics():\n"
                 "            self.create_publisher(Image, t + '/out', 10)\n"
                 "        for i in range(n):\n"
                 "            self.create_publisher(Image, f'n{i}', 10)\n"
                 "        for i in range(0, 4, 0):\n"
                 "            self.create_publisher(Image, f'z{i}', 10)\n")
    assert [n for n, _ in names(result)] == ["big?", "?/out", "n?", "z?"]
    assert [d.code for d in result.diagnostics] == ["PY_DYNAMIC_NAME"] * 4


def test_a_range_defined_in_the_module_is_that_function(tmp_path) -> None:
    result = run(tmp_path,
                 "        for i in range(2):\n"
                 "            self.create_publisher(Image, f'x{i}', 10)\n"
                 "def range(n):\n"
                 "    return ['a']\n")
    assert [n for n, _ in names(result)] == ["xa"]  # what the helper returns


def test_loop_variable_is_unknown_after_the_loop(tmp_path) -> None:
    result = run(tmp_path,
                 "        for side in ['left', 'right']:\n"
                 "            pass\n"
                 "        self.create_publisher(Image, side, 10)\n")
    assert [n for n, _ in names(result)] == ["?"]


def test_a_long_sequence_is_unrolled_in_no_other_unrolled_loop(tmp_path) -> None:
    """mir_driver's mir_bridge.py (noetic): ``for pub_topic in PUB_TOPICS:
    PublisherWrapper(pub_topic, ...)`` over 65 ``TopicConfig`` entries, each making a
    publisher; past ``MAX_UNROLL`` (32) it was one publisher named '?'. A loop inside no
    other unrolled loop costs its items only: unrolled up to ``MAX_UNROLL_OUTER``; in
    an unrolled loop a long one is walked once, as before."""
    result = run(tmp_path,
                 "        topics = [f'topic{i}' for i in range(40)]\n"
                 "        for t in topics:\n"
                 "            self.create_publisher(Image, t, 10)\n"
                 "        for robot in ['r1', 'r2']:\n"
                 "            for i in range(40):\n"
                 "                self.create_publisher(Image, f'{robot}/n{i}', 10)\n")
    got = [n for n, _ in names(result)]
    assert got == [f"topic{i}" for i in range(40)] + ["r1/n?", "r2/n?"]


def test_a_loop_over_a_list_parameter_names_one_call_per_element(tmp_path) -> None:
    """open_manipulator's joint_trajectory_executor.py:70-74: ``for step_name in
    self.step_names: self.declare_parameter(step_name, ...)``, ``self.step_names`` the
    value of the parameter ``step_names``: each call is named by each element of that
    list (``name_each``), which the graph expands from the configuration's value; the
    loop is a "for each". The value is read as the executor does, through the
    ParameterValue message's ``string_array_value``."""
    result = run(tmp_path,
                 "        self.declare_parameter('step_names', ['home'])\n"
                 "        self.steps = (self.get_parameter('step_names')\n"
                 "                      .get_parameter_value().string_array_value)\n"
                 "        for step in self.steps:\n"
                 "            self.declare_parameter(step, [0.0])\n"
                 "            self.get_parameter(step)\n"
                 "        for topic in self.get_parameter('topics').value:\n"
                 "            self.create_subscription(Image, topic, print, 10)\n"
                 "            self.create_publisher(Image, 'fixed', 10)\n")
    made = [(c.kind, c.name, c.name_param, c.name_each, tuple(str(x) for x in c.conditions))
            for c in result.calls if c.name != "step_names"]
    steps = ("for each (step in self.steps)",)
    topics = ("for each (topic in self.get_parameter('topics').value)",)
    assert made == [("declare", "?", "step_names", ".", steps),
                    ("read", "?", "step_names", ".", steps),
                    ("read", "topics", None, None, ()),
                    ("subscribe", "?", "topics", ".", topics),
                    ("publish", "fixed", None, None, topics)]


def test_an_element_of_a_list_parameter_with_text_around_it(tmp_path, write_tree) -> None:
    """``for robot in self.get_parameter('robots').value:
    self.create_publisher(Twist, f'/{robot}/cmd_vel', 10)`` (a fleet's command topics):
    the element with text around it names one call per element as the element alone
    does; the graph puts each element the configuration gives in the place of the
    ``?`` (`/?/cmd_vel` was left unknown)."""
    import os

    from conftest import package_xml

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    code = ("import rclpy\nfrom rclpy.node import Node\n"
            "from geometry_msgs.msg import Twist\n"
            "class Fleet(Node):\n"
            "    def __init__(self):\n"
            "        super().__init__('fleet')\n"
            "        self.declare_parameter('robots', ['a'])\n"
            "        for robot in self.get_parameter('robots').value:\n"
            "            self.create_publisher(Twist, f'/{robot}/cmd_vel', 10)\n"
            "            self.create_publisher(Twist, robot + '/odom_cmd', 10)\n"
            "            self.create_publisher(Twist, f'{robot}/{robot}', 10)\n"
            "        self.declare_parameter('spares', ['s1'])\n"
            "        for spare in self.get_parameter('spares').value:\n"
            "            self.create_publisher(Twist, f'/{spare}/cmd_vel', 10)\n"
            "def main():\n    rclpy.init()\n    Fleet()\n")
    launch = ("from launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    return LaunchDescription([Node(package='fleet', executable='fleet',\n"
              "        parameters=[{'robots': ['r1', 'r2']}])])\n")
    root = write_tree({
        "src/fleet/package.xml": package_xml("fleet", build_type="ament_python"),
        "src/fleet/setup.py": "from setuptools import setup\n"
                              "setup(name='fleet', packages=['fleet'], entry_points="
                              "{'console_scripts': ['fleet = fleet.fleet:main']})\n",
        "src/fleet/resource/fleet": "",
        "src/fleet/fleet/__init__.py": "",
        "src/fleet/fleet/fleet.py": code,
        "src/fleet/launch/fleet.launch.py": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [fleet/launch/fleet.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    calls = [c for p in model.packages for n in p.nodes for c in n.calls
             if c.kind == "publish"]
    assert [(c.name, c.name_param, c.name_each) for c in calls] == [
        ("/?/cmd_vel", "robots", "."), ("?/odom_cmd", "robots", "."),
        ("?/?", None, None), ("/?/cmd_vel", "spares", ".")]
    topics = sorted(t.name for t in model.configurations[0].topics)
    assert "/r1/cmd_vel" in topics and "/r2/cmd_vel" in topics
    assert "/r1/odom_cmd" in topics and "/r2/odom_cmd" in topics
    assert not any("cmd" in t and "?" in t for t in topics)
    # a list the configuration does not set: the elements of its default in code
    assert "/s1/cmd_vel" in topics


def test_comprehensions_are_walked_as_their_loops(tmp_path) -> None:
    """``[rospy.Publisher(t + '/cmd', ...) for t in topics]`` and a dict comprehension
    over a list parameter make one call per element as a ``for`` statement does (they
    were ``?/cmd``, the comprehension's variable unknown); a comprehension over a known
    tuple is unrolled (each item for sure: no loop condition), its ``if`` a condition;
    its variable does not leak."""
    result = run(tmp_path,
                 "        topics = self.get_parameter('topics').value\n"
                 "        self.pubs = [self.create_publisher(Image, t + '/raw', 10)\n"
                 "                     for t in topics]\n"
                 "        self.named = {t: self.create_publisher(Image, f'{t}/rect', 10)\n"
                 "                      for t in self.get_parameter('cams').value}\n"
                 "        t = 'fixed'\n"
                 "        subs = list(self.create_subscription(Image, side, print, 10)\n"
                 "                    for side in ('left', 'right') if side != t)\n"
                 "        self.create_publisher(Image, t, 10)\n")
    made = [(c.kind, c.name, c.name_param, c.name_each, tuple(x.text for x in c.conditions))
            for c in result.calls if c.kind in ("publish", "subscribe")]
    assert made == [
        ("publish", "?/raw", "topics", ".", ("t in topics",)),
        ("publish", "?/rect", "cams", ".", ("t in self.get_parameter('cams').value",)),
        ("subscribe", "left", None, None,
         ("side != t",)),
        ("subscribe", "right", None, None,
         ("side != t",)),
        ("publish", "fixed", None, None, ())]


def test_a_field_of_each_element_of_a_list_or_dict_parameter(write_tree) -> None:
    """A multiplexer's inputs: ``for src in rospy.get_param('~sources'):
    rospy.Subscriber(src['topic'], ...)`` over a list of dictionaries, and ``for name,
    cfg in rospy.get_param('~inputs').items(): ... cfg['topic']`` over a dictionary of
    them, as twist_mux's C++ does: one subscription per entry, named by its ``topic``
    (both were ``/?``). A dictionary a ``rosparam`` sets is its leaves until a node reads
    it whole: the entries are read from them."""
    import os

    from conftest import package_xml

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    code = ("#!/usr/bin/env python\nimport rospy\nfrom std_msgs.msg import String\n"
            "rospy.init_node('mux')\n"
            "for src in rospy.get_param('~sources'):\n"
            "    rospy.Subscriber(src['topic'], String, print, queue_size=1)\n"
            "for name, cfg in rospy.get_param('~inputs', {}).items():\n"
            "    rospy.Subscriber(cfg['topic'] + '_in', String, print, queue_size=1)\n"
            "for cfg in rospy.get_param('~outputs').values():\n"
            "    rospy.Publisher(cfg['topic'], String, queue_size=1)\n")
    launch = ("<launch><node pkg=\"mux\" type=\"mux.py\" name=\"mux\">\n"
              "<rosparam param=\"sources\">[{topic: joy, priority: 1}, {topic: nav}]"
              "</rosparam>\n"
              "<rosparam param=\"inputs\">{a: {topic: left}, b: {topic: right}}</rosparam>\n"
              "<rosparam param=\"outputs\">{o: {topic: merged}}</rosparam>\n"
              "</node></launch>\n")
    root = write_tree({
        "src/mux/package.xml": package_xml("mux"),
        "src/mux/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject(mux)\n"
                                  "find_package(catkin REQUIRED COMPONENTS rospy)\n"
                                  "catkin_package()\n"
                                  "catkin_install_python(PROGRAMS scripts/mux.py "
                                  "DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        "src/mux/scripts/mux.py": code,
        "src/mux/launch/mux.launch": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [mux/launch/mux.launch]\n",
    })
    os.chmod(root / "src/mux/scripts/mux.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    calls = [(c.kind, c.name, c.name_param, c.name_each) for p in model.packages
             for n in p.nodes for c in n.calls if c.kind in ("publish", "subscribe")]
    assert calls == [("subscribe", "?", "~sources", "topic"),
                     ("subscribe", "?_in", "~inputs", "topic"),
                     ("publish", "?", "~outputs", "topic")]
    topics = sorted(t.name for t in model.configurations[0].topics)
    assert topics == ["/joy", "/left_in", "/merged", "/nav", "/right_in"]


def test_an_entry_of_a_ros1_dictionary_parameter_names_a_call(tmp_path) -> None:
    """``cam = rospy.get_param('~camera'); rospy.Subscriber(cam['topic'], ...)``: the
    name is the parameter ``~camera/topic`` (rospy gives the dictionary of what is
    under ``~camera``), ``cam.get('out', 'cam_out')`` the same with a default; both
    were ``?`` with nothing for the graph to fill in."""
    source = tmp_path / "node.py"
    source.write_text("import rospy\nfrom std_msgs.msg import String\n"
                      "rospy.init_node('n')\n"
                      "cam = rospy.get_param('~camera')\n"
                      "rospy.Subscriber(cam['topic'], String, print, queue_size=1)\n"
                      "rospy.Publisher(cam.get('out', 'cam_out'), String, queue_size=1)\n"
                      "rospy.Publisher(cam[key], String, queue_size=1)\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    made = [(c.kind, c.name, c.name_param, c.name_default) for c in result.calls
            if c.kind != "read"]
    assert made == [("subscribe", "?", "~camera/topic", None),
                    ("publish", "?", "~camera/out", "cam_out"),
                    ("publish", "?", None, None)]


def test_product_and_zip_of_lists(tmp_path) -> None:
    """ds4_driver's twist node declares inputs.linear.x ... scales.angular.z over
    ``itertools.product`` of three local lists (12 names, all '?.?.?' before); ``zip``
    pairs lists item by item."""
    source = tmp_path / "node.py"
    source.write_text(
        "import itertools\nfrom itertools import product\n" + HEAD
        + "        kinds = ['inputs', 'scales']\n"
          "        for t, a in itertools.product(kinds, ('x', 'y')):\n"
          "            self.declare_parameter('{}.{}'.format(t, a), '')\n"
          "        for t in product(['p'], ['q', 'r']):\n"
          "            self.declare_parameter('.'.join(t), '')\n"
          "        for topic, depth in zip(['u', 'v', 'w'], [1, 2]):\n"
          "            self.create_publisher(Image, topic, depth)\n")
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    assert names(result) == [(n, ()) for n in (
        "inputs.x", "inputs.y", "scales.x", "scales.y", "p.q", "p.r")] + [
        ("u", ()), ("v", ())]
    assert [c.queue_size for c in result.calls if c.kind == "publish"] == [1, 2]
    assert [d.code for d in result.diagnostics] == []


def test_dict_literal_keys_values_and_items(tmp_path) -> None:
    """A loop over a dict literal takes its keys (the dict, ``keys()``), its values or
    its ``(key, value)`` pairs (``items()``, Python 2's ``iteritems()``), also when the
    dict is passed to a helper: axis_camera's ``read_args_with_defaults`` looks each key
    of its defaults up with ``rospy.search_param`` (all were '?')."""
    result = run(tmp_path,
                 "        topics = {'left': 'cam_l', 'right': 'cam_r'}\n"
                 "        for side in topics:\n"
                 "            self.create_publisher(Image, side + '/raw', 10)\n"
                 "        for name in topics.values():\n"
                 "            self.create_publisher(Image, name + '/rect', 10)\n"
                 "        self.make(topics)\n"
                 "    def make(self, given):\n"
                 "        for side, name in given.iteritems():\n"
                 "            self.create_subscription(Image, f'{side}/{name}', None, 1)\n")
    assert names(result) == [("left/raw", ()), ("right/raw", ()), ("cam_l/rect", ()),
                             ("cam_r/rect", ()), ("left/cam_l", ()), ("right/cam_r", ())]
    assert [d.code for d in result.diagnostics] == []


_FALLBACK = ("#!/usr/bin/env python\nimport rospy\nfrom sensor_msgs.msg import JointState\n"
             "def get_param(name, value=None):\n"
             "    private = '~%s' % name\n"
             "    if rospy.has_param(private):\n"
             "        return rospy.get_param(private)\n"
             "    elif rospy.has_param(name):\n"
             "        return rospy.get_param(name)\n"
             "    else:\n"
             "        return value\n"
             "class Merger(object):\n"
             "    def __init__(self):\n"
             "        sources = get_param('source_list', [])\n"
             "        self.subs = []\n"
             "        for source in sources:\n"
             "            self.subs.append(rospy.Subscriber(source, JointState, self.cb))\n"
             "        rospy.Publisher(get_param('out', 'merged'), JointState, queue_size=1)\n"
             "    def cb(self, msg):\n"
             "        pass\n"
             "rospy.init_node('merger')\nMerger()\n")


def test_a_loop_over_a_helper_that_returns_a_parameter_or_its_default(write_tree) -> None:
    """joint_state_publisher's own ``get_param(name, value)`` returns ``~name`` where it
    is set, else ``name``, else ``value``: a loop over ``get_param('source_list', [])``
    subscribes once per element of the list the configuration gives (it was one ``?``
    subscription, so a misnamed source was never seen), and a name it returns is one
    call per path (the parameter, or the default), each under the helper's
    ``rospy.has_param`` tests written with the name tested, which the graph decides
    (the reads of the name as written: ``~x``, not ``x``); a call they leave out is
    said to be under a false condition, not named by a parameter nobody sets."""
    import os
    import re

    from conftest import package_xml

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    launch = ("<launch><node pkg=\"merger\" type=\"merger.py\" name=\"merger\">\n"
              "<rosparam param=\"source_list\">[arm/joint_states, hand/joint_states]"
              "</rosparam>\n</node></launch>\n")
    root = write_tree({
        "src/merger/package.xml": package_xml("merger"),
        "src/merger/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\n"
                                     "project(merger)\n"
                                     "find_package(catkin REQUIRED COMPONENTS rospy)\n"
                                     "catkin_package()\n"
                                     "catkin_install_python(PROGRAMS scripts/merger.py "
                                     "DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        "src/merger/scripts/merger.py": _FALLBACK,
        "src/merger/launch/merger.launch": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [merger/launch/merger.launch]\n",
    })
    os.chmod(root / "src/merger/scripts/merger.py", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    calls = [(c.kind, c.name, c.name_param, c.name_each, c.conditions[-1].statement)
             for p in model.packages for n in p.nodes for c in n.calls
             if c.kind in ("publish", "subscribe")]
    assert calls == [("subscribe", "?", "~source_list", ".", "for each"),
                     ("subscribe", "?", "source_list", ".", "for each"),
                     ("publish", "?", "~out", None, "if"),
                     ("publish", "?", "out", None, "if"),
                     ("publish", "merged", None, None, "else")]
    # the helper's tests, one name per call: the graph decides them (~source_list is
    # set, source_list, ~out and out are not), so no '?' is left
    tests = [c.conditions[0].text for p in model.packages for n in p.nodes
             for c in n.calls if c.kind == "publish"]
    assert tests == ["rospy.has_param('~out')"] * 3
    topics = sorted((link.kind, link.resource.name) for link in model.configurations[0].links
                    if link.kind in ("publish", "subscribe"))
    assert topics == [("publish", "/merged"), ("subscribe", "/arm/joint_states"),
                      ("subscribe", "/hand/joint_states")]
    # the calls the tests leave out name nothing here: no word of their parameters
    said = model.configurations[0].diagnostics
    assert "NAME_PARAM_UNSET" not in [d.code for d in said]
    dropped = sorted(re.search(r": (no .*?) in this configuration", d.message).group(1)
                     for d in said if d.code == "CONDITION_FALSE")
    # (the global source_list is read only where ~source_list is not set)
    assert dropped == ["no publish ?", "no read /merger/out", "no read /out",
                       "no read /source_list", "no read /source_list", "no subscribe ?"]
