"""Graph assembly from hand-made node models: name resolution, remaps, resources."""

from __future__ import annotations

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Condition, Configuration, Location, Node, PrimitiveCall
from haros_arch.workspace import Workspace


def node(package: str, executable: str, *calls: PrimitiveCall) -> Node:
    return Node(package, executable, calls=list(calls))


def call(kind, name, type_=None, line=1, conditions=()):
    return PrimitiveCall(kind, name, type_, 10, conditions=conditions,
                         location=Location("p", "p/src/x.cpp", line, 3))


def graph(decls, params=(), nodes=()):
    launch = LaunchModel(nodes=list(decls), params=list(params))
    ws = Workspace(root="/nowhere")
    return build(Configuration("c"), launch, ws, {n.name: n for n in nodes})


def test_names_resolve_with_namespace_private_and_remaps():
    talker = node("p", "talker",
                  call("publish", "chatter", "std_msgs/String"),
                  call("publish", "/global", "std_msgs/Int32"),
                  call("read", "~rate", "double"),
                  call("subscribe", "in", "std_msgs/String"),
                  call("client", "motors/reset", "std_srvs/Empty"))
    config = graph([
        NodeDecl("/r1/talker", "p", "talker", "/r1/",
                 remaps=[("in", "/shared_in")], args="chatter:=out __name:=x"),
    ], nodes=[talker])
    links = {(link.kind, link.rosname.given): link.rosname.full for link in config.links}
    assert links == {
        ("publish", "chatter"): "/r1/out",
        ("publish", "/global"): "/global",
        ("read", "~rate"): "/r1/talker/rate",
        ("subscribe", "in"): "/shared_in",
        ("client", "motors/reset"): "/r1/motors/reset",
    }
    assert sorted(t.name for t in config.topics) == ["/global", "/r1/out", "/shared_in"]
    assert [s.name for s in config.services] == ["/r1/motors/reset"]
    assert config.nodes[0].remaps == [("chatter", "out"), ("in", "/shared_in")]


def test_a_ros1_remap_tag_wins_over_the_same_rule_in_args():
    # roslaunch's command line: the node's args, then its <remap> rules; roscpp keeps the
    # last rule of a name
    talker = node("p", "talker", call("publish", "chatter", "std_msgs/String"))
    config = graph([NodeDecl("/talker", "p", "talker", remaps=[("chatter", "from_tag")],
                             args="chatter:=from_args")], nodes=[talker])
    assert [link.rosname.full for link in config.links] == ["/from_tag"]


def test_topics_join_publishers_and_subscribers_with_all_types():
    pub = node("p", "pub", call("publish", "/t", "std_msgs/String"))
    sub = node("p", "sub", call("subscribe", "t", "std_msgs/Int32"))
    config = graph([NodeDecl("/a", "p", "pub"), NodeDecl("/b", "p", "sub")],
                   nodes=[pub, sub])
    (topic,) = config.topics
    assert topic.types == ["std_msgs/Int32", "std_msgs/String"]
    assert [link.node.name for link in topic.publishers] == ["/a"]
    assert [link.node.name for link in topic.subscribers] == ["/b"]
    assert not topic.is_disconnected


def test_unknown_names_are_never_merged():
    a = node("p", "a", call("publish", "?", "x/Y"))
    b = node("p", "b", call("subscribe", "?", "x/Y"))
    config = graph([NodeDecl("/a", "p", "a"), NodeDecl("/b", "p", "b")], nodes=[a, b])
    assert [t.name for t in config.topics] == ["?", "?"]
    assert all(t.is_disconnected and t.is_unresolved for t in config.topics)


def test_conditions_combine_launch_and_source():
    launch_cond = Condition("$(arg sim)", "launch", "if")
    source_cond = Condition("use_reset", "source", "if")
    n = node("p", "n", call("client", "reset", conditions=(source_cond,)))
    config = graph([NodeDecl("/n", "p", "n", conditions=(launch_cond,))], nodes=[n])
    (link,) = config.links
    assert link.conditions == (launch_cond, source_cond)
    assert config.services[0].conditions == (launch_cond, source_cond)


def test_launch_parameters_and_unknown_nodes():
    config = graph([NodeDecl("/x", "missing_pkg", "exe")],
                   params=[ParamDecl("/frequency", 1.0, "double")])
    (param,) = config.parameters
    assert (param.name, param.value, param.type, param.writer_names) == (
        "/frequency", 1.0, "double", ["<launch>"])
    assert config.nodes[0].node is None
    assert [d.code for d in config.diagnostics] == ["NODE_PACKAGE_UNKNOWN"]


def test_duplicate_node_names_keep_apart_and_are_left_to_the_query():
    # the duplicate-node-names query (or roslaunch's LAUNCH_NODE_DUPLICATE) says it once
    config = graph([NodeDecl("/x", "p", "n", location=Location("p", "a.launch", 2)),
                    NodeDecl("/x", "p", "n", location=Location("p", "a.launch", 3))],
                   nodes=[node("p", "n")])
    assert [n.id for n in config.nodes] == ["node:/x", "node:/x#2"]
    assert config.diagnostics == []


