"""A node that links a library of another workspace package runs that library's code:
ROS 1's ``catkin_LIBRARIES`` (move_base links costmap_2d, whose ``Costmap2DROS`` makes
the costmaps' calls on move_base's node), ROS 2's ``ament_target_dependencies``,
``pkg::target`` and ament_cmake_auto's build dependencies. Only the files whose classes
or functions its code names come along, never one that exports plugin classes."""

from __future__ import annotations

from pathlib import Path

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

ROS1 = {
    "costs/package.xml": package_xml("costs", "catkin"),
    "costs/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(costs)
        find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
        catkin_package(LIBRARIES costs layers)
        add_library(costs src/map_ros.cpp src/unused.cpp)
        target_link_libraries(costs ${catkin_LIBRARIES})
        add_library(layers plugins/layer.cpp)
        """,
    "costs/include/costs/map_ros.h": """
        #include <string>
        #include <ros/ros.h>
        namespace costs {
        class MapROS {
        public:
          explicit MapROS(const std::string& name);
        private:
          ros::Publisher pub_;
          double rate_;
        };
        }
        """,
    "costs/src/map_ros.cpp": """
        #include <costs/map_ros.h>
        #include <std_msgs/String.h>
        namespace costs {
        MapROS::MapROS(const std::string& name)
        {
          ros::NodeHandle private_nh("~/" + name);
          pub_ = private_nh.advertise<std_msgs::String>("costmap", 1);
          private_nh.param("update_rate", rate_, 5.0);
        }
        }
        """,
    "costs/src/unused.cpp": """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        namespace costs {
        class Unused { public: void start(); };
        void Unused::start()
        {
          ros::NodeHandle nh;
          nh.advertise<std_msgs::String>("never", 1);
        }
        }
        """,
    "costs/plugins/layer.cpp": """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        #include <pluginlib/class_list_macros.hpp>
        namespace costs {
        class MapROS;
        class Layer { public: void onInitialize(); };
        void Layer::onInitialize()
        {
          ros::NodeHandle nh("~");
          nh.param("layer_only", 1.0);
        }
        }
        PLUGINLIB_EXPORT_CLASS(costs::Layer, costs::Layer)
        """,
    "planner/package.xml": package_xml("planner", "catkin"),
    "planner/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(planner)
        find_package(catkin REQUIRED COMPONENTS roscpp costs)
        catkin_package()
        add_library(planner src/planner.cpp)
        target_link_libraries(planner ${catkin_LIBRARIES})
        add_executable(planner_node src/planner_node.cpp)
        target_link_libraries(planner_node planner)
        """,
    "planner/src/planner.cpp": """
        #include <ros/ros.h>
        #include <costs/map_ros.h>
        namespace planner {
        class Planner { public: Planner(); costs::MapROS* global_; costs::MapROS* local_; };
        Planner::Planner()
        {
          global_ = new costs::MapROS("global_costmap");
          local_ = new costs::MapROS("local_costmap");
        }
        }
        """,
    "planner/src/planner_node.cpp": """
        #include <ros/ros.h>
        namespace planner { class Planner { public: Planner(); }; }
        int main(int argc, char** argv)
        {
          ros::init(argc, argv, "planner");
          planner::Planner p;
          ros::spin();
        }
        """,
}


def _catkin_library(files: dict[str, str], name: str, source: str, text: str) -> None:
    """A catkin package ``name`` that exports one library built from ``source``."""
    files[f"{name}/package.xml"] = package_xml(name, "catkin")
    files[f"{name}/CMakeLists.txt"] = f"""
        cmake_minimum_required(VERSION 3.0.2)
        project({name})
        find_package(catkin REQUIRED COMPONENTS roscpp)
        catkin_package(LIBRARIES {name})
        add_library({name} {source})
        """
    files[f"{name}/{source}"] = text


def _node(write_tree, files: dict[str, str], package: str, name: str):
    root: Path = write_tree(files)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages[package].nodes if n.executable == name)
    found = extract_nodes([node], ws, cache_dir=None, jobs=1)
    return node, found


def test_catkin_libraries_bring_the_named_files_of_another_package(write_tree) -> None:
    node, _ = _node(write_tree, ROS1, "planner", "planner_node")
    assert node.sources == ["planner/src/planner_node.cpp", "planner/src/planner.cpp",
                            "costs/src/map_ros.cpp"]
    calls = sorted((c.kind, c.name) for c in node.calls)
    # the library's calls, with the names the node's constructions give them
    assert ("publish", "~global_costmap/costmap") in calls
    assert ("publish", "~local_costmap/costmap") in calls
    assert ("read", "~global_costmap/update_rate") in calls
    assert ("read", "~local_costmap/update_rate") in calls
    # a file nothing names and a plugin's file stay out
    assert not any(name in ("never", "~layer_only") for _, name in calls)
    assert node.completeness == "complete"


_EXTRA = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    namespace costs {
    class Extra { public: Extra(); };
    Extra::Extra()
    {
      ros::NodeHandle nh;
      nh.advertise<std_msgs::String>("extra", 1);
    }
    }
    """


def _with_extra_library(catkin_package: str) -> dict[str, str]:
    """ROS1 with a library ``extras`` of costs that planner's code names (costs::Extra),
    and costs' ``catkin_package(...)`` as given."""
    files = dict(ROS1)
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "catkin_package(LIBRARIES costs layers)", catkin_package) + (
        "add_library(extras src/extras.cpp)\n")
    files["costs/src/extras.cpp"] = _EXTRA
    files["planner/src/planner.cpp"] = files["planner/src/planner.cpp"].replace(
        "namespace planner {", "namespace costs { class Extra { public: Extra(); }; }\n"
        "namespace planner {").replace(
        'local_ = new costs::MapROS("local_costmap");',
        'local_ = new costs::MapROS("local_costmap");\n  costs::Extra extra;')
    return files


def test_a_catkin_library_not_exported_is_not_linked(write_tree) -> None:
    # catkin puts in ``catkin_LIBRARIES`` only what catkin_package(LIBRARIES) names:
    # stdr_gui linked stdr_robot, which exports stdr_handle_robot, not the motion
    # controllers' library whose base class subscribes to cmd_vel
    files = _with_extra_library("catkin_package(LIBRARIES costs layers)")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "costs/src/extras.cpp" not in node.sources
    assert "costs/src/map_ros.cpp" in node.sources
    assert ("publish", "extra") not in {(c.kind, c.name) for c in node.calls}


