"""The interfaces of installed packages that node code uses (sensor_msgs' Joy,
BatteryState and PointCloud2, control_msgs' FollowJointTrajectory action) come from the
shipped catalogue (``haros-arch models interfaces``), with the fields and constants of
the generation: their fields parse, and a constant in a call's arguments keeps the
call. sensor_msgs' point cloud iterators and the socket and ``nullptr`` comparisons of
the C and C++ libraries are stood in for. The sources are
fixtures/cpp/installed_interfaces."""

from __future__ import annotations

import json
import os

import yaml

from haros_arch.cli import main
from haros_arch.extract.cpp import CppResult, extract_cpp, interfaces
from haros_arch.models import definitions
from haros_arch.models.generate import folder_of
from haros_arch.workspace import scan
from tests.conftest import package_xml

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURES = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "installed_interfaces")


def _extract(write_tree, name: str, build_type: str, distro: str | None = None) -> CppResult:
    with open(os.path.join(FIXTURES, name), encoding="utf-8") as handle:
        source = handle.read()
    root = write_tree({"pkg/package.xml": package_xml("pkg", build_type),
                       "pkg/src/node.cpp": source})
    return extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                       cache_dir=None, distro=distro)


def _errors(result: CppResult) -> list[str]:
    return [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_MESSAGE_FIELD", "CPP_MESSAGE_UNKNOWN")]


def test_ros2_fields_and_constants_of_installed_messages(write_tree) -> None:
    result = _extract(write_tree, "ros2_joy_battery.cpp", "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("declare", "expected_health", "int"),
        ("publish", "cmd_vel", "geometry_msgs/msg/Twist"),
        ("subscribe", "joy", "sensor_msgs/msg/Joy"),
        ("subscribe", "battery_state", "sensor_msgs/msg/BatteryState")]
    # the constants were not declared permissively: the catalogue has them
    assert "CPP_NAMES_DECLARED" not in [d.code for d in result.diagnostics]


def test_ros1_point_cloud_iterators_and_an_installed_action(write_tree) -> None:
    result = _extract(write_tree, "ros1_cloud_action.cpp", "catkin")
    assert _errors(result) == []
    # the action client was lost before: its goal type was not known
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "cloud", "sensor_msgs/PointCloud2"),
        ("subscribe", "points", "sensor_msgs/PointCloud2"),
        ("action-client", "arm_controller/follow_joint_trajectory",
         "control_msgs/FollowJointTrajectory")]


def test_a_humble_parse_reads_humbles_definitions(write_tree) -> None:
    """humble's control_msgs JointTrajectoryControllerState has ``desired`` / ``actual``
    (jazzy's renamed them): a parse for humble reads humble's catalogue, so the fields
    parse and the publisher whose name reads one is resolved; the same source parsed
    for jazzy does not know them (franka_ros2's humble fork of the trajectory
    controller was partial by this)."""
    calls = [("publish", "controller_state", "control_msgs/msg/JointTrajectoryControllerState"),
             ("subscribe", "raw_state", "control_msgs/msg/JointTrajectoryControllerState"),
             # ``"first_error" + (State().desired.positions.empty() ? "" : "_set")``:
             # one call per side of the test
             ("publish", "first_error", "std_msgs/msg/Float64"),
             ("publish", "first_error_set", "std_msgs/msg/Float64")]
    humble = _extract(write_tree, "ros2_humble_controller_state.cpp", "ament_cmake", "humble")
    assert _errors(humble) == []
    assert "CPP_CALL_UNRESOLVED" not in [d.code for d in humble.diagnostics]
    assert [(c.kind, c.name, c.type) for c in humble.calls] == calls
    jazzy = _extract(write_tree, "ros2_humble_controller_state.cpp", "ament_cmake", "jazzy")
    assert any("no member named 'desired'" in m for m in _errors(jazzy))
    assert "CPP_CALL_UNRESOLVED" in [d.code for d in jazzy.diagnostics]


def test_each_distribution_reads_the_nearest_catalogue() -> None:
    """A shipped distribution's own; one in between, the newest shipped before it; one
    older than all, the oldest; none, another ROS's or an unknown one, the default."""
    assert interfaces.catalogue_distro(True, "humble") == "humble"
    assert interfaces.catalogue_distro(True, " Jazzy") == "jazzy"
    assert interfaces.catalogue_distro(True, "iron") == "humble"
    assert interfaces.catalogue_distro(True, "foxy") == "humble"
    assert interfaces.catalogue_distro(True, "rolling") == "jazzy"
    for other in (None, "noetic", "no_such_distro"):
        assert interfaces.catalogue_distro(True, other) == "jazzy"
    assert interfaces.catalogue_distro(False, "humble") == "noetic"
    assert interfaces.catalogue_distro(False, "melodic") == "noetic"
    humble = interfaces.known("control_msgs", "JointTrajectoryControllerState", True,
                              distro="humble")
    jazzy = interfaces.known("control_msgs", "JointTrajectoryControllerState", True)
    assert humble is not None and "trajectory_msgs/JointTrajectoryPoint desired" in humble
    assert jazzy is not None and " desired" not in jazzy


