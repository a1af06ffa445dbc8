"""A ROS 1 costmap without ``plugins`` makes its layers from the pre-Hydro parameters
(costmap_2d's loadOldParameters): a static layer when ``static_map`` is true, an
obstacle (or voxel) layer reading the sources set in the costmap's own namespace, and
an inflation layer. move_base here is the shipped noetic model."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

LAUNCH = """
    <launch>
      <node pkg="move_base" type="move_base" name="move_base">
        <rosparam ns="global_costmap">
          static_map: true
          observation_sources: laser
          laser: {{data_type: LaserScan, topic: base_scan}}
          {extra}
        </rosparam>
        <rosparam ns="local_costmap">
          static_map: false
          map_type: voxel
          observation_sources: cloud
          cloud: {{data_type: PointCloud2, topic: /points}}
        </rosparam>
      </node>
    </launch>
    """


def _subscribed(write_tree, extra: str = "") -> dict[str, set[str]]:
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/nav.launch": LAUNCH.format(extra=extra),
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/nav.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    out: dict[str, set[str]] = {}
    for link in config.links:
        if link.node.name == "/move_base" and link.kind == "subscribe":
            out.setdefault(link.name, set()).add(str(link.location.file))
    return out


def test_pre_hydro_costmap_parameters_make_the_layers(write_tree):
    subscribed = _subscribed(write_tree)
    assert "/map" in subscribed                # the global costmap's static layer
    assert "/base_scan" in subscribed  # its obstacle layer's source (a global handle), moved
    assert "/points" in subscribed             # the local costmap's voxel layer


def test_a_plugins_list_is_used_as_it_is(write_tree):
    subscribed = _subscribed(write_tree, "plugins: [{name: inflation, type: "
                                         "'costmap_2d::InflationLayer'}]")
    assert "/map" not in subscribed and "/base_scan" not in subscribed
    assert "/points" in subscribed


def test_a_source_s_settings_are_read_in_its_turn_of_the_loop(write_tree):
    """The obstacle layer reads each source's settings in its loop over the sources
    (``while (ss >> source)``, obstacle_layer.cpp:85); the copy of those reads made for a
    listed source is that source's turn, made, not under the loop (they were: every
    source setting of a ROS 1 navigation configuration was undecided)."""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/nav.launch": LAUNCH.format(extra=""),
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/nav.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    reads = [link for link in config.links if link.node.name == "/move_base"
             and link.kind == "read" and "/obstacle_layer/laser/" in link.name]
    assert {link.name.rsplit("/", 1)[1] for link in reads} >= {"topic", "data_type",
                                                                "marking", "clearing"}
    assert all(c.statement not in ("while", "for", "for each")
               for link in reads for c in link.conditions)
    # the one search in the loop keeps its own if; it starts at the source's handle
    # (obstacle_layer/laser) and finds the obstacle_range loadOldParameters moved to
    # the layer
    searched = [link for link in config.links if link.node.name == "/move_base"
                and link.kind == "read" and "/obstacle_layer/" in link.name]
    assert any(c.text.startswith("source_node.searchParam") for link in searched
               for c in link.conditions)


def test_a_source_searches_its_layer_for_a_setting_it_does_not_have(write_tree):
    """ObstacleLayer's ``source_node.searchParam("obstacle_range", ...)`` on the handle
    ``NodeHandle(nh, source)``: roscpp searches from that handle's namespace up, so a
    layer's own obstacle_range serves every source without one. It was searched for as
    the key ``laser/obstacle_range`` from the node's namespace: the layer's value was
    set but never read, and the source's read of a parameter nobody sets."""
    launch = """<launch>
      <node pkg="move_base" type="move_base" name="move_base">
        <rosparam ns="local_costmap">
          plugins: [{name: obstacle_layer, type: 'costmap_2d::ObstacleLayer'}]
          obstacle_layer:
            obstacle_range: 2.5
            observation_sources: laser
            laser: {data_type: LaserScan, topic: base_scan}
        </rosparam>
      </node>
    </launch>"""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/nav.launch": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/nav.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    layer = config.parameter("/move_base/local_costmap/obstacle_layer/obstacle_range")
    assert layer is not None and layer.is_read
    assert config.parameter(
        "/move_base/local_costmap/obstacle_layer/laser/obstacle_range") is None


