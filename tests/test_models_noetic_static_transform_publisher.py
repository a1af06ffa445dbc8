"""The shipped noetic model of tf2_ros' static_transform_publisher is whole: the only
ROS call it lacked is the library's ``/tf_static`` advertise in the broadcaster's
constructor, which the model has where the program builds the broadcaster
(``models/overrides/noetic/tf2_ros.yaml``). Every ROS 1 launch file's static transform
(underwater_simulation's four per scene, and most robots') was a partial node, so
checks that claim something is absent did not decide on it."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.models.library import Library
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load


def test_the_shipped_model_is_complete_and_publishes_tf_static():
    found = Library().find("tf2_ros", "noetic")
    assert found is not None
    node = next(n for n in found.nodes if n.executable == "static_transform_publisher")
    assert node.completeness == "complete"
    assert [(c.kind, c.name, c.latch) for c in node.calls if c.kind == "publish"] == [
        ("publish", "/tf_static", True)]


def test_a_launched_static_transform_publisher_is_no_partial_node(write_tree):
    root = write_tree({
        "src/scene/package.xml": package_xml("scene"),
        "src/scene/launch/scene.launch": """
            <launch>
              <node pkg="tf2_ros" type="static_transform_publisher" name="world_to_map"
                    args="0 0 0 0 0 0 world map"/>
            </launch>
            """,
        "project.yaml": "project: p\ndistro: noetic\nconfigurations:\n"
                        "  c: [scene/launch/scene.launch]\n"})
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (instance,) = config.nodes
    assert instance.completeness == "model"
    assert [(link.kind, link.resource.name) for link in instance.links
            if link.kind == "publish"] == [("publish", "/tf_static")]
