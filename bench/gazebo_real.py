"""Gazebo plugins of robot descriptions on real workspaces: what they add to the graph.

    .venv/bin/python bench/gazebo_real.py WORKSPACE [WORKSPACE ...] --launch LAUNCH
        [--launch LAUNCH ...] [--arg NAME:=VALUE ...] [--env NAME=VALUE ...] [--jobs N]

Each LAUNCH (``pkg/path/in/package`` or a path; several joined by ``+``: one
configuration of them all, a simulation with the nodes that use its sensors) is one
configuration. The pipeline runs
twice, with and without the robot-description stage (``robot.attach``), and prints per
configuration: the descriptions read (files, links, joints, completeness), each plugin
with the node instance that makes its calls, the diagnostics of the stage, the links
before and after, and every topic a plugin publishes or subscribes to with its type and
the nodes on the other side (``-`` when none: a sensor topic nothing reads; ``node as
/?/scan?`` when a name with unknown parts has it as a candidate); then, without and with
the stage, the calls of spawned controllers that the instances of the descriptions'
plugins make (ROS 1 gazebo_ros_control's controller manager) and the plugin instances of
their own (controllers with no manager in view, ROS 2 controllers and Gazebo plugins).
"""

from __future__ import annotations

import argparse
import importlib
import os

import checkout  # bench/checkout.py: says which haros_arch is measured

HERE = os.path.dirname(os.path.abspath(__file__))

from haros_arch import pipeline  # noqa: E402
from haros_arch.model.model import Model  # noqa: E402
from haros_arch.project import ConfigurationSpec, Project  # noqa: E402

CODES = ("ROBOT_DESCRIPTION_XACRO", "ROBOT_DESCRIPTION_FILE", "ROBOT_DESCRIPTION_COMMAND_FAILS",
         "ROBOT_DESCRIPTION_LIMIT",
         "ROBOT_DESCRIPTION_UNKNOWN", "GAZEBO_PLUGIN_UNKNOWN", "GAZEBO_NOT_STARTED")


def run(project: Project, env: dict[str, str], jobs: int, enabled: bool) -> Model:
    graph_build = importlib.import_module("haros_arch.graph.build")
    robot_attach = importlib.import_module("haros_arch.robot.attach")
    graph_build.attach_descriptions = robot_attach.attach if enabled else (
        lambda *a: robot_attach.Attached([], []))
    # the run cache keys on the environment, not on the stage switched off here: a
    # variable of our own keeps the two runs apart
    return pipeline.analyse(project, {**env, "HAROS_BENCH_ROBOT_STAGE": str(enabled)},
                            pipeline.Options(cache_dir=pipeline.AUTO_CACHE, jobs=jobs))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace", nargs="+")
    parser.add_argument("--launch", action="append", required=True)
    parser.add_argument("--arg", action="append", default=[])
    parser.add_argument("--env", action="append", default=[])
    parser.add_argument("--jobs", type=int, default=1)
    args = parser.parse_args()
    launch_args = dict(a.split(":=", 1) for a in args.arg)
    env = {**os.environ, **dict(e.split("=", 1) for e in args.env)}
    roots = [os.path.abspath(w) for w in args.workspace]
    project = Project("gazebo", os.path.join(roots[0], "bench.yaml"), workspace=roots,
                      configurations=[ConfigurationSpec(os.path.basename(launch), launch.split("+"),
                                                        dict(launch_args))
                                      for launch in args.launch])
    before = run(project, env, args.jobs, False)
    after = run(project, env, args.jobs, True)
    for old, new in zip(before.configurations, after.configurations, strict=True):
        print(f"== {new.name}: links {len(old.links)} -> {len(new.links)} "
              f"(+{len(new.links) - len(old.links)}), descriptions "
              f"{len(new.robot_descriptions)}")
        for description in new.robot_descriptions:
            print(f"  description {description.name} <- {description.file} "
                  f"({len(description.files)} files, {len(description.links)} links, "
                  f"{len(description.joints)} joints, {description.completeness})")
            for reason in description.completeness_reasons:
                print(f"    partial: {reason}")
            for plugin in description.plugins:
                print(f"    plugin {plugin.name} {plugin.filename} "
                      f"({plugin.location.file}:{plugin.location.line}) -> {plugin.node}")
        for found in new.diagnostics:
            if found.code in CODES:
                print(f"  {found.code} {found.location.file}:{found.location.line} "
                      f"{found.message}")
        made = [link for link in new.links if link.origin == "description"]
        unresolved = [r for r in (*new.topics, *new.services) if "?" in r.name]
        for link in sorted(made, key=lambda x: (x.resource.name, x.kind)):
            peers = [peer.node.name for peer in link.resource.links
                     if peer.kind != link.kind and peer.node is not link.node]
            # a name with unknown parts that may be this one (``?/scan``): a candidate
            peers += [f"{peer.node.name} as {other.name}?" for other in unresolved
                      if link.resource in other.candidates for peer in other.links
                      if peer.kind != link.kind]
            print(f"    {link.kind:9} {link.resource.name} [{link.type}] by {link.node.name}"
                  f" | other side: {', '.join(sorted(set(peers))) or '-'}")
        # the controllers spawners load: on the instance of a description's controller
        # manager (gazebo_ros_control in the gazebo node), or nodes of their own
        for config, when in ((old, "without descriptions"), (new, "with")):
            hosted = {name for name in (p.node for d in config.robot_descriptions
                                        for p in d.plugins) if name}
            files = {f for d in config.robot_descriptions for f in d.files}
            # a camera's image_transport topics keep the plugin's place in the description
            on_gazebo = [link for link in config.links if link.node.name in hosted
                         and link.origin != "description"
                         and link.location.file not in files]
            transports = [link for link in config.links if link.node.name in hosted
                          and link.origin == "plugin" and link.kind == "publish"
                          and link.location.file in files
                          and not (link.type or "").startswith("dynamic_reconfigure/")]
            own = sorted(n.name for n in config.nodes if n.origin == "plugin"
                         and n.name not in hosted and not n.name.startswith("/gazebo"))
            print(f"  controllers {when}: {len(on_gazebo)} calls on "
                  f"{', '.join(sorted(hosted)) or '-'}; plugin instances of their own: "
                  f"{', '.join(own) or '-'}; image_transport topics "
                  f"{', '.join(sorted(link.resource.name for link in transports)) or '-'}")


if __name__ == "__main__":
    checkout.announce()
    main()
