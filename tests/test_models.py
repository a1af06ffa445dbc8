"""Interface models: nodes of packages with no source in the workspace take a model."""

from __future__ import annotations

import json
import os

import pytest
from conftest import package_xml

from haros_arch.launch.model import LaunchModel, NodeDecl
from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.models.attach import choose_distro
from haros_arch.models.format import dumps, from_document
from haros_arch.models.library import Library
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

FIXTURE = os.path.join(os.path.dirname(__file__), "..", "fixtures", "models", "installed_only")
INSTALLED = os.path.join(FIXTURE, "opt", "ros", "noetic", "share")


def _analyse(project_file: str = "project.yaml", env: dict | None = None,
             shipped: bool = True, **changes):
    project = load(os.path.join(FIXTURE, project_file))
    for key, value in changes.items():
        setattr(project, key, value)
    environment = {"ROS_PACKAGE_PATH": INSTALLED} if env is None else env
    model = analyse(project, environment, Options(cache_dir=None, jobs=1, models=shipped))
    (config,) = model.configurations
    return model, config


def _configuration(root):
    """The one configuration of the project file at ``root``, analysed."""
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    return config


def _instance(config, name):
    return next(n for n in config.nodes if n.name == name)


def test_an_installed_only_node_takes_the_users_model():
    _model, config = _analyse()
    amcl = _instance(config, "/amcl")
    assert amcl.completeness == "model"
    assert amcl.node.model == "noetic/amcl 1.17.3 example/navigation@01234567"
    scan = next(t for t in config.topics if t.name == "/base_scan")
    assert [link.node.name for link in scan.publishers] == ["/laser_driver"]
    assert [link.node.name for link in scan.subscribers] == ["/amcl"]
    assert {link.origin for link in amcl.links} == {"model"}
    pose = next(t for t in config.topics if t.name == "/amcl_pose")
    assert not pose.is_disconnected
    codes = {d.code: d for d in config.diagnostics}
    assert "installed at" in codes["MODEL_USED"].message
    assert codes["MODEL_USED"].location.line == 4
    assert "noetic" in codes["MODEL_DISTRO"].message
    assert "NODE_PACKAGE_UNKNOWN" not in codes and "NODE_NOT_FOUND" not in codes


def test_without_a_model_the_node_stays_unknown():
    _model, config = _analyse(models=[], shipped=False)
    amcl = _instance(config, "/amcl")
    assert amcl.completeness == "unknown" and amcl.links == []
    assert "NODE_PACKAGE_UNKNOWN" not in {d.code for d in config.diagnostics}  # installed


def test_without_the_users_model_the_shipped_one_is_used():
    _model, config = _analyse(models=[])
    amcl = _instance(config, "/amcl")
    assert amcl.completeness == "model"
    assert amcl.node.model.startswith("noetic/amcl ") and "ros-planning/navigation@" in (
        amcl.node.model)
    scan = next(t for t in config.topics if t.name == "/base_scan")
    assert [link.node.name for link in scan.subscribers] == ["/amcl"]


def test_a_package_not_found_at_all_takes_the_model_too():
    _model, config = _analyse(env={})
    assert _instance(config, "/amcl").completeness == "model"
    used = next(d for d in config.diagnostics if d.code == "MODEL_USED")
    assert "not found" in used.message


def test_the_json_model_names_the_model_and_reads_back():
    model, _config = _analyse()
    data = model_to_data(model)
    (package,) = [p for p in data["packages"] if p["name"] == "amcl"]
    (node,) = package["nodes"]
    assert node["completeness"] == "model" and node["model"].startswith("noetic/amcl 1.17.3")
    links = [link for link in data["configurations"][0]["links"] if link["node"] == "/amcl"]
    assert links and {link["origin"] for link in links} == {"model"}
    again = from_data(json.loads(json.dumps(data)))
    amcl = _instance(again.configurations[0], "/amcl")
    assert amcl.completeness == "model" and amcl.node.model == node["model"]


def test_rostopic_pub_publishes_what_its_arguments_say():
    _model, config = _analyse()
    pub = _instance(config, "/initial_pose")
    (link,) = pub.links
    assert (link.kind, link.name, link.type) == (
        "publish", "/initialpose", "geometry_msgs/PoseWithCovarianceStamped")
    assert link.latch and link.queue_size == 100 and link.origin == "arguments"
    topic = next(t for t in config.topics if t.name == "/initialpose")
    assert [s.node.name for s in topic.subscribers] == ["/amcl"]