def test_the_old_parameters_are_moved_only_when_no_plugins_are_given(write_tree):
    """Costmap2DROS moves pre-hydro parameters ``if (!private_nh.hasParam("plugins"))``
    and sets ``plugins`` itself in that branch (loadOldParameters): a write after the
    test, which the test cannot see. With no ``plugins`` given the branch runs (the
    move of each observation source, ``~global_costmap/laser``, is made); with them it
    does not (the condition was left undecided by that write, and every parameter the
    move may read was undecided with it)."""
    def moves(extra: str) -> dict[str, tuple[str, ...]]:
        root = write_tree({
            "src/nav/package.xml": package_xml("nav"),
            "src/nav/CMakeLists.txt": "project(nav)\n",
            "src/nav/launch/nav.launch": LAUNCH.format(extra=extra),
            "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/nav.launch]\n",
        })
        model = analyse(load(str(root / "project.yaml")), {},
                        Options(cache_dir=None, jobs=1))
        (config,) = model.configurations
        return {link.name: tuple(c.text for c in link.conditions)
                for link in config.links if link.node.name == "/move_base"
                and link.kind == "read" and link.name.endswith("/global_costmap/laser")}
    assert moves("") == {"/move_base/global_costmap/laser": ()}
    assert moves("plugins: [{name: obstacles, type: 'costmap_2d::ObstacleLayer'}]") == {}


def test_the_moved_sources_are_read_whole_and_not_where_they_were(write_tree):
    """navigation_tutorials 115e46e's navigation_stage sets a pre-Hydro costmap's source
    in the costmap's namespace (``base_scan: {data_type: LaserScan, marking: true, ...}``
    with no ``topic``). loadOldParameters' move_parameter reads the source's namespace
    whole (``getParam(name, XmlRpcValue)`` after ``hasParam(name)``) and the obstacle
    layer reads each setting where the move put it. Every setting was "set but never
    read" (the move's presence test, which reads the keys alone, stood for both reads)
    and ``global_costmap/laser/topic`` "read but never set" (the source's own reads were
    made where the launch file sets it, with no default, beside the layer's)."""
    from haros_arch.query import run_catalogue

    launch = """<launch>
      <node pkg="move_base" type="move_base" name="move_base">
        <rosparam ns="global_costmap">
          observation_sources: laser
          laser: {data_type: LaserScan, marking: true, expected_update_rate: 0.4}
        </rosparam>
      </node>
    </launch>"""
    root = write_tree({
        "src/nav/package.xml": package_xml("nav"),
        "src/nav/CMakeLists.txt": "project(nav)\n",
        "src/nav/launch/nav.launch": launch,
        "project.yaml": "project: p\nconfigurations:\n  c: [nav/launch/nav.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    for key in ("data_type", "marking", "expected_update_rate"):
        param = config.parameter(f"/move_base/global_costmap/laser/{key}")
        assert param is not None and param.read_as_part_of is not None, key
    assert config.parameter("/move_base/global_costmap/laser/topic") is None
    found = {(f.rule, f.entities[0]) for f in run_catalogue(model)
             if f.rule in ("parameter-set-not-read", "parameter-read-not-set")}
    assert not {entity for _rule, entity in found if "/global_costmap/laser/" in entity}
    # the layer reads them where they were moved, with the topic's default its name
    moved = {link.name for link in config.links if link.node.name == "/move_base"
             and link.kind == "read" and "/obstacle_layer/laser/" in link.name}
    assert {"/move_base/global_costmap/obstacle_layer/laser/topic",
            "/move_base/global_costmap/obstacle_layer/laser/data_type"} <= moved
    assert any(link.kind == "subscribe" and link.name == "/laser" for link in config.links
               if link.node.name == "/move_base")
