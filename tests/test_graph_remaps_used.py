"""Which remaps change a name a node instance uses: recorded as the graph is built, kept
in the JSON model, and what the ``remap-unused`` query reads (``Configuration.remaps``)."""

from __future__ import annotations

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Model, Node, PrimitiveCall
from haros_arch.model.load import from_data
from haros_arch.model.serialise import to_data
from haros_arch.workspace import Workspace


def _config(decls: list[NodeDecl], nodes: dict[str, Node]) -> Configuration:
    return build(Configuration("c"), LaunchModel(nodes=decls), Workspace(root="/x"), nodes)


def test_the_remaps_a_node_uses_and_those_it_does_not() -> None:
    # kobuki's auto-docking launch: the mux publishes cmd_vel_mux/output (its private
    # ~output), the remap named cmd_vel_mux/mux_cmd_vel
    mux = Node("yocs_cmd_vel_mux", "mux", calls=[
        PrimitiveCall("publish", "~output", "geometry_msgs/Twist"),
        PrimitiveCall("subscribe", "input/teleop", "geometry_msgs/Twist"),
        PrimitiveCall("read", "~output_rate", "double"),  # a parameter: no hint
        # a NodeHandle("input") namespace is remapped before the name in it
        PrimitiveCall("subscribe", "input/safety", "geometry_msgs/Twist",
                      handle_namespace="input")])
    decl = NodeDecl("/cmd_vel_mux", "yocs_cmd_vel_mux", "mux", "/", remaps=[
        ("cmd_vel_mux/mux_cmd_vel", "mobile_base/commands/velocity"),
        ("input", "/inputs"), ("__ns", "/robot")])
    config = _config([decl], {"yocs_cmd_vel_mux/mux": mux})
    (instance,) = config.nodes
    assert instance.remaps_applied == ["/input"]
    remaps = {r.text: r for r in config.remaps}
    assert set(remaps) == {"cmd_vel_mux/mux_cmd_vel:=mobile_base/commands/velocity",
                           "input:=/inputs"}
    unused = remaps["cmd_vel_mux/mux_cmd_vel:=mobile_base/commands/velocity"]
    assert (unused.users, unused.unseen) == ([], [])
    assert unused.near == ["/cmd_vel_mux/output"]
    assert remaps["input:=/inputs"].users == [instance]
    # the JSON model keeps what was applied
    model = Model("p", configurations=[config])
    again = from_data(to_data(model)).configurations[0]
    assert again.nodes[0].remaps_applied == ["/input"]
    assert [len(r.users) for r in again.remaps] == [len(r.users) for r in config.remaps]


def test_a_remap_shared_by_several_nodes_is_used_when_one_uses_it() -> None:
    planner = Node("nav", "planner", calls=[
        PrimitiveCall("subscribe", "/tf", "tf2_msgs/msg/TFMessage")])
    maps = Node("nav", "map_server", calls=[
        PrimitiveCall("publish", "map", "nav_msgs/msg/OccupancyGrid")])
    shared = [("/tf", "tf")]  # nav2's launch files, for a robot in a namespace
    config = _config([NodeDecl("/r/planner", "nav", "planner", "/r/", remaps=shared),
                      NodeDecl("/r/map_server", "nav", "map_server", "/r/", remaps=shared)],
                     {"nav/planner": planner, "nav/map_server": maps})
    (remap,) = config.remaps
    assert [n.name for n in remap.nodes] == ["/r/planner", "/r/map_server"]
    assert [n.name for n in remap.users] == ["/r/planner"]
    # without a namespace the remap names the name itself: it changes nothing here, and
    # the map server uses no /tf in any namespace
    config = _config([NodeDecl("/map_server", "nav", "map_server", "/", remaps=shared)],
                     {"nav/map_server": maps})
    (remap,) = config.remaps
    assert (remap.users, remap.unseen) == ([], [])


