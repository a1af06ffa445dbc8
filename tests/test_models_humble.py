"""humble's interface models: its own where its packages differ from jazzy's, else jazzy's."""

from __future__ import annotations

import json

import pytest
from conftest import package_xml

from haros_arch.models import library
from haros_arch.models.library import Library
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load


def _model(package: str, distro: str, msg_type: str) -> str:
    return json.dumps({
        "schema": "haros-arch-model/2", "package": package, "distro": distro,
        "version": "1.0.0",
        "source": {"repository": "github:example/" + package, "commit": "0" * 40},
        "nodes": [{
            "name": f"{package}/server", "package": package, "executable": "server",
            "kind": "executable", "language": "cpp", "calls": [{
                "kind": "publish", "name": "cmd_vel", "type": msg_type,
                "location": {"package": package, "file": "src/server.cpp", "line": 3}}]}]})


@pytest.fixture
def shipped(tmp_path, monkeypatch):
    """A small shipped library: humble and jazzy models of ``moving``, a jazzy one only
    of ``steady``."""
    for distro, package, msg_type in (("humble", "moving", "geometry_msgs/msg/Twist"),
                                      ("jazzy", "moving", "geometry_msgs/msg/TwistStamped"),
                                      ("jazzy", "steady", "std_msgs/msg/String")):
        folder = tmp_path / "data" / distro
        folder.mkdir(parents=True, exist_ok=True)
        (folder / f"{package}.json").write_text(_model(package, distro, msg_type))
    monkeypatch.setattr(library, "DATA", str(tmp_path / "data"))
    return tmp_path / "data"


@pytest.mark.parametrize("distro, moving", [("humble", "humble"), ("jazzy", "jazzy"),
                                            ("iron", "jazzy")])
def test_each_package_takes_its_distributions_model_else_jazzys(write_tree, shipped,
                                                                  distro, moving):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot", build_type="ament_cmake"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/base.launch.xml": """
            <launch>
              <node pkg="moving" exec="server" name="moving"/>
              <node pkg="steady" exec="server" name="steady"/>
            </launch>
            """,
        "project.yaml": f"project: p\ndistro: {distro}\n"
                        "configurations:\n  c: [robot/launch/base.launch.xml]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    nodes = {n.name: n for n in config.nodes}
    assert nodes["/moving"].node.model.startswith(f"{moving}/moving ")
    assert nodes["/steady"].node.model.startswith("jazzy/steady ")
    expected = "geometry_msgs/msg/Twist" if moving == "humble" else \
        "geometry_msgs/msg/TwistStamped"
    assert [link.type for link in nodes["/moving"].publishers] == [expected]
    used = {d.message for d in config.diagnostics if d.code == "MODEL_USED"}
    assert any("moving/server" in m and f"{moving}/moving " in m for m in used)
    assert any("steady/server" in m and "jazzy/steady " in m for m in used)


def test_the_library_reads_a_distribution_folder_it_is_given(shipped):
    assert Library(shipped=str(shipped)).find("moving", "humble").distro == "humble"
    assert Library(shipped=str(shipped)).find("steady", "humble") is None


def test_the_shipped_humble_nav2_controller_publishes_an_unstamped_cmd_vel():
    """humble's controller_server publishes geometry_msgs/msg/Twist on cmd_vel, always
    (navigation2 humble 3c3db59d nav2_controller/src/controller_server.cpp:198); jazzy's
    publishes Twist or TwistStamped as enable_stamped_cmd_vel says."""
    model = Library().find("nav2_controller", "humble")
    assert model is not None and model.distro == "humble"
    node = model.node("controller_server")
    assert node is not None and node.rosname == "controller_server"
    cmd_vel = [(c.type, c.conditions) for c in node.calls
               if c.kind == "publish" and c.name == "cmd_vel"]
    assert cmd_vel == [("geometry_msgs/msg/Twist", ())]
    assert not any(c.name == "enable_stamped_cmd_vel" for c in node.calls)


