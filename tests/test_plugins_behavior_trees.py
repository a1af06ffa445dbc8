"""A BehaviorTree.CPP tree host (nav2's bt_navigator) gets the calls of the BT nodes its
tree files instantiate (plugins.behavior_trees)."""

from __future__ import annotations

from pathlib import Path

from haros_arch.graph import build
from haros_arch.launch.model import LaunchModel, NodeDecl, ParamDecl
from haros_arch.model import Configuration, Location, Node
from haros_arch.workspace import scan

HEADER = """#include "behaviortree_cpp/bt_factory.h"
namespace my_bt {
class GoThere : public nav2_behavior_tree::BtActionNode<my_msgs::action::GoThere>
{
public:
  GoThere(const std::string & n, const std::string & a, const BT::NodeConfiguration & c);
};
class CancelGo : public BtCancelActionNode<my_msgs::action::GoThere> {};
class Clear
  : public nav2_behavior_tree::BtServiceNode<my_msgs::srv::Clear>
{
};
class Watch : public BT::ConditionNode
{
public:
  static BT::PortsList providedPorts()
  {
    return {
      BT::InputPort<double>("level", "a level"),
      BT::InputPort<std::string>(
        "watch_topic", "/watched", "Topic watched"),
    };
  }
};
using Trig = std_srvs::srv::Trigger;
class Pause : public BT::ControlNode
{
public:
  static BT::PortsList providedPorts()
  {
    return {BT::InputPort<std::string>("pause_service_name", "Name of the service"),
      BT::InputPort<std::string>("other", "described")};
  }
};
class Updater : public BT::DecoratorNode {};
}  // namespace my_bt
"""

SOURCE = """#include "my_bt/nodes.hpp"
namespace my_bt {
Clear::Clear(const std::string & name, const BT::NodeConfiguration & conf)
: BtServiceNode<my_msgs::srv::Clear>(name, conf, "clear_all")
{
}
Watch::Watch(const std::string & name, const BT::NodeConfiguration & conf)
: BT::ConditionNode(name, conf)
{
  std::string topic;
  getInput("watch_topic", topic);
  topic_ = topic;
  sub_ = node_->create_subscription<std_msgs::msg::Bool>(topic_, 10, cb);
  pub_ = node_->create_publisher<std_msgs::msg::String>("watch_state", 10);
}
Pause::Pause(const std::string & name, const BT::NodeConfiguration & conf)
: BT::ControlNode(name, conf)
{
  getInput("pause_service_name", pause_name_);
  srv_ = node_->create_service<Trig>(pause_name_, cb);
}
void Updater::initialize()
{
  std::string topic_new;
  node_->get_parameter_or<std::string>("updater_topic", topic_new, "goal_update");
  sub_ = node_->create_subscription<geometry_msgs::msg::PoseStamped>(topic_new, 10, cb);
}
}  // namespace my_bt

BT_REGISTER_NODES(factory)
{
  BT::NodeBuilder builder =
    [](const std::string & name, const BT::NodeConfiguration & config)
    {
      return std::make_unique<my_bt::GoThere>(
        name, "go_there", config);
    };
  factory.registerBuilder<my_bt::GoThere>("GoThere", builder);
  BT::NodeBuilder cancel =
    [](const std::string & name, const BT::NodeConfiguration & config)
    {
      return std::make_unique<my_bt::CancelGo>(name, "go_there", config);
    };
  factory.registerBuilder<my_bt::CancelGo>("CancelGo", cancel);
  factory.registerNodeType<my_bt::Clear>("Clear");
  factory.registerNodeType<my_bt::Watch>("Watch");
  factory.registerNodeType<my_bt::Pause>("Pause");
  factory.registerNodeType<my_bt::Updater>("Updater");
}
"""

