"""A component, nodelet or plugin runs what its registered class reaches.

An executable with a ``main()`` runs only what ``main()`` reaches of the libraries it
links (``extract.cpp._reached``); a node with no ``main()`` (an rclcpp component, a
nodelet, a plugin) took its files whole: open-rmf's navgraph_visualizer and
schedule_visualizer_node are component executables that link rmf_traffic_ros2's library
and were given the publishers of its schedule writers. Its container constructs the
class its registration names and calls its methods: that class and its bases start the
reach, as ``main()`` does, with the same rules (a class nobody constructs keeps its
calls, a class named beside a parse error keeps them, a class no registration the parse
read names keeps the whole)."""

from __future__ import annotations

from pathlib import Path

import pytest

from haros_arch.extract import extract_nodes
from haros_arch.model.source import Node
from haros_arch.pipeline import read_build_files
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>{name}</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<buildtool_depend>ament_cmake</buildtool_depend>"
           "<depend>rclcpp</depend><depend>rclcpp_components</depend>{depends}"
           "<export><build_type>ament_cmake</build_type></export></package>\n")

# a library of another package: a class that components use (a mirror of the schedule)
# and one that only the library's own factory builds (a writer to the schedule)
TRAFFIC_HPP = """
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
namespace traffic {
class Mirror {
public:
  explicit Mirror(rclcpp::Node & node);
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
class Writer {
public:
  static std::shared_ptr<Writer> make(rclcpp::Node & node);
  explicit Writer(rclcpp::Node & node);
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
void announce(rclcpp::Node & node);
}  // namespace traffic
"""

TRAFFIC_CPP = """
#include "traffic/traffic.hpp"
namespace traffic {
Mirror::Mirror(rclcpp::Node & node) {
  sub_ = node.create_subscription<std_msgs::msg::String>(
    "itinerary", 10, [](std_msgs::msg::String::SharedPtr) {});
}
Writer::Writer(rclcpp::Node & node) {
  pub_ = node.create_publisher<std_msgs::msg::String>("itinerary_set", 10);
}
std::shared_ptr<Writer> Writer::make(rclcpp::Node & node) {
  return std::make_shared<Writer>(node);
}
void announce(rclcpp::Node & node) {
  static auto pub = node.create_publisher<std_msgs::msg::String>("announce", 10);
}
}  // namespace traffic
"""

TRAFFIC_CMAKE = """
cmake_minimum_required(VERSION 3.16)
project(traffic)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
add_library(traffic_ros2 SHARED src/traffic.cpp)
target_include_directories(traffic_ros2 PUBLIC include)
ament_target_dependencies(traffic_ros2 rclcpp)
ament_export_libraries(traffic_ros2)
ament_package()
"""

VIZ_CMAKE = """
cmake_minimum_required(VERSION 3.16)
project(viz)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(rclcpp_components REQUIRED)
find_package(traffic REQUIRED)
add_library(viz_lib SHARED src/visualizers.cpp)
ament_target_dependencies(viz_lib rclcpp rclcpp_components traffic)
rclcpp_components_register_node(viz_lib PLUGIN "viz::NavGraph" EXECUTABLE navgraph)
rclcpp_components_register_node(viz_lib PLUGIN "viz::Schedule" EXECUTABLE schedule)
ament_package()
"""

# two components in one file: the navgraph visualiser mirrors the schedule and announces
# itself (a function of the library), the schedule one also builds a writer, through a
# helper class of its own
VISUALIZERS = """
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "std_msgs/msg/string.hpp"
#include "traffic/traffic.hpp"
namespace viz {
class Base : public rclcpp::Node {
public:
  explicit Base(const std::string & name, const rclcpp::NodeOptions & options)
  : Node(name, options) {
    markers_ = create_publisher<std_msgs::msg::String>(name + "_markers", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr markers_;
};
class NavGraph : public Base {
public:
  explicit NavGraph(const rclcpp::NodeOptions & options)
  : Base("navgraph", options), mirror_(*this) {
    {ANNOUNCE}
  }
  traffic::Mirror mirror_;
};
class Keeper {
public:
  explicit Keeper(rclcpp::Node & node) : writer_(traffic::Writer::make(node)) {}
  std::shared_ptr<traffic::Writer> writer_;
};
class Schedule : public rclcpp::Node {
public:
  explicit Schedule(const rclcpp::NodeOptions & options)
  : Node("schedule", options), mirror_(*this) {
    keeper_ = std::make_shared<Keeper>(*this);
    pub_ = create_publisher<std_msgs::msg::String>("schedule_markers", 10);
  }
  traffic::Mirror mirror_;
  std::shared_ptr<Keeper> keeper_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace viz
RCLCPP_COMPONENTS_REGISTER_NODE(viz::NavGraph)
{REGISTER}
"""


