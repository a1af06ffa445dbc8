"""ROS 1 message and service definitions, and the C++ headers we synthesise for them.

A synthesised header declares what ``gencpp`` would, as far as parsing node code needs:
the message struct with its fields and constants, ``Ptr`` / ``ConstPtr`` typedefs, and
for a service the ``Request`` / ``Response`` structs. Fields come from the ``.msg`` /
``.srv`` file when we can find it, else from a few well-known definitions below.
"""

from __future__ import annotations

import functools
import json
import os
import re
from dataclasses import dataclass, field

from . import versions

# Packages whose headers are messages or services even when we cannot see their files.
MESSAGE_PACKAGES = frozenset({
    "std_msgs", "std_srvs", "geometry_msgs", "sensor_msgs", "nav_msgs", "actionlib_msgs",
    "diagnostic_msgs", "shape_msgs", "stereo_msgs", "trajectory_msgs", "visualization_msgs",
    "rosgraph_msgs", "tf2_msgs", "map_msgs", "control_msgs", "move_base_msgs", "roscpp",
    "topic_tools", "gazebo_msgs", "pcl_msgs", "dynamic_reconfigure", "mavros_msgs",
    "builtin_interfaces", "example_interfaces", "rcl_interfaces", "action_msgs",
    "lifecycle_msgs", "unique_identifier_msgs", "tf", "turtlesim", "action_tutorials_interfaces",
    "statistics_msgs", "bond",
})

