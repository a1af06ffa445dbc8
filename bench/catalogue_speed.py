"""Time per catalogue query on one big configuration (issue #18, #24: every query well
under a second on an Autoware-size configuration).

    .venv/bin/python bench/catalogue_speed.py [--model MODEL.json] [--nodes 500]
                                              [--parameters 1800] [--unknown 0.1]

Without ``--model`` it synthesises a configuration of Autoware's size (seeded, the same
every run): ``--nodes`` node instances in namespaces, four publishers, four subscribers
and three to four private parameter reads each, ``--parameters`` launch-set parameters
(most of them read, some set under a mistyped name, some never read), a share of nodes
of unknown interface (``--unknown``; 0 makes every absence decided, the costliest case
for pairing), a few reads of names known only at run time. With ``--model`` it reads a
saved JSON model (``haros-arch extract -o``) and times its largest configuration.
Prints seconds and findings per query, and the total.
"""

from __future__ import annotations

import argparse
import json
import random
import sys
import time
import zlib
from pathlib import Path
from typing import Any

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch.graph.candidates import find_candidates
from haros_arch.model.load import from_data
from haros_arch.model.model import Model
from haros_arch.query.catalogue import load_catalogue, run_rule

WORDS = ("pose", "twist", "scan", "points", "objects", "trajectory", "path", "odometry",
         "status", "state", "command", "control", "map", "lanelet", "route", "velocity",
         "acceleration", "steering", "image", "camera_info", "debug", "markers", "grid")
SPACES = ("/perception", "/planning", "/control", "/localization", "/sensing", "/map",
          "/system", "/vehicle", "/simulation")
TYPES = [f"pkg_{i}_msgs/msg/T{i}" for i in range(40)]


def synthesise(nodes: int, parameters: int, unknown: float) -> dict[str, Any]:
    rng = random.Random(18)
    names = [f"{rng.choice(SPACES)}/{rng.choice(WORDS)}_node_{i}" for i in range(nodes)]
    topics = [f"{rng.choice(SPACES)}/{rng.choice(WORDS)}/{rng.choice(WORDS)}_{i}"
              for i in range(nodes * 2)]
    links: list[dict[str, Any]] = []
    node_docs = []
    params: list[dict[str, Any]] = []
    for i, name in enumerate(names):
        known = rng.random() >= unknown
        node_docs.append({"name": name, "node": f"pkg{i}/exec" if known else None})
        if not known:
            continue
        for kind in ("publish", "subscribe"):
            for _ in range(4):
                topic = rng.choice(topics)
                links.append({"kind": kind, "node": name, "name": topic,
                              "given": topic.rsplit("/", 1)[-1],
                              "type": TYPES[zlib.crc32(topic.encode()) % len(TYPES)],
                              "queue_size": rng.choice((1, 10, 100))})
    per_node = max(1, parameters // max(1, nodes))
    for i in range(parameters):
        owner = names[i % nodes]
        own = f"{rng.choice(WORDS)}_{rng.choice(WORDS)}_{i // nodes}"
        read = rng.random()
        set_name = own if read < 0.9 else own[:-1] + "x" if read < 0.95 else own + "_old"
        params.append({"name": f"{owner}/{set_name}", "type": "double", "value": 1.0,
                       "writers": ["<launch>"]})
        if node_docs[i % nodes]["node"] is not None and i // nodes < per_node + 1:
            links.append({"kind": "read", "node": owner, "name": f"{owner}/{own}",
                          "given": f"~{own}", "type": "double"})
    for i in range(0, nodes, 97):  # a few reads of a name known only at run time
        links.append({"kind": "read", "node": names[i], "name": f"{names[i]}/?",
                      "given": "~?"})
    return {"configurations": [{"name": "synthetic", "nodes": node_docs,
                                "parameters": params, "links": links}]}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--model", help="a saved JSON model instead of the synthetic one")
    parser.add_argument("--nodes", type=int, default=500)
    parser.add_argument("--parameters", type=int, default=1800)
    parser.add_argument("--unknown", type=float, default=0.1)
    args = parser.parse_args()
    if args.model:
        data = json.loads(Path(args.model).read_text("utf-8"))
    else:
        data = synthesise(args.nodes, args.parameters, args.unknown)
    model: Model = from_data(data)
    config = max(model.configurations, key=lambda c: len(c.links), default=None)
    if config is None:
        sys.exit("the model has no configuration")
    if not args.model:
        find_candidates(config)
    model.configurations = [config]
    print(f"configuration {config.name}: {len(config.nodes)} nodes "
          f"({len(config.incomplete_nodes)} of partial or unknown interface), "
          f"{len(config.topics)} topics, {len(config.parameters)} parameters, "
          f"{len(config.links)} links")
    total = cpu_total = 0.0
    # CPU seconds beside the wall's: on a busy machine the wall time waits for a processor
    print(f"{'query':34} {'seconds':>8} {'CPU':>8} {'findings':>9}")
    for rule in load_catalogue():
        start, cpu = time.perf_counter(), time.process_time()
        found = run_rule(rule, model)
        spent, cpu = time.perf_counter() - start, time.process_time() - cpu
        total += spent
        cpu_total += cpu
        kinds = sorted({f.rule for f in found} - {rule.id})
        extra = f"  (+{', '.join(kinds)})" if kinds else ""
        print(f"{rule.id:34} {spent:>8.3f} {cpu:>8.3f} {len(found):>9}{extra}", flush=True)
    print(f"{'total':34} {total:>8.3f} {cpu_total:>8.3f}")


if __name__ == "__main__":
    checkout.announce()
    main()
