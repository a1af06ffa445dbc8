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

A ROS 2 capture (``"ros": 2``, from DDS discovery or a bag) also scores service clients,
actions and QoS, and says which kinds it can see at all (``observed``: a bag shows no
subscribers, DDS discovery no parameters); only those are scored. A QoS policy that the
model gives a publish or subscribe link is a difference when no live endpoint of that node
on that topic offers it; a policy the middleware does not announce is not compared.
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
# what every ROS 2 node has (rcl's rosout and parameter services), rosbag2's recorder's
# split events, and the nodes that tools make on their own: the ros2 CLI's daemon,
# `ros2 launch`'s launch_ros_<pid>, the hidden node of a Humble tf2_ros TransformListener
IGNORED_ROS2_NODES = re.compile(r"^/(_ros2cli_|launch_ros_\d+$|transform_listener_impl_)")
IGNORED_ROS2_TOPICS = re.compile(r"^/(rosout|parameter_events|events/write_split)$")
IGNORED_ROS2_SERVICES = re.compile(
    r"/(describe_parameters|get_parameter_types|get_parameters|list_parameters"
    r"|set_parameters|set_parameters_atomically|get_type_description)$")
# what a ROS 1 master shows (a capture from before "observed" existed)
ROS1_KINDS = ("nodes", "topics", "topic types", "publish links", "subscribe links",
              "services", "service links", "parameters")
# QoS policy values that say nothing about what an endpoint offers
VAGUE_QOS = (None, "system_default", "unknown", "best_available")


@dataclass
class Score:
    kind: str
    ours: set[Any] = field(default_factory=set)
    live: set[Any] = field(default_factory=set)
    # for a kind whose elements pair up (a QoS policy: ours and live value), each difference
    # once, in place of the missing and extra elements
    differs: list[str] | None = None

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
        """Per kind: the scores and the elements only live (``missing``), only in the model
        (``extra``) and in both."""
        return {"configuration": self.configuration, "scores": [
            {"kind": s.kind, "ours": len(s.ours), "live": len(s.live),
             "matched": len(s.matched), "precision": round(s.precision, 4),
             "recall": round(s.recall, 4), "missing": [show(x) for x in s.missing],
             "extra": [show(x) for x in s.extra],
             "both": [show(x) for x in sorted(s.matched, key=str)],
             **({"differs": s.differs} if s.differs is not None else {})}
            for s in self.scores]}


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
    ros2 = live.get("ros") == 2
    ignored_nodes = IGNORED_ROS2_NODES if ros2 else IGNORED_NODES
    ignored_topics = IGNORED_ROS2_TOPICS if ros2 else IGNORED_TOPICS
    ignored_services = IGNORED_ROS2_SERVICES if ros2 else IGNORED_SERVICES
    observed = set(live.get("observed") or ROS1_KINDS)

    def ours_links(kind: str) -> set[tuple[str, str]]:
        return {(link["node"], link["name"]) for link in links if link["kind"] == kind}

    def live_links(records: list[dict[str, Any]], key: str) -> set[tuple[str, str]]:
        return {(n, r["name"]) for r in records for n in r.get(key) or ()
                if not ignored_nodes.match(n)}

    live_topics = [t for t in live["topics"] if not ignored_topics.match(t["name"])]
    live_services = [s for s in live["services"] if not ignored_services.search(s["name"])]
    live_servers = {s["name"]: set(s["servers"]) for s in live["services"]}
    live_nodes = {n for n in live["nodes"] if not ignored_nodes.match(n)}
    live_actions = live.get("actions") or []
    scores = [
        Score("nodes", {n["name"] for n in config["nodes"]}, live_nodes),
        Score("topics", {t["name"] for t in config["topics"]},
              {t["name"] for t in live_topics}),
        Score("topic types", {(t["name"], ty) for t in config["topics"] for ty in t["types"]},
              {(t["name"], ty) for t in live_topics for ty in t["types"]}),
        Score("publish links", ours_links("publish"), live_links(live_topics, "publishers")),
        Score("subscribe links", ours_links("subscribe"),
              live_links(live_topics, "subscribers")),
        Score("services", {s["name"] for s in config["services"]},
              {s["name"] for s in live_services}),
        Score("service types", _typed(config["services"]), _typed(live_services)),
        Score("service links", _shadowed(ours_links("server"), live_servers),
              live_links(live_services, "servers")),
        Score("service client links", ours_links("client"),
              live_links(live_services, "clients")),
        Score("actions", {a["name"] for a in config.get("actions", [])},
              {a["name"] for a in live_actions}),
        Score("action types", _typed(config.get("actions", [])), _typed(live_actions)),
        Score("action server links", ours_links("action-server"),
              live_links(live_actions, "servers")),
        Score("action client links", ours_links("action-client"),
              live_links(live_actions, "clients")),
        _qos_score(links, live_topics),
    ]
    if live.get("parameters") is not None:
        # only parameters someone sets can be on the master (code defaults are not), and
        # only leaves (a namespace read whole shows as its leaves)
        scores.append(Score("parameters", _leaf_parameters(config),
                            {p["name"] for p in live["parameters"]
                             if not IGNORED_PARAMS.match(p["name"])}))
    return Comparison(config["name"], [s for s in scores if _observed(s.kind, observed)])


def compare_all(model: dict[str, Any], live: dict[str, Any]) -> dict[str, dict[str, Any]]:
    """Every configuration of a model against one capture, as data by configuration name
    (what the HTML report shows beside each configuration's graph)."""
    return {config["name"]: compare(model, live, config["name"]).to_data()
            for config in model.get("configurations", [])}


def _typed(records: list[dict[str, Any]]) -> set[tuple[str, str]]:
    return {(r["name"], ty) for r in records for ty in r.get("types") or ()}


def _observed(kind: str, observed: set[str]) -> bool:
    """Whether the capture can see this kind (one that sees actions sees their types and
    servers and clients too)."""
    return kind in observed or (kind.startswith("action ") and "actions" in observed)


def _qos_score(links: list[dict[str, Any]], live_topics: list[dict[str, Any]]) -> Score:
    """Each QoS policy of a model link whose node is seen on that topic, against the values
    that node's live endpoints there offer (a policy they do not announce is left out). An
    endpoint that no node claims (a ROS 2 bag's, a participant without
    ``ros_discovery_info``) stands for every node of the model there that has no endpoint."""
    offered: dict[tuple[str | None, str, str], list[dict[str, Any]]] = {}
    for topic in live_topics:
        for end in topic.get("endpoints") or ():
            if end.get("qos") is not None:
                offered.setdefault((end.get("node"), topic["name"], end["kind"]), []).append(
                    end["qos"])
    score, differs = Score("qos"), set()
    for link in links:
        key = (link["node"], link["name"], link["kind"])
        ends = offered.get(key) or offered.get((None, *key[1:]))
        if link["kind"] not in ("publish", "subscribe") or not link.get("qos") or not ends:
            continue
        for policy, value in sorted(link["qos"].items()):
            if value in VAGUE_QOS or (policy == "depth" and
                                      link["qos"].get("history") != "keep_last"):
                continue
            values = [q[policy] for q in ends if policy in q]
            if not values:
                continue
            score.ours.add((*key, f"{policy}={value}"))
            score.live.update((*key, f"{policy}={v}") for v in values)
            if value not in values:
                differs.add(f"{link['node']} {link['name']} {link['kind']} {policy}: model "
                            f"{value}, live {', '.join(sorted({str(v) for v in values}))}")
    score.differs = sorted(differs)
    return score


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
