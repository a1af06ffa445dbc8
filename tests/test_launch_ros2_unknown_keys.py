"""A dict item the launch code sets under a key not known statically is kept, under
that unknown key, and said where it is set: vrx_gz's ``payload[sensor.name()] = ...``
(the name comes from sdformat, which is not run) was dropped without a word, so the
WAM-V's payload held only its thrusters and the loop over it made no node for the
cameras. Unknown is not empty: the loop over the dict also runs for the unknown item,
a lookup of a key the dict does not hold is not known (the unknown key may be it), and
a node given the dict as parameters gets one parameter of an unknown name."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

LAUNCH = """
import sdformat
from launch import LaunchDescription
from launch_ros.actions import Node

def payload_of():
    payload = {'thruster': 'thrust'}
    root = sdformat.Root()
    for sensor in root.sensors():
        payload[sensor.name()] = 'camera'
    return payload

def generate_launch_description():
    payload = payload_of()
    nodes = [Node(package='sim', executable='relay', name=key + '_relay')
             for key in payload]
    for key, kind in payload.items():
        nodes.append(Node(package='sim', executable='bridge', name=key + '_bridge'))
    found = payload.get('front_camera', 'none')
    has = 'front_camera' in payload
    nodes.append(Node(package='sim', executable='probe', name='probe',
                      parameters=[payload, {'found': found, 'has': has,
                                            'count': len(payload)}]))
    return LaunchDescription(nodes)
"""


def _load(write_tree, text: str):
    root = write_tree({
        "src/sim/package.xml": package_xml("sim", "ament_cmake"),
        "src/sim/launch/sim.launch.py": text,
    })
    return load(str(root / "src/sim/launch/sim.launch.py"), scan([str(root / "src")], {}),
                {}, {})


def test_an_item_under_an_unknown_key_is_kept_and_said(write_tree):
    model = _load(write_tree, LAUNCH)
    names = sorted(n.name for n in model.nodes)
    # the known item and the unknown one, by a comprehension and by a loop
    assert names == ["/?_bridge", "/?_relay", "/probe", "/thruster_bridge",
                     "/thruster_relay"], names
    said = [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PY_UNSUPPORTED" and "key not known" in d.message]
    assert [line for line, _ in said] == [9], said  # the assignment
    assert "payload" in said[0][1], said
    params = {p.key: p.value for p in model.params if p.node.endswith("probe")}
    assert params["thruster"] == "thrust"
    # a key the dict does not hold may be the unknown one: nothing known of it (a
    # value not known is None), nor of how many items it holds
    for name in ("found", "has", "count"):
        assert name in params and params[name] is None, (name, params)
    assert params["?"] == "camera", params


def test_known_keys_keep_their_lookups(write_tree):
    # a dict of known keys alone: lookups, len and ``in`` as Python gives them
    model = _load(write_tree, """
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    payload = {'thruster': 'thrust'}
    return LaunchDescription([Node(package='sim', executable='probe', name='probe',
        parameters=[{'found': payload.get('camera', 'none'), 'has': 'camera' in payload,
                     'count': len(payload)}])])
""")
    assert {p.key: p.value for p in model.params} == {
        "found": "none", "has": False, "count": 1}
    assert not [d for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
