"""The shipped jazzy model of foxglove_bridge's executable is one ROS node. Its main makes
a node "dummy" in a block of its own, reads num_threads on it and drops it before it
builds the FoxgloveBridge node, so the two never exist at once
(``models/overrides/jazzy/foxglove_bridge.yaml``). The model kept both names, and a
launch ``Node(name='foxglove_bridge')`` renamed both (rcl's ``__node:=`` renames every
node of the process): the graph held the name twice, a false duplicate-node-names error
on every robot that launches the bridge with a name (ros2-rover's five)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.models.library import Library
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_catalogue


def test_the_shipped_model_is_one_node_that_reads_num_threads():
    found = Library().find("foxglove_bridge", "jazzy")
    assert found is not None
    node = next(n for n in found.nodes if n.executable == "foxglove_bridge")
    assert node.rosname == "foxglove_bridge" and not node.rosnames
    assert ("read", "num_threads") in {(c.kind, c.name) for c in node.calls}


def test_a_named_bridge_is_one_node_and_no_duplicate(write_tree):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot", "ament_python"),
        "src/robot/launch/viz.launch.py": """
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package='foxglove_bridge', executable='foxglove_bridge',
             name='foxglove_bridge', parameters=[{'port': 8765, 'num_threads': 2}]),
    ])
""",
        "project.yaml": "project: p\ndistro: jazzy\nconfigurations:\n"
                        "  c: [robot/launch/viz.launch.py]\n"})
    project = load(str(root / "project.yaml"))
    model = analyse(project, {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    assert [n.name for n in config.nodes] == ["/foxglove_bridge"]
    rules = [r for r in load_catalogue()
             if r.id in ("duplicate-node-names", "parameter-set-not-read")]
    assert [f.rule for f in run_catalogue(model, project, rules)] == []