# Definitions for messages that nodes use most, in .msg syntax ("---" splits services).
WELL_KNOWN: dict[str, str] = {
    "std_msgs/Header": "uint32 seq\ntime stamp\nstring frame_id",
    "std_msgs/Empty": "",
    "std_msgs/String": "string data",
    "std_msgs/Bool": "bool data",
    "std_msgs/Byte": "byte data",
    "std_msgs/Char": "char data",
    "std_msgs/Time": "time data",
    "std_msgs/Duration": "duration data",
    "std_msgs/ColorRGBA": "float32 r\nfloat32 g\nfloat32 b\nfloat32 a",
    **{f"std_msgs/{t.capitalize()}": f"{t} data" for t in (
        "int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64",
        "float32", "float64")},
    **{f"std_msgs/{t.capitalize()}MultiArray": f"{t}[] data" for t in (
        "int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64",
        "float32", "float64")},
    "builtin_interfaces/Time": "int32 sec\nuint32 nanosec",
    "builtin_interfaces/Duration": "int32 sec\nuint32 nanosec",
    "tf2_msgs/TFMessage": "geometry_msgs/TransformStamped[] transforms",
    "tf/tfMessage": "geometry_msgs/TransformStamped[] transforms",
    "sensor_msgs/CameraInfo": "Header header\nuint32 height\nuint32 width\n"
                              "string distortion_model\nfloat64[] D\nfloat64[9] K\n"
                              "float64[9] R\nfloat64[12] P",
    # dynamic_reconfigure's service and the messages of its Config (a node that sets
    # another's parameters through its set_parameters service: move_slow_and_clear)
    "dynamic_reconfigure/Reconfigure": "Config config\n---\nConfig config",
    "dynamic_reconfigure/Config": "BoolParameter[] bools\nIntParameter[] ints\n"
                                  "StrParameter[] strs\nDoubleParameter[] doubles\n"
                                  "GroupState[] groups",
    "dynamic_reconfigure/BoolParameter": "string name\nbool value",
    "dynamic_reconfigure/IntParameter": "string name\nint32 value",
    "dynamic_reconfigure/StrParameter": "string name\nstring value",
    "dynamic_reconfigure/DoubleParameter": "string name\nfloat64 value",
    "dynamic_reconfigure/GroupState": "string name\nbool state\nint32 id\nint32 parent",
    # bondcpp's constants: nav2's lifecycle nodes declare the parameter it names
    "bond/Constants": "float32 DEAD_PUBLISH_PERIOD = 0.05\nfloat32 DEFAULT_CONNECT_TIMEOUT = 10.0\n"
                      "float32 DEFAULT_HEARTBEAT_TIMEOUT = 4.0\n"
                      "float32 DEFAULT_DISCONNECT_TIMEOUT = 2.0\n"
                      "float32 DEFAULT_HEARTBEAT_PERIOD = 1.0\n"
                      "string DISABLE_HEARTBEAT_TIMEOUT_PARAM=/bond_disable_heartbeat_timeout",
    "std_srvs/Empty": "---",
    "std_srvs/Trigger": "---\nbool success\nstring message",
    "std_srvs/SetBool": "bool data\n---\nbool success\nstring message",
    "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z",
    "geometry_msgs/Point32": "float32 x\nfloat32 y\nfloat32 z",
    "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z",
    "geometry_msgs/Quaternion": "float64 x\nfloat64 y\nfloat64 z\nfloat64 w",
    "geometry_msgs/Pose": "Point position\nQuaternion orientation",
    "geometry_msgs/Pose2D": "float64 x\nfloat64 y\nfloat64 theta",
    "geometry_msgs/PoseStamped": "Header header\nPose pose",
    "geometry_msgs/PoseWithCovariance": "Pose pose\nfloat64[36] covariance",
    "geometry_msgs/Twist": "Vector3 linear\nVector3 angular",
    "geometry_msgs/TwistStamped": "Header header\nTwist twist",
    "geometry_msgs/TwistWithCovariance": "Twist twist\nfloat64[36] covariance",
    "geometry_msgs/Transform": "Vector3 translation\nQuaternion rotation",
    "geometry_msgs/TransformStamped": "Header header\nstring child_frame_id\n"
                                      "Transform transform",
    "geometry_msgs/PointStamped": "Header header\nPoint point",
    "geometry_msgs/Wrench": "Vector3 force\nVector3 torque",
    "nav_msgs/Odometry": "Header header\nstring child_frame_id\n"
                         "geometry_msgs/PoseWithCovariance pose\n"
                         "geometry_msgs/TwistWithCovariance twist",
    "nav_msgs/Path": "Header header\ngeometry_msgs/PoseStamped[] poses",
    "nav_msgs/GetMap": "---\nnav_msgs/OccupancyGrid map",
    "nav_msgs/SetMap": "nav_msgs/OccupancyGrid map\n"
                       "geometry_msgs/PoseWithCovarianceStamped initial_pose\n---\nbool success",
    "geometry_msgs/PoseWithCovarianceStamped": "Header header\nPoseWithCovariance pose",
    "geometry_msgs/PoseArray": "Header header\nPose[] poses",
    "sensor_msgs/LaserScan": "Header header\nfloat32 angle_min\nfloat32 angle_max\n"
                             "float32 angle_increment\nfloat32 time_increment\n"
                             "float32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
                             "float32[] ranges\nfloat32[] intensities",
    "sensor_msgs/Imu": "Header header\ngeometry_msgs/Quaternion orientation\n"
                       "float64[9] orientation_covariance\n"
                       "geometry_msgs/Vector3 angular_velocity\n"
                       "float64[9] angular_velocity_covariance\n"
                       "geometry_msgs/Vector3 linear_acceleration\n"
                       "float64[9] linear_acceleration_covariance",
    "sensor_msgs/JointState": "Header header\nstring[] name\nfloat64[] position\n"
                              "float64[] velocity\nfloat64[] effort",
    "sensor_msgs/CompressedImage": "Header header\nstring format\nuint8[] data\n",
    "sensor_msgs/Image": "Header header\nuint32 height\nuint32 width\nstring encoding\n"
                         "uint8 is_bigendian\nuint32 step\nuint8[] data",
    # ROS 2 interfaces that demos and examples use most
    "example_interfaces/AddTwoInts": "int64 a\nint64 b\n---\nint64 sum",
    "example_interfaces/Fibonacci": "int32 order\n---\nint32[] sequence\n---\nint32[] sequence",
    "action_tutorials_interfaces/Fibonacci": "int32 order\n---\nint32[] sequence\n---\n"
                                             "int32[] partial_sequence",
    "nav_msgs/MapMetaData": "time map_load_time\nfloat32 resolution\nuint32 width\n"
                            "uint32 height\ngeometry_msgs/Pose origin",
    "nav_msgs/OccupancyGrid": "Header header\nMapMetaData info\nint8[] data",
    "rcl_interfaces/ParameterType": "\n".join(
        f"uint8 PARAMETER_{kind}={number}" for number, kind in enumerate((
            "NOT_SET", "BOOL", "INTEGER", "DOUBLE", "STRING", "BYTE_ARRAY", "BOOL_ARRAY",
            "INTEGER_ARRAY", "DOUBLE_ARRAY", "STRING_ARRAY"))),
    "rcl_interfaces/ParameterValue": "uint8 type\nbool bool_value\nint64 integer_value\n"
                                     "float64 double_value\nstring string_value\n"
                                     "byte[] byte_array_value\nbool[] bool_array_value\n"
                                     "int64[] integer_array_value\n"
                                     "float64[] double_array_value\n"
                                     "string[] string_array_value",
    "rcl_interfaces/Parameter": "string name\nParameterValue value",
    "rcl_interfaces/ParameterEvent": "time stamp\nstring node\nParameter[] new_parameters\n"
                                     "Parameter[] changed_parameters\n"
                                     "Parameter[] deleted_parameters",
    "rcl_interfaces/ListParametersResult": "string[] names\nstring[] prefixes",
    "rcl_interfaces/ListParameters": "uint64 DEPTH_RECURSIVE=0\nstring[] prefixes\n"
                                     "uint64 depth\n---\nListParametersResult result",
    "rcl_interfaces/LoggerLevel": "string name\nuint32 level",
    "rcl_interfaces/SetLoggerLevelsResult": "bool successful\nstring reason",
    "rcl_interfaces/SetLoggerLevels": "LoggerLevel[] levels\n---\n"
                                      "SetLoggerLevelsResult[] results",
    "rcl_interfaces/GetLoggerLevels": "string[] names\n---\nLoggerLevel[] levels",
    "lifecycle_msgs/State": "\n".join(f"uint8 {name}={number}" for name, number in (
        ("PRIMARY_STATE_UNKNOWN", 0), ("PRIMARY_STATE_UNCONFIGURED", 1),
        ("PRIMARY_STATE_INACTIVE", 2), ("PRIMARY_STATE_ACTIVE", 3),
        ("PRIMARY_STATE_FINALIZED", 4), ("TRANSITION_STATE_CONFIGURING", 10),
        ("TRANSITION_STATE_CLEANINGUP", 11), ("TRANSITION_STATE_SHUTTINGDOWN", 12),
        ("TRANSITION_STATE_ACTIVATING", 13), ("TRANSITION_STATE_DEACTIVATING", 14),
        ("TRANSITION_STATE_ERRORPROCESSING", 15))) + "\nuint8 id\nstring label",
    "lifecycle_msgs/Transition": "\n".join(f"uint8 {name}={number}" for name, number in (
        ("TRANSITION_CREATE", 0), ("TRANSITION_CONFIGURE", 1), ("TRANSITION_CLEANUP", 2),
        ("TRANSITION_ACTIVATE", 3), ("TRANSITION_DEACTIVATE", 4),
        ("TRANSITION_UNCONFIGURED_SHUTDOWN", 5), ("TRANSITION_INACTIVE_SHUTDOWN", 6),
        ("TRANSITION_ACTIVE_SHUTDOWN", 7), ("TRANSITION_DESTROY", 8))) + "\nuint8 id\nstring label",
    "lifecycle_msgs/TransitionDescription": "Transition transition\nState start_state\n"
                                            "State goal_state",
    "lifecycle_msgs/TransitionEvent": "uint64 timestamp\nTransition transition\n"
                                      "State start_state\nState goal_state",
    "lifecycle_msgs/ChangeState": "Transition transition\n---\nbool success",
    "lifecycle_msgs/GetState": "---\nState current_state",
    "lifecycle_msgs/GetAvailableStates": "---\nState[] available_states",
    "lifecycle_msgs/GetAvailableTransitions": "---\nTransitionDescription[] "
                                              "available_transitions",
    "statistics_msgs/StatisticDataPoint": "uint8 data_type\nfloat64 data",
    "statistics_msgs/MetricsMessage": "string measurement_source_name\nstring metrics_source\n"
                                      "string unit\ntime window_start\ntime window_stop\n"
                                      "StatisticDataPoint[] statistics",
}