def test_rosservice_call_is_a_client_of_its_service(write_tree):
    """``rosservice call --wait /prbt/driver/init`` (pilz_robots' robot.launch): a client
    of that service, its type the server's, known when it runs; not a node of unknown
    interface that could be the missing side of every absence in the configuration."""
    root = write_tree({
        "src/arm/package.xml": package_xml("arm"),
        "src/arm/CMakeLists.txt": "project(arm)\n",
        "src/arm/launch/arm.launch": """
            <launch>
              <node pkg="rosservice" type="rosservice" name="robot_init"
                    args="call --wait /prbt/driver/init"/>
              <group ns="prbt">
                <node pkg="rosservice" type="rosservice" name="reset"
                      args="call -v driver/recover '{}'"/>
              </group>
              <node pkg="rosservice" type="rosservice" name="lister" args="list"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch]\n",
    })
    config = _configuration(root)
    init, reset = _instance(config, "/robot_init"), _instance(config, "/prbt/reset")
    assert init.completeness == reset.completeness == "model"
    assert [(link.kind, link.name, link.type) for link in init.links] == [
        ("client", "/prbt/driver/init", None)]
    assert [(link.kind, link.name) for link in reset.links] == [
        ("client", "/prbt/driver/recover")]
    assert _instance(config, "/lister").completeness == "unknown"


def test_dynparam_is_a_client_of_the_reconfigure_server_it_names(write_tree):
    """PX4-Avoidance's safe_landing_planner.launch starts ``dynparam load
    safe_landing_planner_node FILE`` to give the planner its settings: a client of that
    node's reconfigure server (``set_parameters`` and its two topics), not a node of
    unknown interface that could be the missing side of every absence; and a
    ``set_from_parameters`` reads the parameters the launch file gives it."""
    root = write_tree({
        "src/p/package.xml": package_xml("p"),
        "src/p/CMakeLists.txt": "project(p)\n",
        "src/p/launch/p.launch": """
            <launch>
              <node pkg="dynamic_reconfigure" type="dynparam" name="loader"
                    args="load planner_node $(find p)/cfg/planner.yaml"/>
              <group ns="cam">
                <node pkg="dynamic_reconfigure" type="dynparam" name="setter"
                      args="set --timeout=5 driver exposure -3"/>
                <node pkg="dynamic_reconfigure" type="dynparam" name="copier"
                      args="set_from_parameters driver">
                  <param name="brightness" value="58"/>
                </node>
              </group>
              <node pkg="dynamic_reconfigure" type="dynparam" name="lister" args="list"/>
              <node pkg="dynamic_reconfigure" type="dynparam" name="refused"
                    args="set driver"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [p/launch/p.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    loader = _instance(config, "/loader")
    assert loader.completeness == "model"
    assert [(link.kind, link.name, link.type) for link in loader.links] == [
        ("client", "/planner_node/set_parameters", "dynamic_reconfigure/Reconfigure"),
        ("subscribe", "/planner_node/parameter_descriptions",
         "dynamic_reconfigure/ConfigDescription"),
        ("subscribe", "/planner_node/parameter_updates", "dynamic_reconfigure/Config")]
    assert [link.name for link in _instance(config, "/cam/setter").links
            if link.kind == "client"] == ["/cam/driver/set_parameters"]
    # the copier reads what it is given: no parameter set and never read
    assert [f.entities for f in run_catalogue(model)
            if f.rule.startswith("parameter-set-not-read")] == []
    assert _instance(config, "/lister").completeness == "unknown"
    assert _instance(config, "/refused").completeness == "unknown"


def test_rostopic_pub_with_a_rate_does_not_latch():
    from haros_arch.models.commands import command_node

    node = command_node(NodeDecl("/p", "rostopic", "rostopic",
                                 args="pub -r 10 /cmd geometry_msgs/Twist '{}' __name:=x"))
    (call,) = node.calls
    assert (call.name, call.type, call.latch) == ("/cmd", "geometry_msgs/Twist", False)
    assert command_node(NodeDecl("/e", "rostopic", "rostopic", args="info /cmd")) is None
    ros2 = command_node(NodeDecl("/p", "", "ros2", args="topic pub --qos-reliability "
                                 "best_effort -r 5 cmd_vel geometry_msgs/msg/Twist '{}'"))
    (call,) = ros2.calls
    assert (call.name, call.type, call.qos) == ("cmd_vel", "geometry_msgs/msg/Twist",
                                                 {"reliability": "best_effort"})


def test_the_distribution_comes_from_the_project_then_the_environment_then_the_launch():
    ros1 = LaunchModel(nodes=[NodeDecl("/a", "p", "a")])
    ros2 = LaunchModel(nodes=[NodeDecl("/a", "p", "a", ros_version=2)])
    assert choose_distro("humble", {"ROS_DISTRO": "jazzy"}, ros2)[0] == "humble"
    assert choose_distro(None, {"ROS_DISTRO": "melodic"}, ros1)[0] == "melodic"
    assert choose_distro(None, {}, ros1)[0] == "noetic"
    assert choose_distro(None, {}, ros2)[0] == "jazzy"
    _model, config = _analyse(distro="melodic", shipped=False)
    # the user's model is noetic's: it stands for melodic's, the node partial
    amcl = _instance(config, "/amcl")
    assert amcl.completeness == "partial" and amcl.node.model.startswith("noetic/")


def test_a_bad_model_file_is_a_diagnostic(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"schema": "haros-arch-model/1", "package": "x", "nodes": 3}')
    broken = tmp_path / "broken.json"
    broken.write_text('{"schema": \n')
    kind = tmp_path / "kind.json"
    kind.write_text('{"schema": "haros-arch-model/1", "package": "y", "nodes": '
                    '[{"executable": "y", "calls": [{"kind": "teleport", "name": "x"}]}]}')
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100_000 + "]" * 100_000)
    library = Library([str(bad), str(broken), str(tmp_path / "missing.json"), str(kind),
                       str(deep)], shipped=None)
    assert [d.code for d in library.diagnostics] == ["MODEL_INVALID"] * 5
    assert "teleport" in library.diagnostics[3].message
    assert library.diagnostics[1].location.line == 2
    assert library.find("x", "noetic") is None


def test_a_model_file_round_trips():
    with open(os.path.join(FIXTURE, "models", "amcl.json"), encoding="utf-8") as handle:
        first = from_document(json.load(handle))
    again = from_document(json.loads(dumps(first)))
    assert again.label == first.label
    (node,) = again.nodes
    assert [(c.kind, c.name, c.type) for c in node.calls][:2] == [
        ("subscribe", "scan", "sensor_msgs/LaserScan"),
        ("publish", "amcl_pose", "geometry_msgs/PoseWithCovarianceStamped")]
    assert node.calls[3].default == 30 and node.calls[3].has_default


@pytest.mark.parametrize("package, distro", [("amcl", "noetic"), ("nav2_amcl", "jazzy")])
def test_shipped_models_are_found(package, distro):
    found = Library().find(package, distro)
    if found is None:
        pytest.skip("not generated yet")
    assert found.distro == distro and found.source.get("commit")


@pytest.mark.parametrize("distro, joint_states, monitored, limit", [
    ("noetic", "?", "~?", "/?_planning/joint_limits/?/max_position"),
    ("jazzy", "joint_states", "monitored_planning_scene",
     "?_planning.joint_limits.?.max_position")])
def test_shipped_move_group_names_its_planning_scene_monitor_topics(
        distro, joint_states, monitored, limit):
    """The overrides of moveit_ros_move_group (read in MoveIt's source) name the planning
    scene monitor's topics: noetic's from MoveItCpp's options with the monitor's
    defaults, jazzy's from its constants; both publish the monitored scene, which the
    extraction misses, and read the joint limits as RobotModelLoader names them."""
    found = Library().find("moveit_ros_move_group", distro)
    assert found is not None
    node = next(n for n in found.nodes if n.executable == "move_group")
    calls = {(c.kind, c.name, c.name_default) for c in node.calls}
    assert ("subscribe", joint_states, "joint_states" if distro == "noetic" else None) in calls
    assert ("publish", monitored, "monitored_planning_scene" if distro == "noetic"
            else None) in calls
    assert ("read", limit, None) in calls
    assert not [c for c in node.calls
                if c.kind == "subscribe" and c.name == "?" and c.name_param is None]
    # a capability makes no MoveItCpp option read: only move_group's main does
    capability = next(n for n in found.nodes
                      if n.executable == "move_group/MoveGroupGetPlanningSceneService")
    assert [(c.kind, c.name) for c in capability.calls] == [("server", "get_planning_scene")]


LISTENER = """
    import rclpy
    from sensor_msgs.msg import JointState

    def main():
        rclpy.init()
        node = rclpy.create_node('arm_monitor')
        node.create_subscription(JointState, 'joint_states', lambda m: None, 10)
        rclpy.spin(node)
    """


def test_a_ros2_system_takes_the_jazzy_model_named_as_its_code_names_itself(write_tree):
    from conftest import package_xml

    root = write_tree({
        "src/arm/package.xml": package_xml("arm", build_type="ament_python"),
        "src/arm/setup.py": "from setuptools import setup\nsetup(name='arm', packages=["
                            "'arm'], entry_points={'console_scripts': ['monitor = "
                            "arm.monitor:main']})\n",
        "src/arm/resource/arm": "",
        "src/arm/arm/__init__.py": "",
        "src/arm/arm/monitor.py": LISTENER,
        "src/arm/launch/arm.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                return LaunchDescription([
                    Node(package='joint_state_publisher', executable='joint_state_publisher'),
                    Node(package='arm', executable='monitor'),
                ])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [arm/launch/arm.launch.py]\n",
    })
    config = _configuration(root)
    jsp = _instance(config, "/joint_state_publisher")
    assert jsp.completeness == "model" and jsp.node.model.startswith("jazzy/")
    topic = next(t for t in config.topics if t.name == "/joint_states")
    assert ([p.node.name for p in topic.publishers], [s.node.name for s in topic.subscribers]
            ) == (["/joint_state_publisher"], ["/arm_monitor"])
    assert topic.publishers[0].qos["reliability"] == "reliable"
    assert "ROS 2" in next(d for d in config.diagnostics if d.code == "MODEL_DISTRO").message


