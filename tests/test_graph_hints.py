"""Hints, candidates for unknown names, and names that come from parameters."""

from __future__ import annotations

from test_graph import call, graph, node

from haros_arch.graph import apply_hints, apply_node_hints, find_candidates, prune_orphans
from haros_arch.launch.model import NodeDecl, ParamDecl
from haros_arch.model import Location

WHERE = Location(file="project.yaml", line=3)


def test_node_hint_completes_an_unknown_name_and_adds_calls():
    talker = node("p", "talker", call("publish", "?", "std_msgs/String"))
    nodes = {talker.name: talker}
    found = apply_node_hints(nodes, {"p/talker": {
        "publishers": [{"topic": "chatter", "msg_type": "std_msgs/String"}],
        "getters": [{"parameter": "~rate", "param_type": "double"}],
    }}, WHERE)
    assert found == []
    assert [(c.kind, c.name, c.origin) for c in talker.calls] == [
        ("publish", "chatter", "hint"), ("read", "~rate", "hint")]



def test_a_getter_hint_keeps_the_codes_default():
    # noetic dwa_local_planner's override: LatchedStopRotateController reads
    # latch_xy_goal_tolerance with a default (false); a read with a default is never
    # "read but not set", so the hint must say it has one
    planner = node("p", "planner")
    apply_node_hints({planner.name: planner}, {"p/planner": {"getters": [
        {"parameter": "~latch", "param_type": "bool", "default": False},
        {"parameter": "~other", "param_type": "bool"}]}}, WHERE)
    assert [(c.name, c.has_default, c.default) for c in planner.calls] == [
        ("~latch", True, False), ("~other", False, None)]

def test_node_hint_for_a_node_nobody_builds_creates_it():
    nodes = {}
    apply_node_hints(nodes, {"drivers/laser": {
        "publishers": [{"topic": "scan", "msg_type": "sensor_msgs/LaserScan",
                        "queue_size": 5}]}}, WHERE)
    config = graph([NodeDecl("/laser", "drivers", "laser")], nodes=list(nodes.values()))
    (topic,) = config.topics
    assert (topic.name, topic.types) == ("/scan", ["sensor_msgs/LaserScan"])
    assert config.links[0].origin == "hint"
    assert config.links[0].queue_size == 5


def test_configuration_hints_complete_links_and_create_instances():
    pub = node("p", "pub", call("publish", "?", "std_msgs/String"))
    sub = node("p", "sub", call("subscribe", "/chatter", "std_msgs/String"))
    config = graph([NodeDecl("/pub", "p", "pub"), NodeDecl("/sub", "p", "sub")],
                   nodes=[pub, sub])
    found = apply_hints(config, {
        "/pub": {"publishers": [{"topic": "/chatter", "msg_type": "std_msgs/String"}]},
        "/bridge": {"create": True, "node_type": "x/bridge",
                    "subscribers": [{"topic": "/chatter"}]},
        "/ghost": {"publishers": [{"topic": "/x"}]},
        "/sub": {"talkers": []},
    }, {}, WHERE)
    prune_orphans(config)
    assert [d.code for d in found] == ["HINT_UNMATCHED", "HINT_INVALID"]
    (topic,) = config.topics
    assert topic.name == "/chatter"
    assert sorted(link.node.name for link in topic.links) == ["/bridge", "/pub", "/sub"]
    publish = topic.publishers[0]
    assert (publish.origin, publish.rosname.given) == ("hint", "?")
    bridge = config.node("/bridge")
    assert bridge is not None and bridge.origin == "hint"


def test_candidates_match_pattern_and_type():
    a = node("p", "a", call("subscribe", "robot/?/scan", "sensor_msgs/LaserScan"))
    b = node("p", "b", call("publish", "/robot/front/scan", "sensor_msgs/LaserScan"),
             call("publish", "/robot/rear/scan", "sensor_msgs/LaserScan"),
             call("publish", "/robot/cam/scan", "sensor_msgs/Image"),
             call("publish", "/other/front/scan", "sensor_msgs/LaserScan"))
    config = graph([NodeDecl("/a", "p", "a"), NodeDecl("/b", "p", "b")], nodes=[a, b])
    find_candidates(config)
    unknown = next(t for t in config.topics if t.is_unresolved)
    assert [c.name for c in unknown.candidates] == ["/robot/front/scan", "/robot/rear/scan"]
    assert all(not t.candidates for t in config.topics if not t.is_unresolved)


def test_a_parameter_read_with_an_unknown_part_may_read_one_of_another_type():
    """A parameter is one name whatever its value's type: rotors' controllers read
    ``rotor_configuration/<i>/direction`` into an int, and its YAML gives ``-1.0`` (roscpp
    rounds it); the read may be that parameter (a topic of another type is another
    topic: the test above)."""
    ctrl = node("p", "ctrl", call("read", "~rotor_configuration/?/direction", "int"))
    config = graph([NodeDecl("/ctrl", "p", "ctrl")], params=[
        ParamDecl("/ctrl/rotor_configuration/0/direction", -1.0, "double")], nodes=[ctrl])
    find_candidates(config)
    unknown = next(p for p in config.parameters if p.is_unresolved)
    assert [c.name for c in unknown.candidates] == ["/ctrl/rotor_configuration/0/direction"]


