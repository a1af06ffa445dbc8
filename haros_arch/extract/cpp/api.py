"""The roscpp API as data: which calls are ROS primitives and where their values are.

Adding an API is adding rows. A row is keyed by the qualified name of the class or
namespace that declares the function and the function's name, as libclang sees the
declaration the call refers to (so the same row serves our stand-in headers and the
real ones).

Type sources (``type_from``), tried in order until one gives a type:

- ``template``: the first explicit template argument of the call
  (``advertise<std_msgs::String>``);
- ``callback``: the first parameter of the callback (``const std_msgs::String::ConstPtr&``);
- ``service-callback``: the first parameter of a service callback, a request type
  (``example::GetCounter::Request&`` or ``GetCounterRequest&``) named by its service;
- ``arg``: the type of the argument at ``type_arg`` (``ros::service::call(name, srv)``);
- ``value``: the C++ type of a parameter's value at ``type_arg``, as a parameter type
  (``double``, ``int``, ``str``, ``bool``);
- ``template-value``: the first explicit template argument as a parameter type
  (``nh.param<std::string>(...)``).
"""

from __future__ import annotations

from dataclasses import dataclass

from ...model.source import CallKind


@dataclass(frozen=True)
class RosFunction:
    """How one roscpp function maps to a primitive call."""

    kind: CallKind
    name_arg: int = 0
    type_from: tuple[str, ...] = ()
    type_arg: int | None = None
    queue_arg: int | None = None
    latch_arg: int | None = None
    callback_arg: int | None = None
    # True when the name is resolved in the namespace of the NodeHandle the call is made on
    on_handle: bool = True


NODE_HANDLE = "ros::NodeHandle"

_PARAM_READ = RosFunction("read", type_from=("value",), type_arg=1)
_PARAM_READ_DEFAULT = RosFunction("read", type_from=("value", "template-value"), type_arg=1)
_PARAM_WRITE = RosFunction("write", type_from=("value",), type_arg=1)

ROSCPP: dict[tuple[str, str], RosFunction] = {
    # topics
    (NODE_HANDLE, "advertise"): RosFunction(
        "publish", type_from=("template",), queue_arg=1, latch_arg=2),
    (NODE_HANDLE, "subscribe"): RosFunction(
        "subscribe", type_from=("template", "callback"), queue_arg=1, callback_arg=2),
    ("ros::topic", "waitForMessage"): RosFunction(
        "subscribe", type_from=("template",), on_handle=False),
    # services
    (NODE_HANDLE, "advertiseService"): RosFunction(
        "server", type_from=("service-callback", "template"), callback_arg=1),
    (NODE_HANDLE, "serviceClient"): RosFunction("client", type_from=("template",)),
    ("ros::service", "createClient"): RosFunction(
        "client", type_from=("template",), on_handle=False),
    ("ros::service", "call"): RosFunction(
        "client", type_from=("arg",), type_arg=1, on_handle=False),
    # parameters through a NodeHandle
    (NODE_HANDLE, "getParam"): _PARAM_READ,
    (NODE_HANDLE, "getParamCached"): _PARAM_READ,
    (NODE_HANDLE, "param"): _PARAM_READ_DEFAULT,
    (NODE_HANDLE, "hasParam"): RosFunction("read"),
    (NODE_HANDLE, "searchParam"): RosFunction("read"),
    (NODE_HANDLE, "setParam"): _PARAM_WRITE,
    (NODE_HANDLE, "deleteParam"): RosFunction("write"),
    # parameters through ros::param
    ("ros::param", "get"): RosFunction("read", type_from=("value",), type_arg=1, on_handle=False),
    ("ros::param", "getCached"): RosFunction(
        "read", type_from=("value",), type_arg=1, on_handle=False),
    ("ros::param", "param"): RosFunction(
        "read", type_from=("value", "template-value"), type_arg=1, on_handle=False),
    ("ros::param", "has"): RosFunction("read", on_handle=False),
    ("ros::param", "search"): RosFunction("read", on_handle=False),
    ("ros::param", "set"): RosFunction("write", type_from=("value",), type_arg=1, on_handle=False),
    ("ros::param", "del"): RosFunction("write", on_handle=False),
}

# Functions that name the node: (scope, function) -> the index of the name argument, for
# each number of written arguments (ros::init(argc, argv, name) and ros::init(remaps, name)).
NODE_NAME: dict[tuple[str, str], dict[int, int]] = {
    ("ros", "init"): {2: 1, 3: 2, 4: 2},
}

# Classes whose objects are node handles, and functions that return a handle in a fixed
# namespace: (scope, function) -> namespace.
HANDLE_CLASSES = frozenset({NODE_HANDLE})
HANDLE_FACTORIES: dict[tuple[str, str], str] = {
    ("nodelet::Nodelet", "getNodeHandle"): "",
    ("nodelet::Nodelet", "getMTNodeHandle"): "",
    ("nodelet::Nodelet", "getPrivateNodeHandle"): "~",
    ("nodelet::Nodelet", "getMTPrivateNodeHandle"): "~",
}
