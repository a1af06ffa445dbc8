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