TREE = """<root BTCPP_format="4" main_tree_to_execute="Main">
  <BehaviorTree ID="Main">
    <Sequence>
      <Watch level="0.5"/>
      <GoThere goal="{goal}"/>
      <Action ID="GoThere" server_name="other_go"/>
      <Fallback>
        <Clear/>
        <Clear service_name="{from_board}"/>
        <CancelGo/>
      </Fallback>
      <Unregistered/>
    </Sequence>
  </BehaviorTree>
  <TreeNodesModel><Action ID="NotInTheTree"/></TreeNodesModel>
</root>
"""


def _workspace(tmp_path: Path, tree: str = TREE) -> Path:
    package = tmp_path / "my_bt"
    (package / "src").mkdir(parents=True, exist_ok=True)
    (package / "include" / "my_bt").mkdir(parents=True)
    (package / "trees").mkdir()
    (package / "package.xml").write_text(
        '<package format="3"><name>my_bt</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>behaviortree_cpp</depend><export><build_type>ament_cmake</build_type>"
        "</export></package>")
    (package / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.8)\nproject(my_bt)\n"
        "add_library(my_bt_nodes SHARED src/nodes.cpp)\n")
    (package / "include" / "my_bt" / "nodes.hpp").write_text(HEADER)
    (package / "src" / "nodes.cpp").write_text(SOURCE)
    (package / "trees" / "main.xml").write_text(tree)
    return package / "trees" / "main.xml"


def _config(tmp_path: Path, tree: str = TREE, libraries: object = ("my_bt_nodes",)):
    path = _workspace(tmp_path, tree)
    workspace = scan([str(tmp_path)])
    navigator = Node("nav2_bt_navigator", "bt_navigator")
    where = Location("bringup", "bringup/params.yaml", 4, 0)
    launch = LaunchModel(
        nodes=[NodeDecl("/nav/bt_navigator", "nav2_bt_navigator", "bt_navigator", "/nav/",
                        ros_version=2)],
        params=[ParamDecl("/nav/bt_navigator/plugin_lib_names", list(libraries),
                          location=where),
                ParamDecl("/nav/bt_navigator/default_nav_to_pose_bt_xml", str(path),
                          location=where)])
    return build(Configuration("c"), launch, workspace, {navigator.name: navigator})


def _links(config):
    return sorted((link.kind, link.resource.name, link.call.type) for link in config.links
                  if link.node.name == "/nav/bt_navigator" and "/_action/" not in
                  link.resource.name)


def test_tree_nodes_make_their_calls_on_the_navigator(tmp_path):
    config = _config(tmp_path)
    assert _links(config) == [
        ("action-client", "/nav/go_there", "my_msgs/action/GoThere"),  # builder default
        ("action-client", "/nav/other_go", "my_msgs/action/GoThere"),  # server_name
        ("client", "/nav/clear_all", "my_msgs/srv/Clear"),  # the base's default
        # from the blackboard: unknown, in no namespace (it may be global)
        ("client", "?", "my_msgs/srv/Clear"),
        ("publish", "/nav/watch_state", "std_msgs/msg/String"),
        ("subscribe", "/watched", "std_msgs/msg/Bool"),  # the port's default
    ]
    # a tag no library registers: a diagnostic at its line, the instance partial
    (unknown,) = [d for d in config.diagnostics if d.code == "BT_NODE_UNKNOWN"]
    assert unknown.location.line == 12 and "Unregistered" in unknown.message
    instance = config.node("/nav/bt_navigator")
    assert instance.completeness == "partial"
    assert any("Unregistered" in r for r in instance.completeness_reasons)
    # nav2_behavior_tree (its built-in nodes) is not in this workspace: said so
    assert any("nav2_behavior_tree" in r for r in instance.completeness_reasons)


def test_a_port_given_in_the_tag_names_the_topic(tmp_path):
    tree = TREE.replace('<Watch level="0.5"/>', '<Watch watch_topic="/mine"/>')
    assert ("subscribe", "/mine", "std_msgs/msg/Bool") in _links(_config(tmp_path, tree))