def test_a_name_from_each_element_of_a_list_parameter_gives_one_link_each():
    _model, config = _analyse("project_mux.yaml")
    mux = _instance(config, "/twist_mux")
    assert sorted(link.name for link in mux.subscribers) == ["/joy_teleop/cmd_vel",
                                                             "/nav/cmd_vel"]
    joy = next(t for t in config.topics if t.name == "/joy_teleop/cmd_vel")
    assert [p.node.name for p in joy.publishers] == ["/joy_cmd"]
    assert not any(t.is_unresolved for t in config.topics)


def test_without_the_list_the_name_stays_unknown():
    from haros_arch.graph.build import element_calls
    from haros_arch.model.source import PrimitiveCall

    call = PrimitiveCall("subscribe", "?", "geometry_msgs/Twist", name_param="~topics",
                         name_each="topic")
    _model, config = _analyse("project_mux.yaml")
    mux = _instance(config, "/twist_mux")

    class NoParameters:
        by_name: dict = {}

    assert element_calls(call, mux, NoParameters()) == [call]  # type: ignore[arg-type]


def test_every_shipped_model_reads_clean_and_names_its_source():
    from haros_arch.models.library import DATA, read_model

    found: list = []
    files = [os.path.join(DATA, distro, name) for distro in sorted(os.listdir(DATA))
             for name in sorted(os.listdir(os.path.join(DATA, distro)))]
    assert len(files) >= 60
    for path in files:
        model = read_model(path, found)
        assert model is not None and model.distro == os.path.basename(os.path.dirname(path))
        assert model.package + ".json" == os.path.basename(path)
        assert model.source["repository"].startswith("github:")
        assert len(model.source["commit"]) == 40
    assert found == []


def test_a_nodelet_of_a_package_without_source_takes_its_model(write_tree):
    from conftest import package_xml

    root = write_tree({
        "src/cam/package.xml": package_xml("cam"),
        "src/cam/CMakeLists.txt": "project(cam)\n",
        "src/cam/launch/cam.launch": """
            <launch>
              <node pkg="nodelet" type="nodelet" name="manager" args="manager"/>
              <node pkg="nodelet" type="nodelet" name="rectify"
                    args="load image_proc/rectify manager"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [cam/launch/cam.launch]\n",
    })
    config = _configuration(root)
    rectify = _instance(config, "/rectify")
    assert rectify.node is not None and rectify.node.model.startswith("noetic/image_proc ")
    assert {(link.kind, link.name) for link in rectify.links} >= {
        ("subscribe", "/image_mono"), ("publish", "/image_rect")}


def test_image_view_of_its_model_makes_the_calls_of_the_nodelet_it_runs(write_tree):
    # image_view's main runs the nodelet image_view/image under its own name: the
    # model's executable lists it, its instance makes the nodelet's calls (of the same
    # model), with its remaps; the nodelet names its topic nh.resolveName("image")
    from conftest import package_xml

    root = write_tree({
        "src/cam/package.xml": package_xml("cam"),
        "src/cam/CMakeLists.txt": "project(cam)\n",
        "src/cam/launch/view.launch": """
            <launch>
              <group ns="camera">
                <node pkg="image_view" type="image_view" name="view">
                  <remap from="image" to="image_raw"/>
                </node>
              </group>
            </launch>
            """,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [cam/launch/view.launch]\n",
    })
    config = _configuration(root)
    view = _instance(config, "/camera/view")
    assert view.node is not None and view.node.model.startswith("noetic/image_view ")
    assert view.node.nodelets == ["image_view/image"] and view.is_complete
    links = {(link.kind, link.name) for link in view.links}
    assert {("subscribe", "/camera/image_raw"), ("read", "/camera/view/autosize")} <= links
    assert not any("?" in name for _, name in links)


def test_a_nodelet_named_pcl_takes_the_model_of_pcl_ros(write_tree):
    # pcl_ros exports its nodelets as ``pcl/VoxelGrid``, ...: there is no package pcl
    from conftest import package_xml

    root = write_tree({
        "src/cam/package.xml": package_xml("cam"),
        "src/cam/CMakeLists.txt": "project(cam)\n",
        "src/cam/launch/grid.launch": """
            <launch>
              <node pkg="nodelet" type="nodelet" name="voxel_grid"
                    args="standalone pcl/VoxelGrid"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [cam/launch/grid.launch]\n",
    })
    config = _configuration(root)
    grid = _instance(config, "/voxel_grid")
    assert grid.node is not None and grid.node.model.startswith("noetic/pcl_ros ")
    assert ("subscribe", "/tf") in {(link.kind, link.name) for link in grid.links}
    assert "NODE_PACKAGE_UNKNOWN" not in {d.code for d in config.diagnostics}


