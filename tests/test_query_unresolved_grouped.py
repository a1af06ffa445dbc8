"""unresolved-names reports the names with '?' one call of a node instance makes once:
depthai_ros_driver (9132443) reads hundreds of parameters through declareAndLogParam,
``baseName + "." + paramName`` with the base not known, at one line of a header, and an
rclcpp parameter client for a node not known makes six services; check said 2,184 infos
on the tree, one per name. Calls at two places, and one place in two node instances,
stay apart."""

from __future__ import annotations

from test_query_catalogue import configuration

from haros_arch.query.catalogue import load_catalogue, run_rule

RULE = {r.id: r for r in load_catalogue()}["unresolved-names"]


def _link(node: str, name: str, line: int, kind: str = "read") -> dict:
    return {"kind": kind, "node": node, "name": f"/{node.strip('/')}/{name}",
            "given": f"~/{name}", "type": "int",
            "location": {"package": "p", "file": "h.hpp", "line": line}}


def test_the_names_of_one_call_are_one_finding() -> None:
    model = configuration({"links": [
        *(_link("/oak", f"?.{p}", 81) for p in ("a", "b", "c", "d", "e", "f", "g")),
        _link("/oak", "?.other", 90), *(_link("/lite", f"?.{p}", 81) for p in ("a", "b"))]})
    found = run_rule(RULE, model)
    assert [(f.location.line, f.message) for f in found] == [
        (81, "/oak: read name ~/?.a resolves to /oak/?.a; the same call makes 6 more such "
             "names: read ~/?.b, read ~/?.c, read ~/?.d, read ~/?.e and 2 more"),
        (81, "/lite: read name ~/?.a resolves to /lite/?.a; the same call makes 1 more such "
             "name: read ~/?.b"),
        (90, "/oak: read name ~/?.other resolves to /oak/?.other")]
