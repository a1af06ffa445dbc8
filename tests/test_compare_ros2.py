"""compare on ROS 2 captures, from data: which QoS policies count, and what is scored."""

from __future__ import annotations

import json

from haros_arch.cli import main
from haros_arch.live.compare import compare


def link(kind: str, node: str, name: str, **qos) -> dict:
    return {"kind": kind, "node": node, "name": name, "qos": qos or None}


def model(*links: dict) -> dict:
    nodes = sorted({item["node"] for item in links})
    topics = sorted({item["name"] for item in links})
    return {"configurations": [{
        "name": "c", "nodes": [{"name": n} for n in nodes],
        "topics": [{"name": t, "types": []} for t in topics], "services": [],
        "actions": [], "parameters": [], "links": list(links)}]}


def live(*endpoints: tuple[str, str | None, str, dict]) -> dict:
    topics: dict[str, dict] = {}
    for name, node, kind, qos in endpoints:
        topic = topics.setdefault(name, {"name": name, "types": [], "publishers": [],
                                         "subscribers": [], "endpoints": []})
        if node:
            topic["publishers" if kind == "publish" else "subscribers"].append(node)
        topic["endpoints"].append({"kind": kind, "node": node, "qos": qos})
    return {"schema": "haros-arch-live/1", "ros": 2,
            "observed": ["nodes", "topics", "publish links", "qos"],
            "nodes": sorted({e[1] for e in endpoints if e[1]}),
            "topics": list(topics.values()), "services": [], "actions": [],
            "parameters": None}


def qos_score(model_data: dict, live_data: dict):
    return next(s for s in compare(model_data, live_data).scores if s.kind == "qos")


def test_only_what_both_sides_state_is_compared():
    ours = model(link("publish", "/a", "/x", reliability="system_default", depth=5,
                      history="keep_all", durability="transient_local"))
    # the live side does not announce durability (another vendor): nothing to compare
    # there; system_default says nothing; a depth under keep_all means nothing
    score = qos_score(ours, live(("/x", "/a", "publish", {"reliability": "reliable",
                                                         "depth": 1, "history": "keep_all"})))
    assert score.ours == {("/a", "/x", "publish", "history=keep_all")}
    assert score.differs == []


def test_a_policy_no_live_endpoint_offers_is_one_difference():
    ours = model(link("publish", "/a", "/x", reliability="reliable", durability="volatile"))
    score = qos_score(ours, live(
        ("/x", "/a", "publish", {"reliability": "best_effort", "durability": "volatile"}),
        ("/x", "/a", "publish", {"reliability": "best_effort", "durability": "volatile"})))
    assert score.differs == ["/a /x publish reliability: model reliable, live best_effort"]
    # one of the node's endpoints offering it is enough
    score = qos_score(ours, live(
        ("/x", "/a", "publish", {"reliability": "best_effort"}),
        ("/x", "/a", "publish", {"reliability": "reliable"})))
    assert score.differs == []


def test_unowned_endpoints_stand_for_nodes_without_their_own():
    ours = model(link("publish", "/a", "/x", reliability="reliable"),
                 link("publish", "/b", "/x", reliability="reliable"))
    score = qos_score(ours, live(
        ("/x", "/a", "publish", {"reliability": "reliable"}),
        ("/x", None, "publish", {"reliability": "best_effort"})))
    assert score.differs == ["/b /x publish reliability: model reliable, live best_effort"]


def test_only_the_observed_kinds_are_scored():
    ours = model(link("subscribe", "/a", "/x"))
    kinds = [s.kind for s in compare(ours, live(("/x", "/b", "publish", {}))).scores]
    assert kinds == ["nodes", "topics", "publish links", "qos"]


def test_a_capture_of_the_wrong_shape_is_a_usage_error(tmp_path, capsys):
    (tmp_path / "model.json").write_text(json.dumps(model(link("publish", "/a", "/x"))))
    (tmp_path / "live.json").write_text(json.dumps({"nodes": 5, "topics": [3],
                                                    "services": []}))
    assert main(["compare", str(tmp_path / "model.json"), str(tmp_path / "live.json")]) == 2
    assert "cannot compare" in capsys.readouterr().err
    assert main(["report", "--model", str(tmp_path / "model.json"), "--live",
                 str(tmp_path / "live.json"), "-o", str(tmp_path / "r.html")]) == 2
    assert "cannot compare" in capsys.readouterr().err