def test_rviz2_is_partial_its_displays_are_plugins_of_its_configuration(write_tree):
    # UR's ur_moveit.launch.py gives rviz2 warehouse_plugin / warehouse_host, which
    # MoveIt's MotionPlanning display (a plugin moveit.rviz loads) reads: no node of
    # complete interface that reads nothing
    root = write_tree({
        "src/base/package.xml": _package_xml("base"),
        "src/base/launch/view.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                return LaunchDescription([
                    Node(package='rviz2', executable='rviz2', name='rviz2_moveit',
                         arguments=['-d', 'moveit.rviz'],
                         parameters=[{'warehouse_host': 'localhost'}]),
                ])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/view.launch.py]\n",
    })
    config = _configuration(root)
    rviz = _instance(config, "/rviz2_moveit")
    assert rviz.node is not None and rviz.node.model.startswith("jazzy/rviz2 ")
    assert rviz.completeness == "partial"
    assert "plugins its configuration file loads" in " ".join(rviz.node.completeness_reasons)


def test_rviz2_launched_without_a_name_is_named_as_its_code_names_it(write_tree):
    # rviz_common's VisualizerApp::init calls init(argc, argv, "rviz", false) on its
    # RosClientAbstractionIface (visualizer_app.cpp:150 of ros2/rviz jazzy): the node is
    # /rviz, not a name guessed from the executable (the model's rosname was '?')
    root = write_tree({
        "src/base/package.xml": _package_xml("base"),
        "src/base/launch/view.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                return LaunchDescription([Node(package='rviz2', executable='rviz2')])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/view.launch.py]\n",
    })
    config = _configuration(root)
    rviz = _instance(config, "/rviz")
    assert rviz.node is not None and rviz.node.model.startswith("jazzy/rviz2 ")
    assert "NODE_NAME_GUESSED" not in {d.code for d in config.diagnostics}


def test_the_jazzy_spawner_is_in_controller_manager_s_model(write_tree):
    # ros2_control installs spawner from setup.cfg's entry points through
    # ament_python_install_package(... SCRIPTS_DESTINATION ...): the model had no node
    # controller_manager/spawner (MODEL_NODE_MISSING in UR, TIAGo, Clearpath launches)
    root = write_tree({
        "src/base/package.xml": _package_xml("base"),
        "src/base/launch/control.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                return LaunchDescription([
                    Node(package='controller_manager', executable='spawner',
                         arguments=['joint_state_broadcaster']),
                ])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/control.launch.py]\n",
    })
    config = _configuration(root)
    # (and the controller it loads, a node of its own: no manager is started here)
    (spawner,) = [n for n in config.nodes if n.origin != "plugin"]
    # its arguments name its node and the manager's services it calls: they are taken
    # over the model's (``models.commands``), which builds those names from sys.argv
    assert spawner.node is not None and spawner.node.model == (
        "the arguments of controller_manager spawner")
    assert spawner.name == "/spawner_joint_state_broadcaster"
    assert "MODEL_NODE_MISSING" not in {d.code for d in config.diagnostics}


def test_ros2_list_names_come_from_the_parameters_under_a_prefix(write_tree):
    root = write_tree({
        "src/base/package.xml": _package_xml("base"),
        "src/base/launch/mux.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                return LaunchDescription([
                    Node(package='twist_mux', executable='twist_mux', name='twist_mux',
                         parameters=[{'topics': {
                             'navigation': {'topic': 'cmd_vel_nav', 'priority': 10},
                             'joystick': {'topic': 'joy_vel', 'priority': 100}}}]),
                ])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/mux.launch.py]\n",
    })
    config = _configuration(root)
    mux = _instance(config, "/twist_mux")
    assert mux.node.model.startswith("jazzy/twist_mux ")
    assert sorted(link.name for link in mux.subscribers
                  if link.type == "geometry_msgs/msg/Twist") == ["/cmd_vel_nav", "/joy_vel"]


def _package_xml(name: str) -> str:
    from conftest import package_xml

    return package_xml(name, build_type="ament_cmake")


@pytest.mark.parametrize(("schema", "readable"), [
    ("haros-arch-model/1", True), ("haros-arch-model/2", True),
    ("haros-arch-model/3", False), ("haros-arch-model/" + "9" * 5000, False)])
def test_model_files_of_older_versions_read_and_newer_ones_are_refused(schema, readable):
    from haros_arch.models.format import ModelFileError

    data = {"schema": schema, "package": "p", "distro": "noetic", "nodes": []}
    if readable:
        assert from_document(data).package == "p"
    else:
        with pytest.raises(ModelFileError, match="schema version"):
            from_document(data)