def test_an_exported_library_brings_the_libraries_it_links(write_tree) -> None:
    files = _with_extra_library("catkin_package(LIBRARIES costs layers)")
    files["costs/CMakeLists.txt"] += "target_link_libraries(costs extras)\n"
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "costs/src/extras.cpp" in node.sources
    assert ("publish", "extra") in {(c.kind, c.name) for c in node.calls}


def test_exports_not_known_for_certain_keep_every_library(write_tree) -> None:
    # catkin_package() under an if() not decided, or exporting a value not known:
    # which libraries another package links is not known, none is left out
    for call in ("if(WITH_EXTRAS)\ncatkin_package(LIBRARIES costs extras)\nelse()\n"
                 "catkin_package(LIBRARIES costs)\nendif()",
                 "catkin_package(LIBRARIES costs ${EXTRA_LIBRARIES})"):
        files = _with_extra_library(call)
        node, _ = _node(write_tree, files, "planner", "planner_node")
        assert "costs/src/extras.cpp" in node.sources, call


def test_a_member_initialiser_names_no_function(write_tree) -> None:
    # ``: map_(map)`` from the first column is no free function ``map_``: the planner's
    # own member of that name does not bring the checker's file
    files = dict(ROS1)
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "src/unused.cpp", "src/unused.cpp src/checker.cpp")
    files["costs/src/checker.cpp"] = """
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace costs {
class Checker { public: explicit Checker(int * map); int * map_; };
Checker::Checker(int * map)
: map_(map)
{
  ros::NodeHandle nh;
  nh.advertise<std_msgs::String>("checked", 1);
}
}
"""
    files["planner/src/planner.cpp"] = files["planner/src/planner.cpp"].replace(
        "costs::MapROS* local_; };", "costs::MapROS* local_; int * map_; };")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "costs/src/checker.cpp" not in node.sources
    assert "costs/src/map_ros.cpp" in node.sources


def test_a_package_the_node_does_not_link_brings_nothing(write_tree) -> None:
    files = dict(ROS1)
    files["planner/CMakeLists.txt"] = files["planner/CMakeLists.txt"].replace(
        "roscpp costs", "roscpp")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert node.sources == ["planner/src/planner_node.cpp", "planner/src/planner.cpp"]


def test_the_packages_a_linked_package_links_are_not_followed(write_tree) -> None:
    # a package's own dependencies are its business: costs links probe, planner names
    # probe's class, but only links costs (Autoware's planners declare a test-support
    # package that links the test utilities)
    files = dict(ROS1)
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "roscpp std_msgs", "roscpp std_msgs probe")
    _catkin_library(files, "probe", "src/probe.cpp", """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        namespace probe {
        class Probe { public: void run(); };
        void Probe::run()
        {
          ros::NodeHandle nh;
          nh.advertise<std_msgs::String>("probe", 1);
        }
        }
        """)
    files["planner/src/planner.cpp"] = files["planner/src/planner.cpp"].replace(
        "namespace planner {", "namespace probe { class Probe; }\nnamespace planner {")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "probe/src/probe.cpp" not in node.sources
    assert "costs/src/map_ros.cpp" in node.sources


def test_what_one_linked_package_names_brings_nothing_of_another(write_tree) -> None:
    # planner links costs and testkit; costs' kept file names testkit's function, the
    # planner's code does not (Autoware's route handler and its test utilities)
    files = dict(ROS1)
    files["planner/CMakeLists.txt"] = files["planner/CMakeLists.txt"].replace(
        "roscpp costs", "roscpp costs testkit")
    _catkin_library(files, "testkit", "src/fake.cpp", """
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace testkit {
void publish_fake_map(ros::NodeHandle & nh)
{
  nh.advertise<std_msgs::String>("fake_map", 1);
}
}
""")
    files["costs/src/map_ros.cpp"] = files["costs/src/map_ros.cpp"].replace(
        "namespace costs {",
        "// see testkit::publish_fake_map for tests\n        namespace costs {")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "costs/src/map_ros.cpp" in node.sources
    assert "testkit/src/fake.cpp" not in node.sources


def test_a_class_the_node_defines_itself_is_its_own(write_tree) -> None:
    # opennav_following defines its own ParameterHandler; opennav_docking, which it
    # links, has one of the same name whose reads are not the follower's
    files = dict(ROS1)
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "src/unused.cpp", "src/unused.cpp src/handler.cpp")
    files["costs/src/handler.cpp"] = """
#include <ros/ros.h>
namespace costs {
class ParameterHandler { public: ParameterHandler(); };
ParameterHandler::ParameterHandler()
{
  ros::NodeHandle nh("~");
  nh.param("dock_backwards", false);
}
}
"""
    # declared in the planner's own header, defined in its source
    files["planner/include/planner/handler.h"] = """
        namespace planner { class ParameterHandler { public: ParameterHandler(); }; }
        """
    files["planner/src/planner.cpp"] = files["planner/src/planner.cpp"].replace(
        "namespace planner {", "#include <planner/handler.h>\n"
        "        planner::ParameterHandler::ParameterHandler() {}\n"
        "        namespace planner {")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "costs/src/handler.cpp" not in node.sources
    assert "costs/src/map_ros.cpp" in node.sources


def test_a_linked_file_without_ros_code_stays_out(write_tree) -> None:
    # mavros' libmavconn: a serial link the node names, with no ROS call to give (its
    # parse errors would only make the node look partial)
    files = dict(ROS1)
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "src/unused.cpp", "src/unused.cpp src/serial.cpp")
    files["costs/src/serial.cpp"] = """
#include <string>
namespace costs {
class Serial { public: bool open(const std::string & device); };
bool Serial::open(const std::string & device)
{
  return !device.empty();
}
}
"""
    files["planner/src/planner.cpp"] = files["planner/src/planner.cpp"].replace(
        "costs::MapROS* local_; };", "costs::MapROS* local_; costs::Serial * link_; };")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "costs/src/serial.cpp" not in node.sources
    assert "costs/src/map_ros.cpp" in node.sources