def test_sockets_and_nullptr_comparisons(write_tree) -> None:
    result = _extract(write_tree, "ros2_sockets.cpp", "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "ip")]
    assert "CPP_NAMES_DECLARED" not in [d.code for d in result.diagnostics]


def test_each_generation_has_its_own_definitions() -> None:
    """ROS 1's CameraInfo has ``D``/``K``, ROS 2's ``d``/``k``; ROS 2's Header has no
    ``seq``; a workspace-less name falls back to the hand-written table."""
    ros1 = interfaces.known("sensor_msgs", "CameraInfo")
    ros2 = interfaces.known("sensor_msgs", "CameraInfo", ros2=True)
    assert ros1 is not None and "float64[9] K" in ros1.splitlines()
    assert ros2 is not None and "float64[9] k" in ros2.splitlines()
    assert "uint32 seq" not in (interfaces.known("std_msgs", "Header", ros2=True) or "")
    assert interfaces.known("bond", "Constants") == interfaces.WELL_KNOWN["bond/Constants"]
    assert interfaces.known("no_such_msgs", "Thing") is None


def test_bounded_fields_are_read() -> None:
    parsed = interfaces.parse_definition(
        "p", "M", "string<=10 name\nint32[<=5] values\nfloat64[3] fixed\nuint8 A=1")
    assert [(f.type, f.name, f.array, f.constant) for f in parsed.sections[0]] == [
        ("string<=10", "name", None, None), ("int32", "values", "", None),
        ("float64", "fixed", "3", None), ("uint8", "A", None, "1")]


def test_the_shipped_catalogue_matches_its_list() -> None:
    """Every pinned entry of interfaces.yaml is in its distribution's document with the
    same commit and packages, and each package gave definitions: a list edited without
    running ``haros-arch models interfaces`` fails here."""
    with open(definitions.LIST, encoding="utf-8") as handle:
        entries = yaml.safe_load(handle)
    documents = {}
    for distro in {entry["distro"] for entry in entries}:
        with open(os.path.join(definitions.FOLDER, f"{distro}.json"), encoding="utf-8") as h:
            documents[distro] = json.load(h)
    for entry in entries:
        document = documents[entry["distro"]]
        assert {"repository": entry["repository"], "commit": entry["commit"],
                "packages": entry["packages"]} in document["sources"]
        for package in entry["packages"]:
            assert any(key.startswith(package + "/") for key in document["definitions"])


def test_models_interfaces_reads_a_pinned_tree(tmp_path, capsys) -> None:
    commit = "a" * 40
    tree = tmp_path / "sources" / folder_of("github:someone/some_msgs", commit)
    (tree / "some_msgs" / "msg").mkdir(parents=True)
    (tree / "some_msgs" / "srv").mkdir()
    (tree / "some_msgs" / "package.xml").write_text(
        "<package format='3'><name>some_msgs</name></package>")
    (tree / "some_msgs" / "msg" / "Thing.msg").write_text(
        "# a comment\nstd_msgs/Header header  # trailing\nfloat64[] values\n"
        "uint8 MODE_A=1\nstring NOTE=a # kept\n")
    (tree / "some_msgs" / "srv" / "Ask.srv").write_text("string q\n---\nbool ok\n")
    listing = tmp_path / "list.yaml"
    listing.write_text(yaml.safe_dump([{
        "repository": "github:someone/some_msgs", "commit": commit, "distro": "jazzy",
        "packages": ["some_msgs"]}]))
    out = tmp_path / "out"
    assert main(["models", "interfaces", str(listing), "--sources",
                 str(tmp_path / "sources"), "-o", str(out)]) == 0
    document = json.loads((out / "jazzy.json").read_text())
    assert document["sources"] == [{"repository": "github:someone/some_msgs",
                                    "commit": commit, "packages": ["some_msgs"]}]
    assert document["definitions"] == {
        "some_msgs/msg/Thing": "std_msgs/Header header\nfloat64[] values\nuint8 MODE_A=1\n"
                               "string NOTE=a # kept",
        "some_msgs/srv/Ask": "string q\n---\nbool ok"}
    assert "2 definitions" in capsys.readouterr().out
    # a tree that is not there is said, not a traceback
    assert main(["models", "interfaces", str(listing), "--sources",
                 str(tmp_path / "nowhere"), "-o", str(out)]) == 2


def test_models_interfaces_reads_definitions_one_folder_down(tmp_path) -> None:
    """rosidl takes the files a CMakeLists lists, wherever they are; the header is
    ``pkg/msg/name.hpp`` all the same: tier4_perception_msgs keeps its traffic light
    messages in ``msg/traffic_light/``, autoware_adapi_v1_msgs its in ``planning/msg/``.
    A test folder's are no package's."""
    commit = "b" * 40
    tree = tmp_path / "sources" / folder_of("github:someone/deep_msgs", commit)
    package = tree / "deep_msgs"
    for folder in ("msg", "msg/traffic_light", "planning/msg", "test/msg", "srv"):
        (package / folder).mkdir(parents=True)
    (package / "package.xml").write_text("<package format='3'><name>deep_msgs</name></package>")
    (package / "msg" / "Top.msg").write_text("int32 a\n")
    (package / "msg" / "traffic_light" / "Light.msg").write_text("uint8 color\n")
    (package / "planning" / "msg" / "Decision.msg").write_text("string reason\n")
    (package / "test" / "msg" / "Fake.msg").write_text("int8 x\n")
    (package / "planning" / "msg" / "Top.msg").write_text("int64 shadowed\n")
    listing = tmp_path / "list.yaml"
    listing.write_text(yaml.safe_dump([{
        "repository": "github:someone/deep_msgs", "commit": commit, "distro": "humble",
        "packages": ["deep_msgs"]}]))
    out = tmp_path / "out"
    assert main(["models", "interfaces", str(listing), "--sources",
                 str(tmp_path / "sources"), "-o", str(out)]) == 0
    document = json.loads((out / "humble.json").read_text())
    assert document["definitions"] == {"deep_msgs/msg/Decision": "string reason",
                                       "deep_msgs/msg/Light": "uint8 color",
                                       "deep_msgs/msg/Top": "int32 a"}


def test_ros2_interface_named_with_capitals_together(write_tree) -> None:
    # franka's JointImpedanceWithIKExampleController: moveit_msgs (not in the workspace,
    # not in the catalogue) has get_position_ik.hpp for GetPositionIK, which capitalising
    # each word made GetPositionIk: the node's header named a type not declared, its class
    # was invalid and every get_node() call an error (13 places; survey Z23). The type's
    # name is the one the including files write
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "pkg/include/pkg/ik_node.hpp": """
#include <rclcpp/rclcpp.hpp>
#include <moveit_msgs/srv/get_position_ik.hpp>
#include <std_msgs/msg/float64.hpp>
class IkNode : public rclcpp::Node {
public:
  IkNode();
private:
  rclcpp::Client<moveit_msgs::srv::GetPositionIK>::SharedPtr ik_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr out_;
};
""",
        "pkg/src/node.cpp": """
#include "pkg/ik_node.hpp"
IkNode::IkNode() : rclcpp::Node("ik") {
  ik_ = create_client<moveit_msgs::srv::GetPositionIK>("compute_ik");
  auto request = std::make_shared<moveit_msgs::srv::GetPositionIK::Request>();
  out_ = create_publisher<std_msgs::msg::Float64>("out", 1);
}
"""})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("client", "compute_ik", "moveit_msgs/srv/GetPositionIK"),
        ("publish", "out", "std_msgs/msg/Float64")]