def _nodes(root: Path) -> dict[str, Node]:
    workspace = scan([str(root)])
    nodes: list[Node] = []
    for name in ("traffic", "viz"):
        read_build_files(workspace.packages[name], workspace)
        nodes += [n for n in workspace.packages[name].nodes if n.language == "cpp"]
    extract_nodes(nodes, workspace, cache_dir=None, jobs=1)
    return {n.executable: n for n in nodes if n.package == "viz"}


def _write(write_tree, announce: str = "traffic::announce(*this);",
           register: str = "RCLCPP_COMPONENTS_REGISTER_NODE(viz::Schedule)") -> Path:
    return write_tree({
        "traffic/package.xml": PACKAGE.format(name="traffic", depends=""),
        "traffic/CMakeLists.txt": TRAFFIC_CMAKE,
        "traffic/include/traffic/traffic.hpp": TRAFFIC_HPP,
        "traffic/src/traffic.cpp": TRAFFIC_CPP,
        "viz/package.xml": PACKAGE.format(name="viz", depends="<depend>traffic</depend>"),
        "viz/CMakeLists.txt": VIZ_CMAKE,
        "viz/src/visualizers.cpp": VISUALIZERS.replace("{ANNOUNCE}", announce).replace(
            "{REGISTER}", register),
    })


def _rows(node: Node) -> list[tuple[str, str]]:
    return sorted({(c.kind, c.name) for c in node.calls if c.kind in ("publish",
                                                                      "subscribe")})


NAVGRAPH = [("publish", "announce"), ("publish", "navgraph_markers"),
            ("subscribe", "itinerary")]
SCHEDULE = [("publish", "itinerary_set"), ("publish", "schedule_markers"),
            ("subscribe", "itinerary")]


def test_a_component_runs_what_its_class_reaches(write_tree) -> None:
    """The navgraph component and its executable have their class's calls, its base's,
    and those of the library's code it reaches (the mirror it holds, the function it
    calls), not the other component's of the file, nor the writer only that one's
    helper builds; the schedule component keeps all of its own, the writer too."""
    nodes = _nodes(_write(write_tree))
    for name in ("viz::NavGraph", "navgraph"):
        assert _rows(nodes[name]) == NAVGRAPH, name
        assert nodes[name].rosname == "navgraph" and nodes[name].rosnames == [], name
    for name in ("viz::Schedule", "schedule"):
        assert _rows(nodes[name]) == SCHEDULE, name
        assert nodes[name].rosname == "schedule" and nodes[name].rosnames == [], name


def test_a_class_named_beside_a_parse_error_keeps_its_calls(write_tree) -> None:
    """Where the navgraph constructor's code holds an error the parse could not read,
    a class it names there may be built there: the writer keeps its calls."""
    nodes = _nodes(_write(write_tree, announce="traffic::announce(*this); "
                                               "auto w = traffic::Writer::make(*this, "
                                               "missing_argument);"))
    for name in ("viz::NavGraph", "navgraph"):
        assert _rows(nodes[name]) == sorted([*NAVGRAPH, ("publish", "itinerary_set")]), name
        assert nodes[name].completeness == "partial"


def test_a_class_no_registration_names_keeps_the_whole(write_tree) -> None:
    """A registration the parse does not read (under a build option the parse does not
    define): what its container runs of the file is not known, and every class of it
    keeps its calls, as before."""
    nodes = _nodes(_write(write_tree, register=(
        "#ifdef WITH_SCHEDULE\nRCLCPP_COMPONENTS_REGISTER_NODE(viz::Schedule)\n#endif")))
    for name in ("viz::Schedule", "schedule"):
        assert set(SCHEDULE) | {("publish", "navgraph_markers")} <= set(_rows(nodes[name]))
    # the other registration is read: that component runs what its class reaches
    assert _rows(nodes["viz::NavGraph"]) == NAVGRAPH


