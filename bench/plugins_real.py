"""Plugins on real workspaces: what hosts load and what it changes in the graph.

    .venv/bin/python bench/plugins_real.py WORKSPACE LAUNCH [LAUNCH ...]
        [--arg NAME:=VALUE ...] [--jobs N] [--list] [--show PREFIX ...] [--never-read]

Each LAUNCH (``pkg/path/in/package`` or a path; several joined by ``+``: one
configuration of them all) is one configuration. The pipeline runs
twice over the same workspace, with and without plugin attachment, and prints per
configuration: the host instances (nodes started as a host of ``plugins.hosts``), the
plugins resolved (calls attached) and unresolved (PLUGIN_NOT_FOUND /
PLUGIN_CLASS_UNKNOWN), the node instances plugins added (ros2_control controllers), the
links added, and the parameters "set but never read" (set by launch, read by no link;
in brackets those of node instances whose interface is complete) before and after.
The image_transport plugins (``plugins.transports``) are part of the plugin stage here:
the run without it links an image_transport call to its base topic only; with it, the
line ``image_transport`` gives the transports the workspace has (certain) or may have
(conditional), the publishers and subscribers, and the transport topics they add.
``--list`` prints the resolved plugins and the diagnostics; ``--show PREFIX`` the links
(kind, name, type, file:line) of the node instances whose names start with PREFIX, with
plugins; ``--never-read`` the parameters set but never read, with plugins, each with
the file and line that sets it (to read against the sources).
"""

from __future__ import annotations

import argparse
import importlib
import os
from typing import Any

import checkout  # bench/checkout.py: says which haros_arch is measured

HERE = os.path.dirname(os.path.abspath(__file__))

from haros_arch import pipeline  # noqa: E402
from haros_arch.model.model import Model  # noqa: E402
from haros_arch.model.runtime import Configuration  # noqa: E402
from haros_arch.plugins.attach import attach  # noqa: E402
from haros_arch.plugins.hosts import TRANSPORTS, host_of  # noqa: E402
from haros_arch.plugins.transports import Transports  # noqa: E402
from haros_arch.project import ConfigurationSpec, Project  # noqa: E402

UNRESOLVED = ("PLUGIN_NOT_FOUND", "PLUGIN_CLASS_UNKNOWN")


def set_not_read(config: Configuration) -> str:
    """Parameters set and never read: all, and those of complete node instances only
    (what a check that trusts only complete nodes may report)."""
    never = [p for p in config.parameters
             if p.set_by_launch and not p.is_read and "?" not in p.name]
    unsure = [n.name.rstrip("/") + "/" for n in config.nodes if not n.is_complete]
    trusted = [p for p in never if not p.name.startswith(tuple(unsure))]
    return f"{len(never)} ({len(trusted)} of complete nodes)"


class _BaseOnly(Transports):
    """image_transport calls linked to their base topic only (as before the stage)."""

    def calls(self, call: Any, base: str, instance: Any) -> list[Any]:
        return [call]


class _Recording(Transports):
    """The transports stage, recording what each image_transport call stands for."""

    seen: list[tuple[str, str, list[Any]]] = []
    made: list[Transports] = []

    def __init__(self, *args: Any) -> None:
        super().__init__(*args)
        _Recording.made.append(self)

    def calls(self, call: Any, base: str, instance: Any) -> list[Any]:
        out = super().calls(call, base, instance)
        _Recording.seen.append((instance.name, call.kind, out))
        return out


def transports_line(config: Configuration, seen: list[tuple[str, str, list[Any]]]) -> str:
    """The transports the workspace has, and the transport topics image_transport
    publishers and subscribers add."""
    versions = {n.ros_version for n in config.nodes} or {1}
    probe = _Recording.made[-1] if _Recording.made else None
    have = []
    for row in TRANSPORTS:
        if all(row.types[(1 if v == 1 else 2) - 1] is None for v in versions):
            continue
        state = probe.installed(row) if probe is not None else None
        have.append(f"{row.name}{'' if state else '?' if state is None else ' (absent)'}")
    mine = [(node, kind, out) for node, kind, out in seen
            if any(node == n.name for n in config.nodes)]
    publishers = [out for _, kind, out in mine if kind == "publish"]
    subscribers = [out for _, kind, out in mine if kind == "subscribe"]
    topics = [c for out in publishers for c in out[1:] if c.kind == "publish"
              and not (c.type or "").startswith("dynamic_reconfigure/")]
    reconfigure = [c for out in publishers for c in out[1:] if c.kind == "server"]
    conditional = [c for c in topics if any(k.statement == "if" for k in c.conditions)]
    moved = [out[0] for out in subscribers if out[0].transport is None]
    return (f"image_transport: transports {', '.join(have)} (? = only if installed); "
            f"publishers {len(publishers)} add {len(topics)} transport topics "
            f"({len(conditional)} conditional) and {len(reconfigure)} dynamic_reconfigure "
            f"servers; subscribers {len(subscribers)}, "
            f"{len(moved)} through a transport other than raw")


