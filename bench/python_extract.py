"""Python extractor: is the work linear in the size of a node's source? And how many
ROS nodes do real Python executables create?

Writes a generated rospy node at two sizes (10x apart) into a temporary workspace and
prints the ratio of their extraction times (about 10 when linear), plus calls per
second. Run: .venv/bin/python bench/python_extract.py

With workspace folders (``bench/python_extract.py WS [WS ...]``, e.g. the ros2/demos and
ros2/examples sources), it also extracts every ament_python executable there, counts
those that create several rclpy nodes, and builds one graph that starts each executable
once, as a ROS 2 launch ``Node`` without ``name=`` would: node instances and links, and
per multi-node executable the instances it gives.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time

from haros_arch import graph, pysetup
from haros_arch.extract import extract_nodes
from haros_arch.extract.python import extract_python
from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model.runtime import Configuration
from haros_arch.model.source import Node
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?><package format="2"><name>gen</name><version>0.0.0</version>'
           '<description>d</description><maintainer email="a@b.c">m</maintainer>'
           '<license>MIT</license></package>')


def node(functions: int) -> str:
    parts = ["import rospy\nfrom std_msgs.msg import String\nPREFIX = 'robot'\n"]
    for i in range(functions):
        parts.append(
            f"def setup_{i}(name):\n"
            f"    if rospy.get_param('~enable_{i}', True):\n"
            f"        rospy.Publisher(PREFIX + '/' + name, String, queue_size={i % 10 + 1})\n"
            f"    rospy.Subscriber(f'{{PREFIX}}/in_{i}', String, None)\n"
            f"setup_{i}('out_{i}')\n")
    return "".join(parts)


def measure(root: str, functions: int) -> tuple[float, int]:
    path = os.path.join(root, "gen", "scripts", f"node_{functions}.py")
    with open(path, "w") as handle:
        handle.write(node(functions))
    ws = scan([root])
    start = time.perf_counter()
    result = extract_python([path], ws, package="gen")
    return time.perf_counter() - start, len(result.calls)


def several_nodes(roots: list[str]) -> None:
    """Executables of ament_python packages that create several nodes, and the graph
    that starts each of them once (launch namespace ``/``, no name given)."""
    ws = scan(roots)
    nodes: dict[str, Node] = {}
    for package in ws.packages.values():
        if package.build_type == "ament_python":
            package.nodes, _ = pysetup.parse_package(package, ws)
            nodes.update((n.name, n) for n in package.nodes)
    extract_nodes(list(nodes.values()), ws, cache_dir=None)
    several = {}
    for node in nodes.values():
        names = extract_python([os.path.join(ws.root, s) for s in node.sources], ws,
                               package=node.package).names
        if len(names) > 1:
            several[node.name] = names
    launch = LaunchModel(nodes=[
        NodeDecl("/?", n.package, n.executable, ros_version=2) for n in nodes.values()])
    config = graph.build(Configuration("all"), launch, ws, nodes)
    print(f"python executables: {len(nodes)}; with several nodes: {len(several)}")
    print(f"graph starting each once: {len(config.nodes)} node instances, "
          f"{len(config.links)} links, {len(config.topics)} topics, "
          f"{len(config.services)} services")
    for name, names in sorted(several.items()):
        made = [i for i in config.nodes if i.node is nodes[name]]
        print(f"  {name} names {names}: {len(made)} instance(s) "
              f"{[f'{i.name} ({len(i.links)} links)' for i in made]}")


def main() -> None:
    if sys.argv[1:]:
        several_nodes(sys.argv[1:])
        return
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "gen", "scripts"))
        with open(os.path.join(root, "gen", "package.xml"), "w") as handle:
            handle.write(PACKAGE)
        small, small_calls = measure(root, 200)
        large, large_calls = measure(root, 2000)
    print(f"small: {small_calls} calls in {small:.3f}s; large: {large_calls} calls in {large:.3f}s")
    print(f"time ratio large/small: {large / small:.1f} (10x the code; ~10 means linear)")
    print(f"calls per second (large): {large_calls / large:.0f}")


if __name__ == "__main__":
    main()