def test_a_name_from_a_parameter_whose_value_is_empty_stays_unknown() -> None:
    """A name read from a parameter whose default is "" (``declare_parameter<std::string>
    ("topic", "")``, the call guarded by ``if (!topic.empty())``) names no topic; it was
    resolved to the namespace, a topic "/" (survey C, rosbot's simulation)."""
    bridge = Node("gz", "bridge", calls=[
        PrimitiveCall("subscribe", "?", "std_msgs/msg/String", name_param="topic",
                      name_default=""),
        PrimitiveCall("subscribe", "?", "std_msgs/msg/String", name_param="other",
                      name_default="clock")])
    config = _config([NodeDecl("/bridge", "gz", "bridge", "/", ros_version=2)],
                     {"gz/bridge": bridge})
    assert sorted(link.rosname.full for link in config.links) == ["/clock", "?"]


def test_a_node_its_host_makes_is_not_who_the_remap_was_given_to() -> None:
    """nav2's controller_server makes its local costmap's node in its process, which
    takes the process's remaps (``/tf:=tf``): given for the server, they are no finding
    on the costmap when it does not use the name, and a use of it counts."""
    from haros_arch.model import NodeInstance
    from haros_arch.model.runtime import remaps_of

    host = NodeInstance("/r/controller_server", Node("nav", "server"), namespace="/r/",
                        remaps=[("/tf", "tf"), ("odom", "odometry/filtered")],
                        remaps_applied=["/tf"])
    child = NodeInstance("/r/local_costmap/local_costmap", Node("nav", "costmap"),
                         namespace="/r/local_costmap/", remaps=list(host.remaps),
                         origin="plugin", remaps_applied=["/r/local_costmap/odom"])
    found = {r.text: r for r in remaps_of([child, host])}
    assert [n.name for n in found["/tf:=tf"].nodes] == ["/r/controller_server"]
    assert [n.name for n in found["odom:=odometry/filtered"].users] == [
        "/r/local_costmap/local_costmap"]


def test_a_ros1_handle_whose_namespace_is_not_known_may_be_the_remapped_one() -> None:
    # depth_image_proc's disparity nodelet: right_nh_.reset(new NodeHandle(nh, "right"))
    # then subscribe(*right_nh_, "camera_info"); openni_launch remaps right:=projector,
    # and roscpp remaps a handle's namespace: with the handle unknown, not decided
    disparity = Node("depth_image_proc", "disparity", calls=[
        PrimitiveCall("subscribe", "?/camera_info", "sensor_msgs/CameraInfo",
                      handle_namespace="?")])
    for version, unseen in ((1, 1), (2, 0)):
        decl = NodeDecl("/camera/disparity", "depth_image_proc", "disparity", "/camera/",
                        remaps=[("right", "projector")], ros_version=version)
        config = _config([decl], {"depth_image_proc/disparity": disparity})
        (remap,) = config.remaps
        assert (len(remap.users), len(remap.unseen)) == (0, unseen)


def test_a_remap_source_not_known_statically_may_be_a_name_the_node_uses() -> None:
    """spot_ros2's image stitcher: ``(f"{cam_prefix}/left/image", ...)`` with cam_prefix
    ``"/" + spot_name`` or "" and spot_name from a helper not interpreted: the source
    ``?/left/image`` may be the ``left/image`` the node subscribes to, absolute or not
    (undecided); one no name of the node can match is not used."""
    stitcher = Node("spot", "stitcher", calls=[
        PrimitiveCall("subscribe", "left/image", "sensor_msgs/msg/Image")])
    decl = NodeDecl("/?/stitcher", "spot", "stitcher", "/?/", ros_version=2, remaps=[
        ("?/left/image", "?/camera/frontleft/image"),
        ("?/right/image", "?/camera/frontright/image")])
    config = _config([decl], {"spot/stitcher": stitcher})
    (instance,) = config.nodes
    remaps = {r.source: r for r in config.remaps}
    assert (remaps["?/left/image"].users, remaps["?/left/image"].unseen) == ([], [instance])
    assert (remaps["?/right/image"].users, remaps["?/right/image"].unseen) == ([], [])