def test_the_client_library_in_the_workspace_is_not_followed(write_tree) -> None:
    # roscpp built from source beside the node: its API is the extractor's tables, its
    # insides (its own reads at init) are no call of the node
    files = dict(ROS1)
    _catkin_library(files, "roscpp", "src/libros/init.cpp", """
#include <ros/ros.h>
namespace ros {
void init(int& argc, char** argv, const std::string& name)
{
  bool sim = false;
  ros::param::get("/use_sim_time", sim);
}
}
""")
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "roscpp/src/libros/init.cpp" not in node.sources
    assert "costs/src/map_ros.cpp" in node.sources


ROS2 = {
    "vehicle_info/package.xml": package_xml("vehicle_info", "ament_cmake"),
    "vehicle_info/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(vehicle_info)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        add_library(vehicle_info SHARED src/vehicle_info.cpp)
        ament_target_dependencies(vehicle_info rclcpp)
        ament_export_libraries(vehicle_info)
        ament_package()
        """,
    "vehicle_info/include/vehicle_info/vehicle_info.hpp": """
        #include "rclcpp/rclcpp.hpp"
        namespace vehicle_info {
        class VehicleInfoUtils {
        public:
          explicit VehicleInfoUtils(rclcpp::Node & node);
          double wheel_radius;
        };
        }
        """,
    "vehicle_info/src/vehicle_info.cpp": """
        #include "vehicle_info/vehicle_info.hpp"
        namespace vehicle_info {
        VehicleInfoUtils::VehicleInfoUtils(rclcpp::Node & node)
        {
          wheel_radius = node.declare_parameter<double>("wheel_radius");
        }
        }
        """,
    "controller/package.xml": package_xml("controller", "ament_cmake"),
    "controller/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(controller)
        find_package(ament_cmake REQUIRED)
        find_package(rclcpp REQUIRED)
        find_package(vehicle_info REQUIRED)
        add_executable(controller src/controller.cpp)
        ament_target_dependencies(controller rclcpp vehicle_info)
        ament_package()
        """,
    "controller/src/controller.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "vehicle_info/vehicle_info.hpp"
        class Controller : public rclcpp::Node {
        public:
          Controller() : rclcpp::Node("controller") {
            vehicle_info::VehicleInfoUtils info(*this);
            declare_parameter<double>("gain", 1.0);
          }
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<Controller>());
        }
        """,
}


def test_ament_dependencies_bring_the_constructor_given_the_node(write_tree) -> None:
    node, _ = _node(write_tree, ROS2, "controller", "controller")
    assert "vehicle_info/src/vehicle_info.cpp" in node.sources
    assert sorted(c.name for c in node.calls if c.kind == "declare") == [
        "gain", "wheel_radius"]
    # the class given the node is read with it: nothing hidden, the node complete
    assert node.completeness == "complete", node.completeness_reasons


def test_without_the_library_the_node_given_away_is_partial(write_tree) -> None:
    files = dict(ROS2)
    files["controller/CMakeLists.txt"] = files["controller/CMakeLists.txt"].replace(
        "rclcpp vehicle_info)", "rclcpp)")
    node, found = _node(write_tree, files, "controller", "controller")
    assert "vehicle_info/src/vehicle_info.cpp" not in node.sources
    assert any(d.code == "CPP_NODE_PASSED" for d in found)
    assert node.completeness == "partial"


def test_find_package_and_link_forms_name_packages(write_tree) -> None:
    root: Path = write_tree({
        "p/package.xml": package_xml("p", "ament_cmake"),
        "p/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.8)
            project(p)
            find_package(catkin REQUIRED COMPONENTS a b OPTIONAL_COMPONENTS c)
            find_package(d REQUIRED)
            add_library(lib src/x.cpp)
            add_executable(one src/x.cpp)
            target_link_libraries(one PRIVATE lib ${catkin_LIBRARIES} ${d_LIBRARIES} e::core)
            add_executable(two src/x.cpp)
            ament_target_dependencies(two f SYSTEM g)
            """,
        "p/src/x.cpp": "int main() {}\n",
    })
    ws = scan([str(root)])
    targets = {t.name: t for t in cmake.targets_of(ws.packages["p"], ws)[0]}
    assert targets["one"].links == ["lib"]
    assert targets["one"].packages == ["a", "b", "c", "d", "e"]
    assert targets["two"].packages == ["f", "g"]


NODES = {
    "util/package.xml": package_xml("util", "ament_cmake"),
    "util/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(util)
        find_package(rclcpp_lifecycle REQUIRED)
        add_library(util_core SHARED src/lifecycle_node.cpp src/costmap_ros.cpp
                    src/publisher.cpp)
        ament_export_targets(util_core)
        ament_package()
        """,
    "util/include/util/lifecycle_node.hpp": """
        #include "rclcpp_lifecycle/lifecycle_node.hpp"
        namespace util {
        class LifecycleNode : public rclcpp_lifecycle::LifecycleNode {
        public:
          explicit LifecycleNode(const std::string & name);
        };
        }
        """,
    "util/src/lifecycle_node.cpp": """
        #include "util/lifecycle_node.hpp"
        namespace util {
        LifecycleNode::LifecycleNode(const std::string & name)
        : rclcpp_lifecycle::LifecycleNode(name)
        {
          declare_parameter("bond_heartbeat_period", 0.1);
        }
        }
        """,
    "util/include/util/costmap_ros.hpp": """
        #include "util/lifecycle_node.hpp"
        #include "util/publisher.hpp"
        namespace util {
        class CostmapROS : public util::LifecycleNode {
        public:
          explicit CostmapROS(const std::string & name);
          CostmapPublisher * publisher_;
        };
        }
        """,
    "util/src/costmap_ros.cpp": """
        #include "util/costmap_ros.hpp"
        namespace util {
        CostmapROS::CostmapROS(const std::string & name)
        : util::LifecycleNode(name)
        {
          declare_parameter("resolution", 0.05);
          publisher_ = new CostmapPublisher(this);
        }
        }
        """,
    "util/include/util/publisher.hpp": """
        #include "rclcpp_lifecycle/lifecycle_node.hpp"
        namespace util {
        class CostmapPublisher {
        public:
          explicit CostmapPublisher(rclcpp_lifecycle::LifecycleNode * node);
        };
        }
        """,
    "util/src/publisher.cpp": """
        #include "util/publisher.hpp"
        #include "std_msgs/msg/string.hpp"
        namespace util {
        CostmapPublisher::CostmapPublisher(rclcpp_lifecycle::LifecycleNode * node)
        {
          node->create_publisher<std_msgs::msg::String>("costmap", 1);
        }
        }
        """,
    "server/package.xml": package_xml("server", "ament_cmake"),
    "server/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(server)
        find_package(util REQUIRED)
        add_executable(server src/server.cpp)
        target_link_libraries(server util::util_core)
        ament_package()
        """,
    "server/src/server.cpp": """
        #include "util/lifecycle_node.hpp"
        #include "util/costmap_ros.hpp"
        class Server : public util::LifecycleNode {
        public:
          Server() : util::LifecycleNode("server") {
            costmap_ = std::make_shared<util::CostmapROS>("global_costmap");
          }
          std::shared_ptr<util::CostmapROS> costmap_;
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<Server>()->get_node_base_interface());
        }
        """,
}


