"""The Python extractor (rospy and rclpy): the primitive calls in one node's modules.

``extract_python(sources, workspace, package=...)`` parses each source with ``ast``
(never imports or runs it), follows imports into modules of the same package, and walks
the code for the calls listed in the API tables (``rospy.ROWS``, ``rclpy.ROWS``,
``rclpy.NODE_METHODS``), resolving names, types and QoS statically (``values``) and
keeping the control statements around each call as conditions (``conditions``).
Problems become diagnostics; nothing here raises for bad input.
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field

from ... import diagnostics as diag
from ... import safe_yaml
from ...diagnostics import Diagnostic
from ...manifest import ros_version
from ...model.conditions import Condition
from ...model.source import PrimitiveCall
from ...models.library import shipped_packages
from ...workspace import Workspace
from .modules import Loader, Module
from .visitor import Walker

__all__ = ["PythonResult", "extract_python"]


@dataclass
class PythonResult:
    """What one node's Python sources give: calls, and the name the node gives itself
    (``rospy.init_node``, ``Node.__init__``, ``rclpy.create_node``)."""

    calls: list[PrimitiveCall] = field(default_factory=list)
    rosname: str | None = None
    diagnostics: list[Diagnostic] = field(default_factory=list)
    namespace: str | None = None
    anonymous: bool = False
    # every fully known name the code gives a node, in the order met (``rosname`` is one)
    names: list[str] = field(default_factory=list)
    # ROS 2: the rclpy nodes the process creates, when several (each call's ``node_name``
    # is one of them, or None when the walk could not tell which node it is made on)
    nodes: list[str] = field(default_factory=list)


def extract_python(sources: list[str], workspace: Workspace, *,
                   package: str | None = None,
                   environment: Mapping[str, str] | None = None,
                   entry: str | None = None) -> PythonResult:
    """The rospy / rclpy calls in the modules ``sources`` (absolute paths) of one node;
    ``environment``: the one its process runs in, when not the workspace's; ``entry``:
    where the program starts (``Node.entry``; None: not known, every function of the
    modules may run)."""
    result = PythonResult()
    root = _package_root(sources, workspace, package)
    loader = Loader(workspace, root)
    if environment is not None:
        loader.environment = environment
    modules: list[Module] = []
    for path in sources:
        module = loader.load(os.path.abspath(path))
        if module is not None and module not in modules:
            modules.append(module)
    loader.node_version = _node_version(modules, workspace, package)
    for loaded in loader.modules.values():
        if loaded is not None:
            loaded.node_version = loader.node_version
    walker = Walker(loader)
    walker.entry = entry
    walker.unseen_packages = _unseen_packages(workspace, package)
    walker.unseen_dependencies = _unseen_packages(workspace, package, declared=True)
    walker.run(modules)
    result.rosname, result.namespace = walker.rosname, walker.namespace
    result.anonymous = walker.anonymous
    result.names = list(walker.names)
    if len(walker.rclpy_names) > 1:  # one process, several ROS 2 nodes
        result.nodes = list(walker.rclpy_names)
    if len(walker.names) > 1:
        outcome = ("each is a node of its own with its own calls" if result.nodes else
                   f"the model keeps '{result.rosname}' and gives it the calls of all")
        result.diagnostics.append(diag.make(
            "PY_SEVERAL_NODES", walker.names_at[1], names=", ".join(walker.names),
            outcome=outcome))
    seen: dict[tuple[object, ...], PrimitiveCall] = {}
    calls = sorted(walker.calls, key=lambda c: (
        c.location.file or "", c.location.line, c.location.column))
    for call in calls:
        if call.node_name not in result.nodes:
            call.node_name = None
    # a call site also reached with its names known does not keep a '?' variant that
    # one of them fits (the site walked with its function's arguments unbound); one no
    # known name fits is a call of its own (a wrapper given "zeros/" + a joint's name),
    # and so is one a parameter's value names (``for joint in sorted([pan, 'tilt'])``)
    known: dict[tuple[object, ...], list[str]] = {}
    for c in calls:
        if "?" not in c.name:
            known.setdefault((c.kind, c.location, c.node_name), []).append(c.name)
    # and one reached with its type known does not keep its unknown type (a call per
    # type is kept where the paths of an if give it different ones)
    typed = {(c.kind, c.name, c.location, c.node_name) for c in calls
             if c.type not in (None, "?")}
    # and a site whose '?' some walk named by a parameter does not keep the walk that
    # named it by nothing (neither a parameter nor a command-line option: its function
    # walked with its arguments unbound)
    linked = {(c.kind, c.name, c.location, c.node_name) for c in calls
              if c.name_param is not None}
    for call in calls:
        # (one named by an option of the command line is not one named otherwise; nor
        # one named by a parameter, one named by another: rbx1's head_tracker.py names
        # a client per joint of ``[pan, tilt]``, two parameters' values)
        key = (call.kind, call.name, call.location, call.node_name, call.type,
               call.name_option, call.name_param, call.name_default)
        if "?" in call.name and call.name_param is None and call.name_option is None \
                and key[:4] in linked:
            continue
        if key in seen:
            # the same call on both paths of an if (a function given a local the paths
            # left different, gazebo_ros' spawn_entity.py's timeout): under neither
            kept = seen[key]
            kept.conditions = _either(kept.conditions, call.conditions)
            continue
        if ("?" in call.name and call.name_param is None and _fitted(call.name, known.get(
                (call.kind, call.location, call.node_name), []))) or (
                call.type == "?" and key[:4] in typed):
            continue
        seen[key] = call
        result.calls.append(call)
        if "?" in call.name:
            result.diagnostics.append(diag.make(
                "PY_DYNAMIC_NAME", call.location, kind=call.kind, name=call.name))
    result.diagnostics[:0] = loader.diagnostics + walker.diagnostics
    return result


def _either(kept: tuple[Condition, ...], other: tuple[Condition, ...],
            ) -> tuple[Condition, ...]:
    """The conditions of a call made under ``kept`` or under ``other``: without the one
    condition they differ in when that is one test's ``if`` and ``else`` (its two paths);
    else ``kept``, as the call first found has them."""
    if len(kept) != len(other):
        return kept
    differ = [at for at, (one, two) in enumerate(zip(kept, other, strict=True))
              if one != two]
    if len(differ) != 1:
        return kept
    one, two = kept[differ[0]], other[differ[0]]
    if {one.statement, two.statement} == {"if", "else"} and (one.text, one.location) == (
            two.text, two.location) and one.kind == two.kind:
        return kept[:differ[0]] + kept[differ[0] + 1:]
    return kept


def _fitted(unknown: str, names: list[str]) -> bool:
    """Whether one of ``names`` is what ``unknown`` may be, each '?' any text."""
    pattern = re.compile(".*".join(re.escape(part) for part in unknown.split("?")))
    return any(pattern.fullmatch(name) for name in names)


PIP_LIBRARIES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pip_libraries.yaml")


def _pip_libraries() -> frozenset[str]:
    """The import names of the Python libraries rosdep installs from PyPI, less released
    ROS packages' names and libraries that talk to ROS (``pip_libraries.yaml``, written
    by bench/pip_libraries.py from a pinned rosdistro commit): a package.xml that names
    one (``<depend>dt_apriltags</depend>``, whose rosdep key is
    ``python-dt-apriltags-pip``) depends on a Python library, not on a ROS package whose
    code is not read."""
    with open(PIP_LIBRARIES, encoding="utf-8") as handle:
        data = safe_yaml.load(handle.read())
    return frozenset(str(name) for name in data["libraries"])


# ROS packages whose Python code makes no ROS call of its own (math, conversions, file
# formats, tools) or whose classes the API tables model (rospy, rclpy, actionlib, tf,
# tf2_ros, message_filters): building one of their classes hides nothing
NOT_CLIENTS = frozenset({
    "rospy", "rclpy", "actionlib", "tf", "tf2_ros", "message_filters", "tf_transformations",
    "tf2_geometry_msgs", "tf2_sensor_msgs", "tf2_kdl", "tf2_py", "tf_conversions",
    "cv_bridge", "image_geometry", "sensor_msgs_py", "laser_geometry", "rospkg", "roslib",
    "rosgraph", "rosbag", "rosbag2_py", "ament_index_python", "launch", "launch_ros",
    "genpy", "rosidl_runtime_py", "rosidl_parser", "python_qt_binding", "qt_gui",
    "qt_gui_py_common", "urdf_parser_py", "urdfdom_py", "xacro", "kdl_parser_py",
    "pykdl_utils", "angles", "smach", "rospy_message_converter", "ros2cli", "ros2topic",
    "rosunit", "rostest", "launch_testing", "launch_testing_ros", "ament_copyright",
    "ament_flake8", "ament_pep257", "pytest", "catkin_pkg",
    # ros_comm's command-line tools' Python APIs, which a node calls to ask the master
    # (``rostopic.get_topic_class(topic)``, ``get_topic_type``; ``rosnode.
    # get_node_names()``, ``kill_nodes``): they make no publisher, subscriber or client
    # of the node's (the Palouse RoboSub histogram.py subscribes itself with the class it
    # gets); not rosservice, whose ``call_service`` is a client
    "rostopic", "rosnode",
    # a map library released into ROS whose Python binding reads, projects and routes
    # maps (``lanelet2.io.Origin``, ``lanelet2.projection.UtmProjector``,
    # ``lanelet2.routing.RoutingGraph``: autoware_mini's planners and detectors)
    "lanelet2",
    # rigid-body dynamics and optimal control libraries released into ROS (the Stack of
    # Tasks' pinocchio, its eigenpy bindings, crocoddyl): an arm's interface builds
    # ``pinocchio.SE3``, ``pinocchio.Motion`` (adl-ros2's fr3_interface)
    "pinocchio", "eigenpy", "crocoddyl",
    # not ROS packages at all: rosdep keys a package.xml may write that name a Python
    # library by the module it imports (rosdep/python.yaml of github:ros/rosdistro
    # 8468e88c: its keys that are modules; pyquaternion, PyPI's, which jsk_fetch_startup
    # names so through a rosdep rule of its own)
    "paramiko", "pika", "rpy2", "yapf", "black", "gunicorn", "virtualenv", "pydocstyle",
    "epydoc", "nuitka", "platformio", "pyquaternion",
    # and the import names of common Python libraries, which package.xml files write
    # for their rosdep keys (navigation2_dynamic's kf_hungarian_tracker depends on
    # ``cv2`` and builds ``cv2.KalmanFilter``: OpenCV, numerical and learning libraries,
    # serial ports and file formats make no ROS call)
    "cv2", "numpy", "scipy", "sklearn", "torch", "matplotlib", "pandas", "PIL", "shapely",
    "pyproj", "open3d", "transforms3d", "serial", "yaml",
    # neural network runtimes (ros2-rover's tractor_bringup depends on ``rknn``, Rockchip's
    # NPU toolkit, and builds ``rknn.api.RKNN``): inference makes no ROS call
    "rknn", "rknnlite", "onnxruntime", "tensorflow", "tflite_runtime",
    # GUI toolkits, by the module they import where their rosdep keys name them
    # otherwise (``pip_libraries.yaml`` holds the keys' names): wxPython is ``wx``
    # (``python-wxtools``, ``python3-wxgtk4.0``: squirrel_robotino's dialog.py builds
    # ``wx.App`` and ``wx.MessageDialog``), Qt's bindings ``PyQt5`` / ``PyQt6`` /
    # ``PySide2`` / ``PySide6`` (``python3-pyqt5``: pip's lower case)
    "wx", "PyQt5", "PyQt6", "PySide2", "PySide6",
}) | _pip_libraries()


# the standard library of the interpreters ROS code was written for that this one's
# ``sys.stdlib_module_names`` lacks: Python 2.7's modules that Python 3 renamed or
# dropped (PEP 3108: a melodic node's ``import tkFont``, ``Queue``, ``urllib2``), and
# those later Python 3 releases removed (PEP 594, 3.12's ``distutils`` and ``imp``),
# which a noetic node run by Python 3.8 imports. They make no ROS call: a class built
# from one hides nothing.
OLDER_STDLIB = frozenset({
    "__builtin__", "_winreg", "anydbm", "BaseHTTPServer", "Bastion", "bsddb",
    "CGIHTTPServer", "commands", "compiler", "ConfigParser", "Cookie", "cookielib",
    "copy_reg", "cPickle", "cStringIO", "dbhash", "dircache", "dl", "DocXMLRPCServer",
    "dumbdbm", "dummy_thread", "exceptions", "fpformat", "future_builtins", "gdbm",
    "htmlentitydefs", "htmllib", "HTMLParser", "httplib", "ihooks", "imageop", "imputil",
    "md5", "mhlib", "mimetools", "MimeWriter", "mimify", "multifile", "mutex", "new",
    "popen2", "posixfile", "Queue", "repr", "rexec", "rfc822", "robotparser",
    "ScrolledText", "sets", "sgmllib", "sha", "SimpleDialog", "SimpleHTTPServer",
    "SimpleXMLRPCServer", "SocketServer", "statvfs", "StringIO", "thread", "Tix",
    "Tkinter", "tkColorChooser", "tkCommonDialog", "Tkconstants", "Tkdnd",
    "tkFileDialog", "tkFont", "tkMessageBox", "tkSimpleDialog", "ttk", "urllib2",
    "urlparse", "user", "UserDict", "UserList", "UserString", "whichdb", "xmllib",
    "xmlrpclib", "FileDialog", "Dialog", "Canvas", "markupbase", "hotshot",
    # removed from Python 3 after 3.8 (noetic's, foxy's): 3.9-3.13
    "_dummy_thread", "dummy_threading", "formatter", "parser", "symbol", "binhex",
    "distutils", "imp", "asynchat",
    "asyncore", "smtpd", "aifc", "audioop", "cgi", "cgitb", "chunk", "crypt", "imghdr",
    "mailcap", "msilib", "nis", "nntplib", "ossaudiodev", "pipes", "sndhdr", "spwd",
    "sunau", "telnetlib", "uu", "xdrlib", "lib2to3",
})


def _unseen_packages(workspace: Workspace, package: str | None,
                     declared: bool = False) -> frozenset[str]:
    """The ROS packages the workspace does not hold whose code may make ROS calls
    (``NOT_CLIENTS`` do not): those the node's package depends on, and (unless
    ``declared``) those the tool knows by a shipped interface model, which a package may
    use without declaring it (tiago_tutorials' tts builds sound_play's SoundClient, a
    publisher of ``robotsound``, and lists only roscpp and rospy)."""
    found = workspace.packages.get(package) if package is not None else None
    if found is None:
        return frozenset()
    names = {d.name for d in found.dependencies}
    if not declared:
        names |= shipped_packages()
    return frozenset(name for name in names
                     if name not in workspace.packages and name not in NOT_CLIENTS)


def _node_version(modules: list[Module], workspace: Workspace, package: str | None) -> int:
    """The ROS version of a node: that of the client library its own modules import,
    else its package's (an entry point whose module only calls the package's ``main``);
    1 when nothing says."""
    versions = {m.client_version for m in modules} - {None}
    if len(versions) == 1:
        return versions.pop() or 1
    if package is not None and package in workspace.packages:
        return ros_version(workspace.packages[package]) or 1
    return 1


def _package_root(sources: list[str], workspace: Workspace, package: str | None) -> str | None:
    if package is not None and package in workspace.packages:
        return workspace.packages[package].root or None
    for path in sources:
        found = workspace.package_of(path)
        if found is not None:
            return found.root or None
    return None