MAX_DEFINITION_DEPTH = 3  # folders below a package's that may hold its definitions


def definition_walk(folder: str) -> dict[str, str]:
    """Every message, service and action definition file of a package folder, by file
    name, a few levels down, not in hidden, test or build folders (rosidl and genmsg take
    them from the folders its CMakeLists lists: slam_toolbox's ``srvs/``,
    tier4_perception_msgs' ``msg/traffic_light/``, autoware_adapi_v1_msgs'
    ``planning/msg/``, kortex_driver's ``msg/generated/actuator_config/``, one
    ``add_message_files(DIRECTORY ...)`` per folder); a name found twice is the first,
    in sorted order."""
    found: dict[str, str] = {}
    for here, dirs, files in os.walk(folder):
        depth = here[len(folder):].count(os.sep)
        dirs[:] = [] if depth >= MAX_DEFINITION_DEPTH else sorted(
            d for d in dirs if not d.startswith(".") and d not in ("test", "build"))
        for file in sorted(files):
            if file.endswith((".msg", ".srv", ".action", ".idl")):
                found.setdefault(file, os.path.join(here, file))
    return found


def definition_files(folder: str, kind: str,
                     walked: dict[str, str] | None = None) -> dict[str, str]:
    """The ``kind`` (msg, srv, action) definition files of a package folder, by file
    name: those of ``definition_walk`` (``walked``, when already made), the ones in
    ``<folder>/<kind>/`` winning over others of the same name."""
    extension = "." + kind
    found = definition_walk(folder) if walked is None else walked
    chosen = {f: p for f, p in found.items() if f.endswith(extension)}
    # an IDL file in the folder of its kind (``msg/Name.idl``) where no definition file
    # of the name is: read as one (``parse_definition``)
    for file, path in found.items():
        named = file[:-len(".idl")] + extension
        if file.endswith(".idl") and os.path.basename(os.path.dirname(path)) == kind:
            chosen.setdefault(named, path)
    own = os.path.join(folder, kind)
    if os.path.isdir(own):
        chosen.update((f, os.path.join(own, f)) for f in os.listdir(own)
                      if f.endswith(extension) and os.path.isfile(os.path.join(own, f)))
    return chosen


