"""A finding about a call an interface model makes (an installed package's node, its
code not in the workspace) points at the launch file's node, where the user can act:
not at the model's source file, a path of the upstream repository that the workspace
does not hold (a SARIF viewer cannot open it); the code's place stays in the model."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.command import check


def test_a_modelled_subscription_without_publisher_points_at_the_launch_file(
        write_tree) -> None:
    root = write_tree({
        "src/viz/package.xml": package_xml("viz"),
        "src/viz/launch/view.launch": (
            "<launch>\n"
            "  <param name=\"robot_description\" value=\"&lt;robot name='r'/&gt;\"/>\n"
            "  <node name=\"rsp\" pkg=\"robot_state_publisher\"\n"
            "        type=\"robot_state_publisher\"/>\n"
            "</launch>\n"),
        "project.yaml": (
            "project: p\nworkspace: src\ndistro: noetic\n"
            "configurations:\n  c: [viz/launch/view.launch]\n"),
    })
    spec = load(str(root / "project.yaml"))
    model = analyse(spec, {}, Options(cache_dir=None, jobs=1))
    (instance,) = [n for n in model.configurations[0].nodes if n.name == "/rsp"]
    assert instance.node is not None and instance.node.model  # the noetic model's
    (link,) = [k for k in instance.links if k.kind == "subscribe"]
    assert link.origin == "model" and link.location.package == "robot_state_publisher"
    found = [f for f in check(model, spec).findings
             if f.rule == "subscriber-without-publisher" and "/joint_states" in f.message]
    assert len(found) == 1
    assert found[0].location.file.endswith("viz/launch/view.launch")
    assert found[0].location.line == 3
