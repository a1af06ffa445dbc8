"""compare: a service several of our nodes advertise shows one provider on the master."""

from __future__ import annotations

from haros_arch.live.compare import compare


def link(node: str, name: str) -> dict[str, str]:
    return {"kind": "server", "node": node, "name": name}


def test_only_the_provider_the_master_keeps_is_scored() -> None:
    model = {"configurations": [{
        "name": "c", "nodes": [{"name": "/a"}, {"name": "/b"}, {"name": "/c"}],
        "topics": [], "parameters": [],
        "services": [{"name": "/counter"}, {"name": "/reset"}],
        "links": [link("/a", "/counter"), link("/b", "/counter"), link("/c", "/reset"),
                  link("/a", "/reset")]}]}
    live = {"nodes": ["/a", "/b", "/c"], "topics": [], "parameters": [],
            "services": [{"name": "/counter", "servers": ["/b"]},
                         {"name": "/reset", "servers": ["/b"]}]}
    score = {s.kind: s for s in compare(model, live).scores}["service links"]
    assert score.missing == [("/b", "/reset")]  # not ours: still missing
    assert score.extra == [("/a", "/reset"), ("/c", "/reset")]
    assert score.matched == {("/b", "/counter")}  # /a's /counter is shadowed, not extra