def test_class_loaders_own_registration_is_read(write_tree) -> None:
    """class_loader's macro, which rclcpp_components' expands to and some packages
    write themselves (``CLASS_LOADER_REGISTER_CLASS(C, rclcpp_components::
    NodeFactory)``), registers the class as the component macro does: it runs what its
    class reaches, where it kept the whole file (the navgraph markers)."""
    nodes = _nodes(_write(write_tree, register=(
        "#include <class_loader/class_loader.hpp>\n"
        "CLASS_LOADER_REGISTER_CLASS(viz::Schedule, rclcpp_components::NodeFactory)")))
    for name in ("viz::Schedule", "schedule"):
        assert _rows(nodes[name]) == SCHEDULE, name
    assert _rows(nodes["viz::NavGraph"]) == NAVGRAPH


def test_a_nodelet_runs_what_its_class_reaches(write_tree) -> None:
    """ROS 1: two nodelets of one file (a library often exports several) each have
    their own calls and those of the code they reach, not the other's: nothing in the
    node constructs the other class, yet its nodelet manager does, for another node."""
    root = write_tree({
        "lidar/package.xml": (
            "<package format='2'><name>lidar</name><version>1.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
            "<license>BSD</license><buildtool_depend>catkin</buildtool_depend>"
            "<depend>nodelet</depend><depend>roscpp</depend><depend>std_msgs</depend>"
            "<export><nodelet plugin='${prefix}/nodelets.xml'/></export></package>"),
        "lidar/CMakeLists.txt": "project(lidar)\nadd_library(lidar_nodelets src/nodelets.cpp)\n",
        "lidar/nodelets.xml": (
            "<library path='lib/liblidar_nodelets'>\n"
            "<class name='lidar/Driver' type='lidar::Driver' "
            "base_class_type='nodelet::Nodelet'/>\n"
            "<class name='lidar/Cloud' type='lidar::Cloud' "
            "base_class_type='nodelet::Nodelet'/>\n</library>\n"),
        "lidar/src/nodelets.cpp": (
            "#include <nodelet/nodelet.h>\n#include <pluginlib/class_list_macros.h>\n"
            "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
            "namespace lidar {\n"
            "ros::Publisher advertise_status(ros::NodeHandle & nh) {\n"
            "  return nh.advertise<std_msgs::String>(\"status\", 1); }\n"
            "class Driver : public nodelet::Nodelet {\n"
            "  void onInit() override {\n"
            "    pub_ = getNodeHandle().advertise<std_msgs::String>(\"packets\", 1);\n"
            "    status_ = advertise_status(getNodeHandle()); }\n"
            "  ros::Publisher pub_, status_; };\n"
            "class Cloud : public nodelet::Nodelet {\n"
            "  void onInit() override {\n"
            "    pub_ = getNodeHandle().advertise<std_msgs::String>(\"points\", 1); }\n"
            "  ros::Publisher pub_; };\n"
            "}\nPLUGINLIB_EXPORT_CLASS(lidar::Driver, nodelet::Nodelet)\n"
            "PLUGINLIB_EXPORT_CLASS(lidar::Cloud, nodelet::Nodelet)\n"),
    })
    workspace = scan([str(root)])
    read_build_files(workspace.packages["lidar"], workspace)
    nodes = {n.executable: n for n in workspace.packages["lidar"].nodes}
    extract_nodes(list(nodes.values()), workspace, cache_dir=None, jobs=1)
    assert _rows(nodes["lidar/Driver"]) == [("publish", "packets"), ("publish", "status")]
    assert _rows(nodes["lidar/Cloud"]) == [("publish", "points")]