def test_a_bad_tree_file_is_a_diagnostic_with_its_line_and_the_host_is_partial(tmp_path):
    config = _config(tmp_path, TREE.replace("</Fallback>", ""))
    (bad,) = [d for d in config.diagnostics if d.code == "BT_XML_SYNTAX"]
    assert bad.location.file.endswith("main.xml") and bad.location.line > 0
    assert _links(config) == []
    instance = config.node("/nav/bt_navigator")
    assert any("cannot be read" in r for r in instance.completeness_reasons)


def test_a_library_not_found_is_a_diagnostic_and_its_nodes_unknown(tmp_path):
    config = _config(tmp_path, libraries=("elsewhere_nodes",))
    codes = sorted({d.code for d in config.diagnostics if d.code.startswith("BT_")})
    assert codes == ["BT_LIBRARY_NOT_FOUND", "BT_NODE_UNKNOWN"]
    assert _links(config) == []
    assert config.node("/nav/bt_navigator").completeness == "partial"


def test_a_modelled_navigator_without_the_tree_sources_is_partial_not_complete(tmp_path):
    # bt_navigator from its interface model, neither nav2_behavior_tree nor
    # nav2_bt_navigator (its default trees) in the workspace: its tree nodes' calls
    # are not known, so the instance says so
    (tmp_path / "empty").mkdir()
    # the model is partial already, with as many reasons as a node keeps: the trees'
    # come first all the same
    navigator = Node("nav2_bt_navigator", "bt_navigator", completeness="partial",
                     completeness_reasons=[f"model reason {i}" for i in range(5)],
                     model="jazzy/nav2_bt_navigator 1.3.0")
    launch = LaunchModel(nodes=[NodeDecl("/bt_navigator", "nav2_bt_navigator",
                                         "bt_navigator", ros_version=2)])
    config = build(Configuration("c"), launch, scan([str(tmp_path)]),
                   {navigator.name: navigator})
    instance = config.node("/bt_navigator")
    assert instance.completeness == "partial"
    reasons = " ".join(instance.completeness_reasons)
    assert "nav2_behavior_tree" in reasons and "default_nav_to_pose_bt_xml" in reasons
    assert "nav2_behavior_tree" in instance.completeness_reasons[0]
    assert len(navigator.completeness_reasons) == 5  # the shared model is not touched


def test_a_port_without_default_is_unknown_and_a_node_parameter_names_a_topic(tmp_path):
    # InputPort<std::string>(name, description): no default, so a service named by it
    # is '?' unless the tag gives it; an alias (``using Trig = ...``) gives the type; a
    # topic from the node's get_parameter_or is the parameter's value, else its default
    tree = TREE.replace("<Unregistered/>", '<Pause><Updater><Watch/></Updater></Pause>')
    links = _links(_config(tmp_path, tree))
    assert ("server", "?", "std_srvs/srv/Trigger") in links
    assert ("subscribe", "/nav/goal_update", "geometry_msgs/msg/PoseStamped") in links
    assert ("read", "/nav/bt_navigator/updater_topic", "string") in links
    tree = tree.replace("<Pause>", '<Pause pause_service_name="pause">')
    assert ("server", "/nav/pause", "std_srvs/srv/Trigger") in _links(_config(tmp_path / "b",
                                                                           tree))


def test_a_navigator_of_another_class_runs_trees_not_read(tmp_path):
    path = _workspace(tmp_path)
    navigator = Node("nav2_bt_navigator", "bt_navigator")
    launch = LaunchModel(
        nodes=[NodeDecl("/bt_navigator", "nav2_bt_navigator", "bt_navigator", ros_version=2)],
        params=[ParamDecl("/bt_navigator/plugin_lib_names", ["my_bt_nodes"]),
                ParamDecl("/bt_navigator/default_nav_to_pose_bt_xml", str(path)),
                ParamDecl("/bt_navigator/default_nav_through_poses_bt_xml", str(path)),
                ParamDecl("/bt_navigator/navigators", ["navigate_to_pose", "cover"]),
                ParamDecl("/bt_navigator/cover.plugin", "opennav_coverage::Navigator")])
    config = build(Configuration("c"), launch, scan([str(tmp_path)]),
                   {navigator.name: navigator})
    reasons = config.node("/bt_navigator").completeness_reasons
    assert any("navigator cover (opennav_coverage::Navigator)" in r for r in reasons)
    assert not any("navigate_to_pose" in r for r in reasons)


