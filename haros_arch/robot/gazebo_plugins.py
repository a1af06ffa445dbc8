"""What the Gazebo plugins of a robot description publish, subscribe to and serve: data.

One row per plugin library (the ``filename`` of a ``<plugin>`` element), like the API
tables of the extractors. Each ``Entity`` is one topic, service or parameter the plugin
makes, its name a template over the plugin's child elements (``{topicName}``; the row's
``defaults`` give the value when the element is absent, as the plugin's source does),
and ``when`` an element whose truth the entity depends on (``publishTf``).

ROS 1 (gazebo_ros_pkgs noetic-devel, hector_gazebo): the calls are made by the gazebo
node on a node handle in the namespace the row's ``namespace`` rule gives:

- ``"plain"``: ``<robotNamespace>`` or the node's namespace when absent (imu, p3d,
  bumper, planar_move, skid_steer, hector's);
- ``"model"``: ``<robotNamespace>``, the model's name when absent or empty (``GazeboRos``
  of diff_drive, joint_state_publisher; gazebo_ros_control);
- ``"sensor"``: ``<robotNamespace>`` when present (the model's name when empty), else
  the node's namespace (``GetRobotNamespace`` of camera and laser plugins);
- ``"sensor_model"``: ``<robotNamespace>``, else ``/<model name>`` (imu_sensor).

ROS 2 (gazebo_ros_pkgs ros2): each plugin is a node of its own (``gazebo_ros::Node``)
named by the plugin's ``name``, in ``<ros><namespace>`` (``/`` when absent), with the
``<ros><remapping>`` rules; names are relative to that node.

Sources read for every row: ``gazebo_plugins/src/<name>.cpp`` of both branches,
``gazebo_ros_control/src/gazebo_ros_control_plugin.cpp`` (noetic),
``hector_gazebo_plugins/src/gazebo_ros_{imu,gps}.cpp``.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Entity:
    kind: str  # publish | subscribe | server | read (the call kinds)
    name: str  # template over child elements: ``{topicName}``, ``{cameraName}/image_raw``
    type: str  # canonical type of the row's ROS version, or a ``{element}`` template
    # a child element that must be true for it to exist (``a|b``: either), or ``@depth``:
    # the plugin's <sensor> is a depth camera, or ``@camera:<word>``: a <camera> of its
    # multicamera <sensor> is the first whose name holds <word> of those the row tries
    # (``left``, then ``right``)
    when: str | None = None
    when_default: bool = True  # its value when absent
    # published through image_transport (``PrimitiveCall.transport``): the transport
    # plugins' topics beside it (gazebo_ros_camera_utils.cpp's itnode_->advertise; ROS 2
    # gazebo_ros_camera.cpp's image_transport::create_publisher, the depth image too)
    transport: bool = False
    # a read of the parameter found by searching up from the handle's namespace
    # (``searchParam``, ``PrimitiveCall.searched``): gazebo_ros_control's getURDF
    searched: bool = False
    # ROS 1: the template of the namespace of the node handle the call is made on, below
    # the plugin's (``{cameraName}``: gazebo_ros_camera_utils.cpp's LoadThread makes
    # ``ros::NodeHandle(robot_namespace_ + "/" + camera_name_)``), which roscpp remaps
    # before it resolves the name in it (``PrimitiveCall.handle_namespace``); None: the
    # plugin's own handle
    handle: str | None = None


@dataclass(frozen=True)
class Plugin:
    filenames: tuple[str, ...]  # the library, with or without ``lib`` and ``.so``
    ros_version: int
    entities: tuple[Entity, ...]
    defaults: tuple[tuple[str, str], ...] = ()  # element -> value when absent
    namespace: str = "plain"  # ROS 1 rule (module docstring)
    # why the interface is not all known (what it loads in turn), or None
    partial: str | None = None
    manager: bool = False  # it starts a ros2_control controller manager node


def _ros1(*filenames: str, entities: tuple[Entity, ...], namespace: str = "plain",
          defaults: tuple[tuple[str, str], ...] = (), partial: str | None = None) -> Plugin:
    return Plugin(filenames, 1, entities, defaults, namespace, partial)


def _ros2(*filenames: str, entities: tuple[Entity, ...],
          defaults: tuple[tuple[str, str], ...] = (), partial: str | None = None,
          manager: bool = False) -> Plugin:
    return Plugin(filenames, 2, entities, defaults, "ros2", partial, manager)


_CAMERA_1 = (
    Entity("publish", "{cameraName}/{imageTopicName}", "sensor_msgs/Image", transport=True,
           handle="{cameraName}"),
    Entity("publish", "{cameraName}/{cameraInfoTopicName}", "sensor_msgs/CameraInfo",
           handle="{cameraName}"),
)
_CAMERA_1_DEFAULTS = (("cameraName", ""), ("imageTopicName", "image_raw"),
                      ("cameraInfoTopicName", "camera_info"))
# the words gazebo_ros_multicamera looks for in its cameras' names, in its order
MULTICAMERA_SIDES = ("left", "right")
_LASER_1 = (Entity("publish", "{topicName}", "sensor_msgs/LaserScan"),)
_GPU_LASER_1 = _LASER_1
_DRIVE_1 = (
    Entity("subscribe", "{commandTopic}", "geometry_msgs/Twist"),
    Entity("publish", "{odometryTopic}", "nav_msgs/Odometry"),
    Entity("publish", "/tf", "tf2_msgs/TFMessage"),
)
_DRIVE_1_DEFAULTS = (("commandTopic", "cmd_vel"), ("odometryTopic", "odom"))

# ROS 2 drives: cmd_vel, odom when <publish_odom> (false when absent), /tf when either tf
_DRIVE_2 = (
    Entity("subscribe", "cmd_vel", "geometry_msgs/msg/Twist"),
    Entity("publish", "odom", "nav_msgs/msg/Odometry", when="publish_odom",
           when_default=False),
)
_WHEEL_TF_2 = Entity("publish", "/tf", "tf2_msgs/msg/TFMessage",
                     when="publish_odom_tf|publish_wheel_tf", when_default=False)

PLUGINS: tuple[Plugin, ...] = (
    # -- ROS 1: gazebo_ros_pkgs (noetic-devel) -------------------------------------------
    _ros1("gazebo_ros_camera", "gazebo_ros_triggered_camera", namespace="sensor",
          entities=_CAMERA_1, defaults=_CAMERA_1_DEFAULTS),
    # multicamera: a camera utility per <camera> named with ``left`` (else ``right``),
    # its name <cameraName>/left (/right); gazebo_ros_multicamera.cpp's Load
    _ros1("gazebo_ros_multicamera", namespace="sensor", entities=tuple(
        Entity(e.kind, e.name.replace("{cameraName}", "{cameraName}/" + side), e.type,
               when=f"@camera:{side}", transport=e.transport,
               handle="{cameraName}/" + side)
        for side in MULTICAMERA_SIDES for e in _CAMERA_1), defaults=_CAMERA_1_DEFAULTS),
    _ros1("gazebo_ros_depth_camera", "gazebo_ros_openni_kinect", namespace="sensor",
          entities=(*_CAMERA_1,
                    Entity("publish", "{cameraName}/{depthImageTopicName}",
                           "sensor_msgs/Image", handle="{cameraName}"),
                    Entity("publish", "{cameraName}/{depthImageCameraInfoTopicName}",
                           "sensor_msgs/CameraInfo", handle="{cameraName}"),
                    Entity("publish", "{cameraName}/{pointCloudTopicName}",
                           "sensor_msgs/PointCloud2", handle="{cameraName}")),
          defaults=(*_CAMERA_1_DEFAULTS, ("depthImageTopicName", "depth/image_raw"),
                    ("depthImageCameraInfoTopicName", "depth/camera_info"),
                    ("pointCloudTopicName", "points"))),
    _ros1("gazebo_ros_laser", namespace="sensor", entities=_LASER_1,
          defaults=(("topicName", "/world"),)),
    _ros1("gazebo_ros_gpu_laser", namespace="sensor", entities=_GPU_LASER_1,
          defaults=(("topicName", "/world"),)),
    # gazebo_ros_imu: a model plugin; an empty <topicName> publishes nothing
    _ros1("gazebo_ros_imu", entities=(
        Entity("publish", "{topicName}", "sensor_msgs/Imu"),
        Entity("server", "{serviceName}", "std_srvs/Empty")),
        defaults=(("topicName", "/default_imu"), ("serviceName", "/default_imu"))),
    _ros1("gazebo_ros_imu_sensor", namespace="sensor_model",
          entities=(Entity("publish", "{topicName}", "sensor_msgs/Imu"),),
          defaults=(("topicName", "imu_data"),)),
    _ros1("gazebo_ros_diff_drive", namespace="model", entities=(
        Entity("subscribe", "{commandTopic}", "geometry_msgs/Twist"),
        Entity("publish", "{odometryTopic}", "nav_msgs/Odometry", when="publishTf"),
        Entity("publish", "/tf", "tf2_msgs/TFMessage"),
        Entity("publish", "joint_states", "sensor_msgs/JointState",
               when="publishWheelJointState", when_default=False)),
        defaults=_DRIVE_1_DEFAULTS),
    _ros1("gazebo_ros_skid_steer_drive", entities=_DRIVE_1, defaults=_DRIVE_1_DEFAULTS),
    _ros1("gazebo_ros_planar_move", entities=_DRIVE_1, defaults=_DRIVE_1_DEFAULTS),
    _ros1("gazebo_ros_joint_state_publisher", namespace="model", entities=(
        Entity("publish", "joint_states", "sensor_msgs/JointState"),)),
    # p3d refuses to load without <topicName>
    _ros1("gazebo_ros_p3d", entities=(Entity("publish", "{topicName}", "nav_msgs/Odometry"),)),
    # ft_sensor and f3d need <topicName> (no default); range and block_laser have one
    _ros1("gazebo_ros_ft_sensor", entities=(
        Entity("publish", "{topicName}", "geometry_msgs/WrenchStamped"),)),
    _ros1("gazebo_ros_f3d", entities=(
        Entity("publish", "{topicName}", "geometry_msgs/WrenchStamped"),)),
    # force needs <bodyName> and <topicName> (no default): a handle on <robotNamespace>
    # subscribes to the wrench it applies to the body
    _ros1("gazebo_ros_force", entities=(
        Entity("subscribe", "{topicName}", "geometry_msgs/Wrench"),)),
    _ros1("gazebo_ros_range", entities=(Entity("publish", "{topicName}", "sensor_msgs/Range"),),
          defaults=(("topicName", "/range"),)),
    _ros1("gazebo_ros_block_laser", entities=(
        Entity("publish", "{topicName}", "sensor_msgs/PointCloud"),),
        defaults=(("topicName", "/world"),)),
    _ros1("gazebo_ros_tricycle_drive", namespace="model", entities=(
        Entity("subscribe", "{commandTopic}", "geometry_msgs/Twist"),
        Entity("publish", "{odometryTopic}", "nav_msgs/Odometry"),
        Entity("publish", "joint_states", "sensor_msgs/JointState",
               when="publishWheelJointState", when_default=False)),
        defaults=_DRIVE_1_DEFAULTS),
    # gazebo_ros_video: a visual plugin that shows the images it is sent (sawyer's head
    # display); gazebo_ros_video.cpp's Load subscribes on NodeHandle(<robotNamespace>)
    _ros1("gazebo_ros_video", entities=(
        Entity("subscribe", "{topicName}", "sensor_msgs/Image"),),
        defaults=(("topicName", "image_raw"),)),
    _ros1("gazebo_ros_bumper", entities=(
        Entity("publish", "{bumperTopicName}", "gazebo_msgs/ContactsState"),),
        defaults=(("bumperTopicName", "bumper_states"),)),
    # gazebo_ros_control: a ros_control controller manager in the robot's namespace; the
    # controllers the configuration's spawners load into it are attached to the gazebo
    # instance that serves its load_controller (plugins.attach.ros1_controllers)
    _ros1("gazebo_ros_control", namespace="model", entities=(
        Entity("read", "{robotParam}", "string", searched=True),
        Entity("subscribe", "{eStopTopic}", "std_msgs/Bool", when="eStopTopic",
               when_default=False),
        Entity("server", "controller_manager/list_controllers",
               "controller_manager_msgs/ListControllers"),
        Entity("server", "controller_manager/load_controller",
               "controller_manager_msgs/LoadController"),
        Entity("server", "controller_manager/switch_controller",
               "controller_manager_msgs/SwitchController"),
        Entity("server", "controller_manager/unload_controller",
               "controller_manager_msgs/UnloadController")),
        defaults=(("robotParam", "robot_description"),)),
    # -- ROS 1: hector_gazebo_plugins -----------------------------------------------------
    _ros1("hector_gazebo_ros_imu", entities=(
        Entity("publish", "{topicName}", "sensor_msgs/Imu"),
        Entity("publish", "{biasTopicName}", "sensor_msgs/Imu"),
        Entity("server", "{serviceName}", "std_srvs/Empty"),
        Entity("server", "{topicName}/set_accel_bias", "hector_gazebo_plugins/SetBias"),
        Entity("server", "{topicName}/set_rate_bias", "hector_gazebo_plugins/SetBias")),
        defaults=(("topicName", "imu"), ("biasTopicName", "{topicName}/bias"),
                  ("serviceName", "{topicName}/calibrate"))),
    _ros1("hector_gazebo_ros_gps", entities=(
        Entity("publish", "{topicName}", "sensor_msgs/NavSatFix"),
        Entity("publish", "{velocityTopicName}", "geometry_msgs/Vector3Stamped"),
        Entity("server", "{topicName}/set_reference_geopose",
               "hector_gazebo_plugins/SetReferenceGeoPose")),
        defaults=(("topicName", "fix"), ("velocityTopicName", "fix_velocity"))),
    # -- ROS 2: gazebo_ros_pkgs (ros2) -----------------------------------------------------
    # one plugin for cameras and depth cameras: a <sensor type="depth"> adds the depth
    # image, its info and the point cloud; <triggered> a trigger subscription
    _ros2("gazebo_ros_camera", entities=(
        Entity("publish", "{camera_name}/image_raw", "sensor_msgs/msg/Image",
               transport=True),
        Entity("publish", "{camera_name}/camera_info", "sensor_msgs/msg/CameraInfo"),
        Entity("publish", "{camera_name}/depth/image_raw", "sensor_msgs/msg/Image",
               when="@depth", transport=True),
        Entity("publish", "{camera_name}/depth/camera_info", "sensor_msgs/msg/CameraInfo",
               when="@depth"),
        Entity("publish", "{camera_name}/points", "sensor_msgs/msg/PointCloud2",
               when="@depth"),
        Entity("subscribe", "{camera_name}/image_trigger", "std_msgs/msg/Empty",
               when="triggered", when_default=False)),
        defaults=(("camera_name", "{@sensor}"),)),
    _ros2("gazebo_ros_imu_sensor", entities=(
        Entity("publish", "~/out", "sensor_msgs/msg/Imu"),)),
    # ray sensor: <output_type> chooses the message (PointCloud2 when absent)
    _ros2("gazebo_ros_ray_sensor", entities=(Entity("publish", "~/out", "{output_type}"),),
          defaults=(("output_type", "sensor_msgs/PointCloud2"),)),
    _ros2("gazebo_ros_diff_drive", entities=(*_DRIVE_2, _WHEEL_TF_2)),
    _ros2("gazebo_ros_planar_move", entities=(
        Entity("subscribe", "cmd_vel", "geometry_msgs/msg/Twist"),
        Entity("publish", "odom", "nav_msgs/msg/Odometry", when="publish_odom"),
        Entity("publish", "/tf", "tf2_msgs/msg/TFMessage", when="publish_odom_tf"))),
    _ros2("gazebo_ros_ackermann_drive", entities=(
        *_DRIVE_2, _WHEEL_TF_2,
        Entity("publish", "distance", "std_msgs/msg/Float32", when="publish_distance",
               when_default=False),
        Entity("publish", "steerangle", "std_msgs/msg/Float32", when="publish_steerangle",
               when_default=False))),
    _ros2("gazebo_ros_tricycle_drive", entities=(
        *_DRIVE_2,
        Entity("publish", "joint_states", "sensor_msgs/msg/JointState",
               when="publish_wheel_joint_state", when_default=False))),
    _ros2("gazebo_ros_gps_sensor", entities=(
        Entity("publish", "~/out", "sensor_msgs/msg/NavSatFix"),
        Entity("publish", "~/vel", "geometry_msgs/msg/Vector3Stamped"))),
    _ros2("gazebo_ros_ft_sensor", entities=(
        Entity("publish", "wrench", "geometry_msgs/msg/WrenchStamped"),)),
    _ros2("gazebo_ros_joint_state_publisher", entities=(
        Entity("publish", "joint_states", "sensor_msgs/msg/JointState"),)),
    _ros2("gazebo_ros_p3d", entities=(Entity("publish", "odom", "nav_msgs/msg/Odometry"),)),
    _ros2("gazebo_ros_force", entities=(
        Entity("subscribe", "gazebo_ros_force", "geometry_msgs/msg/Wrench"),)),
    _ros2("gazebo_ros_bumper", entities=(
        Entity("publish", "bumper_states", "gazebo_msgs/msg/ContactsState"),)),
    # gazebo_ros2_control: a controller manager node (controller_manager in the plugin's
    # namespace) that loads the controllers spawners name, as ros2_control_node does
    _ros2("gazebo_ros2_control", entities=(), manager=True,
          partial="the plugin node's own calls (how it reads the description) are not "
                  "in the table"),
)


# The plugins Gazebo classic (version 11) ships in its own ``plugins`` folder, each the
# library ``lib<Name>.so``: model, world, sensor, visual, GUI and system plugins that talk
# Gazebo transport only, never ROS (Gazebo classic does not depend on ROS): a robot
# description loading one (unitree_ros' ``libLinkPlot3DPlugin.so``, a fixed wing's
# ``libLiftDragPlugin.so``) adds nothing to the graph and leaves nothing unknown. Names
# from gz-sim's comparison of Gazebo-classic 11's features, its plugin tables.
GAZEBO_CLASSIC = frozenset({
    # model plugins
    "ActorPlugin", "ActorCollisionsPlugin", "ActuatorPlugin", "ArduCopterPlugin",
    "AttachLightPlugin", "BuoyancyPlugin", "CartDemoPlugin", "CessnaPlugin",
    "DiffDrivePlugin", "ElevatorPlugin", "FlashLightPlugin", "FollowerPlugin",
    "GimbalSmall2dPlugin", "GravityCompensationPlugin", "HarnessPlugin", "HydraDemoPlugin",
    "InitialVelocityPlugin", "JointControlPlugin", "JointTrajectoryPlugin",
    "KeysToCmdVelPlugin", "KeysToJointsPlugin", "LedPlugin", "LiftDragPlugin",
    "LinearBatteryConsumerPlugin", "LinearBatteryPlugin", "LinkPlot3DPlugin", "MudPlugin",
    "PlaneDemoPlugin", "RandomVelocityPlugin", "RegionEventBoxPlugin",
    "SimpleTrackedVehiclePlugin", "SkidSteerDrivePlugin", "SphereAtlasDemoPlugin",
    "TouchPlugin", "TrackedVehiclePlugin", "VariableGearboxPlugin", "VehiclePlugin",
    "WheelSlipPlugin", "WheelTrackedVehiclePlugin",
    # world plugins
    "ArrangePlugin", "ContainPlugin", "HydraPlugin", "JoyPlugin", "MisalignmentPlugin",
    "RubblePlugin", "StaticMapPlugin", "TransporterPlugin", "WindPlugin",
    # sensor plugins
    "BreakableJointPlugin", "CameraPlugin", "ContactPlugin", "DepthCameraPlugin",
    "FiducialCameraPlugin", "ForceTorquePlugin", "GpuRayPlugin", "ImuSensorPlugin",
    "LensFlareSensorPlugin", "PressurePlugin", "RayPlugin", "RaySensorNoisePlugin",
    "SonarPlugin",
    # visual, GUI and system plugins
    "AmbientOcclusionVisualPlugin", "BlinkVisualPlugin", "HeightmapLODPlugin",
    "ShaderParamVisualPlugin", "CessnaGUIPlugin", "KeyboardGUIPlugin", "LookAtDemoPlugin",
    "TimerGUIPlugin", "ModelPropShop", "RestUiPlugin", "RestWebPlugin", "StopWorldPlugin",
})


def classic_builtin(filename: str) -> bool:
    """Whether ``filename`` (``libLiftDragPlugin.so``) is one of Gazebo classic's own
    plugins, which have no ROS interface (``GAZEBO_CLASSIC``)."""
    return library_base(filename) in GAZEBO_CLASSIC


def library_base(filename: str) -> str:
    """A plugin library's name without its folder, ``lib`` and ``.so``
    (``/opt/x/libgazebo_ros_imu.so`` -> ``gazebo_ros_imu``): how a description may name it."""
    base = filename.rsplit("/", 1)[-1]
    base = base[:-3] if base.endswith(".so") else base
    return base[3:] if base.startswith("lib") else base


GZ_PREFIXES = ("gz-sim", "ignition-gazebo", "gz_ros2_control", "ign_ros2_control")
# gz sim systems that are ROS nodes after all (gz_ros2_control starts a controller
# manager, robot/attach.py); the others talk gz transport only
GZ_ROS: dict[str, str] = {}


def gz_system(filename: str) -> str | None:
    """For a gz sim system library: "" (no ROS interface: ros_gz bridges make its gz
    topics ROS topics) or why its ROS interface is not known; None for any other."""
    base = library_base(filename)
    if not base.startswith(GZ_PREFIXES):
        return None
    return GZ_ROS.get(base, "")


def plugin_row(filename: str, ros_version: int) -> Plugin | None:
    """The row of a ``<plugin filename=...>`` (``libgazebo_ros_imu.so`` or ``gazebo_ros_imu``)."""
    base = library_base(filename)
    for row in PLUGINS:
        if row.ros_version == ros_version and base in row.filenames:
            return row
    return None
