"""A costmap layer of the workspace derived from navigation2's ObstacleLayer, whose
package is not in the workspace (rtabmap_costmap_plugins' VoxelLayer): the stand-in of
nav2_costmap_2d declares the obstacle layer, its observations and buffers, so the derived
class parses (its declareParameter calls were "undeclared identifier" errors, its
parameters and publishers lost), and the layer subscribes to each of its observation
sources as the base's onInitialize, which it runs, does."""

from __future__ import annotations

from pathlib import Path

from haros_arch.api import analyse_path
from haros_arch.pipeline import Options

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "derived_layer"


def test_a_layer_derived_from_the_obstacle_layer_has_its_calls_and_its_sources() -> None:
    analysis = analyse_path(str(FIXTURE), Options(cache_dir=None, jobs=1))
    assert analysis.model is not None
    (config,) = analysis.model.configurations
    costmap = "/global_costmap/global_costmap"
    links = {(link.kind, link.resource.name, link.type) for link in config.links
             if link.node.name == costmap}
    # the base's subscriptions, one per observation source, of the type it names
    assert ("subscribe", "/front/scan", "sensor_msgs/msg/LaserScan") in links
    assert ("subscribe", "/camera/depth/points", "sensor_msgs/msg/PointCloud2") in links
    # the derived class's own code: its parameters, and its publisher under the
    # parameter it declares true
    assert ("publish", "/global_costmap/marked_points", "sensor_msgs/msg/PointCloud2") in links
    names = {name for kind, name, _type in links if kind in ("read", "declare")}
    assert {f"{costmap}/height_layer.band_margin",
            f"{costmap}/height_layer.publish_marked",
            f"{costmap}/height_layer.front_scan.topic",
            f"{costmap}/height_layer.observation_sources"} <= names
    codes = [d.code for d in analysis.model.diagnostics
             if d.location.file.startswith("my_layers/")]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
