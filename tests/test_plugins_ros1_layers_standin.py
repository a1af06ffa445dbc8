"""Costmap layers and a planner for ROS 1 move_base whose base packages (costmap_2d,
nav_core) are installed, not in the workspace, as fetch_ros' depth layer and
navigation_layers' range and social layers are. The stand-ins of costmap_2d and nav_core
declare the layers' bases and their members (``name_``, ``layered_costmap_``, ``tf_``,
``global_frame_``, the observation buffers), so the plugins parse: before, each use of a
base member was an undeclared identifier beside the ROS calls, and the plugins were
partial. A layer declared in costmap_2d's namespace names its base without one
(``public VoxelLayer``): it runs the modelled VoxelLayer's code, its observation
sources among it. A node that builds the costmap node's wrapper itself (Costmap2DROS,
whose code is not read) stays partial."""

from __future__ import annotations

from pathlib import Path

import pytest

from haros_arch.api import analyse_path
from haros_arch.pipeline import Options

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "ros1_layers"


@pytest.fixture(scope="module")
def analysis():  # type: ignore[no-untyped-def]
    found = analyse_path(str(FIXTURE), Options(cache_dir=None, jobs=1))
    assert found.model is not None
    return found


def _links(analysis, node: str) -> set[tuple[str, str, str | None]]:  # type: ignore[no-untyped-def]
    (config,) = analysis.model.configurations
    return {(link.kind, link.resource.name, link.type) for link in config.links
            if link.node.name == node}


def test_the_layers_parse_clean_and_are_complete(analysis) -> None:  # type: ignore[no-untyped-def]
    codes = {(d.code, d.location.file) for d in analysis.model.diagnostics
             if d.location.file.startswith("my_layers/")}
    assert not {code for code, _ in codes} & {
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_INCLUDE_MISSING"}
    assert ("CPP_NODE_PARTIAL", "my_layers/layers.xml") not in codes
    assert ("CPP_NODE_PARTIAL", "my_layers/planners.xml") not in codes


def test_a_layer_s_calls_are_under_its_plugin_name(analysis) -> None:  # type: ignore[no-untyped-def]
    links = _links(analysis, "/move_base")
    sonar = "/move_base/global_costmap/sonar"
    assert ("subscribe", "/sonar_front", "sensor_msgs/Range") in links
    assert ("read", f"{sonar}/topic", "str") in links
    assert ("read", f"{sonar}/clear_threshold", "double") in links
    # the dynamic_reconfigure server of costmap_2d's GenericPluginConfig reads its one
    # parameter where the layer's handle is
    assert ("read", f"{sonar}/enabled", "bool") in links
    assert ("server", f"{sonar}/set_parameters", "dynamic_reconfigure/Reconfigure") in links


def test_a_layer_derived_from_voxel_layer_in_its_namespace_runs_the_base(analysis) -> None:  # type: ignore[no-untyped-def]
    links = _links(analysis, "/move_base")
    obstacles = "/move_base/global_costmap/obstacles"
    # its own code
    assert ("subscribe", "/head_camera/depth/image", "sensor_msgs/Image") in links
    assert ("read", f"{obstacles}/depth_topic", "str") in links
    # the base's (VoxelLayer's model, ObstacleLayer's onInitialize in it): the
    # parameters and one subscription per observation source
    assert ("subscribe", "/base_scan", "sensor_msgs/LaserScan") in links
    assert ("read", f"{obstacles}/observation_sources", "str") in links
    assert ("read", f"{obstacles}/z_voxels", "int") in links


def test_a_planner_on_nav_core_reads_under_its_name(analysis) -> None:  # type: ignore[no-untyped-def]
    links = _links(analysis, "/move_base")
    assert ("read", "/move_base/StraightPlanner/step", "double") in links
    assert ("publish", "/move_base/StraightPlanner/plan", "nav_msgs/Path") in links


def test_a_node_that_builds_a_costmap_of_its_own_is_partial(analysis) -> None:  # type: ignore[no-untyped-def]
    said = [(d.code, d.location.file, d.location.line) for d in analysis.model.diagnostics]
    assert ("CPP_CLASS_UNSEEN", "my_layers/src/costmap_tool.cpp", 13) in said
    assert ("CPP_NODE_PARTIAL", "my_layers/CMakeLists.txt", 9) in said
    assert ("publish", "/free_ratio", "std_msgs/Float64") in _links(analysis, "/costmap_tool")