def test_a_linked_class_that_is_a_node_of_its_own_stays_out(write_tree) -> None:
    node, _ = _node(write_tree, NODES, "server", "server")
    # the node's own base class runs on it; the costmap node (and what only it names)
    # makes its calls on itself: its host's business, not this node's
    assert node.sources == ["server/src/server.cpp", "util/src/lifecycle_node.cpp"]
    assert [c.name for c in node.calls if c.kind == "declare"] == ["bond_heartbeat_period"]
    assert "costmap" not in {c.name for c in node.calls}


def test_a_linked_node_class_main_builds_is_a_node_of_the_process(write_tree) -> None:
    """PlanSys2's plansys2_node: ``main()`` makes ``std::make_shared<plansys2::
    DomainExpertNode>()``, ``ProblemExpertNode``, ``PlannerNode`` and ``ExecutorNode``,
    classes of four other packages' libraries it links, and spins them in one executor.
    Each is a node of its own, so their files were left out as their host's business:
    plansys2_node had no call at all and was complete, the whole PlanSys2 core missing
    from the graph. A class the program's own ``main()`` builds is one of its nodes."""
    files = dict(NODES)
    # a file naming the client library (a file that names none makes no call)
    files["util/src/costmap_ros.cpp"] = NODES["util/src/costmap_ros.cpp"].replace(
        'declare_parameter("resolution", 0.05);',
        'declare_parameter("resolution", 0.05);\n          '
        'RCLCPP_INFO(rclcpp::get_logger("costmap"), "made");')
    files["server/src/server.cpp"] = """
        #include "util/lifecycle_node.hpp"
        #include "util/costmap_ros.hpp"
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::executors::MultiThreadedExecutor exe;
          auto costmap = std::make_shared<util::CostmapROS>("global_costmap");
          auto other = std::make_shared<util::LifecycleNode>("other");
          exe.add_node(costmap->get_node_base_interface());
          exe.add_node(other->get_node_base_interface());
          exe.spin();
        }
        """
    node, _ = _node(write_tree, files, "server", "server")
    assert "util/src/costmap_ros.cpp" in node.sources
    assert "costmap" in {c.name for c in node.calls}
    assert "resolution" in {c.name for c in node.calls if c.kind == "declare"}


def test_a_component_class_main_builds_is_run_with_its_registering_file(write_tree) -> None:
    """zed_debug's ``zed_debug_proc``: ``main()`` makes ``std::make_shared<stereolabs::
    ZedCamera>(options)`` of zed_components' library, whose constructor is in the file
    that also registers the class as a component (``RCLCPP_COMPONENTS_REGISTER_NODE``).
    A file that exports a class was left out of every program that links it (a loader
    runs it, not the link), so the node had the camera's other files' calls and none
    of its constructor's (264 calls of 728). A class the program's own ``main()`` builds
    runs in it by construction, whatever else its file registers."""
    files = dict(NODES)
    files["util/src/costmap_ros.cpp"] = NODES["util/src/costmap_ros.cpp"].replace(
        'declare_parameter("resolution", 0.05);',
        'declare_parameter("resolution", 0.05);\n          '
        'RCLCPP_INFO(rclcpp::get_logger("costmap"), "made");') + """
        #include "rclcpp_components/register_node_macro.hpp"
        RCLCPP_COMPONENTS_REGISTER_NODE(util::CostmapROS)
        """
    files["server/src/server.cpp"] = """
        #include "util/costmap_ros.hpp"
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto costmap = std::make_shared<util::CostmapROS>("global_costmap");
          rclcpp::spin(costmap->get_node_base_interface());
        }
        """
    node, _ = _node(write_tree, files, "server", "server")
    assert "util/src/costmap_ros.cpp" in node.sources
    assert "resolution" in {c.name for c in node.calls if c.kind == "declare"}
    # a component main() does not build stays its loader's business
    files["server/src/server.cpp"] = files["server/src/server.cpp"].replace(
        "std::make_shared<util::CostmapROS>", "std::make_shared<util::LifecycleNode>")
    node, _ = _node(write_tree, files, "server", "server")
    assert "util/src/costmap_ros.cpp" not in node.sources


def test_a_nodelet_runs_the_named_files_of_another_package_it_links(write_tree) -> None:
    # mrs_uav_managers' nodelets (plugin classes of a library target linking
    # catkin_LIBRARIES) build mrs_lib's Profiler, which advertises "profiler": the
    # library's file was not read for them, as it was for an executable or a component
    files = {key: value for key, value in ROS1.items() if not key.startswith("planner/")}
    files["manager/package.xml"] = package_xml("manager", "catkin").replace(
        "</export>", "<nodelet plugin=\"${prefix}/nodelets.xml\"/></export>")
    files["manager/nodelets.xml"] = (
        '<library path="lib/libmanager">\n'
        '  <class name="manager/Manager" type="manager::Manager"'
        ' base_class_type="nodelet::Nodelet"/>\n'
        "</library>\n")
    files["manager/CMakeLists.txt"] = """
        cmake_minimum_required(VERSION 3.0.2)
        project(manager)
        find_package(catkin REQUIRED COMPONENTS roscpp nodelet costs)
        catkin_package()
        add_library(manager src/manager.cpp)
        target_link_libraries(manager ${catkin_LIBRARIES})
        """
    files["manager/src/manager.cpp"] = """
        #include <ros/ros.h>
        #include <nodelet/nodelet.h>
        #include <pluginlib/class_list_macros.h>
        #include <costs/map_ros.h>
        namespace manager {
        class Manager : public nodelet::Nodelet {
          void onInit() { map_ = new costs::MapROS("map"); }
          costs::MapROS* map_;
        };
        }
        PLUGINLIB_EXPORT_CLASS(manager::Manager, nodelet::Nodelet)
        """
    node, _ = _node(write_tree, files, "manager", "manager/Manager")
    assert node.sources == ["manager/src/manager.cpp", "costs/src/map_ros.cpp"]
    calls = sorted((c.kind, c.name) for c in node.calls)
    assert calls == [("publish", "~map/costmap"), ("read", "~map/update_rate")]
    assert node.completeness == "complete"