def test_a_navigator_left_out_of_the_list_runs_none_of_its_trees(tmp_path):
    """opennav_coverage's demo lists only its coverage navigator: bt_navigator builds
    neither NavigateToPose nor NavigateThroughPoses, so their default trees (their
    clients of spin, backup, compute_path_to_pose, ...) are not the node's; a navigator
    the list names runs its own (the lookup name ``pkg/Class`` as the class)."""
    path = _workspace(tmp_path)
    through = tmp_path / "my_bt" / "trees" / "through.xml"
    through.write_text(TREE.replace("other_go", "through_go"))
    navigator = Node("nav2_bt_navigator", "bt_navigator")

    def links(listed: list[str], plugins: dict[str, str]) -> set[str]:
        launch = LaunchModel(
            nodes=[NodeDecl("/bt_navigator", "nav2_bt_navigator", "bt_navigator",
                            ros_version=2)],
            params=[ParamDecl("/bt_navigator/plugin_lib_names", ["my_bt_nodes"]),
                    ParamDecl("/bt_navigator/default_nav_to_pose_bt_xml", str(path)),
                    ParamDecl("/bt_navigator/default_nav_through_poses_bt_xml",
                              str(through)),
                    ParamDecl("/bt_navigator/navigators", listed),
                    *(ParamDecl(f"/bt_navigator/{ident}.plugin", cls)
                      for ident, cls in plugins.items())])
        config = build(Configuration("c"), launch, scan([str(tmp_path)]),
                       {navigator.name: navigator})
        return {link.resource.name for link in config.links
                if link.node.name == "/bt_navigator" and link.kind == "action-client"}

    both = links(["navigate_to_pose", "navigate_through_poses"], {})
    assert {"/other_go", "/through_go"} <= both
    only = links(["navigate_to_pose", "cover"], {
        "navigate_to_pose": "nav2_bt_navigator/NavigateToPoseNavigator",
        "cover": "opennav_coverage_navigator/CoverageNavigator"})
    assert "/other_go" in only and "/through_go" not in only
    assert not links(["cover"], {"cover": "opennav_coverage_navigator/CoverageNavigator"})


def test_included_files_are_read_and_an_undefined_subtree_is_said(tmp_path):
    tree = """<root BTCPP_format="4" main_tree_to_execute="Main">
  <include path="../more/recovery.xml"/>
  <BehaviorTree ID="Main">
    <Sequence><SubTree ID="Recovery"/><SubTree ID="Elsewhere"/></Sequence>
  </BehaviorTree>
</root>
"""
    more = tmp_path / "my_bt" / "more"
    more.mkdir(parents=True)
    (more / "recovery.xml").write_text(
        '<root><BehaviorTree ID="Recovery"><GoThere server_name="recover"/></BehaviorTree>'
        '<include path="missing.xml"/></root>')
    config = _config(tmp_path, tree)
    assert _links(config) == [("action-client", "/nav/recover", "my_msgs/action/GoThere")]
    reasons = " ".join(config.node("/nav/bt_navigator").completeness_reasons)
    assert "subtree Elsewhere not defined" in reasons and "Recovery not" not in reasons
    assert "include missing.xml not read" in reasons