FILTER_MODEL = {
    "schema": "haros-arch-model/2", "package": "fusion", "distro": "noetic", "nodes": [{
        "package": "fusion", "executable": "ekf", "rosname": "ekf", "calls": [
            {"kind": "subscribe", "name": "?", "type": "sensor_msgs/Imu",
             "name_param": "~imu", "name_each": "#"},
            {"kind": "subscribe", "name": "?", "type": "nav_msgs/Odometry",
             "name_param": "~odom", "name_each": "#"},
            {"kind": "subscribe", "name": "?", "type": "geometry_msgs/TwistStamped",
             "name_param": "~twist", "name_each": "#"}]}]}


def test_names_from_a_numbered_family_of_parameters_come_from_launch_and_yaml(write_tree):
    from conftest import package_xml

    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/config/ekf.yaml": "imu0: imu/data\nimu1: /imu2/data\nimu3: skipped\n",
        "src/robot/launch/ekf.launch": """
            <launch>
              <node pkg="fusion" type="ekf" name="ekf">
                <rosparam command="load" file="$(find robot)/config/ekf.yaml"/>
                <param name="odom0" value="wheel/odom"/>
              </node>
            </launch>
            """,
        "models/fusion.json": json.dumps(FILTER_MODEL),
        "project.yaml": "project: p\nmodels: [models]\n"
                        "configurations:\n  c: [robot/launch/ekf.launch]\n",
    })
    config = _configuration(root)
    ekf = _instance(config, "/ekf")
    # imu0, imu1 and odom0 are set; imu3 is not read (imu2 is not set); twist0 is not set
    assert sorted(link.name for link in ekf.subscribers) == [
        "/imu/data", "/imu2/data", "/wheel/odom", "?"]
    unknown = next(link for link in ekf.subscribers if link.name == "?")
    assert unknown.type == "geometry_msgs/TwistStamped"
    (why,) = [d.message for d in config.diagnostics if d.code == "NAME_PARAM_UNSET"]
    assert why == ("/ekf: the name of this subscribe is the value of the parameters "
                   "~twist0, ~twist1, ..., which the configuration does not set; it stays "
                   "unknown")


def test_topic_tools_nodes_take_their_topics_from_their_arguments(write_tree):
    from conftest import package_xml

    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/tools.launch": """
            <launch>
              <node pkg="topic_tools" type="relay" name="relay" args="scan front/scan"/>
              <node pkg="topic_tools" type="relay" name="echo" args="odom"/>
              <node pkg="topic_tools" type="mux" name="mux" args="cmd_vel nav_vel joy_vel"/>
              <node pkg="topic_tools" type="throttle" name="slow"
                    args="messages camera/image 2.0"/>
              <node pkg="topic_tools" type="drop" name="drop" args="imu 1 2 imu_half"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [robot/launch/tools.launch]\n",
    })
    config = _configuration(root)

    def sides(name):
        node = _instance(config, name)
        return (sorted(link.name for link in node.subscribers),
                sorted(link.name for link in node.publishers))

    assert sides("/relay") == (["/scan"], ["/front/scan"])
    assert sides("/echo") == (["/odom"], ["/odom_relay"])
    assert sides("/mux") == (["/joy_vel", "/nav_vel"], ["/cmd_vel", "/mux/selected"])
    assert sides("/slow") == (["/camera/image"], ["/camera/image_throttle"])
    assert sides("/drop") == (["/imu"], ["/imu_half"])
    mux = _instance(config, "/mux")
    assert mux.completeness == "model" and "/mux/select" in {
        link.name for link in mux.links if link.kind == "server"}
    # every private parameter a tool reads has a default in its source (getParam into a
    # variable that holds a value): an unset one is no parameter-read-not-set
    # (hector_slam's mapping_box.launch runs a throttle that sets none of them)
    reads = {(name, link.name): (link.call.type, link.call.default)
             for name in ("/relay", "/mux", "/slow")
             for link in _instance(config, name).links if link.kind == "read"}
    assert all(link.call.has_default for name in ("/relay", "/mux", "/slow")
               for link in _instance(config, name).links if link.kind == "read")
    assert reads[("/slow", "/slow/force_latch")] == ("bool", True)
    assert reads[("/mux", "/mux/initial_topic")] == ("str", "")


def test_a_ros1_spawner_calls_the_controller_manager_of_its_namespace_argument(write_tree):
    from conftest import package_xml

    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/control.launch": """
            <launch>
              <node pkg="controller_manager" type="spawner" name="spawner"
                    args="--namespace arm --wait-for ready joint_state_controller"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [robot/launch/control.launch]\n",
    })
    config = _configuration(root)
    spawner = _instance(config, "/spawner")
    assert sorted((link.kind, link.name) for link in spawner.links
                  if link.kind in ("client", "subscribe")) == [
        ("client", "/arm/controller_manager/load_controller"),
        ("client", "/arm/controller_manager/switch_controller"),
        ("client", "/arm/controller_manager/unload_controller"),
        ("subscribe", "/ready")]
    # rospy.get_param('/use_sim_time', False): a read with a default, never reported
    # as read but not set (Husky's base_controller_spawner was)
    (sim_time,) = [link for link in spawner.links if link.name == "/use_sim_time"]
    assert sim_time.call.has_default and sim_time.call.default is False