def test_pcl_and_geographic_messages_come_from_the_catalogue(write_tree) -> None:
    """pcl_msgs and geographic_msgs, installed with pcl_ros and geographic_info, are in the
    catalogue (ROS 1 and ROS 2): their fields parse. Without them a node reading
    ``indices.indices`` was partial (Autoware's pointcloud preprocessor filters), and an
    error in a call's arguments cost the call."""
    ros2 = _extract(write_tree, "ros2_pcl_geographic.cpp", "ament_cmake", "humble")
    assert _errors(ros2) == []
    assert sorted((c.kind, c.name, c.type) for c in ros2.calls) == [
        ("publish", "altitude", "std_msgs/msg/Float64"),
        ("publish", "altitude_in_frame", "std_msgs/msg/Float64"),
        ("publish", "inliers", "pcl_msgs/msg/PointIndices"),
        ("subscribe", "fix", "geographic_msgs/msg/GeoPointStamped")]
    jazzy = _extract(write_tree, "ros2_pcl_geographic.cpp", "ament_cmake", "jazzy")
    assert _errors(jazzy) == []
    ros1 = _extract(write_tree, "ros1_pcl_geographic.cpp", "catkin", "noetic")
    assert _errors(ros1) == []
    assert sorted((c.kind, c.name, c.type) for c in ros1.calls) == [
        ("publish", "plane", "pcl_msgs/ModelCoefficients"),
        ("subscribe", "fix", "geographic_msgs/GeoPointStamped")]