def test_plansys2_bt_action_node_is_a_tree_host_of_its_plugins_and_file(tmp_path):
    path = _workspace(tmp_path)
    node = Node("plansys2_bt_actions", "bt_action_node")
    decl = NodeDecl("/move", "plansys2_bt_actions", "bt_action_node", ros_version=2)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/move/plugins", ["my_bt_nodes"]),
        ParamDecl("/move/bt_xml_file", str(path))])
    config = build(Configuration("c"), launch, scan([str(tmp_path)]), {node.name: node})
    names = {(link.kind, link.resource.name) for link in config.links
             if link.node.name == "/move"}
    assert {("action-client", "/go_there"), ("client", "/clear_all")} <= names
    # no built-in library, so only the unregistered tag makes it partial
    assert [r.split(" (")[0] for r in config.node("/move").completeness_reasons] == [
        "behavior tree node Unregistered has no registered class found"]
    # without its file the tree is not known
    launch = LaunchModel(nodes=[decl], params=[ParamDecl("/move/plugins", ["my_bt_nodes"])])
    config = build(Configuration("c"), launch, scan([str(tmp_path)]), {node.name: node})
    assert config.node("/move").completeness_reasons == [
        "behavior tree bt_xml_file not set: the tree is not known"]


def test_a_library_of_a_package_on_behaviortree_cpp_through_another(tmp_path):
    """PlanSys2's plansys2_bt_example builds its tree nodes' libraries
    (``plansys2_move_bt_node``, ``BT_REGISTER_NODES``) and depends on plansys2_bt_actions,
    which depends on behaviortree_cpp; it names none of BehaviorTree.CPP's packages
    itself. Its libraries were not read: BT_LIBRARY_NOT_FOUND for each one the
    bt_action_node instances load (10), BT_NODE_UNKNOWN for each tree node (10), and
    the move action's ``navigate_to_pose`` client lost."""
    path = _workspace(tmp_path)
    manifest = path.parent.parent / "package.xml"
    manifest.write_text(manifest.read_text().replace(
        "<depend>behaviortree_cpp</depend>", "<depend>bt_base</depend>"))
    base = tmp_path / "bt_base"
    base.mkdir()
    (base / "package.xml").write_text(
        '<package format="3"><name>bt_base</name><version>1.0.0</version>'
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>x</license><buildtool_depend>ament_cmake</buildtool_depend>"
        "<depend>behaviortree_cpp</depend><export><build_type>ament_cmake</build_type>"
        "</export></package>")
    (base / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.8)\n"
                                         "project(bt_base)\n")
    node = Node("plansys2_bt_actions", "bt_action_node")
    decl = NodeDecl("/move", "plansys2_bt_actions", "bt_action_node", ros_version=2)
    launch = LaunchModel(nodes=[decl], params=[
        ParamDecl("/move/plugins", ["my_bt_nodes"]),
        ParamDecl("/move/bt_xml_file", str(path))])
    config = build(Configuration("c"), launch, scan([str(tmp_path)]), {node.name: node})
    assert not [d for d in config.diagnostics if d.code == "BT_LIBRARY_NOT_FOUND"]
    names = {(link.kind, link.resource.name) for link in config.links
             if link.node.name == "/move"}
    assert {("action-client", "/go_there"), ("client", "/clear_all")} <= names


SIMPLE = """#include "behaviortree_cpp/bt_factory.h"
namespace my_bt {
BT::NodeStatus ready(BT::TreeNode & node)
{
  return node.config().blackboard->get<bool>("ready") ? BT::NodeStatus::SUCCESS
                                                     : BT::NodeStatus::FAILURE;
}
}  // namespace my_bt

BT_REGISTER_NODES(factory)
{
  factory.registerSimpleCondition(
    "Ready", std::bind(&my_bt::ready, std::placeholders::_1));
}
"""