def run(project: Project, jobs: int, enabled: bool,
        resolved: dict[str, list[str]]) -> Model:
    def recording(config: Configuration, *args: Any) -> Any:
        found = attach(config, *args)
        resolved.setdefault(config.name, []).extend(
            f"{instance.name}: {calls[0].location.file if calls else '(no calls)'} "
            f"({len(calls)} calls)" for instance, calls in found
            if not calls or calls[0].origin != "plugin")  # not the loading reads
        return found

    graph_build = importlib.import_module("haros_arch.graph.build")
    graph_build.attach_plugins = recording if enabled else (lambda *a: [])
    graph_build.Transports = _Recording if enabled else _BaseOnly
    _Recording.seen = []
    # the run cache keys on the environment, not on the stage switched off here: a
    # variable of our own keeps the two runs apart
    return pipeline.analyse(project, {**os.environ, "HAROS_BENCH_PLUGIN_STAGE": str(enabled)},
                            pipeline.Options(cache_dir=pipeline.AUTO_CACHE, jobs=jobs))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace")
    parser.add_argument("launch", nargs="+")
    parser.add_argument("--arg", action="append", default=[])
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--show", action="append", default=[])
    parser.add_argument("--never-read", action="store_true")
    args = parser.parse_args()
    launch_args = dict(a.split(":=", 1) for a in args.arg)
    project = Project("plugins", os.path.join(args.workspace, "bench.yaml"),
                      workspace=[os.path.abspath(args.workspace)],
                      configurations=[ConfigurationSpec(os.path.basename(launch),
                                                        launch.split("+"), dict(launch_args))
                                      for launch in args.launch])
    resolved: dict[str, list[str]] = {}
    before = run(project, args.jobs, False, {})
    after = run(project, args.jobs, True, resolved)
    for old, new in zip(before.configurations, after.configurations, strict=True):
        hosts = [n for n in new.nodes if n.origin != "plugin" and n.node is not None
                 and host_of(n.node.package, n.node.executable, n.ros_version)]
        hosts_unknown = [n for n in new.nodes if n.node is None]
        unresolved = [d for d in new.diagnostics if d.code in UNRESOLVED]
        added = [n for n in new.nodes if n.origin == "plugin"]
        print(f"{new.name}: host instances {len(hosts)} (+{len(hosts_unknown)} instances of "
              f"unknown nodes), plugins resolved {len(resolved.get(new.name, []))} "
              f"unresolved {len(unresolved)}, instances added {len(added)}, links "
              f"{len(old.links)} -> {len(new.links)} (+{len(new.links) - len(old.links)}), "
              f"set but never read {set_not_read(old)} -> {set_not_read(new)}")
        print("   " + transports_line(new, _Recording.seen))
        if args.list:
            for line in resolved.get(new.name, []):
                print("   resolved", line)
            for found in unresolved:
                print(f"   {found.code} {found.location.file}:{found.location.line} "
                      f"{found.message}")
        for node in new.nodes:
            if args.show and node.name.startswith(tuple(args.show)):
                print(f"   node {node.name} ({node.node.name if node.node else 'unknown'}, "
                      f"{node.completeness}, {node.origin})")
                for link in sorted(node.links, key=lambda k: (k.kind, k.resource.name)):
                    print(f"      {link.kind} {link.resource.name} {link.type} "
                          f"{link.location.file}:{link.location.line}")
        if args.never_read:
            for param in new.parameters:
                if param.set_by_launch and not param.is_read and "?" not in param.name:
                    where = param.launch_location
                    print(f"   never read {param.name} {where.file}:{where.line}")


if __name__ == "__main__":
    checkout.announce()
    main()
