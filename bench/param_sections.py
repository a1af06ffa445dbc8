"""Parameters a ROS 2 launch gives each node instance, and how many of those it reads.

    PYTHONPATH=. .venv/bin/python bench/param_sections.py WORKSPACE LAUNCH [NAME=VALUE ...]

NAME=VALUE pairs are the environment the launch file reads (TurtleBot3's
``TURTLEBOT3_MODEL``, ``ROS_DISTRO``, ``LDS_MODEL``). For each node instance that reads
parameters: how many it reads, how many of those the launch sets, and the names it reads
that the launch does not set. A parameter file given to a node launched without
``name=`` applies its sections for particular nodes once the graph names the node from
its code (issue #17), so those counts measure that.

    TurtleBot3 humble (ROBOTIS-GIT/turtlebot3, /work/ws/lead/tb3):
    bench/param_sections.py /work/ws/lead/tb3 \\
        /work/ws/lead/tb3/src/turtlebot3_bringup/launch/robot.launch.py \\
        TURTLEBOT3_MODEL=burger ROS_DISTRO=humble LDS_MODEL=LDS-01
"""

from __future__ import annotations

import os
import sys

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch.pipeline import Options, analyse
from haros_arch.project import ConfigurationSpec, Project


def main() -> None:
    if len(sys.argv) < 3:
        print(__doc__)
        raise SystemExit(2)
    workspace, launch = sys.argv[1], sys.argv[2]
    environment = dict(pair.split("=", 1) for pair in sys.argv[3:] if "=" in pair)
    project = Project("bench", os.path.join(workspace, "project.yaml"), [workspace],
                      configurations=[ConfigurationSpec("c", [launch], {})])
    model = analyse(project, environment, Options(jobs=1))
    (config,) = model.configurations
    for node in config.nodes:
        read = sorted({p.name for p in config.parameters
                       if any(r.node is node for r in p.readers)})
        if not read:
            continue
        given = {p.name for p in config.parameters if p.set_by_launch}
        missing = [name for name in read if name not in given]
        print(f"{node.name}: reads {len(read)}, set by the launch {len(read) - len(missing)}")
        for name in missing:
            print(f"    not set: {name}")


if __name__ == "__main__":
    checkout.announce()
    main()
