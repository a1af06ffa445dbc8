"""A call named by each element of a list parameter (``PrimitiveCall.name_each``) that
the configuration sets to an empty list makes no call: warthog's teleop.launch gives
twist_mux ``<rosparam param="locks">[]</rosparam>``, and twist_mux subscribes one topic
per lock, so none. It was kept as a subscription named ``?`` with a NAME_PARAM_UNSET
saying the configuration sets no list. An empty list set under a launch condition the
configuration does not decide leaves the call as it is."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

MUX_MODEL = {
    "schema": "haros-arch-model/2", "package": "mux", "distro": "noetic", "nodes": [{
        "package": "mux", "executable": "mux", "rosname": "mux", "calls": [
            {"kind": "subscribe", "name": "?", "type": "geometry_msgs/Twist",
             "name_param": "~topics", "name_each": "topic"},
            {"kind": "subscribe", "name": "?", "type": "std_msgs/Bool",
             "name_param": "~locks", "name_each": "topic"},
            {"kind": "publish", "name": "cmd_vel_out", "type": "geometry_msgs/Twist"}]}]}

LAUNCH = """
<launch>
  <arg name="pause" default="false"/>
  <node pkg="mux" type="mux" name="mux">
    <rosparam>
      topics:
        - {name: joy, topic: joy/cmd_vel, priority: 10}
    </rosparam>
    <rosparam param="locks">[]</rosparam>
  </node>
  <node pkg="mux" type="mux" name="mux_if">
    <rosparam param="topics">[]</rosparam>
    <rosparam param="locks" if="$(arg pause)">[]</rosparam>
  </node>
</launch>
"""


def _configuration(root):
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return config


def test_an_empty_list_parameter_names_no_call(write_tree) -> None:
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/mux.launch": LAUNCH,
        "models/mux.json": json.dumps(MUX_MODEL),
        "project.yaml": "project: p\nmodels: [models]\n"
                        "configurations:\n  c:\n    launch: [robot/launch/mux.launch]\n"
                        "    args: {pause: $(env PAUSE)}\n",
    })
    config = _configuration(root)
    subscribed = {n.name: sorted(link.name for link in n.subscribers) for n in config.nodes}
    # /mux: one topic, no lock; /mux_if: no topic, its locks set only if pause
    assert subscribed == {"/mux": ["/joy/cmd_vel"], "/mux_if": ["?"]}
    unset = [d.location.line for d in config.diagnostics if d.code == "NAME_PARAM_UNSET"]
    assert len(unset) == 1  # /mux_if's locks, whose list may not be set