# the catalogue of the standard interface packages' definitions, per ROS distribution
# (``haros-arch models interfaces`` writes it from pinned public sources); the default
# of each ROS generation is read when the run names no distribution of that ROS
CATALOGUE = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "models", "interfaces")
CATALOGUE_DISTROS = {False: "noetic", True: "jazzy"}


@functools.lru_cache(maxsize=16)
def catalogue_distro(ros2: bool, distro: str | None = None) -> str:
    """The distribution whose catalogue a parse for ``distro`` reads: its own when one
    is shipped; else, for a distribution of that ROS, the newest shipped one released
    before it (the oldest shipped for one older than all: interface packages drop and
    rename fields over time, so an older release fits older code better); else the
    generation's default (no distribution, or one of the other ROS)."""
    library = versions.RCLCPP if ros2 else versions.ROSCPP
    order = list(library.table)  # the releases in order
    name = (distro or "").strip().lower()
    shipped = [d for d in order
               if os.path.isfile(os.path.join(CATALOGUE, d + ".json"))]
    if name not in order or not shipped:
        return CATALOGUE_DISTROS[ros2]
    earlier = [d for d in shipped if order.index(d) <= order.index(name)]
    return earlier[-1] if earlier else shipped[0]


def catalogue(ros2: bool, distro: str | None = None) -> dict[str, str]:
    """The shipped definitions for ``distro`` (``catalogue_distro``) by
    ``package/kind/Name`` (empty when the file is missing or does not read), with
    those of a package its catalogue has none of from the nearest other release of
    that ROS whose catalogue has it (``_with_others``)."""
    return _with_others(catalogue_distro(ros2, distro))


@functools.lru_cache(maxsize=4)
def _with_others(name: str) -> dict[str, str]:
    """The catalogue of release ``name``, and the packages it has none of from the
    other shipped releases of that ROS, the nearest first (an older before a newer one
    as near): a package the release does not ship (gazebo_msgs, which Jazzy dropped)
    is still the one the tree builds against, whose definitions an installed release
    has (control_quadrupeds_soft_contacts, read as Jazzy's with its files naming Iron
    and Humble, reads ``gazebo_msgs::msg::ModelStates``' ``name`` and ``pose``); a
    field-less stand-in made every use of them a parse error."""
    table = dict(_catalogue_file(name))
    library = versions.RCLCPP if name in versions.RCLCPP.table else versions.ROSCPP
    order = list(library.table)
    if name not in order:
        return table
    others = sorted((d for d in order if d != name and os.path.isfile(
        os.path.join(CATALOGUE, d + ".json"))),
        key=lambda d: (abs(order.index(d) - order.index(name)), order.index(d)))
    packages = {key.split("/", 1)[0] for key in table}
    for other in others:
        added = {key: text for key, text in _catalogue_file(other).items()
                 if key.split("/", 1)[0] not in packages}
        table.update(added)
        packages |= {key.split("/", 1)[0] for key in added}
    return table


@functools.lru_cache(maxsize=4)
def _catalogue_file(name: str) -> dict[str, str]:
    path = os.path.join(CATALOGUE, name + ".json")
    try:
        with open(path, encoding="utf-8") as handle:
            found = json.load(handle).get("definitions")
    except (OSError, ValueError, AttributeError):
        return {}
    if not isinstance(found, dict):
        return {}
    return {k: v for k, v in found.items() if isinstance(k, str) and isinstance(v, str)}


def catalogue_names(ros2: bool, distro: str | None = None) -> dict[str, list[str]]:
    """The type names of the catalogue by package."""
    return _catalogue_names(catalogue_distro(ros2, distro))


@functools.lru_cache(maxsize=4)
def _catalogue_names(name: str) -> dict[str, list[str]]:
    names: dict[str, list[str]] = {}
    for key in _with_others(name):
        package, _kind, type_name = key.split("/", 2)
        names.setdefault(package, []).append(type_name)
    return names


def known(package: str, name: str, ros2: bool = False,
          kinds: tuple[str, ...] = ("msg", "srv"), distro: str | None = None) -> str | None:
    """The definition of ``package/Name`` that does not come from the workspace: the
    shipped catalogue's for ``distro`` (as the installed package has it), else one of
    ``WELL_KNOWN``."""
    table = catalogue(ros2, distro)
    for kind in kinds:
        text = table.get(f"{package}/{kind}/{name}")
        if text is not None:
            return text
    return WELL_KNOWN.get(f"{package}/{name}")