def test_ros2_parameters_belong_to_their_node():
    n = node("p", "n", call("declare", "gains.kp", "double"), call("publish", "out"))
    decl = NodeDecl("/arm/ctrl", "p", "n", "/arm/")
    decl.ros_version = 2
    config = graph([decl], params=[ParamDecl("/arm/ctrl/gains.kp", 2.0, "double")],
                   nodes=[n])
    assert [(p.name, p.value, [r.node.name for r in p.readers]) for p in config.parameters] == [
        ("/arm/ctrl/gains.kp", 2.0, ["/arm/ctrl"])]
    assert [t.name for t in config.topics] == ["/arm/out"]
    assert config.nodes[0].ros_version == 2


def test_nodelets_loaded_by_the_nodelet_executable_get_their_interface():
    plugin = node("stereo", "stereo/disparity", call("publish", "disparity", "x/Disparity"))
    plugin.kind = "nodelet"
    config = graph([
        NodeDecl("/manager", "nodelet", "nodelet", args="manager"),
        NodeDecl("/cam/disparity", "nodelet", "nodelet", "/cam/",
                 args="load stereo/disparity /manager"),
        NodeDecl("/cam/other", "nodelet", "nodelet", "/cam/",
                 args="standalone stereo/missing"),
    ], nodes=[plugin])
    assert [t.name for t in config.topics] == ["/cam/disparity"]
    assert config.node("/cam/disparity").node is plugin
    # the manager's own node: its loader's services and thread count, known whole
    manager = config.node("/manager")
    assert manager.node is not None and manager.is_complete
    assert sorted(link.resource.name for link in manager.links) == [
        "/manager/list", "/manager/load_nodelet", "/manager/num_worker_threads",
        "/manager/unload_nodelet"]
    assert [(d.code, d.message) for d in config.diagnostics] == [
        ("NODE_PACKAGE_UNKNOWN", "package stereo of node stereo/missing is not in the "
                                 "workspace nor installed here; its interface is unknown")]


def test_a_nodelet_whose_lookup_name_is_not_its_package_s_gets_its_interface():
    # perception_pcl: pcl_ros exports ``pcl/VoxelGrid`` (plugins/nodelet/*.xml), and
    # sample_voxel_grid.launch runs ``nodelet standalone pcl/VoxelGrid``
    grid = node("pcl_ros", "pcl/VoxelGrid", call("publish", "~output", "s/PointCloud2"))
    grid.kind = "nodelet"
    other = node("cam", "cam/Driver", call("publish", "image", "s/Image"))
    other.kind = "nodelet"
    config = graph([
        NodeDecl("/voxel_grid", "nodelet", "nodelet", args="standalone pcl/VoxelGrid"),
        NodeDecl("/driver", "nodelet", "nodelet", args="standalone cam/Driver"),
    ], nodes=[grid, other])
    assert config.node("/voxel_grid").node is grid
    assert config.node("/driver").node is other
    assert sorted(t.name for t in config.topics) == ["/image", "/voxel_grid/output"]
    assert config.diagnostics == []


def test_namespace_reads_and_searched_names_follow_the_parameter_server():
    reader = node("p", "r", call("read", "gains"), call("read", "global_example"),
                  call("read", "~rate"), call("read", "missing"))
    reader.calls[1].searched = True
    reader.calls[2].has_default = True
    reader.calls[3].searched = True
    config = graph([NodeDecl("/foo/r", "p", "r", "/foo/")], params=[
        ParamDecl("/global_example", "g", "str"),
        ParamDecl("/foo/gains/P", 1.0, "double"), ParamDecl("/foo/gains/I", 2.0, "double"),
    ], nodes=[reader])
    gains = config.parameter("/foo/gains")
    assert (gains.value, gains.type, gains.writer_names) == (
        {"P": 1.0, "I": 2.0}, "dict", ["<launch>"])
    assert config.parameter("/foo/gains/P").read_as_part_of is gains
    assert config.parameter("/foo/gains/P").is_read
    names = sorted(link.name for link in config.links)
    # searched: found at the root; the missing one stays in the node's namespace
    assert names == ["/foo/gains", "/foo/missing", "/foo/r/rate", "/global_example"]
    assert config.parameter("/foo/r/rate").has_default
    assert not config.parameter("/foo/missing").has_default


def test_a_key_searched_on_a_namespaced_handle_is_searched_from_that_namespace():
    # roscpp's NodeHandle("arm").searchParam("robot_description", key) asks the master
    # from /foo/arm up: /foo/arm/robot_description, /foo/robot_description, ...; it was
    # searched as the key "arm/robot_description" from the node's namespace, never found
    # where the launch file sets it
    reader = node("p", "r", call("read", "arm/robot_description"),
                  call("read", "arm/missing"))
    for read in reader.calls:
        read.searched, read.handle_namespace = True, "arm"
    config = graph([NodeDecl("/foo/r", "p", "r", "/foo/")], params=[
        ParamDecl("/robot_description", "<robot/>", "str")], nodes=[reader])
    # found at the root; the missing one stays in the handle's namespace
    assert sorted(link.name for link in config.links) == [
        "/foo/arm/missing", "/robot_description"]


