"""Gaps of our stand-in headers that made shipped interface models partial: each
source uses what one modelled package does (robot_state_publisher's URDF read and
system_error, tf_echo's floatfield, ublox's time and stat calls, joy_linux's fd_set,
nav2's action server timeout, rcutils' logging macros, the graph API of image_view and
pointcloud_to_laserscan, robot_localization's add_timer, image_view's descriptor
setters, topic_tools' QoS !=; ROS 1: tf's LinearMath and listener methods, gmapping's
is_zero, mavros' maxDatagramSize, polled_camera's getTopic, OpenCV's version macros,
urg_node's ROS 1 bond::Bond; tf2_ros' lookupTransform result as a message, ROS 1 and 2;
humble image_view's HighGUI windows and message_filters subscription, turtlebot3_node's
parameter events, ros2_controllers' Duration == and std::optional{value}; wiimote's
ROS 1 publisher compared with nullptr, ros::master's topic list; MoveIt 1's
kinematics plugin loader's std::stringstream state and std::ws; mqtt_client's
std::optional compared with std::nullopt; book_ros2's lifecycle trigger_transition and a
constant divided into a permissive value; ros_whill's long double math).
Each parses with no error and keeps its calls. The sources are
fixtures/cpp/standin_gaps (the short ones here)."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURES = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "standin_gaps")


def _source(name: str) -> str:
    with open(os.path.join(FIXTURES, name), encoding="utf-8") as handle:
        return handle.read()


def _extract(write_tree, source: str, build_type: str) -> CppResult:
    root = write_tree({"pkg/package.xml": package_xml("pkg", build_type),
                       "pkg/src/node.cpp": source})
    return extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                       cache_dir=None)


def _errors(result: CppResult) -> list[str]:
    return [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]


def test_ros2_std_libc_rcl_and_graph_api(write_tree) -> None:
    result = _extract(write_tree, _source("ros2_std.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "colormap"), ("publish", "robot_description")]


def test_ros1_tf_time_and_transport_hints(write_tree) -> None:
    result = _extract(write_tree, _source("ros1_tf.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "chatter"), ("publish", "out"),
        # the bond's heartbeat, both ways (bondcpp's Bond)
        ("publish", "/diagnostics_agg/bond"), ("subscribe", "/diagnostics_agg/bond"),
        ("publish", "opencv3"),
        ("subscribe", "/tf"),
        ("subscribe", "/tf_static")]


def test_ros1_tf_quaternion_message_from_yaw(write_tree) -> None:
    """tf::createQuaternionMsgFromYaw (and ..FromRollPitchYaw) returns a
    geometry_msgs::Quaternion: declared as a template of its return type, it matched no
    call, an error in the function that publishes, so the ROS wiki's odometry publisher
    (turtlebot3_fake's, kobuki's) was partial."""
    result = _extract(write_tree, _source("ros1_tf_quaternion_msg.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "odom"),
                                                        ("publish", "/tf")]


def test_members_of_declared_names_in_code_without_ros_calls(write_tree) -> None:
    """The first parse with the unknown names declared has more errors than the parse
    without (members a macro forwards to, in a helper class with no ROS call): those
    members are learnt and the unit parsed once more, so the nodelet's class is valid
    and its node handles known (stereo_image_proc's disparity nodelet had '?' names)."""
    result = _extract(write_tree, _source("macro_members.cpp"), "catkin")
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~queue_size"), ("publish", "disparity")]
    assert "CPP_NAMES_DECLARED" in [d.code for d in result.diagnostics]


def test_a_listener_on_a_buffer_core(write_tree) -> None:
    """tf2_ros::TransformListener built on a tf2::BufferCore (nav2_util's
    BaseFootprintPublisherListener derives from it): /tf and /tf_static."""
    result = _extract(write_tree, _source("tf2_listener.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "/tf"), ("subscribe", "/tf_static"), ("declare", "base_link_frame"),
        ("publish", "/tf")]


def test_a_looked_up_transform_as_a_message(write_tree) -> None:
    """lookupTransform's and eigenToTransform's result initialises, is assigned to and is
    passed as a geometry_msgs TransformStamped with no ambiguous conversion (two
    conversion templates, to M and to M&, made both copy and operator= ambiguous), and
    ``auto`` keeps its fields: no error beside the publisher's call."""
    result = _extract(write_tree, _source("tf2_lookup_result.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "lookup_done")]


def test_a_looked_up_transform_as_a_message_in_ros1(write_tree) -> None:
    result = _extract(write_tree, _source("ros1_tf2_lookup_result.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "lookup_done")]


def test_a_time_point_cast(write_tree) -> None:
    """px4_ros_com's debug_vect_advertiser stamps its message with
    ``std::chrono::time_point_cast<std::chrono::microseconds>(steady_clock::now())
    .time_since_epoch().count()`` inside the timer lambda of the function that makes
    its publisher: the stand-in <chrono> lacked time_point_cast, an error near the call
    made the node partial."""
    result = _extract(write_tree, """
#include <chrono>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/int64.hpp>

class Stamper : public rclcpp::Node {
public:
  Stamper() : Node("stamper") {
    publisher_ = this->create_publisher<std_msgs::msg::Int64>("stamp", 10);
    auto tick = [this]() -> void {
      std_msgs::msg::Int64 msg;
      msg.data = std::chrono::time_point_cast<std::chrono::microseconds>(
          std::chrono::steady_clock::now()).time_since_epoch().count();
      auto ms = std::chrono::time_point_cast<std::chrono::milliseconds>(
          std::chrono::system_clock::now());
      msg.data += ms.time_since_epoch().count();
      publisher_->publish(msg);
    };
    timer_ = this->create_wall_timer(std::chrono::milliseconds(500), tick);
  }
private:
  rclcpp::Publisher<std_msgs::msg::Int64>::SharedPtr publisher_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Stamper>());
  return 0;
}
""", "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls if c.kind == "publish"] == [
        ("publish", "stamp", "std_msgs/msg/Int64")]


def test_ros2_parameter_callbacks_chrono_and_spin(write_tree) -> None:
    """teleop_twist_joy's parameter callback (get_value<rclcpp::PARAMETER_INTEGER>()) and
    main (rclcpp::spin of a unique_ptr), create3_sim's constexpr control period, its
    callback registered on the parameters interface and Duration::max(), ros2/demos'
    ``time_left < wait_period ? time_left : wait_period``: each was a clang error in a
    function that calls the ROS API, and the node partial."""
    result = _extract(write_tree, _source("ros2_params_chrono.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "cmd")]


def test_get_parameter_or_that_returns_the_value(write_tree) -> None:
    """rclcpp's ``T get_parameter_or(name, alternative)``: controller_manager's
    ros2_control_node (jazzy) calls it five times in main, and waits for its clock
    (``Clock::wait_until_started``); each was a clang error in main, which makes the
    node partial."""
    result = _extract(write_tree, """
#include <rclcpp/rclcpp.hpp>
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto cm = std::make_shared<rclcpp::Node>("controller_manager");
  const bool use_sim_time = cm->get_parameter_or("use_sim_time", false);
  const bool lock_memory = cm->get_parameter_or<bool>("lock_memory", true);
  cm->get_clock()->wait_until_started();
  return use_sim_time && lock_memory;
}
""", "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name, c.has_default, c.default) for c in result.calls] == [
        ("read", "use_sim_time", True, False), ("read", "lock_memory", True, True)]


def test_ros2_highgui_filter_subscription_and_parameter_events(write_tree) -> None:
    """image_view's window set-up (humble: ``cv::WINDOW_KEEPRATIO`` flags, the node given
    to ``cv::setMouseCallback``), stereo_view's ``sub.getSubscriber()->get_topic_name()``
    and turtlebot3_node's parameter event callback (``event->changed_parameters``,
    ``rclcpp::Parameter::from_parameter_msg``), rtabmap CoreWrapper's
    ``on_parameter_event(callback, qos, options)``: clang errors in the constructor, or
    the node handed to a function the parse does not know, each made the node partial."""
    result = _extract(write_tree, _source("ros2_gui_param_events.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_NODE")] == []
    assert [(c.kind, c.name) for c in result.calls
            if c.kind in ("declare", "subscribe")] == [
        ("declare", "autosize"), ("subscribe", "left/image"),
        ("subscribe", "/parameter_events")]


def test_ros2_duration_equality_and_deduced_optional(write_tree) -> None:
    """ros2_controllers (jazzy): diff_drive_controller.cpp:481 and
    omni_wheel_drive_controller.cpp:113 compare ``rclcpp::Duration``s with ``==``,
    pose_broadcaster.cpp:90 builds ``std::optional{rclcpp::Duration::from_seconds(..)}``:
    clang errors in ``on_configure``, which calls the ROS API, made each partial."""
    result = _extract(write_tree, _source("ros2_duration_optional.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "cmd_vel"), ("publish", "out")]


def test_ros1_handles_compare_with_null(write_tree) -> None:
    """roscpp's Publisher, Subscriber, ServiceServer, ServiceClient and Timer have
    ``operator void*()`` (and ==, !=, <), not an explicit ``operator bool``: comparing
    one with nullptr or NULL (wiimote_controller.cpp:591, advertised while the nunchuk is
    attached) was an error in the function that publishes, so wiimote_node was
    partial."""
    result = _extract(write_tree, _source("ros1_handle_void_ptr.cpp"), "catkin")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("client", "reset"), ("publish", "extra"), ("publish", "main"),
        ("subscribe", "extra_in")]


def test_ros1_master_queries(write_tree) -> None:
    """roscpp's ros::master (getTopics, TopicInfo, getNodes, check, getURI) had no
    stand-in: ``ros::master::getTopics (t_list);`` parsed as a declaration of a second
    ``t_list`` (sac_inc_ground_removal_standalone.cpp:107), an error in the constructor
    that subscribes, so the node was partial."""
    result = _extract(write_tree, _source("ros1_master_topics.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "cloud_in"), ("publish", "cloud_out")]


def test_ros2_wait_sets_client_pruning_and_timer_calls(write_tree) -> None:
    """ros2/examples (jazzy): rclcpp's WaitSet was an empty class (wait_set.cpp:38 "no
    matching constructor", listener.cpp:48 no add_subscription, static_wait_set.cpp:34
    StaticWaitSet unknown), Subscription::take, TimerBase::call, Client's
    prune_requests_older_than / remove_pending_request (async_client main.cpp:46,
    minimal_client main.cpp:44), get_network_flow_endpoints, wait_for_all_acked, the
    random engine's result_type and std::shuffle (random_talker.hpp:33), a duration
    over a duration (cbg_executor ping_node.cpp:82): each a clang error in a function
    that calls the ROS API, 22 nodes partial."""
    result = _extract(write_tree, _source("ros2_wait_set_client_timer.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert "CPP_NODE_PARTIAL" not in [d.code for d in result.diagnostics]
    assert [(c.kind, c.name) for c in result.calls
            if c.kind in ("subscribe", "publish", "client")] == [
        ("subscribe", "fixed_in"), ("subscribe", "in"), ("publish", "out"),
        ("client", "add"), ("publish", "ready"), ("publish", "idle")]
    # ``ready ? "ready" : "idle"`` over a count known at run time: a call per side
    status = [[(k.statement, k.text) for k in c.conditions] for c in result.calls
              if c.name in ("ready", "idle")]
    assert status == [[("if", "ready")], [("else", "ready")]]


def test_ros1_action_goal_handles_and_boost_time(write_tree) -> None:
    """actionlib's ActionServer had no GoalHandle, ACTION_DEFINITION types nor callback
    registration, ActionClient no sendGoal / ClientGoalHandle, boost's thread_group no
    remove_thread, and ros::Time no toBoost: move_base_flex's AbstractActionBase
    (abstract_action_base.hpp:77 ``typename actionlib::ActionServer<Action>::GoalHandle``)
    was an invalid class, so the constructors that build on it (controller_action.cpp:49,
    which advertises ``~controller_goal``) were errors and mbf_costmap_nav partial;
    bebop_driver's onInit (``ros::Time::now().toBoost()``, bebop_driver_nodelet.cpp:117)
    likewise."""
    result = _extract(write_tree, _source("ros1_action_goal_handle.cpp"), "catkin")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("action-client", "follow_joint_trajectory"),
        ("action-server", "joint_trajectory_action"),
        ("publish", "~controller_goal")]


def test_ros1_boost_foreach(write_tree) -> None:
    """boost/foreach.hpp had no stand-in: ``BOOST_FOREACH(VAR, COL) { ... }`` (naoqi_driver
    writes it ``for_each``, naoqi_driver.cpp:111) left the rest of the file unparsed
    ("expected '}'" at its last line), so none of its functions was read; amcl_node.cpp
    and slam_gmapping.cpp use it too."""
    result = _extract(write_tree, _source("ros1_boost_foreach.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "names"), ("publish", "relayed")]


def test_ros1_declaration_macro_scoped_ptr_and_shared_from_this(write_tree) -> None:
    """naoqi_driver: ``QI_REGISTER_OBJECT(Driver, ...)`` with no ``;`` at the end of its
    namespace (libqi missing) took the namespace's ``}`` for a function body and lost the
    unit's functions; ``boost::scoped_ptr<ros::NodeHandle> nhPtr_`` had no stand-in, so
    ``nhPtr_.reset(new ros::NodeHandle("~"))`` gave the node to an unknown function
    (naoqi_driver.cpp:997), and ``boost::enable_shared_from_this`` none either."""
    result = _extract(write_tree, _source("ros1_declaration_macro.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~info")]
    assert not [d for d in result.diagnostics if d.code == "CPP_NODE_TO_UNKNOWN"]


def test_ros2_stream_iterators(write_tree) -> None:
    """plansys2 (jazzy-devel) reads its PDDL files whole with
    ``std::string s((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>())``
    in on_configure (DomainExpertNode.cpp:143, ProblemExpertNode.cpp:230) and in the
    terminal (Terminal.cpp:246), and the executor assigns one so (``s.assign(first,
    last)``, ExecutorNode.cpp:130) and names a file by ``path.stem().u8string()``
    (ComputeBT.cpp:328): a clang error in a function that calls the ROS API made
    domain_expert_node, problem_expert_node and plansys2_terminal partial."""
    result = _extract(write_tree, _source("ros2_stream_iterators.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "model_file"), ("publish", "domain")]


def test_ros2_a_container_derived_from_the_component_manager(write_tree) -> None:
    """ros2_canopen's DeviceContainer (device_container.hpp:54-76) derives from
    rclcpp_components' ComponentManager: ``weak_ptr<MultiThreadedExecutor>`` converted to
    ``weak_ptr<rclcpp::Executor>`` and its ``loadNode_srv_`` / ``unloadNode_srv_`` members
    were errors in the constructor that declares its parameters (6 nodes partial); and
    the container's own services, which the manager's constructor serves, were missing."""
    result = _extract(write_tree, _source("ros2_component_manager.cpp"), "ament_cmake")
    assert _errors(result) == []
    # private names, as written or as the extractor keeps them (``~x`` is ``~/x``)
    assert sorted((c.kind, c.name.replace("~/", "~"), c.type) for c in result.calls) == [
        ("declare", "bus_config", "str"),
        ("server", "~_container/list_nodes", "composition_interfaces/srv/ListNodes"),
        ("server", "~_container/load_node", "composition_interfaces/srv/LoadNode"),
        ("server", "~_container/unload_node", "composition_interfaces/srv/UnloadNode"),
        ("server", "~init_driver", "std_srvs/srv/Trigger")]


def test_ros2_gflags_flags_name_calls_not_known_statically(write_tree) -> None:
    """ros_gz_sim's create.cpp defines its options with gflags (``DEFINE_string(param,
    "", ...)``, create.cpp:41-53) and reads ``FLAGS_param`` / ``FLAGS_topic`` for a
    parameter and a topic (:185-196): gflags' header missing, every ``FLAGS_x`` was an
    error in main and the node partial. A flag's value comes from the command line:
    the names are not known (``?``), not the flag's default."""
    result = _extract(write_tree, _source("ros2_gflags.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "?"), ("subscribe", "?")]


def test_ros1_video_capture_back_end_and_tf2_set_euler(write_tree) -> None:
    """OpenCV's ``VideoCapture::open(path, cv::CAP_V4L)`` (cv_camera) and tf2's
    ``Quaternion::setEuler`` (multirobot_map_merge) were errors in functions that call the
    ROS API: both models partial for them."""
    result = _extract(write_tree, _source("ros1_capture_euler.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "~image_raw"), ("publish", "~init_pose")]


def test_ros1_posix_strtok_r(write_tree) -> None:
    """POSIX ``strtok_r`` (um7's covariance parameter) was undeclared by the stand-in C
    library: an error in the function that reads the parameters, so the node was partial."""
    result = _extract(write_tree, _source("ros1_strtok_r.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~values"),
                                                        ("publish", "sum")]


def test_ros1_tf2_to_msg_of_linear_math_types(write_tree) -> None:
    """``tf2::toMsg`` of a tf2::Quaternion is a geometry_msgs::Quaternion (and of a
    tf2::Vector3 a geometry_msgs::Vector3): the stand-in gave back the tf2 type, an error in
    the function that advertises (create_driver's odometry), so the node was partial."""
    result = _extract(write_tree, _source("ros1_tf2_to_msg.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "odom")]


def test_ros2_posix_shared_memory_signals_and_eight_placeholders(write_tree) -> None:
    """OrbbecSDK_ROS2's camera driver installs handlers for SIGSEGV / SIGABRT / SIGFPE /
    SIGILL and shares a process-shared pthread mutex through shm_open / ftruncate / mmap
    in init(), which makes its publishers; dynamic_params compares two
    rclcpp::ParameterValue, ob_camera_node locks with std::try_to_lock, and its examples
    bind eight placeholders. Each was undeclared by the stand-ins: errors in functions
    that call the ROS API, and all 58 driver instances of the workspace partial."""
    result = _extract(write_tree, _source("ros2_shared_memory.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls if c.kind == "publish"] == [
        ("publish", "status")]


# ros2_control's controller base and manager (jazzy): an atomic stored with a memory
# order, a lifecycle callback registered on the node, typeid (ControllerManager::
# load_controller); their errors sat in functions that call the ROS API
ROS2_CONTROL_BASE = """
#include <atomic>
#include <typeinfo>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
class Base {
public:
  void init()
  {
    node_ = std::make_shared<rclcpp_lifecycle::LifecycleNode>("base", "", rclcpp::NodeOptions(),
                                                              false);
    id_.store(1, std::memory_order_release);
    node_->register_on_configure(
      [this](const rclcpp_lifecycle::State &) {
        id_.store(2, std::memory_order_release);
        return rclcpp_lifecycle::LifecycleNode::CallbackReturn::SUCCESS;
      });
    RCLCPP_INFO(node_->get_logger(), "%s", typeid(*this).name());
    pub_ = node_->create_publisher<std_msgs::msg::String>("state", 1);
  }
  virtual ~Base() = default;
private:
  std::atomic<int> id_;
  rclcpp_lifecycle::LifecycleNode::SharedPtr node_;
  std::shared_ptr<rclcpp::Publisher<std_msgs::msg::String>> pub_;
};
"""


def test_ros2_control_base_atomic_order_lifecycle_registration_typeid(write_tree) -> None:
    result = _extract(write_tree, "#include \"std_msgs/msg/string.hpp\"\n" + ROS2_CONTROL_BASE,
                      "ament_cmake")
    assert _errors(result) == []
    assert ("publish", "state") in [(c.kind, c.name) for c in result.calls]


def test_ros2_eigen_views_filters_and_temporary_streams(write_tree) -> None:
    """Eigen's coefficient views (robot_localization's ``covariance.diagonal() =
    VectorXd::Map(...)``, ``noalias()``, ``eval()``), ``rclcpp::ok(context)``
    (pointcloud_to_laserscan's listener thread), ``get_service_name`` (zed,
    robot_localization), a ``std::ostringstream`` written while a temporary
    (realsense2_camera's STREAM_NAME), ``std::array``'s ``cbegin`` (franka), tf2's
    ``toMsg`` of a transform and ROS 2 ``Stamped`` time, ``rclcpp::Time !=`` and a
    message's ``to_yaml`` (robot_localization's filter): each was an error in a function
    that calls the ROS API, so the node was partial. A declaration whose default is an
    ``rclcpp::ParameterValue`` of a string has the type str (beluga's, typed only while
    its ``constexpr std::string_view`` was an error)."""
    result = _extract(write_tree, _source("ros2_eigen_filter.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert {(c.kind, c.name, c.type) for c in result.calls
            if c.name == "model_type"} == {("declare", "model_type", "str")}
    assert {(c.kind, c.name) for c in result.calls} == {
        ("declare", "two_d_mode"), ("declare", "model_type"), ("publish", "out"),
        ("subscribe", "in"),
        ("server", "reset"), ("declare", "joint_index"), ("declare", "listening"),
        ("publish", "/diagnostics"), ("declare", "diagnostic_updater.period"),
        ("declare", "diagnostic_updater.use_fqn"), ("publish", "odometry/filtered")}


def test_ros1_message_cache_urdf_safety_and_tf2_timeout(write_tree) -> None:
    """message_filters' ``Cache`` fed by ``connectInput`` (elevation_mapping), a URDF
    joint's ``safety`` limits (franka), ``ros::Time::sleepUntil`` (cartographer_ros) and
    ``tf2::TimeoutException``: no error, every call kept."""
    result = _extract(write_tree, _source("ros1_cache_urdf.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "pose"), ("read", "robot_description"), ("publish", "soft_limit"),
        ("publish", "elevation")]


def test_ros1_bag_replay_and_camera_model_of_installed_packages(write_tree) -> None:
    """rosbag (slam_gmapping's replay: ``m.instantiate<sensor_msgs::LaserScan>()`` was an
    error beside its advertise calls) and image_geometry (turtlebot_actions' fiducial
    finder: a PinholeCameraModel of an installed package, CPP_CLASS_UNSEEN) make no ROS
    call: the fallback stand-ins declare them when the workspace does not have them."""
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin").replace(
            "</license>", "</license><depend>roscpp</depend><depend>rosbag</depend>"
            "<depend>image_geometry</depend>"),
        "pkg/src/node.cpp": _source("ros1_bag_camera_model.cpp")})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert _errors(result) == []
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_")] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "~entropy"), ("publish", "scan_replayed"), ("publish", "target")]


def test_ros1_controllers_and_robot_hw_of_installed_ros_control(write_tree) -> None:
    """ROS 1 ros_control installed, not in the workspace: franka's controllers take their
    interfaces with ``robot_hw->get<hardware_interface::VelocityJointInterface>()`` (an
    error beside init's calls: 11 franka_ros controllers were partial); a RobotHW
    registers its interfaces. Two PLUGINLIB_EXPORT_CLASS in one file are two exports, not
    a redefinition."""
    result = _extract(write_tree, _source("ros1_controller_robot_hw.cpp"), "catkin")
    assert _errors(result) == []
    # each on the NodeHandle its init is given (the controller's, named where it is loaded)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "?/arm_id"), ("subscribe", "?/command"), ("read", "?/joint"),
        ("read", "?/robot_ip")]


STREAM_WORDS = """\
#include <ros/ros.h>
#include <sstream>
#include <string>
#include <vector>

// MoveIt 1's kinematics_plugin_loader.cpp:316-327: a parameter's words read from a
// std::stringstream, tested with good() and eof(), spaces skipped with std::ws
int main(int argc, char** argv) {
  ros::init(argc, argv, "loader");
  ros::NodeHandle nh("~");
  std::string solvers;
  if (nh.getParam("solvers", solvers)) {
    std::stringstream ss(solvers);
    std::vector<std::string> names;
    while (ss.good() && !ss.eof()) {
      std::string solver;
      ss >> solver >> std::ws;
      names.push_back(solver);
      nh.param("timeout_" + solver, 0.1);
    }
    if (!ss || ss.fail())
      return 1;
  }
  return 0;
}
"""


def test_ros1_stringstream_state_and_ws(write_tree) -> None:
    """A stream that reads and writes has one state (basic_ios'): ``ss.good()`` on a
    std::stringstream is no ambiguity, and ``std::ws`` skips white space; the C++ errors
    these gave hid the reads of the loop (MoveIt's kinematics solver parameters)."""
    result = _extract(write_tree, STREAM_WORDS, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~solvers"), ("read", "~timeout_?")]


def test_ros2_cpp17_parallel_algorithms_and_utilities(write_tree) -> None:
    """beluga's particle filter core: execution policies (a class template over one,
    checked by is_execution_policy_v), reduce, tuple_size_v, invoke_result_t /
    is_invocable_v, std::plus<>, as_const, make_reverse_iterator, nth_element, and
    Eigen's Matrix2Xd / Matrix3Xd, variant_npos / variant_size_v."""
    result = _extract(write_tree, _source("ros2_cpp17_parallel.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "total")]


def test_ros2_parameter_service_without_its_include(write_tree) -> None:
    """webots_ros2's WebotsNode holds an ``rclcpp::Client<rcl_interfaces::srv::
    SetParameters>`` with no include of its own (rclcpp's headers bring it): its type was
    an error, the node class invalid and every call of its constructor lost. rclcpp's
    own rcl_interfaces and builtin_interfaces messages are guarded as their generated
    headers are, so either may come first."""
    result = _extract(write_tree, _source("ros2_unincluded_service.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("declare", "robot_description", "str"),
        ("client", "/robot_state_publisher/set_parameters", "rcl_interfaces/srv/SetParameters"),
        ("publish", "/remove_urdf_robot", "std_msgs/msg/String")]


def test_ros1_param_into_a_vendor_value_and_timer_options(write_tree) -> None:
    """elevation_mapping's ``param("track_point_x", parameters.trackPoint_.x(), 0.0)``: the
    value's type is declared permissively, the default a double, and roscpp's one type
    for both could not be deduced (an error in the function that reads every parameter);
    ``createTimer(TimerOptions&)`` was missing."""
    result = _extract(write_tree, _source("ros1_param_vendor_value_timer_options.cpp"),
                      "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~track_point_x"), ("read", "~point_cloud_topic"), ("publish", "~elevation_map")]


def test_ros2_parameter_value_as_text_and_topic_endpoint_info(write_tree) -> None:
    """orca4's camera_info_publisher logs each parameter with ros2_shared's context
    macros, ``rclcpp::to_string(rclcpp::ParameterValue{cxt_.n_})``: the stand-ins had
    only ``to_string(FutureReturnCode)``, so the constructor that creates the node's
    publisher had an error and the node was partial. topic_tools' ToolBaseNode reads its
    input's publishers with ``get_publishers_info_by_topic``, a vector of
    ``rclcpp::TopicEndpointInfo`` whose QoS it copies: unknown to the stand-ins."""
    source = (
        "#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "class Node : public rclcpp::Node {\n public:\n"
        "  Node() : rclcpp::Node(\"relay\") {\n"
        "    rate_ = declare_parameter(\"rate\", rate_);\n"
        "    RCLCPP_INFO(get_logger(), \"rate = %s\",\n"
        "                rclcpp::to_string(rclcpp::ParameterValue{rate_}).c_str());\n"
        "    std::vector<rclcpp::TopicEndpointInfo> found =\n"
        "        get_publishers_info_by_topic(\"in\");\n"
        "    rclcpp::QoS qos{10};\n"
        "    if (!found.empty()) {\n"
        "      qos.reliability(found[0].qos_profile().reliability());\n"
        "      std::string type = found[0].topic_type();\n    }\n"
        "    auto graph = get_node_graph_interface();\n"
        "    size_t readers = graph->get_subscriptions_info_by_topic(\"out\").size();\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"out\", qos);\n"
        "    (void) readers;\n  }\n"
        "  double rate_{1.0};\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    result = _extract(write_tree, source, "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "rate"), ("publish", "out")]


def test_ros2_std_string_literals_name_a_topic(write_tree) -> None:
    """ouster's ``create_client<ChangeState>(name + "/change_state"s)``: the ``s`` literal
    is a call of ``operator""s``, whose value was unknown (the client ``os_driver?``)."""
    source = (
        "#include <string>\n#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "using namespace std::string_literals;\n"
        "class N : public rclcpp::Node {\n public:\n"
        "  N() : rclcpp::Node(\"n\") {\n"
        "    pub_ = create_publisher<std_msgs::msg::String>(\"base\"s + \"/state\"s, 10);\n  }\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n")
    result = _extract(write_tree, source, "ament_cmake")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "base/state")]


def test_ros1_bind_with_nine_placeholders(write_tree) -> None:
    result = _extract(write_tree, _source("ros1_bind_many_placeholders.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


def test_ros1_time_bounds_and_compound_assignments(write_tree) -> None:
    """novatel_gps_driver's nodelet shifts each message's stamp by a rolling offset
    (``msg->header.stamp += sync_offset``) and starts its sync time at ``ros::TIME_MIN``:
    errors in the functions that publish its messages, which made it partial."""
    source = (
        "#include <ros/ros.h>\n#include <std_msgs/Header.h>\n"
        "ros::Time last = ros::TIME_MIN;\n"
        "int main(int argc, char **argv) {\n"
        "  ros::init(argc, argv, \"stamper\");\n  ros::NodeHandle nh;\n"
        "  std_msgs::Header h;\n  ros::Duration offset(0.5);\n"
        "  h.stamp += offset;\n  h.stamp -= -offset;\n  offset *= 2.0;\n"
        "  offset += ros::DURATION_MIN;\n"
        "  if (last != ros::TIME_MIN && offset != ros::DURATION_MAX && h.stamp < ros::TIME_MAX) {\n"
        "    ros::Publisher pub = nh.advertise<std_msgs::Header>(\"stamped\", 1);\n  }\n"
        "  ros::spin();\n}\n")
    result = _extract(write_tree, source, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "stamped")]


def test_ros1_steady_time(write_tree) -> None:
    """robotnik_base_hw's control loop measures its period with ``ros::SteadyTime``
    (rostime's monotonic clock, beside WallTime, since Melodic): ``ros::Duration
    elapsed((now - last).toSec())`` was an ambiguous constructor call, an error in the
    function that advertises, and the node partial."""
    source = (
        "#include <ros/ros.h>\n#include <std_msgs/Float64.h>\n"
        "int main(int argc, char **argv) {\n"
        "  ros::init(argc, argv, \"loop\");\n  ros::NodeHandle nh;\n"
        "  ros::SteadyTime last = ros::SteadyTime::now();\n"
        "  ros::Publisher pub = nh.advertise<std_msgs::Float64>(\"period\", 1);\n"
        "  while (ros::ok()) {\n"
        "    ros::SteadyTime now = ros::SteadyTime::now();\n"
        "    ros::Duration elapsed((now - last).toSec());\n"
        "    std_msgs::Float64 msg;\n    msg.data = elapsed.toSec();\n"
        "    pub.publish(msg);\n    last = now;\n  }\n}\n")
    result = _extract(write_tree, source, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "period")]


def test_ros1_opencv_regions_as_small_matrices_and_a_time_synchronizers_inputs(
        write_tree) -> None:
    """msckf_vio's image processor reads its camera transforms into ``cv::Matx33d`` and
    ``cv::Vec3d`` from regions of a ``cv::Mat``, transposes and negates them, and connects
    its stereo ``TimeSynchronizer`` built with a queue size only: 8 errors in the
    functions that read its parameters and subscribe, which made it partial."""
    source = (
        "#include <ros/ros.h>\n#include <opencv2/opencv.hpp>\n"
        "#include <sensor_msgs/Image.h>\n#include <message_filters/subscriber.h>\n"
        "#include <message_filters/time_synchronizer.h>\n"
        "int main(int argc, char **argv) {\n"
        "  ros::init(argc, argv, \"stereo\");\n  ros::NodeHandle nh(\"~\");\n"
        "  cv::Mat T = cv::Mat::eye(4, 4, CV_64FC1);\n"
        "  cv::Matx33d R(T(cv::Rect(0, 0, 3, 3)));\n"
        "  cv::Vec3d t = T(cv::Rect(3, 0, 1, 3));\n"
        "  cv::Matx33d R_inv = R.t();\n  cv::Vec3d t_inv = -R.t() * t;\n"
        "  cv::Matx13d row = t.t();\n"
        "  message_filters::Subscriber<sensor_msgs::Image> left, right;\n"
        "  message_filters::TimeSynchronizer<sensor_msgs::Image, sensor_msgs::Image> sync(10);\n"
        "  left.subscribe(nh, \"cam0_image\", 10);\n  right.subscribe(nh, \"cam1_image\", 10);\n"
        "  sync.connectInput(left, right);\n"
        "  ros::spin();\n}\n")
    result = _extract(write_tree, source, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "~cam0_image"), ("subscribe", "~cam1_image")]


def test_ros2_opencv_contours_with_hierarchy_and_moments(write_tree) -> None:
    """raspimouse_ros2_examples' camera_line_follower: ``cv::findContours`` with the
    contours' hierarchy, ``cv::drawContours`` given a line type and the hierarchy,
    ``cv::morphologyEx``, ``cv::contourArea``, ``cv::moments`` and ``cv::LINE_4``: clang
    errors in a function that reads a parameter made the node partial."""
    result = _extract(write_tree, _source("ros2_opencv_contours.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [d.code for d in result.diagnostics if d.code.startswith("CPP_NODE")] == []
    assert [(c.kind, c.name) for c in result.calls
            if c.kind in ("declare", "read", "publish")] == [
        ("declare", "min_brightness"), ("publish", "area"), ("read", "min_brightness")]


def test_ros2_optional_compared_with_nullopt(write_tree) -> None:
    """mqtt_client's setupSubscriptions compares a ``std::optional`` QoS policy with
    ``std::nullopt``: the stand-in had no such operator, and the clang error in the
    function that subscribes made the node partial."""
    result = _extract(write_tree, _source("ros2_optional_nullopt.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "in")]


def test_ros1_glog_logging_and_checks_beside_the_calls(write_tree) -> None:
    """voxblox's servers and cartographer_ros log and check with glog: with its header
    missing, ``google::InitGoogleLogging(argv[0]);`` was read as a declaration of a new
    ``argv`` (the name declared permissively as a class) and every CHECK / DCHECK / LOG
    an error, in functions that call the ROS API: the node partial, its handles' calls
    in doubt. With a stand-in (gflags' functions in namespace google too, as Ubuntu's
    build has them), no error and every call."""
    result = _extract(write_tree, _source("ros1_glog.cpp"), "catkin")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~mesh"), ("read", "~voxel_size"), ("subscribe", "input")]
    assert "CPP_NODE_PARTIAL" not in {d.code for d in result.diagnostics}


def test_ros1_c_library_functions_beside_the_calls(write_tree) -> None:
    """microstrain_mips' service clients read their arguments with ``atoll`` (23 programs,
    each partial: 'use of undeclared identifier' in main, which calls the API), its
    driver times out with ``clock()``; VINS-Fusion's ``fminf`` / ``ceilf``, voxblox's
    ``std::remainder`` / ``std::log2``, rovio's ``std::sinh`` and its stream's
    ``imbue(std::locale(...))``: the C library's and <cmath>'s functions are declared,
    so none is an error."""
    result = _extract(write_tree, _source("ros1_libc.cpp"), "catkin")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("client", "SetAccelBias"), ("publish", "gain")]


def test_tf2_advanced_lookup_and_a_scalar_of_another_type_in_ros1(write_tree) -> None:
    """hdl_localization's odometry prediction: tf2's advanced ``canTransform`` /
    ``lookupTransform(target, target_time, source, source_time, fixed, timeout)``, whose
    second argument is a time, and Eigen's ``double * Vector3f`` (the scalar is converted
    to the matrix's): both were errors in the callback that publishes, and the node
    partial."""
    result = _extract(write_tree, _source("ros1_tf2_advanced_eigen_scalar.cpp"), "catkin")
    assert _errors(result) == []
    # the listener at its initialiser ``listener_(buffer_)`` (line 9), its one
    # construction, before the publisher's member initialiser (line 19)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "/tf"), ("subscribe", "/tf_static"), ("publish", "delta")]


def test_a_serial_port_opened_with_termios_and_fcntl(write_tree) -> None:
    # limo_ros2's limo_base: B460800 in the node's constructor was an error beside its
    # ROS calls, and the node partial
    result = _extract(write_tree, _source("ros2_serial.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "port_name"), ("publish", "status")]


def test_strcasecmp_and_the_standard_file_descriptors(write_tree) -> None:
    # unitree_legged_real's ros_udp: strcasecmp in main, beside its advertise calls,
    # was an error and the node partial; xarm_ros2's driver: setlinebuf (survey Z19)
    result = _extract(write_tree, _source("ros1_strcasecmp_stdin.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("publish", "low_state"), ("publish", "high_state")]


def test_memory_locking_and_cpu_affinity(write_tree) -> None:
    # KUKA's kuka_drivers_core control_node: munlockall in main (after the control loop)
    # was an error in the function that makes the node's calls, and the node partial;
    # cpu_set_t and CPU_ZERO were declared permissively (survey Z20)
    result = _extract(write_tree, _source("ros2_realtime_memory.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert "CPP_NAMES_DECLARED" not in [d.code for d in result.diagnostics]
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "cpu_affinity"), ("publish", "locked")]


def test_string_view_search_and_substrings(write_tree) -> None:
    # KUKA's sunrise robot_manager_node splits an IP address held in a std::string_view
    # (find, npos, substr): 5 errors in a method of the node (survey Z20)
    result = _extract(write_tree, """
#include <string>
#include <string_view>
#include <vector>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/bool.hpp"
bool valid(std::string_view ip, const std::string& s) {
  std::vector<std::string> parts;
  size_t i = 0;
  auto pos = ip.find('.');
  while (pos != std::string_view::npos) {
    parts.emplace_back(ip.substr(i, pos - i));
    i = ++pos;
    pos = ip.find('.', pos);
  }
  return parts.size() == 3 && s == "x" && ip == "y" && ip.starts_with("1");
}
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("n");
  auto pub = node->create_publisher<std_msgs::msg::Bool>("ok", 1);
  return valid("1.2.3.4", "x") ? 0 : 1;
}
""", "ament_cmake")
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "ok")]


def test_library_fundamentals_ts_optional_and_filesystem(write_tree) -> None:
    # f1tenth's vesc_driver keeps its command limits in std::experimental::optional
    # (<experimental/optional>, C++14) and compares a value with one: the header was an
    # empty stand-in, the node's class invalid, and its 15 calls in the constructor errors
    # (survey Z23)
    result = _extract(write_tree, """
#include <experimental/optional>
#include <experimental/filesystem>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/float64.hpp"
namespace fs = std::experimental::filesystem;
class Driver : public rclcpp::Node {
public:
  Driver() : rclcpp::Node("driver") {
    if (fs::exists(fs::path("/dev/ttyACM0"))) {
      limit_ = std::experimental::make_optional(declare_parameter<double>("limit", 1.0));
    }
    pub_ = create_publisher<std_msgs::msg::Float64>("out", 10);
  }
  double clip(double value) const {
    if (limit_ && value > limit_) { return *limit_; }
    return limit_ != std::experimental::nullopt ? value : 0.0;
  }
private:
  std::experimental::optional<double> limit_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
""", "ament_cmake")
    assert _errors(result) == []
    assert "CPP_INCLUDE_MISSING" not in [d.code for d in result.diagnostics]
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "limit"), ("publish", "out")]


def test_the_parameter_callback_type_alias_and_glibc_short_names(write_tree) -> None:
    # realsense-ros' ParametersBackend (NodeParametersInterface::OnParametersSetCallbackType:
    # 86 errors, the camera node partial) and ros2_control_demos' ``for (uint i = 0; ...)``
    # in its hardware (51 errors), found by the bugs of bench/real_bugs.yaml
    result = _extract(write_tree, _source("ros2_param_callback_uint.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "align_depth.enable"), ("publish", "status")]


# Boost.Asio's handlers take ``const boost::system::error_code&``; with no stand-in,
# ``boost::system`` named the C library's ``system`` function: an error in every handler
# (rosserial_server's sessions, whose timers read ``~require``), and rosserial's
# ``std::make_signed<size_t>`` and ``boost::function::clear()`` were errors too
ASIO = """#include <type_traits>
#include <boost/asio.hpp>
#include <boost/bind.hpp>
#include <boost/function.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
typedef std::make_signed<size_t>::type signed_size_t;
class Session {
 public:
  Session(boost::asio::io_service& io) : timer_(io) {
    threshold_ = ros::param::param("~threshold", 0);
    timer_.async_wait(boost::bind(&Session::check, this, boost::asio::placeholders::error));
  }
  void check(const boost::system::error_code& error) {
    if (error != boost::asio::error::operation_aborted && ros::param::has("~require")) {
      pub_ = nh_.advertise<std_msgs::String>("out", 1);
      callback_.clear();
    }
  }
 private:
  ros::NodeHandle nh_;
  ros::Publisher pub_;
  boost::asio::deadline_timer timer_;
  boost::function<void(int)> callback_;
  signed_size_t threshold_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "session");
  boost::asio::io_service io;
  Session session(io);
  io.run();
}
"""


def test_asio_handlers_with_boost_system_error_codes(write_tree) -> None:
    result = _extract(write_tree, ASIO, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~threshold"), ("read", "~require"), ("publish", "out")]


# ROS 1 sensor_msgs' point_cloud_conversion.h (costmap_2d's obstacle layer converts a
# PointCloud to a PointCloud2 in its callback): it was an empty stand-in and an error
CONVERSION = """#include <ros/ros.h>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud_conversion.h>
class Layer {
 public:
  Layer() {
    sub_ = nh_.subscribe("cloud", 1, &Layer::convert, this);
    pub_ = nh_.advertise<sensor_msgs::PointCloud2>("cloud2", 1);
  }
  void convert(const sensor_msgs::PointCloudConstPtr& message) {
    sensor_msgs::PointCloud2 cloud2;
    if (!sensor_msgs::convertPointCloudToPointCloud2(*message, cloud2)) return;
    int x = sensor_msgs::getPointCloud2FieldIndex(cloud2, "x");
    pub_.publish(cloud2);
  }
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  ros::Publisher pub_;
};
int main(int argc, char** argv) { ros::init(argc, argv, "layer"); Layer l; ros::spin(); }
"""


def test_ros1_point_cloud_conversions(write_tree) -> None:
    result = _extract(write_tree, CONVERSION, "catkin")
    assert _errors(result) == []
    assert "CPP_INCLUDE_MISSING" not in [d.code for d in result.diagnostics]
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "cloud"), ("publish", "cloud2")]


def test_a_lifecycle_transition_and_a_constant_beside_a_permissive_value(write_tree) -> None:
    # book_ros2's object_tracker: ``trigger_transition`` was no member of the stand-in
    # LifecycleNode, and ``msg->bbox.center.position.x / IMG_WIDTH`` (``bbox`` declared
    # permissively) bound a reference to the constant, which the callback then had to
    # capture: three errors in main, the node partial
    result = _extract(write_tree, _source("ros2_lifecycle_trigger.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls if not c.name.startswith("~")) == [
        ("publish", "/command"), ("subscribe", "/detection")]


def test_eigen_matrix_base_decompositions_and_boost_microseconds(write_tree) -> None:
    """image_undistort's ``xmlRpcToMatrix(value, Eigen::MatrixBase<Derived>* out)`` beside
    its camera parameter reads, and open_vins' ``A.colPivHouseholderQr().solve(I)``,
    ``S.llt().solve(r)`` and ``(t2 - t1).total_microseconds()``: the stand-ins had no
    MatrixBase, no decompositions and only total_milliseconds, an error in each function
    that reads parameters or advertises, so the nodes were partial (CPP_NODE_PARTIAL on
    image_undistort's three nodelets and six of open_vins' nodes)."""
    result = _extract(write_tree, _source("ros1_eigen_decompositions.cpp"), "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~K"), ("publish", "~chi2")]


def test_ros2_declaration_macros_one_after_another(write_tree) -> None:
    """autoware_utils_geometry's boost_geometry.hpp registers its points and ring with
    ``BOOST_GEOMETRY_REGISTER_POINT_2D(..)``, ``_3D(..)`` and ``BOOST_GEOMETRY_REGISTER_RING
    (..)`` in a row at namespace scope. With Boost.Geometry's headers missing clang read
    the three as one declarator wanting a body, which swallowed everything after it: the
    macro before the error was not learnt (the statement was not one call) and the one
    after it not seen, so every node including the header (Autoware's goal distance
    calculator, 0 calls) lost its calls."""
    result = _extract(write_tree, _source("ros2_declaration_macros_in_a_row.cpp"), "ament_cmake")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "chatter")]


def test_ros2_a_simulator_plugin_that_starts_the_controller_manager(write_tree) -> None:
    """gazebo_ros2_control (humble 42d875b4, gazebo_ros2_control_plugin.cpp:204-256, 365):
    the plugin parses its parameter files into the rcl context's global arguments
    (``Context::get_rcl_context``, ``rcl_parse_arguments`` and the other argument
    functions were not declared), builds a ``hardware_interface::ResourceManager`` from
    the URDF (its header and the component parser's were missing) and hands it to
    ``controller_manager::ControllerManager``, whose stand-in had only ros2_control_node's
    constructor: five clang errors in the function that makes its calls, the node
    partial. Its component, of a class derived from ``SystemInterface``, is imported
    with ``import_component`` (one overload per component kind: ambiguous to the parse
    if declared so). Jazzy's constructors (clock and logging interfaces, the manager's
    URDF one) too."""
    result = _extract(write_tree, _source("ros2_simulated_control_manager.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert "CPP_NODE_PARTIAL" not in [d.code for d in result.diagnostics]
    assert [(c.kind, c.name) for c in result.calls if c.kind != "server"] == [
        ("read", "update_rate"), ("publish", "sim_status")]
    assert ("server", "~switch_controller") in [(c.kind, c.name) for c in result.calls]


def test_a_macro_of_a_missing_header_used_as_an_operand_is_a_value(write_tree) -> None:
    """ROBOTIS-THORMANG-MPC's motion modules (head_control_module.cpp:469,
    manipulation_module.cpp:593): robotis_math's ``DEGREE2RADIAN`` / ``RADIAN2DEGREE``
    (``#define``d there, the header missing) written before ``)`` (``/ (30 *
    DEGREE2RADIAN)``) were declared as types, and every use an error, "does not refer
    to a value". An operand of ``*``, ``/``, ``-``, ``!``, ``?``/``:`` is a value, and an
    unqualified name in capitals not called is declared as one."""
    result = _extract(write_tree, """
        #include <ros/ros.h>
        #include <std_msgs/Float64.h>
        #include "robotis_math/robotis_math.h"
        class Module {
         public:
          void init(ros::NodeHandle& nh, double value, double angle, bool c) {
            joint_ = value * DEGREE2RADIAN;
            moving_ = fabs(angle - value) / (30 * DEGREE2RADIAN);
            ROS_INFO("x : %f", angle * RADIAN2DEGREE);
            limit_ = c ? Vendor::K * 2.0 : -Vendor::L;
            flag_ = c && !Vendor::FLAG;
            pub_ = nh.advertise<std_msgs::Float64>("angle", 1);
          }
          double joint_, moving_, limit_;
          bool flag_;
          vendor::Port port_;
          ros::Publisher pub_;
        };
        int main(int argc, char** argv) {
          ros::init(argc, argv, "m");
          ros::NodeHandle nh;
          Module m;
          m.init(nh, 1, 2, argc > 1);
        }
        """, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "angle")]


def test_a_conditional_between_arithmetic_on_a_permissive_value_and_a_number(
        write_tree) -> None:
    """abb_robot_driver's EGM hardware interface (egm_hardware_interface.cpp:664):
    ``limits.max_velocity = (joint.rotational ? 10.0*Constants::DEG_TO_RAD : 0.1);``,
    ``Constants`` of abb_egm_rws_managers, not here. The product of a number and a
    permissive value was a permissive value, which converts to ``double`` and is built
    from one: the conditional was ambiguous, an error in the function that reads the
    joint limits, and the node partial. Both sides permissive stay one type."""
    result = _extract(write_tree, """
        #include <ros/ros.h>
        #include <std_msgs/Float64.h>
        #include <vendor/constants.h>
        struct Joint { bool rotational; };
        void configure(ros::NodeHandle& nh, const Joint& joint) {
          vendor::Manager manager;
          double limit = (joint.rotational ? 10.0*Constants::DEG_TO_RAD : 0.1);
          int steps = joint.rotational ? 2 : Constants::STEPS * 2;
          auto both = joint.rotational ? 2.0 * Constants::DEG_TO_RAD : Constants::DEG_TO_RAD;
          nh.setParam("limit", limit + steps);
          ros::Publisher pub = nh.advertise<std_msgs::Float64>("velocity", 1);
        }
        int main(int argc, char** argv) {
          ros::init(argc, argv, "hw");
          ros::NodeHandle nh;
          configure(nh, Joint{argc > 1});
          ros::spin();
        }
        """, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("write", "limit"), ("publish", "velocity")]


def test_qt_members_the_stand_in_lacks(write_tree) -> None:
    """mapviz's window and autorally's console call Qt members our stand-in does not
    declare (``setMaximumSize``, ``QList::front``, ``QPainter::drawRect``): each is given
    to the stand-in's classes from the unit's errors (``synthesis.QT_MORE``), and the
    constructor that makes the node's calls parses."""
    result = _extract(write_tree, _source("ros2_qt_members.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "config"), ("publish", "status"), ("subscribe", "command")]


def test_std_abs_named_globally_and_utf_conversions(write_tree) -> None:
    """navigation2_tutorials: ``using std::abs;`` at namespace scope was an error (the
    stand-in's ``std::abs(int)`` a second function beside the C library's), and its SMS
    behaviour's ``std::wstring_convert<std::codecvt_utf8<char16_t>, char16_t>`` and
    ``std::u16string`` were not declared."""
    result = _extract(write_tree, _source("ros2_abs_codecvt.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "lookahead"), ("declare", "message"),
        ("publish", "long_messages"), ("publish", "short_messages")]


def test_cxx17_traits_addressof_and_distribution_parameters(write_tree) -> None:
    """beluga: ``std::is_const_v``, ``is_lvalue_reference_v``, ``is_invocable_r_v``,
    ``result_of_t``, ``std::addressof`` and ``normal_distribution<>::param_type`` were not
    declared (98 errors in beluga_amcl's units, the AMCL node's class among them)."""
    result = _extract(write_tree, _source("ros2_type_traits_random.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "sigma"), ("publish", "negative"), ("publish", "positive")]


def test_ros2_code_including_cv_bridge_h_gets_the_ros2_api(write_tree) -> None:
    """apriltag_ros, depthai-ros: ``#include <cv_bridge/cv_bridge.h>`` in a ROS 2 unit
    was ROS 1's stand-in (``toCvShare(sensor_msgs::ImageConstPtr)``), so every
    conversion of a ROS 2 image was an error near the node's calls."""
    result = _extract(write_tree, _source("ros2_cv_bridge_h.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "image_mono"), ("subscribe", "image")]


def test_posix_descriptors_and_processes(write_tree) -> None:
    """urg_node's getID: ``dup``, ``dup2`` and ``pipe`` were undeclared (and ``fork``,
    ``exec*``, ``waitpid``, which drivers running a helper program use)."""
    result = _extract(write_tree, _source("ros2_posix_processes.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "probe_status")]


def test_fill_image_and_every_image_encoding(write_tree) -> None:
    """flir_camera_driver: ``sensor_msgs::fillImage`` (fill_image.hpp) and the 16-bit
    Bayer encodings were not declared (declared permissively, the parse's errors near
    the driver's calls)."""
    result = _extract(write_tree, _source("ros2_fill_image.cpp"), "ament_cmake")
    assert _errors(result) == []
    assert not {d.code for d in result.diagnostics} & {"CPP_NAMES_DECLARED",
                                                        "CPP_INCLUDE_MISSING"}
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "image_raw")]


LONG_DOUBLE = """#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <math.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "odom");
  ros::NodeHandle nh("~");
  long double theta = 0.5L, d = 1.0L;
  long double x = d * cosl(theta), y = d * sinl(theta);
  long double r = sqrtl(x * x + y * y) + fabsl(atan2l(y, x)) + powl(r, 2.0L);
  ros::Publisher pub = nh.advertise<std_msgs::Float64>("odom", 100);
  ros::spin();
}
"""


def test_long_double_math(write_tree) -> None:
    # ros_whill a03988c's odom.cpp:84 (``cosl``, ``sinl`` of <math.h>)
    result = _extract(write_tree, LONG_DOUBLE, "catkin")
    # declared by the stand-in, not taken as names the parse does not know
    assert _errors(result) == [] and not [
        d for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "~odom")]


# A serial driver's port options (zeabus' IMU on a Lord Microstrain, through its own
# SerialPort class): ``serial_port_base::flow_control::none`` and the overloads of
# ``set_option_port`` on each option class need Boost.Asio's real nested classes and
# enums; declared permissively, every such line was an error in ``main``, which
# advertises, and ``namespace Asio = boost::asio;`` redefined a permissive ``Asio``
SERIAL = """#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <boost/asio.hpp>
namespace Asio = boost::asio;
class Port {
 public:
  explicit Port(const std::string& name) : port_(io_) { port_.open(name); }
  void set_option_port(Asio::serial_port_base::baud_rate b) { port_.set_option(b); }
  void set_option_port(Asio::serial_port_base::flow_control f) { port_.set_option(f); }
  void set_option_port(Asio::serial_port_base::parity p) { port_.set_option(p); }
  void set_option_port(Asio::serial_port_base::stop_bits s) { port_.set_option(s); }
  void set_option_port(Asio::serial_port_base::character_size c) { port_.set_option(c); }
 private:
  boost::asio::io_service io_;
  boost::asio::serial_port port_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "imu");
  ros::NodeHandle nh;
  Port imu(nh.param<std::string>("~port", "/dev/ttyACM0"));
  imu.set_option_port(Asio::serial_port_base::baud_rate(115200));
  imu.set_option_port(Asio::serial_port_base::flow_control(
      Asio::serial_port_base::flow_control::none));
  imu.set_option_port(Asio::serial_port_base::parity(Asio::serial_port_base::parity::none));
  imu.set_option_port(Asio::serial_port_base::stop_bits(
      Asio::serial_port_base::stop_bits::one));
  imu.set_option_port(Asio::serial_port_base::character_size((size_t) 8));
  ros::Publisher pub = nh.advertise<std_msgs::String>("imu/data", 1);
  ros::spin();
}
"""


def test_asio_serial_port_options(write_tree) -> None:
    result = _extract(write_tree, SERIAL, "catkin")
    assert _errors(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~port"), ("publish", "imu/data")]