def interface_package(package: str, ros2: bool = False, distro: str | None = None) -> bool:
    """Whether ``package`` is one whose headers are interfaces even unseen."""
    return package in MESSAGE_PACKAGES or package in catalogue_names(ros2, distro)


PRIMITIVES = {
    "bool": "uint8_t", "int8": "int8_t", "uint8": "uint8_t", "byte": "int8_t",
    "char": "uint8_t", "int16": "int16_t", "uint16": "uint16_t", "int32": "int32_t",
    "uint32": "uint32_t", "int64": "int64_t", "uint64": "uint64_t", "float32": "float",
    "float64": "double", "string": "std::string", "time": "ros::Time",
    "duration": "ros::Duration",
}

_STRING_CONSTANT = re.compile(r"^string\s+\w+\s*=")
# ``type[N] name``, ``type NAME=value`` (a constant) or ``type name default`` (ROS 2;
# also its bounded ``string<=N`` and ``type[<=N]``, a sequence of variable length)
_FIELD = re.compile(
    r"^\s*([A-Za-z][\w/]*(?:<=\d+)?)\s*(\[(<=)?(\d*)\])?\s+([A-Za-z]\w*)\s*"
    r"(?:(=\s*(.*))|\s[^=\s].*)?$")


@dataclass(frozen=True)
class Field:
    type: str           # as written: "float64", "Header", "geometry_msgs/Point"
    name: str
    array: str | None   # None, "" (variable length) or the fixed length
    constant: str | None = None


@dataclass
class Interface:
    """A message (one section) or a service (request and response sections)."""

    package: str
    name: str
    sections: list[list[Field]] = field(default_factory=list)
    known: bool = True

    @property
    def is_service(self) -> bool:
        return len(self.sections) == 2


def parse_definition(package: str, name: str, text: str) -> Interface:
    """Fields of a .msg / .srv text (or of the ROS 2 IDL a package may write instead,
    ``idl_definition``); lines that are not fields are ignored."""
    if _IDL_MODULE.search(text):
        text = idl_definition(text, name)
    sections: list[list[Field]] = [[]]
    for raw in text.splitlines():
        line = raw.strip()
        if line.startswith("---"):
            sections.append([])
            continue
        if not _STRING_CONSTANT.match(line):  # only string constants may hold a '#'
            line = line.split("#", 1)[0].strip()
        match = _FIELD.match(line)
        if match is None:
            continue
        kind, array, bounded, size, fname, _, value = match.groups()
        sections[-1].append(Field(kind, fname, None if not array else "" if bounded else size,
                                  value.strip() if value is not None else None))
    return Interface(package, name, sections[:3])


# the ROS 2 IDL a package may write its interfaces in (``msg/Name.idl``: rosidl's OMG IDL
# subset; reference-system's reference_interfaces), read for the same fields
_IDL_MODULE = re.compile(r"^\s*module\s+\w+\s*\{", re.MULTILINE)
_IDL_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)
_IDL_ANNOTATION = re.compile(r"@\w+(?:\s*\((?:[^()]|\([^()]*\))*\))?")
_IDL_STRUCT = re.compile(r"\bstruct\s+(\w+)\s*\{(.*?)\}\s*;", re.DOTALL)
_IDL_CONSTANTS = re.compile(r"\bmodule\s+(\w+)_Constants\s*\{(.*?)\}\s*;", re.DOTALL)
_IDL_CONSTANT = re.compile(r"const\s+(.+?)\s+(\w+)\s*=\s*(.+?)\s*;", re.DOTALL)
_IDL_MEMBER = re.compile(r"(.+?)\s+(\w+)\s*(?:\[\s*(\d+)\s*\])?\s*;", re.DOTALL)
_IDL_TYPES = {
    "boolean": "bool", "octet": "byte", "char": "char", "wchar": "wchar",
    "float": "float32", "double": "float64", "long double": "float64",
    "short": "int16", "unsigned short": "uint16", "long": "int32",
    "unsigned long": "uint32", "long long": "int64", "unsigned long long": "uint64",
    "string": "string", "wstring": "wstring",
}
# the structs of a service's and an action's sections, in order
_IDL_SECTIONS = (("",), ("_Request", "_Response"), ("_Goal", "_Result", "_Feedback"))


