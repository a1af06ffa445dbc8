"""A call named by each element of a ROS 1 list parameter that nothing sets makes no
call: twist_mux reads ``~locks`` with ``xh::fetchParam``, which throws when the
parameter is not set (its caller catches it and makes no lock), so a configuration that
gives twist_mux no locks has no lock subscription. It was kept as a subscription named
``?`` (with a NAME_PARAM_UNSET). Where the list may still be set unseen (a read with a
default the model does not know, an include not read) the call stays as it was."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load


def _calls(default: bool) -> list[dict]:
    return [
        {"kind": "read", "name": "~topics", "type": None},
        {"kind": "subscribe", "name": "?", "type": "geometry_msgs/Twist",
         "name_param": "~topics", "name_each": "topic"},
        {"kind": "read", "name": "~locks", "type": None, "has_default": default},
        {"kind": "subscribe", "name": "?", "type": "std_msgs/Bool",
         "name_param": "~locks", "name_each": "topic"},
        {"kind": "publish", "name": "cmd_vel_out", "type": "geometry_msgs/Twist"}]


MUX_MODEL = {
    "schema": "haros-arch-model/2", "package": "mux", "distro": "noetic", "nodes": [
        {"package": "mux", "executable": "mux", "rosname": "mux", "calls": _calls(False)},
        {"package": "mux", "executable": "mux_default", "rosname": "mux_default",
         "calls": _calls(True)}]}

LAUNCH = """
<launch>
  <node pkg="mux" type="mux" name="mux">
    <rosparam>
      topics:
        - {name: joy, topic: joy/cmd_vel, priority: 10}
    </rosparam>
  </node>
  <node pkg="mux" type="mux_default" name="mux_default">
    <rosparam param="topics">[]</rosparam>
  </node>
  %s
</launch>
"""


def _configuration(write_tree, extra: str = ""):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/mux.launch": LAUNCH % extra,
        "models/mux.json": json.dumps(MUX_MODEL),
        "project.yaml": "project: p\nmodels: [models]\n"
                        "configurations:\n  c:\n    launch: [robot/launch/mux.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return config


def test_a_list_nothing_sets_names_no_call(write_tree) -> None:
    config = _configuration(write_tree)
    subscribed = {n.name: sorted(link.name for link in n.subscribers) for n in config.nodes}
    # /mux: its one topic, no lock; /mux_default: its locks read with a default not known
    assert subscribed == {"/mux": ["/joy/cmd_vel"], "/mux_default": ["?"]}
    said = [d.message for d in config.diagnostics if d.code == "CONDITION_FALSE"]
    assert len(said) == 1 and "/mux" in said[0] and "~locks" in said[0]


def test_a_list_an_unread_include_may_set_keeps_its_call(write_tree) -> None:
    config = _configuration(write_tree, '<include file="$(env NOT_KNOWN)/x.launch"/>')
    subscribed = {n.name: sorted(link.name for link in n.subscribers) for n in config.nodes}
    assert subscribed["/mux"] == ["/joy/cmd_vel", "?"]