def test_a_library_of_function_nodes_only_is_found(tmp_path):
    """nav2's nav2_initial_pose_received_condition_bt_node (humble) registers one node
    made of a function, ``registerSimpleCondition("InitialPoseReceived", ...)``, and no
    class: the library was not indexed, so a navigator listing it (every humble
    nav2_params.yaml) got BT_LIBRARY_NOT_FOUND with the library's source in the
    workspace, and the tree's tag BT_NODE_UNKNOWN."""
    tree = TREE.replace("<Unregistered/>", "<Ready/>")
    path = _workspace(tmp_path, tree)
    (path.parents[1] / "src" / "simple.cpp").write_text(SIMPLE)
    cmake = path.parents[1] / "CMakeLists.txt"
    cmake.write_text(cmake.read_text() + "add_library(my_ready_node SHARED src/simple.cpp)\n")
    workspace = scan([str(tmp_path)])
    navigator = Node("nav2_bt_navigator", "bt_navigator")
    where = Location("bringup", "bringup/params.yaml", 4, 0)
    launch = LaunchModel(
        nodes=[NodeDecl("/nav/bt_navigator", "nav2_bt_navigator", "bt_navigator", "/nav/",
                        ros_version=2)],
        params=[ParamDecl("/nav/bt_navigator/plugin_lib_names",
                          ["my_bt_nodes", "my_ready_node"], location=where),
                ParamDecl("/nav/bt_navigator/default_nav_to_pose_bt_xml", str(path),
                          location=where)])
    config = build(Configuration("c"), launch, workspace, {navigator.name: navigator})
    codes = [d.code for d in config.diagnostics if d.code.startswith("BT_")]
    assert codes == []
    assert ("publish", "/nav/watch_state", "std_msgs/msg/String") in _links(config)


def _modelled_navigator(tmp_path, distro, libraries=None):
    from haros_arch.models.attach import Attacher
    from haros_arch.models.library import Library

    (tmp_path / "empty").mkdir(parents=True)
    where = Location("bringup", "bringup/params.yaml", 4, 0)
    params = [] if libraries is None else [
        ParamDecl("/bt_navigator/plugin_lib_names", list(libraries), location=where)]
    launch = LaunchModel(nodes=[NodeDecl("/bt_navigator", "nav2_bt_navigator",
                                         "bt_navigator", ros_version=2)], params=params)
    workspace = scan([str(tmp_path)])
    attacher = Attacher(Library(), distro, [])
    nodes = attacher.nodes_for(launch, workspace, {}, {}, [])
    return build(Configuration("c"), launch, workspace, nodes,
                 attacher.plugin_models(launch, {}))


def test_a_modelled_navigator_runs_the_modelled_tree_nodes_of_its_default_trees(tmp_path):
    # navigation2 installed, not in the workspace (every robot on a binary nav2): the
    # models of nav2_behavior_tree (its BT libraries) and nav2_bt_navigator (its default
    # trees) stand for their sources; the libraries a parameter file lists (Humble's
    # plugin_lib_names, kept by many robots) are nav2_behavior_tree's, no
    # BT_LIBRARY_NOT_FOUND per library (stretch_ros2 said 40)
    for distro in ("jazzy", "humble"):
        config = _modelled_navigator(
            tmp_path / distro, distro, ["nav2_compute_path_to_pose_action_bt_node",
                                        "nav2_spin_action_bt_node"])
        assert not [d for d in config.diagnostics if d.code.startswith("BT_")], distro
        made = {(link.kind, link.resource.name, link.call.type) for link in config.links
                if link.node.name == "/bt_navigator" and link.call.origin == "plugin"}
        assert {("action-client", "/compute_path_to_pose",
                 "nav2_msgs/action/ComputePathToPose"),
                ("action-client", "/follow_path", "nav2_msgs/action/FollowPath"),
                ("action-client", "/spin", "nav2_msgs/action/Spin"),
                ("client", "/global_costmap/clear_entirely_global_costmap",
                 "nav2_msgs/srv/ClearEntireCostmap")} <= made, distro
        reasons = " ".join(config.node("/bt_navigator").completeness_reasons)
        assert "nav2_behavior_tree" not in reasons and "bt_xml" not in reasons, distro


def test_a_library_no_model_holds_is_still_not_found(tmp_path):
    config = _modelled_navigator(tmp_path, "jazzy", ["vendor_custom_bt_node"])
    assert [d.code for d in config.diagnostics if d.code.startswith("BT_")] == [
        "BT_LIBRARY_NOT_FOUND"]
    assert config.node("/bt_navigator").completeness == "partial"