def test_a_gazebo_plugin_runs_what_its_class_reaches(write_tree) -> None:
    """Gazebo classic's ``GZ_REGISTER_MODEL_PLUGIN(C)`` registers the class Gazebo
    constructs, as pluginlib's export does: the plugin runs what that class reaches
    (its ``Load`` and the function it calls), not a class of its file that only a
    function nothing of it calls constructs (the plugin kept its files whole: the
    debugger's publisher too)."""
    root = write_tree({
        "mover/package.xml": (
            "<package format='2'><name>mover</name><version>1.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
            "<license>BSD</license><buildtool_depend>catkin</buildtool_depend>"
            "<depend>gazebo_ros</depend><depend>roscpp</depend><depend>std_msgs</depend>"
            "</package>"),
        "mover/CMakeLists.txt": (
            "project(mover)\nfind_package(gazebo REQUIRED)\n"
            "add_library(mover_plugin src/mover.cpp)\n"),
        "mover/src/mover.cpp": (
            "#include <gazebo/gazebo.hh>\n#include <gazebo/physics/physics.hh>\n"
            "#include <ros/ros.h>\n#include <std_msgs/String.h>\n"
            "namespace mover {\n"
            "class Debugger {\n public:\n  Debugger() {\n    ros::NodeHandle nh;\n"
            "    pub_ = nh.advertise<std_msgs::String>(\"debug\", 1); }\n"
            "  ros::Publisher pub_; };\n"
            "void start_debugger() { static Debugger debugger; }\n"
            "ros::Publisher advertise_status(ros::NodeHandle & nh) {\n"
            "  return nh.advertise<std_msgs::String>(\"status\", 1); }\n"
            "}\nnamespace gazebo {\n"
            "class Mover : public ModelPlugin {\n"
            "public:\n"
            "  void Load(physics::ModelPtr model, sdf::ElementPtr sdf) {\n"
            "    nh_.reset(new ros::NodeHandle(\"mover\"));\n"
            "    pub_ = nh_->advertise<std_msgs::String>(\"odom\", 1);\n"
            "    status_ = mover::advertise_status(*nh_); }\n"
            "  boost::shared_ptr<ros::NodeHandle> nh_;\n"
            "  ros::Publisher pub_, status_; };\n"
            "GZ_REGISTER_MODEL_PLUGIN(Mover)\n}\n"),
    })
    workspace = scan([str(root)])
    read_build_files(workspace.packages["mover"], workspace)
    nodes = {n.executable: n for n in workspace.packages["mover"].nodes}
    assert nodes["mover_plugin"].plugin_class == "Mover"
    extract_nodes(list(nodes.values()), workspace, cache_dir=None, jobs=1)
    assert _rows(nodes["mover_plugin"]) == [("publish", "mover/odom"),
                                            ("publish", "mover/status")]


PLANNER = """
#include <pluginlib/class_list_macros.hpp>
#include <nav2_core/global_planner.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace smac {
class Debugger {
public:
  Debugger() : node_(std::make_shared<rclcpp::Node>("debugger")) {
    pub_ = node_->create_publisher<std_msgs::msg::String>("debug", 1);
  }
  rclcpp::Node::SharedPtr node_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
void start_debugger() { static Debugger debugger; }
struct NodeHybrid {};
template<typename NodeT = NodeHybrid>
class PlannerT : public nav2_core::GlobalPlanner {
public:
  void setup(rclcpp::Node::SharedPtr node) {
    pub_ = node->create_publisher<std_msgs::msg::String>("plan", 1);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
using PlannerHybrid = PlannerT<NodeHybrid>;
}
PLUGINLIB_EXPORT_CLASS(smac::PlannerHybrid, nav2_core::GlobalPlanner)
"""


def test_a_plugin_registered_by_an_alias_runs_what_its_class_reaches(write_tree) -> None:
    """navigation2's smac planners: ``using SmacPlannerHybrid = SmacPlannerHybridT<
    NodeHybrid>;`` and the export (and the plugin description) name the alias. The
    registration names the alias's class: the plugin runs what that class reaches, not
    a class only a function nothing of it calls constructs (it kept its file whole)."""
    root = write_tree({
        "smac/package.xml": PACKAGE.format(name="smac", depends="<depend>pluginlib</depend>"
                                           "<depend>nav2_core</depend>").replace(
            "</export>", '<nav2_core plugin="${prefix}/plugins.xml"/></export>'),
        "smac/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.16)\nproject(smac)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(pluginlib REQUIRED)\n"
            "add_library(smac_planner SHARED src/planner.cpp)\n"
            "pluginlib_export_plugin_description_file(nav2_core plugins.xml)\n"
            "ament_package()\n"),
        "smac/plugins.xml": ('<library path="smac_planner"><class type="smac::PlannerHybrid"'
                             ' base_class_type="nav2_core::GlobalPlanner"/></library>\n'),
        "smac/src/planner.cpp": PLANNER,
    })
    workspace = scan([str(root)])
    read_build_files(workspace.packages["smac"], workspace)
    nodes = {n.executable: n for n in workspace.packages["smac"].nodes}
    extract_nodes(list(nodes.values()), workspace, cache_dir=None, jobs=1)
    assert _rows(nodes["smac::PlannerHybrid"]) == [("publish", "plan")]