def idl_definition(text: str, name: str) -> str:
    """The .msg / .srv / .action text of the interface ``name`` that a ROS 2 IDL file
    defines: the fields of ``struct Name`` (of ``Name_Request`` and ``Name_Response``,
    or ``Name_Goal``, ``Name_Result`` and ``Name_Feedback``, as sections), each IDL type
    as the definition writes it (``double`` float64, ``sequence<T, N>`` ``T[<=N]``,
    ``string<N>`` ``string<=N``, ``pkg::msg::T`` ``pkg/T``, ``T x[N]`` ``T[N] x``),
    and the constants of ``module Name_Constants``; annotations and comments left out."""
    text = _IDL_ANNOTATION.sub(" ", _IDL_COMMENT.sub(" ", text))
    structs = {m.group(1): m.group(2) for m in _IDL_STRUCT.finditer(text)}
    constants = {m.group(1): m.group(2) for m in _IDL_CONSTANTS.finditer(text)}
    suffixes = next((found for found in _IDL_SECTIONS[::-1]
                     if all(name + suffix in structs for suffix in found)), ("",))
    sections: list[str] = []
    for suffix in suffixes:
        lines = [f"{_idl_type(kind)} {const}={value}" for kind, const, value in
                 _IDL_CONSTANT.findall(constants.get(name + suffix, ""))]
        for kind, member, size in _IDL_MEMBER.findall(structs.get(name + suffix, "")):
            written = _idl_type(kind)
            if size:
                written = f"{written}[{size}]"
            lines.append(f"{written} {member}")
        sections.append("\n".join(lines))
    return "\n---\n".join(sections)


def _idl_type(kind: str) -> str:
    kind = " ".join(kind.split())
    match = re.fullmatch(r"sequence\s*<\s*(.+?)\s*(?:,\s*(\d+)\s*)?>", kind)
    if match:
        inner = _idl_type(match.group(1))
        return f"{inner}[<={match.group(2)}]" if match.group(2) else f"{inner}[]"
    match = re.fullmatch(r"(w?string)\s*<\s*(\d+)\s*>", kind)
    if match:
        return f"{match.group(1)}<={match.group(2)}"
    if "::" in kind:
        parts = kind.split("::")
        return f"{parts[0]}/{parts[-1]}"
    return _IDL_TYPES.get(kind, kind)


def dependencies(interface: Interface) -> list[str]:
    """``pkg/Name`` of the message types that the fields use."""
    found: list[str] = []
    for section in interface.sections:
        for fld in section:
            full = qualified(fld.type, interface.package)
            if full is not None and full not in found:
                found.append(full)
    return found


def qualified(kind: str, package: str) -> str | None:
    """``pkg/Name`` of a field type, or None for a primitive."""
    if kind in PRIMITIVES:
        return None
    if kind == "Header":
        return "std_msgs/Header"
    return kind if "/" in kind else f"{package}/{kind}"


# the workspace's packages by name, with their folders (``use_workspace``): ``wire_key``
# reads their own definitions before the catalogue's
_WORKSPACE: dict[str, str] = {}


def use_workspace(roots: dict[str, str]) -> None:
    """Read the definitions of these packages (name: folder) from their folders in
    ``wire_key`` (the queries' model's workspace; a package without a folder, a model
    read back from JSON, is the catalogue's only)."""
    wanted = {name: root for name, root in roots.items() if root}
    if wanted != _WORKSPACE:
        _WORKSPACE.clear()
        _WORKSPACE.update(wanted)
        _workspace_text.cache_clear()
        wire_key.cache_clear()


@functools.lru_cache(maxsize=1024)
def _workspace_text(package: str, name: str, kind: str) -> str | None:
    root = _WORKSPACE.get(package)
    path = definition_files(root, kind).get(f"{name}.{kind}") if root else None
    if path is None:
        return None
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            return handle.read()
    except OSError:
        return None


@functools.lru_cache(maxsize=4096)  # asked per link by the queries; the table is fixed
def wire_key(type_name: str | None, depth: int = 0, kind: str = "msg") -> str | None:
    """What a ROS 1 connection compares for ``pkg/Name``: roscpp and rospy check the
    md5sum, made from the definition (nested types by their own sums), not the name, so
    two names with one definition connect (``tf/tfMessage`` and ``tf2_msgs/TFMessage``;
    a service too, ``kind`` srv: godel's ``godel_msgs/OffsetBoundary`` client of a
    ``godel_polygon_offset/OffsetPolygon`` server, the same request and response). The
    definition, nested types expanded, when every part is one we know (the workspace's,
    ``use_workspace``, else the catalogue's); else the name (ROS 2 names, ``pkg/msg/Name``,
    match by name)."""
    if not type_name or type_name.count("/") != 1 or depth > 8:
        return type_name
    package, name = type_name.split("/", 1)
    text = _workspace_text(package, name, kind)
    if text is None:
        text = known(package, name, kinds=(kind,))
    sections = parse_definition(package, type_name, text).sections if text is not None else []
    if len(sections) != (2 if kind == "srv" else 1):
        return type_name
    keys = []
    for section in sections:
        parts = []
        for fld in section:
            nested = qualified(fld.type, package)
            if nested is None:
                field_kind = fld.type
            else:
                field_kind = wire_key(nested, depth + 1) or nested
                if field_kind == nested:  # a nested type we do not know: no claim
                    return type_name
                field_kind = "{" + field_kind + "}"
            parts.append(f"{field_kind}[{fld.array}] {fld.name}" if fld.array is not None
                         else f"{field_kind} {fld.name}={fld.constant}"
                         if fld.constant is not None else f"{field_kind} {fld.name}")
        keys.append(";".join(parts))
    return "ros1:" + "|".join(keys)


