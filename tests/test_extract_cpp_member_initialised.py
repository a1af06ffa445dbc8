"""A member of an API class whose construction alone communicates (a diagnostic
updater, tf broadcasters and listeners) is built by default at its declaration only
where a constructor leaves it out of its initialisers: where every constructor
initialises it (or delegates to one that does), the initialiser is its one
construction, as mavros' ``Router`` and ``UAS`` build theirs with ``this``; the
declaration made a second set of calls, of no node."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

ROS2 = """#include <rclcpp/rclcpp.hpp>
#include <diagnostic_updater/diagnostic_updater.hpp>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <tf2_ros/transform_broadcaster.h>

class Router : public rclcpp::Node
{
public:
  explicit Router(const std::string & node_name = "router")
  : Router(rclcpp::NodeOptions(), node_name) {}

  Router(const rclcpp::NodeOptions & options, const std::string & node_name)
  : rclcpp::Node(node_name, options),
    diagnostic_updater(this, 1.0),
    tf2_buffer(get_clock()),
    tf2_listener(tf2_buffer, true),
    tf2_broadcaster(this)
  {
  }

  Router(const Router &) = delete;

  diagnostic_updater::Updater diagnostic_updater;
  tf2_ros::Buffer tf2_buffer;
  tf2_ros::TransformListener tf2_listener;
  tf2_ros::TransformBroadcaster tf2_broadcaster;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Router>());
}
"""

ROS1 = """#include <ros/ros.h>
#include <tf/transform_broadcaster.h>

class Pose
{
public:
  Pose() : nh_("~") {}
  explicit Pose(const ros::NodeHandle & nh) : nh_(nh), br_() {}

private:
  ros::NodeHandle nh_;
  tf::TransformBroadcaster br_;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "pose");
  Pose pose;
  ros::spin();
}
"""


DEFAULT_INITIALISER = """#include <rclcpp/rclcpp.hpp>
#include <diagnostic_updater/diagnostic_updater.hpp>

class Sync : public rclcpp::Node
{
public:
  explicit Sync(const rclcpp::NodeOptions & options);

private:
  diagnostic_updater::Updater diagnostic_updater_{this};
};

Sync::Sync(const rclcpp::NodeOptions & options) : rclcpp::Node("sync", options) {}
"""


def _calls(write_tree, source: str, build_type: str,
           columns: bool = False) -> list[tuple[str, str, int] | tuple[str, str, int, int]]:
    root = write_tree({"pkg/package.xml": package_xml("pkg", build_type),
                       "pkg/src/node.cpp": source})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    if columns:
        return [(c.kind, c.name, c.location.line, c.location.column) for c in result.calls]
    return [(c.kind, c.name, c.location.line) for c in result.calls]


def test_members_every_constructor_initialises_are_built_there_only(write_tree) -> None:
    assert _calls(write_tree, ROS2, "ament_cmake") == [
        ("publish", "/diagnostics", 15),
        ("declare", "diagnostic_updater.period", 15),
        ("declare", "diagnostic_updater.use_fqn", 15),
        ("subscribe", "/tf", 17), ("subscribe", "/tf_static", 17),
        ("publish", "/tf", 18)]


def test_a_member_a_constructor_leaves_out_is_built_at_its_declaration(write_tree) -> None:
    # Pose() leaves br_ out: built by default, at its declaration
    assert _calls(write_tree, ROS1, "catkin") == [("publish", "/tf", 12)]


def test_a_member_with_a_default_initialiser_is_built_once_at_its_declaration(
        write_tree) -> None:
    # Autoware's concatenate_and_time_sync_node.hpp:111 ``Updater diagnostic_updater_{this}``
    # (as on main: units that do not define the constructor must give the same call)
    assert _calls(write_tree, DEFAULT_INITIALISER, "ament_cmake", columns=True) == [
        ("publish", "/diagnostics", 10, 3),
        ("declare", "diagnostic_updater.period", 10, 3),
        ("declare", "diagnostic_updater.use_fqn", 10, 3)]


def test_a_member_with_a_default_initialiser_in_a_unit_without_its_constructor(
        write_tree) -> None:
    header_only = DEFAULT_INITIALISER.replace(
        'Sync::Sync(const rclcpp::NodeOptions & options) : rclcpp::Node("sync", options) {}',
        "")
    assert _calls(write_tree, header_only, "ament_cmake", columns=True) == [
        ("publish", "/diagnostics", 10, 3),
        ("declare", "diagnostic_updater.period", 10, 3),
        ("declare", "diagnostic_updater.use_fqn", 10, 3)]


TEMPLATE = """#include <rclcpp/rclcpp.hpp>
#include <tf2_ros/static_transform_broadcaster.h>

template <typename NodeT>
class StaticFrames
{
public:
  explicit StaticFrames(NodeT * parent) : node(parent), tf_bcast(parent) {}

private:
  NodeT * node;
  tf2_ros::StaticTransformBroadcaster tf_bcast;
};

class Cloud : public rclcpp::Node
{
public:
  Cloud() : rclcpp::Node("cloud"), frames(this) {}

private:
  StaticFrames<rclcpp::Node> frames;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Cloud>());
}
"""


def test_a_member_a_class_template_initialises_with_a_dependent_argument(
        write_tree) -> None:
    """ouster_ros' ``OusterStaticTransformsBroadcaster<NodeT>`` builds its
    ``tf_bcast(parent)`` from a ``NodeT*``: in the template that initialiser calls
    nothing the walk can read, so the declaration stands for the construction (the
    /tf_static publisher of os_cloud and os_driver was lost)."""
    assert _calls(write_tree, TEMPLATE, "ament_cmake") == [("publish", "/tf_static", 12)]