def test_a_plugin_runs_the_classes_it_builds_of_another_package(write_tree) -> None:
    # dwa_local_planner's DWAPlannerROS holds base_local_planner's OdometryHelperRos by
    # value (its constructor subscribes to odom) and is handed move_base's costmap: the
    # helper's file runs in the plugin, the costmap's (its builder's calls) does not
    files = {key: value for key, value in ROS1.items() if not key.startswith("planner/")}
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "src/unused.cpp", "src/unused.cpp src/odometry.cpp")
    files["costs/include/costs/odometry.h"] = """
        #include <string>
        #include <ros/ros.h>
        namespace costs {
        class Odometry {
        public:
          explicit Odometry(const std::string& topic);
          void setTopic(const std::string& topic);
        private:
          ros::Subscriber sub_;
        };
        }
        """
    files["costs/src/odometry.cpp"] = """
        #include <costs/odometry.h>
        #include <std_msgs/String.h>
        namespace costs {
          void received(const std_msgs::String::ConstPtr& message) {}

          Odometry::Odometry(const std::string& topic) { setTopic(topic); }

          void Odometry::setTopic(const std::string& topic) {
            ros::NodeHandle nh;
            sub_ = nh.subscribe<std_msgs::String>(topic, 1, received);
          }
        }
        """
    files["local/package.xml"] = package_xml("local", "catkin").replace(
        "</export>", "<nav_core plugin=\"${prefix}/plugins.xml\"/></export>")
    files["local/plugins.xml"] = (
        '<library path="lib/liblocal">\n'
        '  <class name="local/Local" type="local::Local"'
        ' base_class_type="nav_core::BaseLocalPlanner"/>\n'
        "</library>\n")
    files["local/CMakeLists.txt"] = """
        cmake_minimum_required(VERSION 3.0.2)
        project(local)
        find_package(catkin REQUIRED COMPONENTS roscpp nav_core costs)
        catkin_package()
        add_library(local src/local.cpp)
        target_link_libraries(local ${catkin_LIBRARIES})
        """
    files["local/src/local.cpp"] = """
        #include <ros/ros.h>
        #include <nav_core/base_local_planner.h>
        #include <pluginlib/class_list_macros.h>
        #include <costs/map_ros.h>
        #include <costs/odometry.h>
        namespace local {
        class Local : public nav_core::BaseLocalPlanner {
        public:
          Local() : odometry_("odom") {}
          void initialize(std::string name, costs::MapROS* costmap) { costmap_ = costmap; }
        private:
          costs::Odometry odometry_;
          costs::MapROS* costmap_;
        };
        }
        PLUGINLIB_EXPORT_CLASS(local::Local, nav_core::BaseLocalPlanner)
        """
    node, _ = _node(write_tree, files, "local", "local/Local")
    assert node.sources == ["local/src/local.cpp", "costs/src/odometry.cpp"]
    assert sorted((c.kind, c.name) for c in node.calls) == [("subscribe", "odom")]
    assert node.completeness == "complete"


def test_a_class_of_the_plugins_own_package_named_unqualified_is_its_own(
        write_tree) -> None:
    # nav2's RotationShimController builds ``std::make_unique<ParameterHandler>(...)``,
    # its own package's class, in its namespace: nav2_controller's class of that name
    # (a linked package) ran in it, 48 calls of the controller server's parameters
    files = {key: value for key, value in ROS1.items() if not key.startswith("planner/")}
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "src/unused.cpp", "src/unused.cpp src/handler.cpp")
    files["costs/src/handler.cpp"] = """
        #include <ros/ros.h>
        namespace costs {
          Handler::Handler() { ros::NodeHandle nh("~"); nh.param("frequency", f_, 20.0); }
        }
        """
    files["local/package.xml"] = package_xml("local", "catkin").replace(
        "</export>", "<nav_core plugin=\"${prefix}/plugins.xml\"/></export>")
    files["local/plugins.xml"] = (
        '<library path="lib/liblocal">\n'
        '  <class name="local/Local" type="local::Local"'
        ' base_class_type="nav_core::BaseLocalPlanner"/>\n'
        "</library>\n")
    files["local/CMakeLists.txt"] = """
        cmake_minimum_required(VERSION 3.0.2)
        project(local)
        find_package(catkin REQUIRED COMPONENTS roscpp nav_core costs)
        catkin_package()
        add_library(local src/local.cpp src/handler.cpp)
        target_link_libraries(local ${catkin_LIBRARIES})
        """
    files["local/src/handler.cpp"] = """
        #include <ros/ros.h>
        namespace local {
          Handler::Handler() { ros::NodeHandle nh("~"); nh.param("angular_dist", d_, 0.7); }
        }
        """
    files["local/src/local.cpp"] = """
        #include <memory>
        #include <ros/ros.h>
        #include <nav_core/base_local_planner.h>
        #include <pluginlib/class_list_macros.h>
        namespace local {
        class Handler { public: Handler(); double d_; };
        class Local : public nav_core::BaseLocalPlanner {
        public:
          void initialize(std::string name) { handler_ = std::make_unique<Handler>(); }
        private:
          std::unique_ptr<Handler> handler_;
        };
        }
        PLUGINLIB_EXPORT_CLASS(local::Local, nav_core::BaseLocalPlanner)
        """
    node, _ = _node(write_tree, files, "local", "local/Local")
    assert "costs/src/handler.cpp" not in node.sources