def render(interface: Interface) -> str:
    """C++ source of the header that declares ``interface``."""
    pkg, name = interface.package, interface.name
    guard = f"HAROS_SYNTH_{pkg.upper()}_{name.upper()}_H"
    lines = [f"// synthesised by haros_arch for {pkg}/{name}", f"#ifndef {guard}",
             f"#define {guard}", "#include <stdint.h>", "#include <string>",
             "#include <vector>", "#include <boost/array.hpp>", "#include <boost/shared_ptr.hpp>",
             "#include <ros/time.h>"]
    lines += [f"#include <{dep}.h>" for dep in dependencies(interface)]
    lines.append(f"namespace {pkg} {{")
    if interface.is_service:
        request, response = interface.sections
        lines += _struct(f"{name}Request", request, pkg, interface.known)
        lines += _struct(f"{name}Response", response, pkg, interface.known)
        lines += [template_name(f"{name}Request"), template_name(f"{name}Response")]
        lines += [f"struct {name} {{",
                  f"  typedef {name}Request Request;", f"  typedef {name}Response Response;",
                  "  Request request;", "  Response response;"]
        if not interface.known:
            # a header we know nothing about may name a message as well as a service
            lines += [f"  typedef boost::shared_ptr<{name}> Ptr;",
                      f"  typedef boost::shared_ptr<{name} const> ConstPtr;", "};"]
            lines += _pointers(name)
        else:
            lines.append("};")
    else:
        lines += _struct(name, interface.sections[0] if interface.sections else [], pkg,
                         interface.known)
        lines.append(template_name(name))
    lines += [f"}}  // namespace {pkg}", "#endif", ""]
    return "\n".join(lines)


def fields_hook(qualified: str) -> list[str]:
    """The lines that give a message known only by name the fields the code uses: the
    names the parse learnt (``synthesis.Names``) define a macro of the struct's
    qualified name to their declarations."""
    macro = fields_macro(qualified)
    return [f"#ifdef {macro}", f"  {macro}", "#endif"]


def string_literal(value: str) -> str:
    """``value`` as a C++ string literal: printable ASCII as it is (``\\`` and ``"``
    escaped), every other byte of its UTF-8 as an octal escape. A string constant's
    value (bond's ``DISABLE_HEARTBEAT_TIMEOUT_PARAM``) is then what the parse reads."""
    out = []
    for byte in value.encode("utf-8"):
        char = chr(byte)
        if char in '\\"':
            out.append("\\" + char)
        elif 0x20 <= byte < 0x7F:
            out.append(char)
        else:
            out.append(f"\\{byte:03o}")
    return '"' + "".join(out) + '"'


_INTEGER_TYPES = ("byte", "char", "int8", "uint8", "int16", "uint16", "int32", "uint32",
                  "int64", "uint64")


def constant_value(kind: str, text: str, ros2: bool) -> str | int | float | bool | None:
    """The value a message constant's text (``string NAME = 'core/dvl'``: ``'core/dvl'``)
    has in the generated code; None when it does not read. A ROS 2 string loses one pair
    of outer quotes, ``"`` or ``'``, and the escapes of that quote inside (rosidl_adapter's
    ``parse_primitive_value_string``), and ends at a ``#``, which rosidl reads as a
    comment on any line; ROS 1's genmsg keeps the text as written, quotes and ``#``
    included. Integers (``0x10`` too, as rosidl reads them), floats and booleans are
    themselves."""
    text = text.strip()
    if kind.split("<=")[0] in ("string", "wstring"):
        if ros2:
            # rosidl cuts every line at its first '#', a string constant's too
            text = text.split("#", 1)[0].rstrip()
            for quote in ('"', "'"):
                if len(text) >= 2 and text.startswith(quote) and text.endswith(quote):
                    return text[1:-1].replace("\\" + quote, quote)
        return text
    try:
        if kind in _INTEGER_TYPES:
            return int(text, 0)
        if kind in ("float32", "float64"):
            return float(text)
    except ValueError:
        return None
    if kind == "bool":
        lowered = text.lower()
        return True if lowered in ("true", "1") else False if lowered in ("false", "0") \
            else None
    return None


def fields_macro(qualified: str) -> str:
    return "HAROS_FIELDS_" + qualified.replace("::", "__")


