"""Shipped interface models rebuilt at their pinned commits with a later extractor: what
the rebuild changed, as the extractor's fixes say it should."""

from __future__ import annotations

from haros_arch.models.library import Library


def test_the_shipped_realsense_model_is_partial_only_for_its_build_macro() -> None:
    # rebuilt at its pinned commit after the fiftieth session's fixes: librealsense's
    # base classes run no ROS call, and ``sensor.rs2::sensor::is<T>()`` parses
    model = Library().find("realsense2_camera", "jazzy")
    assert model is not None
    (node,) = [n for n in model.nodes if n.executable == "realsense2_camera_node"]
    reasons = " ".join(node.completeness_reasons)
    assert "is given to" not in reasons and "cannot refer to member" not in reasons
    assert "ACCELERATE_GPU_WITH_GLSL" in reasons


def test_the_shipped_teb_model_subscribes_to_the_odometry_its_settings_name() -> None:
    # teb_local_planner noetic-devel b68c3288: TebConfig's constructor writes
    # odom_topic = "odom", loadRosParamFromNodeHandle (another source) reads the
    # parameter into it, and the planner subscribes to cfg_.odom_topic: not known here,
    # not the constructor's text
    model = Library().find("teb_local_planner", "noetic")
    assert model is not None
    (plugin,) = [n for n in model.nodes if n.kind == "plugin"]
    assert plugin.plugin_class == "teb_local_planner::TebLocalPlannerROS"
    subscribed = sorted(c.name for c in plugin.calls if c.kind == "subscribe")
    assert subscribed == ["?", "~?/obstacles", "~?/via_points"]
    assert "~?/odom_topic" in {c.name for c in plugin.calls if c.kind == "read"}
