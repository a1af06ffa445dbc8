"""bondpy's Bond(topic, id) exchanges its heartbeat (bond/Status) on the topic given, both
ways, as bondcpp's does: diagnostic_aggregator's add_analyzers bonds with the aggregator
so. Before, the class was one of a ROS package whose code is not read, and the node was
partial for it."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

SCRIPT = """#!/usr/bin/env python
import rospy
from bondpy import bondpy
from diagnostic_msgs.srv import AddDiagnostics


def main():
    rospy.init_node('add_analyzers')
    bond = bondpy.Bond("/diagnostics_agg/bond/robot", "robot")
    bond.start()
    add = rospy.ServiceProxy('/diagnostics_agg/add_diagnostics', AddDiagnostics)
    rospy.spin()


if __name__ == '__main__':
    main()
"""


def test_a_bond_is_its_topic_both_ways(write_tree: Any) -> None:
    manifest = package_xml("agg").replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("rospy", "bondpy", "diagnostic_msgs")) + "</package>")
    root = write_tree({
        "src/agg/package.xml": manifest,
        "src/agg/CMakeLists.txt": "project(agg)\ncatkin_install_python(PROGRAMS "
                                  "scripts/add_analyzers DESTINATION bin)\n",
        "src/agg/scripts/add_analyzers": SCRIPT,
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n"})
    os.chmod(root / "src/agg/scripts/add_analyzers", 0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    node = next(n for p in model.packages for n in p.nodes if n.name.endswith("add_analyzers"))
    assert node.completeness == "complete", node.completeness_reasons
    assert sorted((c.kind, c.name, c.type) for c in node.calls) == [
        ("client", "/diagnostics_agg/add_diagnostics", "diagnostic_msgs/AddDiagnostics"),
        ("publish", "/diagnostics_agg/bond/robot", "bond/Status"),
        ("subscribe", "/diagnostics_agg/bond/robot", "bond/Status")]