def _struct(name: str, fields: list[Field], package: str, known: bool = True) -> list[str]:
    lines = [f"struct {name} {{", f"  {name}();"]
    if not known:
        lines += fields_hook(f"{package}::{name}")
    for fld in fields:
        cpp = _cpp_type(fld.type, package)
        if fld.constant is not None:
            if cpp == "std::string":
                lines.append(f"  static inline const std::string {fld.name} = "
                             f"{string_literal(fld.constant)};")
            else:
                lines.append(f"  static const {cpp} {fld.name} = {_number(fld.constant)};")
        else:
            if fld.array:  # fixed size: gencpp's boost::array (``float64[9] K``)
                cpp = f"boost::array<{cpp}, {fld.array}>"
            elif fld.array is not None:
                cpp = f"std::vector<{cpp}>"
            # gencpp's typedef of each field's type, which code names (``_buttons_type``)
            lines += [f"  typedef {cpp} _{fld.name}_type;", f"  {cpp} {fld.name};"]
    lines += [f"  typedef boost::shared_ptr<{name}> Ptr;",
              f"  typedef boost::shared_ptr<{name} const> ConstPtr;", "};"]
    return lines + _pointers(name)


def template_name(name: str) -> str:
    """The class template a generator makes a message struct from, named with a trailing
    ``_`` and its allocator as argument (rosidl_generator_cpp's ``template<class
    ContainerAllocator> struct Name_``, ``using Name = Name_<std::allocator<void>>``;
    gencpp's the same with a typedef), as code copied from compiler messages or written
    against the generated headers names it (the Omron AMR's goals_marker.cpp takes a
    ``std::shared_ptr<om_aiv_msg::srv::ArclApi_Request_<std::allocator<void>>>&``): an
    alias template of the synthesised struct, whatever the allocator."""
    return f"template<class ContainerAllocator> using {name}_ = {name};"


def _pointers(name: str) -> list[str]:
    return [f"typedef boost::shared_ptr<{name}> {name}Ptr;",
            f"typedef boost::shared_ptr<{name} const> {name}ConstPtr;"]


def _cpp_type(kind: str, package: str) -> str:
    full = qualified(kind, package)
    return PRIMITIVES[kind] if full is None else full.replace("/", "::")


def _number(text: str) -> str:
    return text if re.fullmatch(r"-?\d+(\.\d*)?([eE]-?\d+)?", text) else "0"


ACTION_PARTS = ("Action", "ActionGoal", "ActionResult", "ActionFeedback", "Goal", "Result",
                "Feedback")


def render_action(interface: Interface) -> str:
    """C++ source of the header that declares ROS 1 action ``interface`` (3 sections):
    ``NameAction``, ``NameGoal`` ... as ``genaction`` makes them, for every part's header."""
    pkg, name = interface.package, interface.name
    sections = [*interface.sections, [], [], []][:3]
    guard = f"HAROS_SYNTH_{pkg.upper()}_{name.upper()}_ACTION_H"
    lines = [f"// synthesised by haros_arch for action {pkg}/{name}", f"#ifndef {guard}",
             f"#define {guard}", "#include <stdint.h>", "#include <string>",
             "#include <vector>", "#include <boost/array.hpp>", "#include <boost/shared_ptr.hpp>",
             "#include <ros/time.h>", "#include <std_msgs/Header.h>"]
    lines += [f"#include <{dep}.h>" for dep in dependencies(interface)]
    lines.append(f"namespace {pkg} {{")
    for part, fields in zip(("Goal", "Result", "Feedback"), sections, strict=True):
        lines += _struct(f"{name}{part}", fields, pkg)
    for part in ("Goal", "Result", "Feedback"):
        wrapper = f"{name}Action{part}"
        lines += _struct(wrapper, [Field("std_msgs/Header", "header", None)], pkg)[:-3]
        lines += [f"  {name}{part} {part.lower()};",
                  f"  typedef {name}{part} _{part.lower()}_type;",
                  f"  typedef boost::shared_ptr<{wrapper}> Ptr;",
                  f"  typedef boost::shared_ptr<{wrapper} const> ConstPtr;", "};"]
        lines += _pointers(wrapper)
    lines += _struct(f"{name}Action", [], pkg)[:-3]
    for part in ("Goal", "Result", "Feedback"):
        lines += [f"  {name}Action{part} action_{part.lower()};",
                  f"  typedef {name}Action{part} _action_{part.lower()}_type;",
                  f"  typedef {name}{part} {part};"]
    lines += [f"  typedef boost::shared_ptr<{name}Action> Ptr;",
              f"  typedef boost::shared_ptr<{name}Action const> ConstPtr;", "};"]
    lines += _pointers(f"{name}Action")
    lines += [template_name(f"{name}{part}") for part in ACTION_PARTS]
    lines += [f"}}  // namespace {pkg}", "#endif", ""]
    return "\n".join(lines)
