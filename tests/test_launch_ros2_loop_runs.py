"""A Python test of a ROS 2 launch file that cannot be known statically, run once per
item of a loop, may come out otherwise for each item though its text is the same: vrx_gz
starts an ``optical_frame_publisher`` for each payload item whose sensor type (not known)
is a camera. The two nodes one ``Node(...)`` makes for two items were read as starting
under the same conditions, a definite duplicate-node-names error; whether both items
are cameras is not known, so it is undecided. Two ``Node(...)`` entries of one name
under one run of the test (an RGBD camera's two nodes) stay an error, in the model and
in the model read back from its JSON."""

from __future__ import annotations

import json
import os

from conftest import package_xml

from haros_arch.model.load import from_data
from haros_arch.model.serialise import to_data
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load as load_project
from haros_arch.query.catalogue import load_catalogue, run_rule

LAUNCH = """
import sdformat
from launch import LaunchDescription
from launch_ros.actions import Node

def node(name):
    return Node(package='robot_state_publisher', executable='robot_state_publisher',
                name=name)

def generate_launch_description():
    nodes = []
    for sensor in [sdformat.front(), sdformat.rear()]:
        if sensor.kind == 'camera':
            nodes.append(node('optical'))
        elif sensor.kind == 'rgbd':
            nodes.append(node('depth'))
            nodes.append(node('depth'))
    return LaunchDescription(nodes)
"""


def test_one_entry_in_two_runs_of_a_test_is_undecided(write_tree) -> None:
    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_python"),
        "src/p/launch/a.launch.py": LAUNCH,
        "project.yaml": "project: p\ndistro: jazzy\n"
                        "configurations:\n  c: [p/launch/a.launch.py]\n",
    })
    model = analyse(load_project(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    names = sorted(n.name for n in model.configuration("c").nodes)
    assert names == ["/depth"] * 4 + ["/optical"] * 2, names
    rule = next(r for r in load_catalogue() if r.id == "duplicate-node-names")
    saved = from_data(json.loads(json.dumps(to_data(model))))
    for checked in (model, saved):
        found = sorted((f.rule, f.severity, f.message.split(" (")[0])
                       for f in run_rule(rule, checked))
        assert found == [
            ("duplicate-node-names", "error", "4 nodes are named /depth"),
            ("duplicate-node-names-undecided", "info", "1 possible finding(s) not reported"),
        ], found
        undecided = [f for f in run_rule(rule, checked) if f.severity == "info"]
        assert "/optical" in undecided[0].message, undecided[0].message