def test_a_node_known_from_a_model_of_code_that_loads_no_plugins_is_judged() -> None:
    """A complete interface model lists every name its code makes (its options' under
    their conditions), as the workspace's own code would: a remap none of them is was
    left undecided for every modelled node (jackal's teleop.launch gave cmd_vel:=/cmd_vel
    to interactive_marker_twist_server, which publishes ~cmd_vel). A model of code that
    loads plugins by name stays undecided: a plugin's names are not in it."""
    def server(loads: list[str]) -> Node:
        return Node("twist", "marker_server", completeness="complete", model="noetic/twist",
                    plugin_loads=loads, calls=[
                        PrimitiveCall("publish", "~cmd_vel", "geometry_msgs/Twist")])
    decl = NodeDecl("/twist_marker_server", "twist", "marker_server", "/",
                    remaps=[("cmd_vel", "/cmd_vel_out")])
    config = _config([decl], {"twist/marker_server": server([])})
    (remap,) = config.remaps
    assert (remap.users, remap.unseen) == ([], [])
    assert remap.near == ["/twist_marker_server/cmd_vel"]
    config = _config([decl], {"twist/marker_server": server(["src/server.cpp:40"])})
    (remap,) = config.remaps
    assert (remap.users, [n.name for n in remap.unseen]) == ([], ["/twist_marker_server"])


def test_a_remap_of_a_name_to_itself_that_no_node_uses() -> None:
    """A remap of a name to itself changes nothing, but says the author took the name to
    be the node's: robot_localization's dual_ekf_navsat_example gave navsat_transform
    imu/data:=imu/data, and the node subscribes imu; jackal's teleop.launch gave the
    marker server cmd_vel:=/cmd_vel in the root namespace, and it publishes ~cmd_vel.
    Both were left out as changing nothing. A remap of a name to itself that the node
    uses stays quiet."""
    navsat = Node("rl", "navsat", calls=[
        PrimitiveCall("subscribe", "imu", "sensor_msgs/msg/Imu"),
        PrimitiveCall("subscribe", "gps/fix", "sensor_msgs/msg/NavSatFix")])
    decl = NodeDecl("/navsat_transform", "rl", "navsat", "/", ros_version=2,
                    remaps=[("imu/data", "imu/data"), ("gps/fix", "gps/fix")])
    config = _config([decl], {"rl/navsat": navsat})
    remaps = {r.text: r for r in config.remaps}
    assert (remaps["imu/data:=imu/data"].users, remaps["imu/data:=imu/data"].unseen) == ([], [])
    assert [n.name for n in remaps["gps/fix:=gps/fix"].users] == ["/navsat_transform"]


def test_one_text_given_in_two_namespaces_is_two_remaps() -> None:
    """The same from:=to written for two nodes of different namespaces remaps two names:
    each is judged by its own nodes (jackal: teleop_twist_joy in /bluetooth_teleop uses
    cmd_vel, the marker server in / does not)."""
    teleop = Node("joy", "teleop", calls=[
        PrimitiveCall("publish", "cmd_vel", "geometry_msgs/Twist")])
    marker = Node("twist", "marker", calls=[
        PrimitiveCall("publish", "~cmd_vel", "geometry_msgs/Twist")])
    given = [("cmd_vel", "/cmd_vel")]
    config = _config([NodeDecl("/bluetooth_teleop/teleop", "joy", "teleop", "/bluetooth_teleop/",
                               remaps=given),
                      NodeDecl("/twist_marker_server", "twist", "marker", "/", remaps=given)],
                     {"joy/teleop": teleop, "twist/marker": marker})
    found = sorted(([n.name for n in r.nodes], [n.name for n in r.users]) for r in config.remaps)
    assert found == [(["/bluetooth_teleop/teleop"], ["/bluetooth_teleop/teleop"]),
                     (["/twist_marker_server"], [])]


def test_an_empty_parameter_value_inside_a_ros1_name_drops_its_segment() -> None:
    """heron_nmea's command_publisher calls ``"/" + ns + "/activate_control"`` with ``ns``
    its ``~namespace``, which the launch file sets to "" (``$(optenv ROBOT_NAMESPACE)``):
    roscpp cleans ``//activate_control`` to ``/activate_control``; the name stayed
    ``/?/activate_control`` with a diagnostic saying the parameter was not set (survey
    Z39). A ``?`` that begins the name before ``/`` leaves the global rest (``"" +
    "/cmd"`` is ``/cmd``: aau_multi_robot's map_merger, ``robot_prefix`` set to ""); one
    that ends it still names nothing known."""
    commands = Node("heron_nmea", "command_publisher", calls=[
        PrimitiveCall("client", "/?/activate_control", "std_srvs/SetBool",
                      name_param="~namespace"),
        PrimitiveCall("publish", "?/cmd", "std_msgs/Bool", name_param="~prefix"),
        PrimitiveCall("publish", "robot/?", "std_msgs/Bool", name_param="~prefix")])
    decl = NodeDecl("/nmea_if/nmea_commands", "heron_nmea", "command_publisher", "/nmea_if/")
    params = [ParamDecl("/nmea_if/nmea_commands/namespace", ""),
              ParamDecl("/nmea_if/nmea_commands/prefix", "")]
    config = build(Configuration("c"), LaunchModel(nodes=[decl], params=params),
                   Workspace(root="/x"), {"heron_nmea/command_publisher": commands})
    assert sorted(link.rosname.full for link in config.links) == [
        "/activate_control", "/cmd", "/nmea_if/robot/?"]
    # as written: the code's global name (the global-names query quotes it)
    assert "/activate_control" in [link.rosname.given for link in config.links]
    assert [d.code for d in config.diagnostics if d.code == "NAME_PARAM_UNSET"] == [
        "NAME_PARAM_UNSET"]


