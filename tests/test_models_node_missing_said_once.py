"""A launched executable the interface model of its package lacks is said once, as the
model's gap (``MODEL_NODE_MISSING``), not also as a package neither in the workspace nor
installed: stretch_calibration's launch files start robot_state_publisher's old
``state_publisher``, which noetic's release no longer installs."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load


def test_a_node_the_model_lacks_is_not_an_unknown_package(write_tree) -> None:
    root = write_tree({
        "src/cal/package.xml": package_xml("cal"),
        "src/cal/launch/view.launch": (
            "<launch>\n"
            "  <node name=\"rsp\" pkg=\"robot_state_publisher\" type=\"state_publisher\"/>\n"
            "  <node name=\"other\" pkg=\"no_such_package\" type=\"x\"/>\n"
            "</launch>\n"),
        "project.yaml": (
            "project: p\nworkspace: src\ndistro: noetic\n"
            "configurations:\n  c: [cal/launch/view.launch]\n"),
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    said = sorted((d.code, d.location.line) for d in config.diagnostics
                  if d.code in ("MODEL_NODE_MISSING", "NODE_PACKAGE_UNKNOWN"))
    assert said == [("MODEL_NODE_MISSING", 2), ("NODE_PACKAGE_UNKNOWN", 3)]