def test_the_shipped_humble_diff_drive_controller_takes_an_unstamped_command_too():
    """humble's DiffDriveController subscribes ~/cmd_vel_unstamped (Twist) when
    use_stamped_vel is false (ros2_controllers humble ad559d9c
    diff_drive_controller/src/diff_drive_controller.cpp:34); jazzy's has no such topic."""
    humble = Library().find("diff_drive_controller", "humble")
    jazzy = Library().find("diff_drive_controller", "jazzy")
    assert humble is not None and jazzy is not None

    def subscribed(model):
        return {(c.name, c.type) for n in model.nodes for c in n.calls
                if c.kind == "subscribe"}
    assert ("~cmd_vel_unstamped", "geometry_msgs/msg/Twist") in subscribed(humble)
    assert not any(name == "~cmd_vel_unstamped" for name, _ in subscribed(jazzy))


@pytest.mark.parametrize("distro", ["humble", "jazzy"])
def test_the_shipped_costmap_node_has_the_calls_of_costmap2dros(distro):
    """nav2_costmap_2d's node links its core library by the ALIAS
    ``${PROJECT_NAME}::nav2_costmap_2d_core`` (CMakeLists.txt:48, 150-154), whose
    Costmap2DROS its main makes; the models were built without that library, so every
    costmap a nav2 server makes had no parameter of its own (humble's then said
    global_frame, resolution, ... were set but never read)."""
    model = Library().find("nav2_costmap_2d", distro)
    assert model is not None and model.distro == distro
    node = model.node("nav2_costmap_2d")
    assert node is not None
    reads = {c.name for c in node.calls if c.kind == "read"}
    assert {"global_frame", "robot_base_frame", "resolution", "plugins"} <= reads
    assert "costmap" in {c.name for c in node.calls if c.kind == "publish"}


def test_the_shipped_humble_mux_subscribes_each_of_its_input_topics():
    """humble's topic_tools mux subscribes its selected element of input_topics
    (topic_tools humble 5cdfce6c mux_node.cpp:35-38, tool_base_node.cpp:56); the humble
    override names that subscription by each element, as jazzy's does, and humble has no
    demux node."""
    model = Library().find("topic_tools", "humble")
    assert model is not None and model.distro == "humble"
    mux = model.node("mux")
    assert mux is not None and model.node("demux") is None
    (sub,) = [c for c in mux.calls if c.kind == "subscribe"]
    assert (sub.name_param, sub.name_each) == ("input_topics", ".")


def test_the_shipped_humble_ackermann_controller_takes_an_unstamped_reference_too():
    """humble's steering controllers subscribe ~/reference_unstamped (Twist) when
    use_stamped_vel is false (ros2_controllers humble ad559d9c,
    steering_controllers_library.cpp:127); jazzy's only ~/reference."""
    model = Library().find("ackermann_steering_controller", "humble")
    assert model is not None and model.distro == "humble"
    subscribed = {(c.name, c.type) for n in model.nodes for c in n.calls
                  if c.kind == "subscribe"}
    assert ("~reference_unstamped", "geometry_msgs/msg/Twist") in subscribed


def test_the_shipped_humble_controller_manager_subscribes_its_description_only_without_one(
        write_tree):
    """humble's ros2_control_node subscribes ~/robot_description only when no
    robot_description parameter is given (ros2_control humble 0941f73c
    controller_manager/src/controller_manager.cpp:289-291; the other constructor, which
    the node never builds, subscribes under another condition). The model carried no
    condition: franka_ros2, which gives the manager its description, had a false
    subscriber-without-publisher in 11 configurations (survey Z23)."""
    model = Library().find("controller_manager", "humble")
    assert model is not None and model.distro == "humble"
    node = model.node("ros2_control_node")
    assert node is not None
    (sub,) = [c for c in node.calls if c.kind == "subscribe"
              and c.name == "~robot_description"]
    assert [(c.statement, c.text) for c in sub.conditions] == [
        ("if", "robot_description.empty()")]
    root = write_tree({
        "src/robot/package.xml": package_xml("robot", build_type="ament_cmake"),
        "src/robot/CMakeLists.txt": "project(robot)\n",
        "src/robot/launch/control.launch.xml": """
            <launch>
              <node pkg="controller_manager" exec="ros2_control_node">
                <param name="robot_description" value="&lt;robot name='r'/&gt;"/>
              </node>
            </launch>
            """,
        "project.yaml": "project: p\ndistro: humble\n"
                        "configurations:\n  c: [robot/launch/control.launch.xml]\n",
    })
    model_ = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model_.configurations
    assert not [link for link in config.links if link.kind == "subscribe"
                and link.rosname.full.endswith("/robot_description")]
