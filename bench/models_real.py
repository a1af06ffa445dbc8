"""Interface models on real systems that launch third-party nodes.

    PYTHONPATH=. .venv/bin/python bench/models_real.py [--root /work/ws/models-bench]
        [--case NAME] [--list]

Each case is a fetched workspace (robot packages only: amcl, move_base, nav2's servers,
robot_localization, ... are not in it, as on a machine where they are installed) and
its launch files. It is analysed twice, without the shipped interface models and with
them, and prints: the node instances that took a model (and its completeness), the
links the models added, the topics they connect between the workspace's nodes and the
modelled ones, and the "subscriber without publisher" / "publisher without subscriber"
findings before and after (``--list`` prints the remaining ones, to check against the
sources), with the number the catalogue leaves undecided because a node of partial or
unknown interface runs in the configuration (and the nodes it names).

Trees (from the mirrors the `fetch` tool brings; see scripts/models-fetch for the
pinned model sources):

    husky          github:husky/husky@noetic-devel
    turtlebot3     github:ROBOTIS-GIT/turtlebot3@noetic (without turtlebot3_description)
    jackal         github:jackal/jackal@noetic-devel (navigation + control)
    fetch          github:fetchrobotics/fetch_ros@melodic-devel (without fetch_description)
    nav2_bringup   github:ros-navigation/navigation2@jazzy, nav2_bringup only
    nav2_gps       github:ros-navigation/navigation2@jazzy, nav2_system_tests' package.xml
                   and src/gps_navigation only (robot_localization's dual EKF + navsat
                   setup: two ekf_node filters and navsat_transform_node)

Husky's and Jackal's control.launch start robot_localization (ROS 1) with odom0 / imu0 in
a rosparam file; nav2_gps starts it in ROS 2 with a parameter file keyed by node name.
"""

from __future__ import annotations

import argparse
import os
import time
from dataclasses import dataclass, field

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch.model.model import Model
from haros_arch.pipeline import Options, analyse
from haros_arch.project import ConfigurationSpec, Project
from haros_arch.query import run_catalogue
from haros_arch.query.catalogue import UNDECIDED

# the catalogue's absence rules: each leaves undecided (one info) the matches a node of
# partial or unknown interface could be the missing side of
ABSENCE = ("subscriber-without-publisher", "publisher-without-subscriber",
           "parameter-set-not-read", "parameter-read-not-set", "similar-disconnected-topics")


@dataclass
class Case:
    name: str
    folder: str
    launch: list[str]
    args: dict[str, str] = field(default_factory=dict)
    environment: dict[str, str] = field(default_factory=dict)


CASES = [
    Case("husky", "husky", ["husky_navigation/launch/amcl_demo.launch",
                            "husky_control/launch/control.launch",
                            "husky_control/launch/teleop.launch"]),
    Case("turtlebot3", "tb3", ["turtlebot3_navigation/launch/turtlebot3_navigation.launch"],
         {"model": "burger", "open_rviz": "false"}),
    Case("jackal", "jackal", ["jackal_navigation/launch/amcl_demo.launch",
                              "jackal_control/launch/control.launch",
                              "jackal_control/launch/teleop.launch"]),
    Case("fetch", "fetch_ros", ["fetch_navigation/launch/fetch_nav.launch"]),
    Case("nav2_bringup", "nav2_bringup", ["nav2_bringup/launch/bringup_launch.py"],
         {"map": "map.yaml", "use_composition": "False"}),
    Case("nav2_gps", "nav2_gps",
         ["nav2_system_tests/src/gps_navigation/dual_ekf_navsat.launch.py"]),
]


def _run(case: Case, root: str, models: bool) -> Model:
    folder = os.path.join(root, case.folder)
    project = Project(case.name, os.path.join(folder, "project.yaml"), [folder],
                      configurations=[ConfigurationSpec(case.name, list(case.launch),
                                                        dict(case.args))])
    return analyse(project, dict(case.environment), Options(jobs=1, models=models))


