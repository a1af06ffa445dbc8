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


def _node(package: str, distro: str, name: str):
    model = Library().find(package, distro)
    assert model is not None
    (node,) = [n for n in model.nodes if n.executable == name]
    return node


def test_the_shipped_noetic_rosbag_tools_are_whole_without_roscpps_own_code() -> None:
    # ros_comm 845f7460 rebuilt (2026-12-07): SubscribeOptions' helper, rosbag_storage's
    # View::iterator (a boost::iterator_facade) and encrypt's print of options.param no
    # longer leave them partial; roscpp's libros, in the same tree, is not read with them
    for name in ("record", "play", "encrypt"):
        node = _node("rosbag", "noetic", name)
        assert node.completeness == "complete", node.completeness_reasons
        assert not [s for s in node.sources if s.startswith("clients/roscpp/")]
    play = _node("rosbag", "noetic", "play")
    assert ("publish", "clock") in {(c.kind, c.name) for c in play.calls}


def test_the_shipped_noetic_topic_tools_publish_what_they_relay() -> None:
    # ShapeShifter::advertise (relay.cpp:99, once the first message came): the output
    # topic, named from the command line (models.commands fills it where it is known);
    # not again inside the library's definition of it (shape_shifter.cpp:70, dropped by
    # overrides/noetic/topic_tools.yaml)
    relay = _node("topic_tools", "noetic", "relay")
    published = [c for c in relay.calls if c.kind == "publish"]
    assert [(c.name, c.type) for c in published] == [("?/?", "topic_tools/ShapeShifter")]
    assert [c.text for c in published[0].conditions] == ["!g_advertised"]


def test_the_shipped_noetic_hector_mapping_publishes_its_map_and_metadata() -> None:
    node = _node("hector_mapping", "noetic", "hector_mapping")
    assert node.completeness == "complete"
    assert {("map", "nav_msgs/OccupancyGrid"), ("map_metadata", "nav_msgs/MapMetaData")} <= {
        (c.name, c.type) for c in node.calls if c.kind == "publish"}


def test_the_shipped_noetic_pcl_ros_nodelets_are_whole() -> None:
    model = Library().find("pcl_ros", "noetic")
    assert model is not None
    assert [n.name for n in model.nodes if n.completeness == "partial"] == []
    shot = next(n for n in model.nodes if n.executable == "pcl/SHOTEstimation")
    assert ("~output", "sensor_msgs/PointCloud2") in {
        (c.name, c.type) for c in shot.calls if c.kind == "publish"}


def test_the_shipped_jazzy_tf2_monitor_is_whole() -> None:
    assert _node("tf2_ros", "jazzy", "tf2_monitor").completeness == "complete"


def test_the_shipped_ros2_turtlesim_nodes_are_whole() -> None:
    # ros_tutorials rebuilt after the Qt stand-in's fillRect(x, y, w, h, color): its
    # paintEvent (turtle_frame.cpp), which reads the background parameters, parses
    for distro in ("humble", "jazzy"):
        assert _node("turtlesim", distro, "turtlesim_node").completeness == "complete"


def test_the_shipped_cartographer_model_builds_the_node_where_the_code_builds_it() -> None:
    # rebuilt after tmplK's fix: cartographer_offline_node builds its Node in
    # RunOfflineNode (offline_node.cc), a capitalised free function, so node.cc's
    # publishers and servers are the program's; the tools that build no Node (the
    # occupancy grid node, pbstream_to_ros_map) no longer take node.cc's /tf
    offline = _node("cartographer_ros", "noetic", "cartographer_offline_node")
    published = {c.name for c in offline.calls if c.kind == "publish"}
    assert {"submap_list", "trajectory_node_list", "~bagfile_progress"} <= published
    assert "start_trajectory" in {c.name for c in offline.calls if c.kind == "server"}
    for tool in ("cartographer_occupancy_grid_node", "cartographer_pbstream_to_ros_map"):
        assert "/tf" not in {c.name for c in _node("cartographer_ros", "noetic", tool).calls}


def test_the_shipped_jazzy_image_transport_programs_make_no_library_publisher() -> None:
    # image_common d04d2c83 rebuilt (2026-12-07): the library's create_camera_publisher
    # (image_transport.cpp:85), the API's implementation, called by neither program, is
    # not read: list_transports makes no topic, republish publishes ``out`` once, at its
    # own create_publisher (republish.cpp:137), and has no camera_info
    lister = _node("image_transport", "jazzy", "list_transports")
    assert [c for c in lister.calls if c.kind in ("publish", "subscribe")] == []
    republish = _node("image_transport", "jazzy", "republish")
    published = [(c.name, c.location.line) for c in republish.calls if c.kind == "publish"]
    assert published == [("out", 137)]
    assert sorted({c.name for c in republish.calls if c.kind == "subscribe"}) == ["in"]


def test_the_shipped_noetic_rosserial_nodes_bridge_alike() -> None:
    # rosserial c169ae21 rebuilt (2026-12-07): socket_node's sessions are built by
    # TcpServer<>'s ``new Session(io_service_)`` (tcp_server.h:65), a parameter of the
    # template with a default: its publisher (topic_handlers.h:66) and service client
    # (line 148) as serial_node's, each named at run time by the client
    expected = {("publish", "?", "topic_tools/ShapeShifter"),
                ("subscribe", "?", "topic_tools/ShapeShifter"), ("client", "?", "?")}
    for name in ("serial_node", "socket_node", "udp_socket_node"):
        node = _node("rosserial_server", "noetic", name)
        assert expected <= {(c.kind, c.name, c.type) for c in node.calls}, name
        assert node.completeness == "complete", name


def test_the_shipped_noetic_moveit_ros_planning_reads_the_searched_solver_keys() -> None:
    # moveit 7c0343f0 rebuilt (2026-12-07): kinematics_plugin_loader.cpp reads the
    # parameter searchParam found (``getParam(ksolver_timeout_param_name, ...)``, line
    # 339), named by the key searched for, not by a parameter's value; the adapters that
    # build geometric_shapes' bodies (collision_distance_field) are not partial for them
    node = _node("moveit_ros_planning", "noetic", "moveit_display_random_state")
    reads = {(c.name, c.name_param) for c in node.calls
             if c.kind == "read" and c.location.line == 339}
    assert reads == {("~?/kinematics_solver_timeout", None)}
    model = Library().find("moveit_ros_planning", "noetic")
    assert model is not None
    assert not [r for n in model.nodes for r in n.completeness_reasons
                if "geometric_shapes" in r]