def test_an_empty_parameter_value_that_begins_a_name_leaves_its_global_rest() -> None:
    """aau_multi_robot's map_merger calls ``robot_prefix + "/adhoc_communication/
    send_position"`` on its private handle with ``~robot_prefix`` set to "" by the launch
    file (an argument's empty default): the name is the global
    ``/adhoc_communication/send_position``, not ``?/adhoc_communication/send_position``
    with a NAME_PARAM_UNSET saying the configuration does not set the parameter. On a
    handle with a namespace the same: a global name ignores it. Given a value, the
    value and the rest (the private handle's namespace before a relative one)."""
    merger = Node("map_merger", "map_merger", calls=[
        PrimitiveCall("client", "~?/adhoc_communication/send_position",
                      "std_srvs/Trigger", name_param="~robot_prefix",
                      handle_namespace="~"),
        PrimitiveCall("publish", "ns/?/all_positions", "std_msgs/String",
                      name_param="~robot_prefix", handle_namespace="ns")])
    for value, names in (("", ["/adhoc_communication/send_position", "/all_positions"]),
                         ("robot_1", ["/merger/robot_1/adhoc_communication/send_position",
                                      "/ns/robot_1/all_positions"])):
        decl = NodeDecl("/merger", "map_merger", "map_merger", "/")
        params = [ParamDecl("/merger/robot_prefix", value)]
        config = build(Configuration("c"), LaunchModel(nodes=[decl], params=params),
                       Workspace(root="/x"), {"map_merger/map_merger": merger})
        assert sorted(link.rosname.full for link in config.links) == names
        assert [d.code for d in config.diagnostics if d.code == "NAME_PARAM_UNSET"] == []


def test_a_ros1_action_topic_remapped_alone_moves_and_the_remap_is_used() -> None:
    """explore_lite's ``SimpleActionClient move_base_client_("move_base")`` publishes
    ``move_base/goal`` and ``move_base/cancel`` and subscribes ``move_base/status``,
    ``/feedback``, ``/result``; omniveyor's explore launch file remaps each to
    ``motion_manager/move_base/<topic>``. roscpp (and rospy) remap every name actionlib
    resolves, so the topics move there and the remaps are used: they were five
    ``remap-unused`` warnings and the topics stayed under ``/move_base``. A remap of
    the action itself (``move_base:=other``) was followed already."""
    explore = Node("explore_lite", "explore", calls=[
        PrimitiveCall("action-client", "move_base", "move_base_msgs/MoveBaseAction")])
    remaps = [(f"move_base/{t}", f"motion_manager/move_base/{t}")
              for t in ("goal", "cancel", "status", "feedback", "result")]
    decl = NodeDecl("/explore", "explore_lite", "explore", "/", remaps=remaps)
    config = build(Configuration("c"), LaunchModel(nodes=[decl]), Workspace(root="/x"),
                   {"explore_lite/explore": explore})
    assert sorted(link.rosname.full for link in config.links) == [
        "/motion_manager/move_base/cancel", "/motion_manager/move_base/feedback",
        "/motion_manager/move_base/goal", "/motion_manager/move_base/result",
        "/motion_manager/move_base/status", "/move_base"]
    assert sorted(config.nodes[0].remaps_applied) == sorted(
        f"/move_base/{t}" for t in ("goal", "cancel", "status", "feedback", "result"))