def _connected(model: Model) -> set[str]:
    (config,) = model.configurations
    return {t.name for t in config.topics if t.publishers and t.subscribers
            and {link.node.name for link in t.links} != {t.publishers[0].node.name}}


def _absences(model: Model) -> list[str]:
    """The absence findings, and the catalogue's one info per rule for those it leaves
    undecided (a node of partial or unknown interface could be the missing side)."""
    return sorted(f"{f.rule}: {f.message}" for f in run_catalogue(model)
                  if f.rule.removesuffix(UNDECIDED) in ABSENCE)


def _undecided(lines: list[str], rule: str) -> str:
    """How many matches the rule's undecided info stands for, and the nodes it names."""
    line = next((x for x in lines if x.startswith(rule + UNDECIDED + ":")), None)
    if line is None:
        return "0"
    count = line.split(": ", 1)[1].split(" ", 1)[0]
    return f"{count} ({line.rsplit('missing side: ', 1)[-1]})"


def measure(case: Case, root: str, listing: bool) -> None:
    start = time.monotonic()
    before = _run(case, root, models=False)
    after = _run(case, root, models=True)
    (config,) = after.configurations
    modelled = [n for n in config.nodes if n.node is not None and n.node.model]
    added = [link for link in config.links if link.origin == "model"]
    joined = sorted({link.resource.name for link in added
                     if any(other.node.node is not None and not other.node.node.model
                            for other in link.resource.links)})
    connected = {"before": _connected(before), "after": _connected(after)}
    unknown = [n.name for n in config.nodes if n.node is None]
    incomplete = sorted(n.name for n in config.incomplete_nodes)
    was, now = _absences(before), _absences(after)
    print(f"== {case.name} ({time.monotonic() - start:.1f} s)")
    print(f"  node instances {len(config.nodes)}, from models {len(modelled)}, still "
          f"unknown {len(unknown)}: {', '.join(unknown) or '-'}")
    for node in modelled:
        state = node.completeness
        print(f"    {node.name}: {node.node.model if node.node else ''} [{state}]")
    print(f"  incomplete node instances {len(incomplete)}: {', '.join(incomplete) or '-'}")
    unnamed = [link for link in added if "?" in link.name
               and link.kind in ("publish", "subscribe", "server", "client")]
    print(f"  links added by models {len(added)} (topics and services named '?': "
          f"{len(unnamed)}); resources joining the workspace's own nodes and modelled "
          f"ones {len(joined)}")
    for name in joined:
        print(f"    {name}")
    print(f"  topics with a publisher and a subscriber: before {len(connected['before'])}, "
          f"after {len(connected['after'])}: "
          f"{', '.join(sorted(connected['after'] - connected['before']))}")
    for rule in ABSENCE:
        print(f"  {rule}: before {sum(1 for f in was if f.startswith(rule + ':'))}, after "
              f"{sum(1 for f in now if f.startswith(rule + ':'))}; undecided before "
              f"{_undecided(was, rule)}, after {_undecided(now, rule)}")
    gone = sorted(set(was) - set(now))
    new = sorted(set(now) - set(was))
    print(f"  findings gone {len(gone)}, new {len(new)}")
    if listing:
        for line in new:
            print(f"    new: {line}")
        for line in now:
            print(f"    after: {line}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default="/work/ws/models-bench",
                        help="folder of the cases' trees (a case missing there is said)")
    parser.add_argument("--case", action="append", default=[])
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    for case in CASES:
        if args.case and case.name not in args.case:
            continue
        if not os.path.isdir(os.path.join(args.root, case.folder)):
            print(f"== {case.name}: no tree at {os.path.join(args.root, case.folder)}")
            continue
        measure(case, args.root, args.list)


if __name__ == "__main__":
    checkout.announce()
    main()