def test_a_member_named_in_an_expression_is_no_definition(tmp_path) -> None:
    # mavros' imu.cpp writes ``cond ? Eigen::Vector3d::Zero() : v) {``: no member of a
    # Vector3d defined there, so a plugin holding a Vector3d does not run that file
    from haros_arch.model.location import Location
    from haros_arch.plugins.inherit import _defines

    class Files:
        root = str(tmp_path)

        def location(self, path, line=0, column=0):
            return Location(None, path, line, column)

    (tmp_path / "a.cpp").write_text(
        "namespace costs {\n"
        "  Odometry::Odometry(const std::string& topic) : topic_(topic) {\n  }\n"
        "  void Odometry::setTopic(const std::string& t)\n  {\n  }\n"
        "  bool Grid::ready() const { return true; }\n"
        "  void use(bool c) {\n"
        "    if (c ? Eigen::Vector3d::Zero() : other) {\n    }\n"
        "    Helper::call(x);\n"
        "    return Maker::make(a) ;\n  }\n"
        "}\n")
    assert _defines("a.cpp", Files()) == {"Odometry", "Grid"}


def test_a_library_linked_by_its_alias_is_linked(write_tree) -> None:
    """navigation2's nav2_costmap_2d (humble 3c3db59d nav2_costmap_2d/CMakeLists.txt:33-48,
    145-154): ``add_library(${PROJECT_NAME}::nav2_costmap_2d_core ALIAS
    nav2_costmap_2d_core)``, then the costmap node links
    ``${PROJECT_NAME}::nav2_costmap_2d_core``, whose Costmap2DROS its main makes. The alias
    was dropped and the link read as the package itself: the node had none of the
    costmap's calls, and its model said it whole."""
    root: Path = write_tree({
        "p/package.xml": package_xml("p", "ament_cmake"),
        "p/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.8)
            project(p)
            add_library(core SHARED src/x.cpp)
            add_library(${PROJECT_NAME}::core ALIAS core)
            add_library(again ALIAS p::core)
            add_executable(node src/x.cpp)
            target_link_libraries(node ${PROJECT_NAME}::core)
            add_executable(other src/x.cpp)
            target_link_libraries(other again)
            """,
        "p/src/x.cpp": "int main() {}\n",
    })
    ws = scan([str(root)])
    targets = {t.name: t for t in cmake.targets_of(ws.packages["p"], ws)[0]}
    assert targets["node"].links == ["core"] and targets["node"].packages == []
    assert targets["other"].links == ["core"]
    assert "p::core" not in targets and "again" not in targets


def test_a_base_class_named_in_a_header_of_include_slash_package_is_run(write_tree) -> None:
    """aerostack2's as2_platform_gazebo: its CMake says
    ``include_directories(include include/${PROJECT_NAME})`` and its source includes
    ``"as2_platform_gazebo.hpp"``, which is ``include/as2_platform_gazebo/``'s and says
    the class derives from as2_core's ``AerialPlatform``, a node class of a library it
    links. The header was looked for only beside the source and in ``include/``: the
    base class was not seen, its file was left out as a node of its own, and the
    platform lost every subscription and service of its base while staying complete."""
    files = {
        "base/package.xml": package_xml("base", "ament_cmake"),
        "base/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.8)
            project(base)
            find_package(rclcpp REQUIRED)
            add_library(base_core SHARED src/platform.cpp)
            ament_export_targets(base_core)
            ament_package()
            """,
        "base/include/base/platform.hpp": """
            #include "rclcpp/rclcpp.hpp"
            namespace base {
            class Platform : public rclcpp::Node {
            public:
              Platform();
            };
            }
            """,
        "base/src/platform.cpp": """
            #include "base/platform.hpp"
            #include "std_msgs/msg/string.hpp"
            namespace base {
            Platform::Platform() : rclcpp::Node("platform")
            {
              create_subscription<std_msgs::msg::String>(
                "command", 1, [](std_msgs::msg::String::ConstSharedPtr) {});
            }
            }
            """,
        "sim/package.xml": package_xml("sim", "ament_cmake"),
        "sim/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.8)
            project(sim)
            find_package(base REQUIRED)
            include_directories(include include/${PROJECT_NAME})
            add_executable(sim_node src/sim.cpp)
            target_link_libraries(sim_node base::base_core)
            ament_package()
            """,
        "sim/include/sim/sim.hpp": """
            #include "base/platform.hpp"
            namespace sim {
            class SimPlatform : public base::Platform {
            public:
              SimPlatform();
            };
            }
            """,
        "sim/src/sim.cpp": """
            #include "sim.hpp"
            #include "std_msgs/msg/string.hpp"
            namespace sim {
            SimPlatform::SimPlatform() : base::Platform()
            {
              create_publisher<std_msgs::msg::String>("state", 1);
            }
            }
            int main(int argc, char ** argv)
            {
              rclcpp::init(argc, argv);
              rclcpp::spin(std::make_shared<sim::SimPlatform>());
            }
            """,
    }
    node, _ = _node(write_tree, files, "sim", "sim_node")
    assert node.sources == ["sim/src/sim.cpp", "base/src/platform.cpp"]
    assert {c.name for c in node.calls if c.kind in ("publish", "subscribe")} == {
        "state", "command"}


def test_a_plugin_loader_runs_what_it_links_but_the_plugins_themselves(write_tree) -> None:
    """nav2's costmap node loads its layers by name and links the library that builds
    them: it runs its filters' base class (no class of it exported), but each layer's
    own file is the layer's, run only when a parameter chooses it (``plugins.attach``).
    All linked files were run: the costmap of neo_simulation2's humble configuration,
    with an obstacle and an inflation layer, published the voxel layer's
    ``voxel_grid`` and read the static layer's ``map_topic``."""
    files = {
        "costmap/package.xml": package_xml("costmap", "ament_cmake"),
        "costmap/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.8)
            project(costmap)
            find_package(rclcpp REQUIRED)
            find_package(pluginlib REQUIRED)
            add_library(layers SHARED src/costmap.cpp plugins/filter.cpp
                        plugins/voxel_layer.cpp)
            add_executable(costmap_node src/main.cpp)
            target_link_libraries(costmap_node layers)
            ament_package()
            """,
        "costmap/include/costmap/layer.hpp": """
            #include "rclcpp/rclcpp.hpp"
            namespace costmap {
            class Layer { public: virtual void initialize(rclcpp::Node * node) = 0; };
            }
            """,
        "costmap/include/costmap/costmap.hpp": """
            #include "rclcpp/rclcpp.hpp"
            #include "pluginlib/class_loader.hpp"
            #include "costmap/layer.hpp"
            namespace costmap {
            class Costmap : public rclcpp::Node {
            public:
              Costmap();
              pluginlib::ClassLoader<Layer> loader_{"costmap", "costmap::Layer"};
            };
            }
            """,
        "costmap/src/costmap.cpp": """
            #include "costmap/costmap.hpp"
            #include "std_msgs/msg/string.hpp"
            namespace costmap {
            Costmap::Costmap() : rclcpp::Node("costmap")
            {
              create_publisher<std_msgs::msg::String>("costmap", 1);
              auto layer = loader_.createSharedInstance(
                declare_parameter("layer", std::string("costmap::VoxelLayer")));
              layer->initialize(this);
            }
            }
            """,
        "costmap/include/costmap/filter.hpp": """
            #include "costmap/layer.hpp"
            namespace costmap {
            class Filter : public Layer { public: void initialize(rclcpp::Node * node) override; };
            }
            """,
        "costmap/plugins/filter.cpp": """
            #include "costmap/filter.hpp"
            #include "std_msgs/msg/string.hpp"
            namespace costmap {
            void Filter::initialize(rclcpp::Node * node)
            {
              node->create_subscription<std_msgs::msg::String>(
                "filter_info", 1, [](std_msgs::msg::String::ConstSharedPtr) {});
            }
            }
            """,
        "costmap/plugins/voxel_layer.cpp": """
            #include "costmap/layer.hpp"
            #include "std_msgs/msg/string.hpp"
            #include "pluginlib/class_list_macros.hpp"
            namespace costmap {
            class VoxelLayer : public Layer {
            public:
              void initialize(rclcpp::Node * node) override
              {
                node->create_publisher<std_msgs::msg::String>("voxel_grid", 1);
              }
            };
            }
            PLUGINLIB_EXPORT_CLASS(costmap::VoxelLayer, costmap::Layer)
            """,
        "costmap/src/main.cpp": """
            #include "costmap/costmap.hpp"
            int main(int argc, char ** argv)
            {
              rclcpp::init(argc, argv);
              rclcpp::spin(std::make_shared<costmap::Costmap>());
            }
            """,
    }
    node, _ = _node(write_tree, files, "costmap", "costmap_node")
    assert node.sources == ["costmap/src/main.cpp", "costmap/src/costmap.cpp",
                            "costmap/plugins/filter.cpp"]
    assert "voxel_grid" not in {c.name for c in node.calls}
    assert {"costmap", "filter_info"} <= {c.name for c in node.calls}


def _xml(name: str, depends: list[str]) -> str:
    deps = "".join(f"<depend>{d}</depend>" for d in depends)
    return (f'<?xml version="1.0"?>\n<package format="3"><name>{name}</name>'
            f"<version>0.1.0</version><description>d</description>"
            f'<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
            f"<buildtool_depend>ament_cmake_auto</buildtool_depend>{deps}"
            f"<export><build_type>ament_cmake</build_type></export></package>\n")


UMBRELLA = {
    # a header-only package that re-exports its parts (autoware_utils 1.3: its CMake is
    # ``ament_auto_package()`` alone, its package.xml depends on autoware_utils_logging, ...)
    "utils/package.xml": _xml("utils", ["utils_logging"]),
    "utils/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.14)
        project(utils)
        find_package(ament_cmake_auto REQUIRED)
        ament_auto_find_build_dependencies()
        ament_auto_package()
        """,
    "utils/include/utils/utils.hpp": """
        #include "utils_logging/logger_level_configure.hpp"
        """,
    "utils_logging/package.xml": _xml("utils_logging", ["rclcpp"]),
    "utils_logging/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.14)
        project(utils_logging)
        find_package(ament_cmake_auto REQUIRED)
        ament_auto_find_build_dependencies()
        ament_auto_add_library(${PROJECT_NAME} SHARED src/logger_level_configure.cpp)
        ament_auto_package()
        """,
    "utils_logging/include/utils_logging/logger_level_configure.hpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_srvs/srv/trigger.hpp"
        namespace utils_logging {
        class LoggerLevelConfigure {
        public:
          explicit LoggerLevelConfigure(rclcpp::Node * node);
        private:
          rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr srv_;
        };
        }
        """,
    "utils_logging/src/logger_level_configure.cpp": """
        #include "utils_logging/logger_level_configure.hpp"
        namespace utils_logging {
        LoggerLevelConfigure::LoggerLevelConfigure(rclcpp::Node * node)
        {
          srv_ = node->create_service<std_srvs::srv::Trigger>(
            "~/config_logger",
            [](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
               std::shared_ptr<std_srvs::srv::Trigger::Response>) {});
        }
        }
        """,
    "calibrator/package.xml": _xml("calibrator", ["rclcpp", "utils"]),
    "calibrator/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.14)
        project(calibrator)
        find_package(ament_cmake_auto REQUIRED)
        ament_auto_find_build_dependencies()
        ament_auto_add_executable(calibrator src/calibrator.cpp)
        ament_auto_package()
        """,
    "calibrator/src/calibrator.cpp": """
        #include <memory>
        #include "rclcpp/rclcpp.hpp"
        #include "utils/utils.hpp"
        class Calibrator : public rclcpp::Node {
        public:
          Calibrator() : rclcpp::Node("calibrator") {
            logger_configure_ = std::make_unique<utils_logging::LoggerLevelConfigure>(this);
            declare_parameter<double>("gain", 1.0);
          }
        private:
          std::unique_ptr<utils_logging::LoggerLevelConfigure> logger_configure_;
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          rclcpp::spin(std::make_shared<Calibrator>());
        }
        """,
}


def test_a_header_only_package_brings_the_libraries_it_exports(write_tree) -> None:
    """Autoware's accel_brake_map_calibrator depends on autoware_utils, which builds no
    library and exports autoware_utils_logging, ...; the calibrator builds
    ``LoggerLevelConfigure(this)``, whose constructor (in autoware_utils_logging's
    library) serves ``~/config_logger``. The linked package's own dependencies were
    never followed: the constructor was not read and the node partial
    (CPP_NODE_PASSED)."""
    node, _ = _node(write_tree, UMBRELLA, "calibrator", "calibrator")
    assert "utils_logging/src/logger_level_configure.cpp" in node.sources
    assert sorted((c.kind, c.name) for c in node.calls) == [
        ("declare", "gain"), ("server", "~config_logger")]
    assert node.completeness == "complete", node.completeness_reasons


def test_a_package_with_a_library_does_not_bring_what_it_exports(write_tree) -> None:
    """Only a package with no library of its own hands on its dependencies' libraries;
    one with a library of its own keeps them its own business, as before."""
    files = dict(UMBRELLA)
    files["utils/CMakeLists.txt"] = files["utils/CMakeLists.txt"].replace(
        "ament_auto_package()", "ament_auto_add_library(utils SHARED src/utils.cpp)\n"
        "        ament_auto_package()")
    files["utils/src/utils.cpp"] = '#include "utils/utils.hpp"\nnamespace utils { int x; }\n'
    node, _ = _node(write_tree, files, "calibrator", "calibrator")
    assert "utils_logging/src/logger_level_configure.cpp" not in node.sources
    assert node.completeness == "partial"


def test_what_a_linked_package_names_of_a_package_it_links_comes_along(write_tree) -> None:
    # Autoware's trajectory follower links the MPC controller's library, whose code
    # builds autoware_vehicle_info_utils' VehicleInfoUtils with the node: that
    # constructor declares the vehicle's parameters on the node, so its file is run
    files = dict(ROS1)
    files["costs/CMakeLists.txt"] = files["costs/CMakeLists.txt"].replace(
        "roscpp std_msgs", "roscpp std_msgs probe")
    _catkin_library(files, "probe", "src/probe.cpp", """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        namespace probe {
        class Probe { public: explicit Probe(ros::NodeHandle & nh); };
        Probe::Probe(ros::NodeHandle & nh)
        {
          nh.advertise<std_msgs::String>("probe", 1);
        }
        }
        """)
    _catkin_library(files, "unlinked", "src/other.cpp", """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        namespace unlinked {
        class Other { public: explicit Other(ros::NodeHandle & nh); };
        Other::Other(ros::NodeHandle & nh)
        {
          nh.advertise<std_msgs::String>("other", 1);
        }
        }
        """)
    files["costs/src/map_ros.cpp"] = files["costs/src/map_ros.cpp"].replace(
        "namespace costs {",
        "namespace probe { class Probe { public: explicit Probe(ros::NodeHandle & nh); }; }\n"
        "namespace unlinked { class Other { public: explicit Other(ros::NodeHandle & nh); };"
        " }\nnamespace costs {").replace(
        'private_nh.param("update_rate", rate_, 5.0);',
        'private_nh.param("update_rate", rate_, 5.0);\n'
        '  probe::Probe probe(private_nh);\n  unlinked::Other other(private_nh);')
    node, _ = _node(write_tree, files, "planner", "planner_node")
    assert "costs/src/map_ros.cpp" in node.sources
    assert "probe/src/probe.cpp" in node.sources
    # a package costs does not link: its class is not costs' to build
    assert "unlinked/src/other.cpp" not in node.sources
    calls = {(c.kind, c.name) for c in node.calls}
    assert {("publish", "~global_costmap/probe"), ("publish", "~local_costmap/probe")} <= calls


def test_a_wrapper_runs_the_nodelets_it_loads_by_lookup_name(write_tree) -> None:
    """image_proc's ROS 1 wrapper loads ``"image_proc/debayer"`` and
    ``"image_proc/rectify"`` with ``nodelet::Loader`` in its process, by their lookup
    names: since the loader rule kept only the exported classes its code names, a
    rebuild of the image_proc model dropped both nodelets' files (and their calls) and
    called the node complete. A lookup name the package's description maps to a class
    names that class; a nodelet it does not load (resize) stays out."""
    files = {
        "improc/package.xml": package_xml("improc", None).replace(
            "</package>", "<depend>roscpp</depend><depend>nodelet</depend>"
            '<export><nodelet plugin="${prefix}/nodelet_plugins.xml"/></export></package>'),
        "improc/nodelet_plugins.xml": (
            '<library path="lib/libimproc">'
            '<class name="improc/debayer" type="improc::DebayerNodelet" '
            'base_class_type="nodelet::Nodelet"/>'
            '<class name="improc/resize" type="improc::ResizeNodelet" '
            'base_class_type="nodelet::Nodelet"/></library>'),
        "improc/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(improc)
            find_package(catkin REQUIRED COMPONENTS roscpp nodelet)
            catkin_package(LIBRARIES improc)
            add_library(improc src/debayer.cpp src/resize.cpp)
            add_executable(improc_node src/main.cpp)
            target_link_libraries(improc_node improc ${catkin_LIBRARIES})
            """,
        "improc/src/debayer.cpp": """
            #include <ros/ros.h>
            #include <nodelet/nodelet.h>
            #include <std_msgs/String.h>
            #include <pluginlib/class_list_macros.h>
            namespace improc {
            class DebayerNodelet : public nodelet::Nodelet {
              void onInit() {
                pub_ = getNodeHandle().advertise<std_msgs::String>("image_mono", 1);
              }
              ros::Publisher pub_;
            };
            }
            PLUGINLIB_EXPORT_CLASS(improc::DebayerNodelet, nodelet::Nodelet)
            """,
        "improc/src/resize.cpp": """
            #include <ros/ros.h>
            #include <nodelet/nodelet.h>
            #include <std_msgs/String.h>
            #include <pluginlib/class_list_macros.h>
            namespace improc {
            class ResizeNodelet : public nodelet::Nodelet {
              void onInit() {
                pub_ = getPrivateNodeHandle().advertise<std_msgs::String>("image", 1);
              }
              ros::Publisher pub_;
            };
            }
            PLUGINLIB_EXPORT_CLASS(improc::ResizeNodelet, nodelet::Nodelet)
            """,
        "improc/src/main.cpp": """
            #include <ros/ros.h>
            #include <nodelet/loader.h>
            int main(int argc, char** argv) {
              ros::init(argc, argv, "improc");
              nodelet::Loader manager(false);
              nodelet::M_string remappings;
              nodelet::V_string my_argv;
              manager.load(ros::this_node::getName() + "_debayer", "improc/debayer",
                           remappings, my_argv);
              ros::spin();
              return 0;
            }
            """,
    }
    node, _ = _node(write_tree, files, "improc", "improc_node")
    assert node.sources == ["improc/src/main.cpp", "improc/src/debayer.cpp"]
    assert "image_mono" in {c.name for c in node.calls}
