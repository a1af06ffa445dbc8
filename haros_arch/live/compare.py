"""Compare an extracted configuration with a captured live system: precision and recall.

Several nodes may advertise the same service; the ROS 1 master keeps only the last one
to register (``lookupService`` answers one provider). A service link of ours is scored
as matched when the live provider of that service is one of our providers for it: our
other providers of the same name are neither extra nor missing (the running system
cannot show them).

A parameter counts as set by our model when a launch file or a node sets it, except when
it ends up deleted (``rospy.delete_param``, ``ros::param::del``,
``NodeHandle::deleteParam``: write links with ``deletes``). Launch files set parameters
before any node runs, so a parameter that some node deletes is gone at the end unless
some node's last write to it is a set; deleting a namespace deletes what is under it.
A node's writes are ordered by their place in one source file; when they are in several
files their order is unknown and the parameter counts as set.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

# what roscore and roslaunch add on their own
IGNORED_NODES = re.compile(r"^/rosout$")
IGNORED_TOPICS = re.compile(r"^/rosout(_agg)?$")
IGNORED_SERVICES = re.compile(r"(/get_loggers|/set_logger_level)$")
IGNORED_PARAMS = re.compile(r"^(/run_id|/rosdistro|/rosversion|/roslaunch/.*)$")


@dataclass
class Score:
    kind: str
    ours: set[Any] = field(default_factory=set)
    live: set[Any] = field(default_factory=set)

    @property
    def matched(self) -> set[Any]:
        return self.ours & self.live

    @property
    def precision(self) -> float:
        return len(self.matched) / len(self.ours) if self.ours else 1.0

    @property
    def recall(self) -> float:
        return len(self.matched) / len(self.live) if self.live else 1.0

    @property
    def missing(self) -> list[Any]:
        return sorted(self.live - self.ours, key=str)

    @property
    def extra(self) -> list[Any]:
        return sorted(self.ours - self.live, key=str)


@dataclass
class Comparison:
    configuration: str
    scores: list[Score]

    def to_data(self) -> dict[str, Any]:
        return {"configuration": self.configuration, "scores": [
            {"kind": s.kind, "ours": len(s.ours), "live": len(s.live),
             "matched": len(s.matched), "precision": round(s.precision, 4),
             "recall": round(s.recall, 4), "missing": [show(x) for x in s.missing],
             "extra": [show(x) for x in s.extra]} for s in self.scores]}


def show(item: Any) -> str:
    """An element as text: a link ``(node, name)`` is written ``node name``."""
    return " ".join(item) if isinstance(item, tuple) else str(item)


class CompareError(Exception):
    pass


def _configuration(model: dict[str, Any], name: str | None) -> dict[str, Any]:
    configs = model.get("configurations", [])
    if not configs:
        raise CompareError("the model has no configurations")
    if name is None:
        return configs[0]
    for config in configs:
        if config["name"] == name:
            return config
    raise CompareError(f"no configuration named {name} "
                       f"(have: {', '.join(c['name'] for c in configs)})")


def compare(model: dict[str, Any], live: dict[str, Any], name: str | None = None) -> Comparison:
    """Score one configuration of a model (JSON data) against a capture (JSON data)."""
    config = _configuration(model, name)
    links = config.get("links", [])

    def ours_links(kind: str) -> set[tuple[str, str]]:
        return {(link["node"], link["name"]) for link in links if link["kind"] == kind}

    live_topics = [t for t in live["topics"] if not IGNORED_TOPICS.match(t["name"])]
    live_servers = {s["name"]: set(s["servers"]) for s in live["services"]}
    live_nodes = {n for n in live["nodes"] if not IGNORED_NODES.match(n)}
    scores = [
        Score("nodes", {n["name"] for n in config["nodes"]}, live_nodes),
        Score("topics", {t["name"] for t in config["topics"]},
              {t["name"] for t in live_topics}),
        Score("topic types", {(t["name"], ty) for t in config["topics"] for ty in t["types"]},
              {(t["name"], ty) for t in live_topics for ty in t["types"]}),
        Score("publish links", ours_links("publish"),
              {(n, t["name"]) for t in live_topics for n in t["publishers"]
               if not IGNORED_NODES.match(n)}),
        Score("subscribe links", ours_links("subscribe"),
              {(n, t["name"]) for t in live_topics for n in t["subscribers"]
               if not IGNORED_NODES.match(n)}),
        Score("services", {s["name"] for s in config["services"]},
              {s["name"] for s in live["services"]
               if not IGNORED_SERVICES.search(s["name"])}),
        Score("service links", _shadowed(ours_links("server"), live_servers),
              {(n, s["name"]) for s in live["services"] for n in s["servers"]
               if not IGNORED_SERVICES.search(s["name"])}),
        # only parameters someone sets can be on the master (code defaults are not), and
        # only leaves (a namespace read whole shows as its leaves)
        Score("parameters", _leaf_parameters(config),
              {p["name"] for p in live["parameters"]
               if not IGNORED_PARAMS.match(p["name"])}),
    ]
    return Comparison(config["name"], scores)


def _shadowed(ours: set[tuple[str, str]],
              live: dict[str, set[str]]) -> set[tuple[str, str]]:
    """Our service links without the providers the master cannot show: of several of our
    nodes serving one name, only the one the master holds is kept."""
    return {(node, name) for node, name in ours
            if not live.get(name) or node in live[name]
            or not any((other, name) in ours for other in live[name])}


def _leaf_parameters(config: dict[str, Any]) -> set[str]:
    deleted = _deleted_parameters(config.get("links", []))
    names = {p["name"] for p in config["parameters"] if p["writers"]
             and not any(p["name"] == d or p["name"].startswith(d.rstrip("/") + "/")
                         for d in deleted)}
    return {name for name in names
            if not any(other.startswith(name.rstrip("/") + "/") for other in names)}


def _deleted_parameters(links: list[dict[str, Any]]) -> set[str]:
    """Parameters some node deletes and no node sets after (or without) deleting."""
    writes: dict[str, dict[str, list[dict[str, Any]]]] = {}
    for link in links:
        if link["kind"] == "write":
            writes.setdefault(link["name"], {}).setdefault(link["node"], []).append(link)
    return {name for name, by_node in writes.items()
            if any(w.get("deletes") for ws in by_node.values() for w in ws)
            and not any(_sets_last(ws) for ws in by_node.values())}


def _sets_last(writes: list[dict[str, Any]]) -> bool:
    """Whether one node's last write to a parameter sets it (in doubt: yes)."""
    if all(w.get("deletes") for w in writes):
        return False
    files = {(w.get("location") or {}).get("file") for w in writes}
    if len(files) != 1 or None in files:
        return True
    last = max(writes, key=lambda w: ((w.get("location") or {}).get("line") or 0,
                                      (w.get("location") or {}).get("column") or 0))
    return not last.get("deletes")