def test_interfaces_of_widely_used_stacks_come_from_the_catalogue(write_tree) -> None:
    """MoveIt's, Navigation2's, ros_control's / ros2_control's controller manager's,
    Gazebo's, MAVROS's, vision_msgs', ackermann_msgs', turtlesim's and Autoware's
    interfaces, which a workspace
    usually has installed, are in the catalogue: a field read in a call's arguments keeps
    the call. Without them MoveIt's ``get_parameter(param + ".name", constraints.name)``
    (kinematic_constraints' utils.cpp) was lost and 8 of MoveIt's nodes were partial."""
    for distro in ("jazzy", "humble"):
        ros2 = _extract(write_tree, "ros2_stacks.cpp", "ament_cmake", distro)
        assert _errors(ros2) == [], distro
        assert sorted((c.kind, c.name, c.type) for c in ros2.calls) == [
            ("client", "controller_manager/list_controllers",
             "controller_manager_msgs/srv/ListControllers"),
            ("declare", "controllers", "int"), ("declare", "default_tree", "str"),
            ("declare", "frame", "str"), ("declare", "max_speed", "double"),
            ("declare", "mode", "str"), ("declare", "start_x", "double"),
            ("declare", "trajectory_frame", "str"),
            ("read", "path_constraints.name", "str")], distro
    ros1 = _extract(write_tree, "ros1_stacks.cpp", "catkin", "noetic")
    assert _errors(ros1) == []
    assert sorted((c.kind, c.name, c.type) for c in ros1.calls) == [
        ("client", "controller_manager/switch_controller",
         "controller_manager_msgs/SwitchController"),
        ("read", "constraints/name", "str"), ("read", "max_speed", "double"),
        ("read", "mode", "str"), ("read", "models", "str[]"), ("read", "start", "str[]"),
        ("read", "start_x", "double")]


MODEL_STATES = """
#include <rclcpp/rclcpp.hpp>
#include <gazebo_msgs/msg/model_states.hpp>
#include <std_msgs/msg/float64.hpp>

class Follower : public rclcpp::Node {
public:
  Follower() : Node("follower") {
    sub_ = create_subscription<gazebo_msgs::msg::ModelStates>(
        "/gazebo/model_states", 1,
        [this](const gazebo_msgs::msg::ModelStates::SharedPtr msg) {
          std_msgs::msg::Float64 z;
          z.data = msg->pose[0].position.z;
          if (msg->name.size() > 1) { height_->publish(z); }
        });
    height_ = create_publisher<std_msgs::msg::Float64>("height", 10);
  }
private:
  rclcpp::Subscription<gazebo_msgs::msg::ModelStates>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr height_;
};
"""


def test_a_package_the_release_does_not_ship_is_read_from_another_release(write_tree):
    """gazebo_msgs is in Humble's catalogue, not in Jazzy's (Jazzy dropped Gazebo
    classic): control_quadrupeds_soft_contacts' teleop node, read for Jazzy (its files
    name Iron and Humble), had a field-less ModelStates, each ``msg->pose`` and
    ``msg->name`` a parse error. A package the release's catalogue has none of is read
    from the nearest release whose catalogue has it; one the release has keeps its own
    (Jazzy's control_msgs, above, still has no ``desired``)."""
    assert interfaces.known("gazebo_msgs", "ModelStates", True, distro="jazzy") == \
        interfaces.known("gazebo_msgs", "ModelStates", True, distro="humble")
    assert "gazebo_msgs" in interfaces.catalogue_names(True, "jazzy")
    assert interfaces.known("sensor_msgs", "CameraInfo", True, distro="jazzy") == \
        interfaces._catalogue_file("jazzy")["sensor_msgs/msg/CameraInfo"]
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/src/node.cpp": MODEL_STATES})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    assert _errors(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("subscribe", "/gazebo/model_states", "gazebo_msgs/msg/ModelStates"),
        ("publish", "height", "std_msgs/msg/Float64")]