SCHEDULE_LIB_HPP = """
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
namespace lib {
class Registry {
public:
  explicit Registry(rclcpp::Node & node);
  class Implementation;
private:
  std::unique_ptr<Implementation> _pimpl;
};
class Negotiation {
public:
  explicit Negotiation(rclcpp::Node & node);
  class Implementation;
private:
  std::unique_ptr<Implementation> _pimpl;
};
}  // namespace lib
"""

SCHEDULE_LIB_CPP = """
#include "lib/schedule.hpp"
namespace lib {
class Registry::Implementation {
public:
  Implementation() {}
};
Registry::Registry(rclcpp::Node &) : _pimpl(std::make_unique<Implementation>()) {}
class Negotiation::Implementation {
public:
  explicit Implementation(rclcpp::Node & node) {
    pub_ = node.create_publisher<std_msgs::msg::String>("negotiation_proposal", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
Negotiation::Negotiation(rclcpp::Node & node)
: _pimpl(std::make_unique<Implementation>(node)) {}
}  // namespace lib
"""

SCHEDULE_MAIN = """
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "lib/schedule.hpp"
class ScheduleNode : public rclcpp::Node {
public:
  ScheduleNode() : Node("schedule") {
    registry_ = std::make_shared<lib::Registry>(*this);
    {ERROR}
    pub_ = create_publisher<std_msgs::msg::String>("negotiation_notice", 10);
  }
  std::shared_ptr<lib::Registry> registry_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ScheduleNode>());
  return 0;
}
"""


# a statement the parse cannot read, which names the library's namespace
UNREAD = "auto version = lib::current_version(*this, missing_argument);"


@pytest.mark.parametrize("error", ["", UNREAD])
def test_a_pimpl_declaration_names_its_own_implementation(write_tree, error) -> None:
    """open-rmf's rmf_traffic_schedule: its node builds a library class whose
    constructor's code is not in the unit (ParticipantRegistry, ``make_shared``), so the
    words of that class's declaration may name what the constructor builds; one is
    ``Implementation``, its own private class. That word kept the calls of every other
    ``X::Implementation`` of the library the executable links (rmf_traffic_ros2's
    Negotiation::Implementation: seven negotiation publishers the schedule node never
    makes). It names the class's own: the Negotiation's publisher goes, also where code
    the parse could not read names the namespace (``lib``), not ``Negotiation``."""
    root = write_tree({
        "lib/package.xml": PACKAGE.format(name="lib", depends=""),
        "lib/CMakeLists.txt": (
            "cmake_minimum_required(VERSION 3.16)\nproject(lib)\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            "add_library(lib_schedule SHARED src/schedule.cpp)\n"
            "target_include_directories(lib_schedule PUBLIC include)\n"
            "ament_target_dependencies(lib_schedule rclcpp)\n"
            "add_executable(schedule src/main.cpp)\n"
            "target_link_libraries(schedule lib_schedule)\nament_package()\n"),
        "lib/include/lib/schedule.hpp": SCHEDULE_LIB_HPP,
        "lib/src/schedule.cpp": SCHEDULE_LIB_CPP,
        "lib/src/main.cpp": SCHEDULE_MAIN.replace("{ERROR}", error),
    })
    workspace = scan([str(root)])
    read_build_files(workspace.packages["lib"], workspace)
    nodes = {n.executable: n for n in workspace.packages["lib"].nodes}
    extract_nodes(list(nodes.values()), workspace, cache_dir=None, jobs=1)
    assert _rows(nodes["schedule"]) == [("publish", "negotiation_notice")]