def test_a_ros1_spawner_that_names_no_controller_exits(write_tree):
    # turtlebot3_manipulation's ros_controllers.launch (noetic): ``args=""``. The
    # spawner's argparse wants one controller at least (nargs='+') and exits before
    # init_node: no node, no controller loaded. Its interface model (a ``?`` wait-for
    # subscription, ...) stood for it; now it makes no call, and a warning says why.
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/control.launch": """
            <launch>
              <node pkg="controller_manager" type="spawner" name="spawner" args=""/>
              <node pkg="controller_manager" type="spawner" name="named"
                    args="--namespace arm"/>
              <node pkg="controller_manager" type="spawner" name="fine" args="arm"/>
            </launch>
            """,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [robot/launch/control.launch]\n",
    })
    config = _configuration(root)
    for name in ("/spawner", "/named"):
        assert _instance(config, name).links == []
    assert _instance(config, "/fine").links
    exits = sorted(d.location.line for d in config.diagnostics if d.code == "NODE_EXITS")
    assert exits == [2, 3]
    assert not [d for d in config.diagnostics if d.code == "MODEL_USED"
                and "spawner" in d.message]


def test_a_ros1_gazebo_spawner_reads_the_parameter_its_arguments_name(write_tree):
    # gazebo_ros' spawn_model: its interface model reads '?' (rospy.get_param(args.param)),
    # so any parameter of its namespace could have been read; its -param names it
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/sim.launch": """
            <launch>
              <group ns="r1">
                <param name="robot_description" value="&lt;robot name='r'/&gt;"/>
                <param name="unused" value="1"/>
                <node pkg="gazebo_ros" type="spawn_model" name="spawn"
                      args="-urdf -param robot_description -model r1 -x -1.5 -J arm 0.3
                            -unpause -wait ground"/>
              </group>
            </launch>
            """,
        "project.yaml": "project: p\ndistro: noetic\nconfigurations:\n"
                        "  c: [robot/launch/sim.launch]\n",
    })
    config = _configuration(root)
    spawner = _instance(config, "/r1/spawn")
    assert sorted((link.kind, link.name) for link in spawner.links) == [
        ("client", "/gazebo/set_model_configuration"),
        ("client", "/gazebo/spawn_urdf_model"),
        ("client", "/gazebo/unpause_physics"),
        ("read", "/r1/robot_description"),
        ("subscribe", "/gazebo/model_states")]
    assert spawner.node.completeness == "model"


def test_ros2_topic_tools_take_their_topics_from_their_parameters(write_tree):
    root = write_tree({
        "src/base/package.xml": _package_xml("base"),
        "src/base/launch/tools.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                return LaunchDescription([
                    Node(package='topic_tools', executable='relay', name='relay',
                         parameters=[{'input_topic': 'scan', 'output_topic': 'scan_out'}]),
                    Node(package='topic_tools', executable='mux', name='mux',
                         parameters=[{'input_topics': ['nav_vel', 'joy_vel']}]),
                ])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/tools.launch.py]\n",
    })
    config = _configuration(root)
    relay, mux = _instance(config, "/relay"), _instance(config, "/mux")
    assert ([link.name for link in relay.subscribers], [link.name for link in relay.publishers]
            ) == (["/scan"], ["/scan_out"])
    assert (sorted(link.name for link in mux.subscribers),
            [link.name for link in mux.publishers]) == (["/joy_vel", "/nav_vel"],
                                                        ["/mux/selected"])


def test_ros2_throttle_takes_its_output_topic_from_the_argument_its_mode_reads(write_tree):
    # the model keeps the conditions over what rclcpp leaves of the arguments
    # (``args.at(1) == "messages"``, ``args.size() >= 5``): the instance's words decide
    # them, so each mode's output topic is the argument that mode reads
    root = write_tree({
        "src/base/package.xml": _package_xml("base"),
        "src/base/launch/throttle.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                return LaunchDescription([
                    Node(package='topic_tools', executable='throttle', name='scan_slow',
                         arguments=['messages', '/scan', '2.0', '/scan_2hz']),
                    Node(package='topic_tools', executable='throttle', name='image_slow',
                         arguments=['bytes', '/image', '1000', '1.0', '/image_1k']),
                    Node(package='topic_tools', executable='throttle', name='odom_slow',
                         arguments=['messages', '/odom', '5.0']),
                    Node(package='topic_tools', executable='relay', name='echo',
                         parameters=[{'input_topic': 'imu'}]),
                ])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/throttle.launch.py]\n",
    })
    config = _configuration(root)
    # without an output topic, the default the code declares: the input topic's value
    # and "_throttle" / "_relay" (relay_node.cpp declares it, tool_base_node.cpp uses it)
    for name, topics in (("/scan_slow", (["/scan"], ["/scan_2hz"])),
                         ("/image_slow", (["/image"], ["/image_1k"])),
                         ("/odom_slow", (["/odom"], ["/odom_throttle"])),
                         ("/echo", (["/imu"], ["/imu_relay"]))):
        instance = _instance(config, name)
        assert ([link.name for link in instance.subscribers],
                [link.name for link in instance.publishers]) == topics


def test_a_modelled_node_launched_without_name_takes_its_section_of_a_parameter_file(
        write_tree):
    root = write_tree({
        "src/base/package.xml": _package_xml("base"),
        "src/base/config/ekf.yaml": "ekf_filter_node:\n  ros__parameters:\n"
                                    "    imu0: imu/data\n    odom0: wheel/odom\n"
                                    "other_node:\n  ros__parameters:\n    imu0: nowhere\n",
        "src/base/launch/ekf.launch.py": """
            import os
            from launch import LaunchDescription
            from launch_ros.actions import Node

            def generate_launch_description():
                here = os.path.dirname(os.path.abspath(__file__))
                return LaunchDescription([
                    Node(package='robot_localization', executable='ekf_node',
                         parameters=[os.path.join(here, '..', 'config', 'ekf.yaml')]),
                ])
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/ekf.launch.py]\n",
    })
    config = _configuration(root)
    ekf = _instance(config, "/ekf_filter_node")  # the name its code (and model) gives it
    names = {link.name for link in ekf.subscribers}
    assert {"/imu/data", "/wheel/odom"} <= names and "/nowhere" not in names


