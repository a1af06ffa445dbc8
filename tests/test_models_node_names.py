"""A model's node name built from a namespace passed as ``""`` (nav2's jazzy models:
``LifecycleNode(name, ns = "")`` written as ``//controller_server``) reads as the
extraction writes it now, ``controller_server``: a launch ``Node`` without ``name=``
made ``//controller_server`` of it (stretch_nav2's navigation_launch.py:86)."""

from __future__ import annotations

from haros_arch.models.format import from_document
from haros_arch.models.library import Library


def _model(rosname: str):
    return from_document({"schema": "haros-arch-model/2", "package": "srv", "nodes": [
        {"name": "srv/server", "package": "srv", "executable": "server", "kind": "executable",
         "language": "cpp", "rosname": rosname, "calls": []}]})


def test_a_namespace_given_empty_adds_no_slash() -> None:
    assert _model("//controller_server").nodes[0].rosname == "controller_server"
    assert _model("//robot/server").nodes[0].rosname == "/robot/server"
    assert _model("/robot/server").nodes[0].rosname == "/robot/server"


def test_the_shipped_nav2_models_name_their_servers_without_a_double_slash() -> None:
    model = Library().find("nav2_controller", "jazzy")
    assert model is not None
    assert {n.rosname for n in model.nodes if n.rosname} == {"controller_server"}