def test_a_private_key_is_searched_from_the_node_s_own_namespace_up():
    # roscpp's NodeHandle("~").searchParam and ros::param::search(key, ..), rospy's
    # search_param: the master searches from the node's own name up (paramserver.py's
    # search_param tests ns + key first), so /foo/r/tf_prefix, set inside the node's
    # <node> tag, is found before /foo/tf_prefix; it was searched from /foo up, and the
    # node's own parameter was "set but not read"
    reader = node("p", "r", call("read", "~tf_prefix"), call("read", "~frame"),
                  call("read", "~missing"))
    for read in reader.calls:
        read.searched, read.handle_namespace = True, "~"
    config = graph([NodeDecl("/foo/r", "p", "r", "/foo/")], params=[
        ParamDecl("/foo/r/tf_prefix", "robot1", "str"),
        ParamDecl("/foo/tf_prefix", "other", "str"),
        ParamDecl("/frame", "map", "str")], nodes=[reader])
    # found in the node's namespace, and at the root; the missing one stays private
    assert sorted(link.name for link in config.links) == [
        "/foo/r/missing", "/foo/r/tf_prefix", "/frame"]
    assert config.parameter("/foo/r/tf_prefix").is_read
    assert not config.parameter("/foo/tf_prefix").is_read


def test_actions_are_also_their_topics_and_services():
    server = node("p", "server", call("action-server", "fib", "tut/Fibonacci"))
    client = node("p", "client", call("action-client", "/fib", "tut/Fibonacci"))
    ros2 = node("p", "ros2", call("action-server", "nav", "nav2_msgs/action/NavigateToPose"))
    decl2 = NodeDecl("/bt", "p", "ros2")
    decl2.ros_version = 2
    config = graph([NodeDecl("/s", "p", "server"), NodeDecl("/c", "p", "client"), decl2],
                   nodes=[server, client, ros2])
    goal = config.topic("/fib/goal")
    assert goal.types == ["tut/FibonacciActionGoal"]
    assert [link.node.name for link in goal.publishers] == ["/c"]
    assert [link.node.name for link in goal.subscribers] == ["/s"]
    assert all(link.origin == "action" for link in goal.links)
    feedback = config.topic("/fib/feedback")
    assert [link.node.name for link in feedback.publishers] == ["/s"]
    assert not any(t.is_disconnected for t in config.topics if t.name.startswith("/fib/"))
    (action,) = [a for a in config.actions if a.name == "/fib"]
    assert action.servers and action.clients
    send_goal = config.service("/nav/_action/send_goal")
    assert send_goal.types == ["nav2_msgs/action/NavigateToPose_SendGoal"]
    assert [link.node.name for link in send_goal.servers] == ["/bt"]
    assert config.topic("/nav/_action/status").types == ["action_msgs/msg/GoalStatusArray"]


def test_a_delete_is_not_a_set():
    sim = Condition("$(arg sim)", "launch", "if")
    cleaner = node("p", "cleaner", PrimitiveCall("write", "/calib", deletes=True),
                   PrimitiveCall("write", "/mode"), PrimitiveCall("write", "/old", deletes=True))
    config = graph([NodeDecl("/cleaner", "p", "cleaner")],
                   params=[ParamDecl("/calib", 1.0, "double", conditions=(sim,)),
                           ParamDecl("/mode", "a", "str", conditions=(sim,))],
                   nodes=[cleaner])
    calib, mode, old = (config.parameter(n) for n in ("/calib", "/mode", "/old"))
    # set under the launch condition and deleted by a node: it exists only under it
    assert calib.conditions == (sim,) and calib.is_set and calib.setters == []
    # a node sets it whatever the launch file does
    assert mode.conditions == () and [w.node.name for w in mode.setters] == ["/cleaner"]
    assert not old.is_set and [w.node.name for w in old.writers] == ["/cleaner"]


def test_ros2_plain_arguments_are_no_remaps():
    # ros2_control_demos' spawners: ``arguments=[..., "--controller-ros-args",
    # "-r ~/cmd_vel:=/cmd_vel"]`` remaps the controller's topic, not the spawner's; rcl
    # reads remaps only after --ros-args, which the launch reader gives as remaps
    spawner = node("p", "spawner", call("subscribe", "cmd_vel", "geometry_msgs/msg/Twist"))
    config = graph([NodeDecl("/spawner", "p", "spawner", ros_version=2,
                             args="ctrl --controller-ros-args '-r ~/cmd_vel:=/cmd_vel' a:=b",
                             remaps=[("x", "y")])], nodes=[spawner])
    assert config.nodes[0].remaps == [("x", "y")]
    assert [t.name for t in config.topics] == ["/cmd_vel"]
    # ROS 1: every ``from:=to`` of the command line
    config = graph([NodeDecl("/spawner", "p", "spawner", args="cmd_vel:=/base/cmd_vel")],
                   nodes=[spawner])
    assert [t.name for t in config.topics] == ["/base/cmd_vel"]