def test_a_release_name_of_the_executable_and_a_distribution_without_models(write_tree):
    """humble has no model of cartographer_ros: jazzy's is used, and said; its releases install
    cartographer_ros' occupancy_grid_node as cartographer_occupancy_grid_node, which
    takes that node (the shipped model lists the alias)."""
    root = write_tree({
        "src/robot/package.xml": package_xml("robot", build_type="ament_cmake"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/slam.launch.xml": """
            <launch>
              <node pkg="cartographer_ros" exec="cartographer_occupancy_grid_node"
                    name="occupancy_grid_node"/>
              <node pkg="cartographer_ros" exec="occupancy_grid_node" name="old_name"/>
            </launch>
            """,
        "project.yaml": "project: p\ndistro: humble\n"
                        "configurations:\n  c: [robot/launch/slam.launch.xml]\n",
    })
    config = _configuration(root)
    new, old = _instance(config, "/occupancy_grid_node"), _instance(config, "/old_name")
    assert new.node is old.node and new.node.model.startswith("jazzy/cartographer_ros ")
    assert sorted(link.name for link in new.links if link.kind == "publish") == ["/map"]
    said = [d.message for d in config.diagnostics]
    assert any("interface models of distribution humble" in m for m in said)
    assert any("cartographer_ros/cartographer_occupancy_grid_node" in m and
               "its node occupancy_grid_node, which releases also install as "
               "cartographer_occupancy_grid_node" in m for m in said)
    assert not any(d.code == "MODEL_NODE_MISSING" for d in config.diagnostics)


def test_a_model_node_is_found_by_an_alias():
    data = {"schema": "haros-arch-model/2", "package": "p", "distro": "jazzy",
            "nodes": [{"name": "p/old", "aliases": ["p_old"]}, {"name": "p/p_old_too"}]}
    model = from_document(json.loads(json.dumps(data)))
    assert model.node("old") is model.node("p_old") is model.nodes[0]
    assert model.node("p_old_too") is model.nodes[1] and model.node("other") is None


def test_the_shipped_jazzy_static_transform_publisher_publishes_tf_static():
    """The jazzy tf2_ros model (geometry2 646342c6) was built before the extractor read
    a stand-in package's own headers: static_transform_publisher was partial with no call
    at all (no /tf_static publisher in any ROS 2 configuration that starts it; create3_sim
    and others). Rebuilt with ``models build --only tf2_ros`` from the pinned tree."""
    from haros_arch.models.library import Library

    model = Library().find("tf2_ros", "jazzy")
    assert model is not None
    node = model.node("static_transform_publisher")
    assert node is not None and node.completeness == "complete"
    made = {(c.kind, c.name) for c in node.calls}
    assert ("publish", "/tf_static") in made
    assert {("declare", f"translation.{axis}") for axis in "xyz"} <= made


def test_a_ros1_trajectory_controller_takes_the_joint_trajectory_controller_model(write_tree):
    # ros_controllers exports effort_controllers/JointTrajectoryController (and its
    # position, velocity, pos_vel and pos_vel_acc kin) from joint_trajectory_controller,
    # not from effort_controllers: CHAMP's gazebo.launch spawned one, PLUGIN_NOT_FOUND,
    # and its command topic had no subscriber
    from conftest import package_xml

    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/control.launch": """
            <launch>
              <rosparam>
                arm_controller: {type: effort_controllers/JointTrajectoryController,
                                 joints: [shoulder]}
              </rosparam>
              <node pkg="controller_manager" type="spawner" name="spawner"
                    args="arm_controller"/>
            </launch>
            """,
        "project.yaml": "project: p\ndistro: noetic\n"
                        "configurations:\n  c: [robot/launch/control.launch]\n",
    })
    config = _configuration(root)
    arm = _instance(config, "/arm_controller")
    assert arm.node is not None and arm.node.model.startswith(
        "noetic/joint_trajectory_controller ")
    links = {(link.kind, link.name) for link in arm.links}
    assert {("subscribe", "/arm_controller/command"),
            ("publish", "/arm_controller/state"),
            ("action-server", "/arm_controller/follow_joint_trajectory"),
            ("server", "/arm_controller/query_state")} <= links
    assert not [d for d in config.diagnostics if d.code == "PLUGIN_NOT_FOUND"]


def test_a_ros1_launch_file_takes_ros1_models_whatever_a_ros2_distro_says():
    """A ROS 1 launch file runs under roslaunch, of a ROS 1 distribution: a ROS_DISTRO
    of ROS 2 in the environment (elevation_mapping_cupy's ros2 branch keeps catkin
    packages and their .launch files beside the ported ones, checked with humble's) is
    not the one its nodes run in. humble's models gave its tf2_ros
    static_transform_publisher ``tf2_msgs/msg/TFMessage`` on /tf_static, which the ROS 1
    nodes subscribe as ``tf2_msgs/TFMessage``: a false topic-type-mismatch."""
    ros1 = LaunchModel(nodes=[NodeDecl("/a", "p", "a")])
    ros2 = LaunchModel(nodes=[NodeDecl("/a", "p", "a", ros_version=2)])
    distro, why = choose_distro(None, {"ROS_DISTRO": "humble"}, ros1)
    assert distro == "noetic" and "ROS_DISTRO humble" in why and "ROS 2" in why
    assert choose_distro(None, {"ROS_DISTRO": "noetic"}, ros2)[0] == "jazzy"
    assert choose_distro(None, {"ROS_DISTRO": "humble"}, ros2)[0] == "humble"
    assert choose_distro(None, {"ROS_DISTRO": "mydistro"}, ros1)[0] == "mydistro"
    _model, config = _analyse(env={"ROS_PACKAGE_PATH": INSTALLED, "ROS_DISTRO": "humble"})
    amcl = _instance(config, "/amcl")
    assert amcl.completeness == "model" and amcl.node.model.startswith("noetic/amcl ")
    (chosen,) = [d for d in config.diagnostics if d.code == "MODEL_DISTRO"]
    assert "noetic" in chosen.message and "humble" in chosen.message


def test_rostopic_echo_hz_delay_and_bw_subscribe_to_what_they_name(write_tree):
    """``<node pkg="rostopic" type="rostopic" args="echo velodyne_scan">`` (multimaster_fkie's
    demos start a dozen): a subscriber of the topic, in the node's namespace, of whatever
    type its publishers have; not a node of unknown interface that could be the missing
    side of every absence in the configuration. ``echo -b`` reads a bag: no subscriber."""
    root = write_tree({
        "src/p/package.xml": package_xml("p"),
        "src/p/CMakeLists.txt": "project(p)\n",
        "src/p/launch/p.launch": """
            <launch>
              <group ns="robot">
                <node pkg="rostopic" type="rostopic" name="scan"
                      args="pub scan std_msgs/String -r 1 'scan'"/>
                <node pkg="rostopic" type="rostopic" name="echo" args="echo -n 3 scan"/>
                <node pkg="rostopic" type="rostopic" name="hz"
                      args="hz --window 10 scan /odom"/>
              </group>
              <node pkg="rostopic" type="rostopic" name="bw" args="bw /robot/scan"/>
              <node pkg="rostopic" type="rostopic" name="delay" args="delay -w 5 /odom"/>
              <node pkg="rostopic" type="rostopic" name="bag" args="echo -b a.bag /odom"/>
              <node pkg="rostopic" type="rostopic" name="two" args="echo /a /b"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [p/launch/p.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    echo = _instance(config, "/robot/echo")
    assert echo.completeness == "model"
    assert [(link.kind, link.name, link.type) for link in echo.links] == [
        ("subscribe", "/robot/scan", None), ("read", "/use_sim_time", "bool")]
    assert [(link.kind, link.name) for link in _instance(config, "/robot/hz").links] == [
        ("subscribe", "/robot/scan"), ("subscribe", "/odom"),
        ("read", "/robot/use_sim_time")]
    assert [(link.kind, link.name) for link in _instance(config, "/bw").links] == [
        ("subscribe", "/robot/scan")]
    assert [(link.kind, link.name) for link in _instance(config, "/delay").links] == [
        ("subscribe", "/odom"), ("read", "/use_sim_time")]
    bag = _instance(config, "/bag")
    assert bag.completeness == "model" and bag.links == []
    assert _instance(config, "/two").completeness == "unknown"  # optparse refuses it
    topic = next(t for t in config.topics if t.name == "/robot/scan")
    assert sorted(s.node.name for s in topic.subscribers) == ["/bw", "/robot/echo", "/robot/hz"]
    # each subscriber takes the publisher's type: no type mismatch with a typeless side
    assert [f.rule for f in run_catalogue(model) if "type" in f.rule] == []


def test_ros2_topic_echo_hz_bw_and_delay_subscribe_to_what_they_name(write_tree):
    """``ExecuteProcess(cmd=['ros2', 'topic', 'echo', ...])`` in a ROS 2 launch file: a
    subscriber of the topic, of the type given (else its publishers'), with the QoS its
    options say (else unknown: echo adapts to the publishers); ``hz`` (several topics),
    ``bw`` and ``delay`` subscribe with ``qos_profile_sensor_data``."""
    root = write_tree({
        "src/p/package.xml": package_xml("p", "ament_cmake"),
        "src/p/CMakeLists.txt": "project(p)\n",
        "src/p/launch/p.launch.py": """
from launch import LaunchDescription
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=['ros2', 'topic', 'pub', '--node-name', 'scan_pub', '/scan',
                            'std_msgs/msg/String', '{}']),
        ExecuteProcess(cmd=['ros2', 'topic', 'echo', '--qos-reliability', 'best_effort',
                            '/scan', 'std_msgs/msg/String']),
        ExecuteProcess(cmd=['ros2', 'topic', 'hz', '-w', '10', '/scan', '/odom']),
        ExecuteProcess(cmd=['ros2', 'topic', 'bw', '/scan', '/odom']),
    ])
""",
        "project.yaml": "project: p\nconfigurations:\n  c: [p/launch/p.launch.py]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    echo, hz, bw = [n for n in config.nodes if n.name != "/scan_pub"]
    assert echo.completeness == hz.completeness == "model"
    assert [(link.kind, link.name, link.type, link.qos) for link in echo.links] == [
        ("subscribe", "/scan", "std_msgs/msg/String", {"reliability": "best_effort"})]
    sensor = {"depth": 5, "history": "keep_last", "reliability": "best_effort",
              "durability": "volatile"}
    assert [(link.kind, link.name, link.qos) for link in hz.links] == [
        ("subscribe", "/scan", sensor), ("subscribe", "/odom", sensor)]
    assert bw.completeness == "unknown"  # argparse refuses a second topic
    topic = next(t for t in config.topics if t.name == "/scan")
    assert len(topic.subscribers) == 2 and len(topic.publishers) == 1


def test_rostopic_watchers_subscribe_to_the_topic_a_field_name_is_in(write_tree):
    """``rostopic echo /robot/odom/pose/pose`` prints a field of ``/robot/odom``'s
    messages: rostopic subscribes to the longest published topic that begins the name
    (ros_comm's ``_get_topic_type``; hz, delay and bw too), not to a topic nobody
    publishes. A name that is a topic itself, or has no published topic before it,
    stays as written."""
    root = write_tree({
        "src/p/package.xml": package_xml("p"),
        "src/p/CMakeLists.txt": "project(p)\n",
        "src/p/launch/p.launch": """
            <launch>
              <node pkg="rostopic" type="rostopic" name="odom"
                    args="pub /robot/odom std_msgs/String -r 1 'x'"/>
              <node pkg="rostopic" type="rostopic" name="deep"
                    args="pub /robot/odom/pose std_msgs/String -r 1 'x'"/>
              <node pkg="rostopic" type="rostopic" name="field"
                    args="echo /robot/odom/twist/twist"/>
              <node pkg="rostopic" type="rostopic" name="deeper" args="hz /robot/odom/pose/x"/>
              <node pkg="rostopic" type="rostopic" name="whole" args="bw /robot/odom/pose"/>
              <node pkg="rostopic" type="rostopic" name="none" args="delay /other/field"/>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [p/launch/p.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations

    def subscribed(name: str) -> list[str]:
        return [link.name for link in _instance(config, name).links
                if link.kind == "subscribe"]

    assert subscribed("/field") == ["/robot/odom"]
    assert subscribed("/deeper") == ["/robot/odom/pose"]  # the longest
    assert subscribed("/whole") == ["/robot/odom/pose"]
    assert subscribed("/none") == ["/other/field"]
    names = sorted(t.name for t in config.topics)
    assert names == ["/other/field", "/robot/odom", "/robot/odom/pose"]
    odom = next(t for t in config.topics if t.name == "/robot/odom")
    assert [s.node.name for s in odom.subscribers] == ["/field"]
    rules = [f.rule for f in run_catalogue(model) if f.rule.startswith("subscriber-")]
    assert rules == ["subscriber-without-publisher"]  # /other/field alone