def test_a_ros1_read_with_an_unknown_part_may_read_the_parameters_under_it():
    """diagnostic_aggregator's AnalyzerGroup reads ``analyzers`` whole in the namespace an
    add_diagnostics request names (``?/analyzers``): the parameters set under any
    ``<ns>/analyzers/`` (add_analyzers' ``/add_localization_analyzers/analyzers/jackal/
    type``) may be what it reads, as the parameter server answers a namespace with its
    tree; a name that only begins the same (``analyzers_old``) may not."""
    agg = node("p", "agg", call("read", "?/analyzers"))
    config = graph([NodeDecl("/agg", "p", "agg")], params=[
        ParamDecl("/add/analyzers/jackal/type", "GenericAnalyzer", "str"),
        ParamDecl("/add/analyzers", "x", "str"),
        ParamDecl("/add/analyzers_old/type", "y", "str"),
        ParamDecl("/elsewhere/type", "z", "str")], nodes=[agg])
    find_candidates(config)
    unknown = next(p for p in config.parameters if p.is_unresolved)
    assert [c.name for c in unknown.candidates] == ["/add/analyzers",
                                                    "/add/analyzers/jackal/type"]


def test_names_from_parameters_take_the_launch_value_then_the_default():
    def listener(executable):
        n = node("p", executable, call("subscribe", "?", "sensor_msgs/LaserScan"))
        n.calls[0].name_param = "~topic"
        n.calls[0].name_default = "scan"
        return n

    config = graph(
        [NodeDecl("/with_param", "p", "l1"), NodeDecl("/without", "p", "l2")],
        params=[ParamDecl("/with_param/topic", "base_scan", "str")],
        nodes=[listener("l1"), listener("l2")])
    assert sorted(t.name for t in config.topics) == ["/base_scan", "/scan"]


def test_an_absolute_name_from_a_parameter_ignores_the_handles_namespace():
    # fetch_depth_layer: NodeHandle private_nh("~/" + name_); param("depth_topic", t,
    # std::string("/head_camera/depth_downsample/image_raw")); subscribe(t, ...): an
    # absolute name is not resolved in the handle's namespace
    def layer(executable, default):
        n = node("p", executable, call("subscribe", "~costmap/obstacles/?",
                                       "sensor_msgs/Image"))
        n.calls[0].name_param = "~costmap/obstacles/depth_topic"
        n.calls[0].name_default = default
        return n

    config = graph(
        [NodeDecl("/absolute", "p", "l1"), NodeDecl("/relative", "p", "l2"),
         NodeDecl("/launch_set", "p", "l3")],
        params=[ParamDecl("/launch_set/costmap/obstacles/depth_topic", "/camera/depth",
                          "str")],
        nodes=[layer("l1", "/head_camera/image_raw"), layer("l2", "image_raw"),
               layer("l3", "image_raw")])
    assert sorted(t.name for t in config.topics) == [
        "/camera/depth", "/head_camera/image_raw", "/relative/costmap/obstacles/image_raw"]


def test_an_absolute_name_from_a_parameter_on_the_private_handle_is_that_name():
    # octomap_server's TrackingOctomapServer: ``NodeHandle private_nh("~");
    # private_nh.param("topic_changes", t, "changes"); private_nh.subscribe(t, ...)``,
    # its launch files setting ``/octomap_tracking_server/changeset``: roscpp takes a
    # global name as it is, whatever the handle (the call's name is ``~?``, no slash)
    def tracker(executable):
        n = node("p", executable, call("subscribe", "~?", "sensor_msgs/PointCloud2"))
        n.calls[0].name_param = "~topic_changes"
        n.calls[0].name_default = "changes"
        return n

    config = graph(
        [NodeDecl("/listener", "p", "l1"), NodeDecl("/plain", "p", "l2")],
        params=[ParamDecl("/listener/topic_changes", "/tracking/changeset", "str")],
        nodes=[tracker("l1"), tracker("l2")])
    assert sorted(t.name for t in config.topics) == ["/plain/changes",
                                                      "/tracking/changeset"]


def test_a_handle_namespace_from_a_parameter_takes_its_value_then_remaps():
    # pointgrey's stereo nodelet: ``pnh.param("first_namespace", firstcam, "left");
    # ros::NodeHandle lnh(nh, firstcam); it.advertiseCamera("image_raw", 5)`` on lnh:
    # the handle's namespace is the parameter's value, resolved and remapped first
    def stereo(executable):
        n = node("p", executable, call("publish", "?/image_raw", "sensor_msgs/Image"))
        n.calls[0].handle_namespace = "?"
        n.calls[0].name_param = "~first_namespace"
        n.calls[0].name_default = "left"
        return n

    config = graph(
        [NodeDecl("/cam/set", "p", "s1", "/cam/"), NodeDecl("/cam/unset", "p", "s2", "/cam/"),
         NodeDecl("/cam/remapped", "p", "s3", "/cam/", remaps=[("front", "/front_cam")])],
        params=[ParamDecl("/cam/set/first_namespace", "wide", "str"),
                ParamDecl("/cam/remapped/first_namespace", "front", "str")],
        nodes=[stereo("s1"), stereo("s2"), stereo("s3")])
    assert sorted(t.name for t in config.topics) == [
        "/cam/left/image_raw", "/cam/wide/image_raw", "/front_cam/image_raw"]
