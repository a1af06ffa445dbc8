"""A ROS 1 node that builds an object of another ROS package's class whose code is not
read is partial (CPP_CLASS_UNSEEN): in ROS 1 any code can make its own NodeHandle, so
the class may read parameters and make topics under the names it is given without being
handed the node. navigation_experimental's assisted_teleop builds costmap_2d's
Costmap2DROS("costmap", tf) and a base_local_planner TrajectoryPlannerROS, neither in the
workspace; its launch file's costmap and planner parameters were called unread. Classes
whose API the rows model, classes of packages that are no ROS client, and ROS 2 code
(which communicates only through a node it is given) leave the node complete."""

from __future__ import annotations

import os
import re
from typing import Any

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

TELEOP = """
    #include <string>
    #include <ros/ros.h>
    #include <costmap_2d/costmap_2d_ros.h>
    #include <base_local_planner/trajectory_planner_ros.h>
    #include <tf2_ros/buffer.h>
    #include <tf2_ros/transform_listener.h>

    class Teleop {
     public:
      Teleop() : tfl_(tf_), costmap_ros_("costmap", tf_) {
        ros::NodeHandle private_nh("~");
        private_nh.param("controller_frequency", frequency_, 10.0);
        planner_.initialize("planner", &tf_, &costmap_ros_);
      }
     private:
      double frequency_;
      tf2_ros::Buffer tf_;
      tf2_ros::TransformListener tfl_;
      costmap_2d::Costmap2DROS costmap_ros_;
      base_local_planner::TrajectoryPlannerROS planner_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "teleop");
      Teleop teleop;
      ros::spin();
    }
    """


def _depends(name: str, *deps: str, build_type: str | None = None) -> str:
    return package_xml(name, build_type).replace(
        "</package>", "".join(f"<depend>{d}</depend>" for d in deps) + "</package>")


def _model(write_tree: Any, files: dict[str, str]) -> Any:
    root = write_tree({**files,
                       "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n"})
    return analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def _teleop(write_tree: Any, code: str, *deps: str) -> Any:
    model = _model(write_tree, {
        "src/teleop/package.xml": _depends("teleop", "roscpp", "tf2_ros", *deps),
        "src/teleop/CMakeLists.txt": "project(teleop)\nadd_executable(teleop src/teleop.cpp)\n",
        "src/teleop/src/teleop.cpp": code,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "teleop/teleop")
    return node, model


def test_a_missing_ros_package_class_built_by_the_node_makes_it_partial(
        write_tree: Any) -> None:
    node, _ = _teleop(write_tree, TELEOP, "costmap_2d", "base_local_planner")
    assert node.completeness == "partial"
    reasons = node.completeness_reasons
    # the construction in the initialiser list, and the member built by default
    assert any(r.startswith("teleop/src/teleop.cpp:10:")
               and "costmap_2d::Costmap2DROS of ROS package costmap_2d is built here" in r
               for r in reasons), reasons
    assert any(r.startswith("teleop/src/teleop.cpp:20:")
               and "base_local_planner::TrajectoryPlannerROS of ROS package "
               "base_local_planner" in r for r in reasons), reasons
    # the node's own reads are still read
    assert "~controller_frequency" in [c.name for c in node.calls]


def test_a_class_in_no_dependency_namespace_leaves_it_complete(write_tree: Any) -> None:
    # a vendor library's class: its namespace is no package the node depends on
    code = TELEOP.replace("costmap_2d::Costmap2DROS", "vendor::Grid").replace(
        "base_local_planner::TrajectoryPlannerROS", "vendor::Planner")
    node, _ = _teleop(write_tree, code, "costmap_2d", "base_local_planner")
    assert node.completeness == "complete", node.completeness_reasons


def test_a_locally_built_and_a_new_object(write_tree: Any) -> None:
    code = TELEOP.replace("      Teleop teleop;\n", "      Teleop teleop;\n"
                          "      voxel_grid::VoxelGrid grid(\"double\");\n"
                          "      auto* map = new costmap_2d::Costmap2DROS(\"map\", 0);\n")
    node, _ = _teleop(write_tree, code.replace("costmap_2d::Costmap2DROS costmap_ros_;",
                                               "int costmap_ros_;").replace(
        "base_local_planner::TrajectoryPlannerROS planner_;", "int planner_;").replace(
        "planner_.initialize(\"planner\", &tf_, &costmap_ros_);", ""),
        "costmap_2d", "voxel_grid")
    reasons = node.completeness_reasons
    # (filters::FilterChain was this example: its API is modelled now)
    assert any(r.startswith("teleop/src/teleop.cpp:26:")
               and "voxel_grid::VoxelGrid of ROS package voxel_grid" in r
               for r in reasons), reasons
    assert any(r.startswith("teleop/src/teleop.cpp:27:")
               and "costmap_2d::Costmap2DROS" in r for r in reasons), reasons


MODELLED = """
    #include <ros/ros.h>
    #include <tf/transform_listener.h>
    #include <actionlib/client/simple_action_client.h>
    #include <move_base_msgs/MoveBaseAction.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "teleop");
      tf::TransformListener listener;
      actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction> client("move_base", true);
      ros::spin();
    }
    """


def test_classes_the_api_rows_model_leave_it_complete(write_tree: Any) -> None:
    node, _ = _teleop(write_tree, MODELLED, "tf", "actionlib", "move_base_msgs")
    assert node.completeness == "complete", node.completeness_reasons
    assert {c.name for c in node.calls} >= {"move_base", "/tf"}


LIBRARY_HEADER = """
    #include <string>
    namespace grid {
    class Map {
     public:
      explicit Map(const std::string & name);
     private:
      std::string name_;
    };
    }  // namespace grid
    """

LIBRARY_SOURCE = """
    #include <ros/ros.h>
    #include "grid/map.h"
    namespace grid {
    Map::Map(const std::string & name) : name_(name) {
      ros::NodeHandle nh("~/" + name);
      int size; nh.param("size", size, 10);
    }
    }  // namespace grid
    """

USER = """
    #include <ros/ros.h>
    #include "grid/map.h"
    int main(int argc, char** argv) {
      ros::init(argc, argv, "user");
      grid::Map map("map");
      ros::spin();
    }
    """


def _user(write_tree: Any, grid_deps: tuple[str, ...], links: bool,
          source: str = LIBRARY_SOURCE) -> Any:
    link = "target_link_libraries(user ${catkin_LIBRARIES})\n" if links else ""
    model = _model(write_tree, {
        "src/grid/package.xml": _depends("grid", *grid_deps),
        "src/grid/CMakeLists.txt":
            "project(grid)\nfind_package(catkin REQUIRED)\n"
            "catkin_package(INCLUDE_DIRS include LIBRARIES grid)\n"
            "add_library(grid src/map.cpp)\n",
        "src/grid/include/grid/map.h": LIBRARY_HEADER,
        "src/grid/src/map.cpp": source,
        "src/user/package.xml": _depends("user", "roscpp", "grid"),
        "src/user/CMakeLists.txt":
            "project(user)\nfind_package(catkin REQUIRED COMPONENTS roscpp grid)\n"
            "add_executable(user src/user.cpp)\n" + link,
        "src/user/src/user.cpp": USER,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "user/user")
    node.said = [d for d in model.diagnostics if d.code == "CPP_CLASS_UNSEEN"]
    return node


def test_a_workspace_ros_class_whose_library_is_not_read(write_tree: Any) -> None:
    node = _user(write_tree, ("roscpp",), False)
    assert node.completeness == "partial"
    assert [d.location.line for d in node.said] == [5]
    assert any(r.startswith("user/src/user.cpp:5:")
               and "grid::Map of ROS package grid" in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_a_workspace_class_whose_library_is_linked_is_read(write_tree: Any) -> None:
    node = _user(write_tree, ("roscpp",), True)
    assert node.completeness == "complete", node.completeness_reasons
    assert "~map/size" in [c.name for c in node.calls]
    # the unit's information is not said either: the class's code is read
    assert node.said == []


def test_a_workspace_class_of_a_package_without_roscpp(write_tree: Any) -> None:
    node = _user(write_tree, (), False)
    assert node.completeness == "complete", node.completeness_reasons


ROS2 = """
    #include <memory>
    #include <rclcpp/rclcpp.hpp>
    #include <costmap_2d/costmap_2d_ros.hpp>

    class Teleop : public rclcpp::Node {
     public:
      Teleop() : Node("teleop"), grid_("costmap") {
        rate_ = declare_parameter<double>("rate", 10.0);
      }
     private:
      double rate_;
      costmap_2d::Grid grid_;
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Teleop>());
    }
    """


def test_ros2_a_class_not_given_the_node_leaves_it_complete(write_tree: Any) -> None:
    # a ROS 2 class communicates only through a node it is given
    model = _model(write_tree, {
        "src/teleop/package.xml": _depends("teleop", "rclcpp", "costmap_2d",
                                           build_type="ament_cmake"),
        "src/teleop/CMakeLists.txt": "project(teleop)\nadd_executable(teleop src/teleop.cpp)\n",
        "src/teleop/src/teleop.cpp": ROS2,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "teleop/teleop")
    assert node.completeness == "complete", node.completeness_reasons


def test_a_workspace_class_whose_code_makes_no_handle(write_tree: Any) -> None:
    # grid depends on roscpp (for its logging), but Map's constructor names no
    # NodeHandle nor a parameter, topic or service function: it communicates nothing
    node = _user(write_tree, ("roscpp",), False, LIBRARY_SOURCE.replace(
        'ros::NodeHandle nh("~/" + name);', 'ROS_INFO("map %s", name.c_str());').replace(
        'int size; nh.param("size", size, 10);', ''))
    assert node.completeness == "complete", node.completeness_reasons


NOT_CLASSES = """
    #include <ros/ros.h>
    #include <vendor_msgs/Mode.h>
    #include <vendor_msgs/SetMode.h>
    #include <costmap_2d/cost_values.h>
    #include <geometry_msgs/PoseStamped.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "teleop");
      ros::NodeHandle nh;
      vendor_msgs::Mode mode;
      vendor_msgs::SetMode srv;
      vendor_msgs::SetModeRequest request;
      geometry_msgs::QuaternionStamped q;
      double cost = costmap_2d::scaled_cost(mode, 3);
      costmap_2d::convert(q, mode);
      vendor_msgs::ModeConstPtr last;
      costmap_2d::Layer copy = costmap_2d::layer_of(mode);
      ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>("pose", 1);
      ros::spin();
    }
    """


def test_messages_services_and_function_calls_are_no_classes(write_tree: Any) -> None:
    # a message or service of a package the node depends on whose header is missing
    # (<vendor_msgs/Mode.h>: named as ROS 1 generates it), one of the catalogue used
    # without its header, and calls of names of a missing header: nothing is built
    node, _ = _teleop(write_tree, NOT_CLASSES, "vendor_msgs", "costmap_2d", "geometry_msgs")
    assert node.completeness == "complete", node.completeness_reasons


LASER = """
    #include <ros/ros.h>
    #include <laser_geometry/laser_geometry.h>
    #include <sensor_msgs/LaserScan.h>
    #include <sensor_msgs/PointCloud2.h>
    #include <tf/transform_listener.h>

    class Filter {
     public:
      Filter() {
        sub_ = nh_.subscribe("scan", 5, &Filter::scan, this);
        pub_ = nh_.advertise<sensor_msgs::PointCloud2>("cloud", 5);
      }
     private:
      void scan(const sensor_msgs::LaserScanConstPtr& msg) {
        sensor_msgs::PointCloud2 cloud;
        projector_.transformLaserScanToPointCloud("base", *msg, cloud, listener_, -1.0,
                                                  laser_geometry::channel_option::Distance);
        projector_.projectLaser(*msg, cloud);
        pub_.publish(cloud);
      }
      ros::NodeHandle nh_;
      ros::Subscriber sub_;
      ros::Publisher pub_;
      tf::TransformListener listener_;
      laser_geometry::LaserProjection projector_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "teleop");
      Filter filter;
      ros::spin();
    }
    """


def test_laser_geometry_is_a_stand_in(write_tree: Any) -> None:
    # laser_geometry installed, not in the workspace: its LaserProjection computes and
    # makes no ROS call (a stand-in of FALLBACK), so the node stays complete
    node, model = _teleop(write_tree, LASER, "laser_geometry", "tf", "sensor_msgs")
    assert node.completeness == "complete", node.completeness_reasons
    assert {(c.kind, c.name) for c in node.calls} >= {("subscribe", "scan"),
                                                      ("publish", "cloud")}
    assert not [d for d in model.diagnostics if d.code in (
        "CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR", "CPP_NAMES_DECLARED")], [
        d.message for d in model.diagnostics if d.code.startswith("CPP")]


MESHES = """
    #include <ros/ros.h>
    #include <resource_retriever/retriever.h>
    #include <sensor_msgs/PointCloud2.h>

    class SelfFilter {
     public:
      SelfFilter() {
        nh_.param<std::string>("mesh", url_, "package://robot/meshes/base.stl");
        load(url_);
        pub_ = nh_.advertise<sensor_msgs::PointCloud2>("cloud_filtered", 1);
      }
     private:
      bool load(const std::string& url) {
        resource_retriever::Retriever retriever;
        resource_retriever::MemoryResource res;
        try {
          res = retriever.get(url);
        } catch (resource_retriever::Exception& e) {
          ROS_ERROR("%s", e.what());
          return false;
        }
        const uint8_t* first = res.data.get();
        return res.size > 0 && first != nullptr && res.data[0] != 0;
      }
      ros::NodeHandle nh_;
      ros::Publisher pub_;
      std::string url_;
      mutable resource_retriever::Retriever cached_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "teleop");
      SelfFilter filter;
      ros::spin();
    }
    """


def test_resource_retriever_is_a_stand_in(write_tree: Any) -> None:
    # resource_retriever installed, not in the workspace: its Retriever reads a URL into
    # memory and makes no ROS call (a stand-in of FALLBACK), so the node that loads its
    # meshes stays complete (pr2_navigation_self_filter's self_mask.h:95, load_mesh.cpp)
    node, model = _teleop(write_tree, MESHES, "resource_retriever", "sensor_msgs")
    assert node.completeness == "complete", node.completeness_reasons
    assert [(c.kind, c.name) for c in node.calls] == [("read", "mesh"),
                                                      ("publish", "cloud_filtered")]
    assert not [d for d in model.diagnostics if d.code in (
        "CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR", "CPP_NAMES_DECLARED")], [
        d.message for d in model.diagnostics if d.code.startswith("CPP")]


def test_the_cache_follows_the_file_that_defines_the_class(write_tree: Any,
                                                           tmp_path: Any) -> None:
    # the unit's cached result holds what the library's source said: a changed source
    # (its constructor now makes a handle) is read again
    quiet = LIBRARY_SOURCE.replace(
        'ros::NodeHandle nh("~/" + name);', 'ROS_INFO("map %s", name.c_str());').replace(
        'int size; nh.param("size", size, 10);', '')
    root = write_tree({
        "src/grid/package.xml": _depends("grid", "roscpp"),
        "src/grid/CMakeLists.txt": "project(grid)\nadd_library(grid src/map.cpp)\n",
        "src/grid/include/grid/map.h": LIBRARY_HEADER,
        "src/grid/src/map.cpp": quiet,
        "src/user/package.xml": _depends("user", "roscpp", "grid"),
        "src/user/CMakeLists.txt": "project(user)\nadd_executable(user src/user.cpp)\n",
        "src/user/src/user.cpp": USER,
        "project.yaml": "project: p\nworkspace: [src]\nconfigurations: {}\n",
    })
    cache = str(tmp_path / "cache")

    def user() -> Any:
        model = analyse(load(str(root / "project.yaml")),
                        {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=cache))
        return next(n for p in model.packages for n in p.nodes if n.name == "user/user")

    assert user().completeness == "complete"
    (root / "src/grid/src/map.cpp").write_text(LIBRARY_SOURCE)
    assert user().completeness == "partial"


def test_a_message_no_header_declares_is_no_class(write_tree: Any) -> None:
    """open_manipulator_control_gui (noetic, qnode.hpp:120): a member
    ``open_manipulator_msgs::KinematicsPose kinematics_pose_;`` whose header no include
    gives (open_manipulator_msgs is not in the workspace), so the name is declared
    permissively: a message of a ``_msgs`` package is data, built without running any
    ROS code; the node was partial for it (CPP_CLASS_UNSEEN)."""
    node, _ = _teleop(write_tree, """
        #include <ros/ros.h>
        #include <std_msgs/String.h>

        class Gui {
         public:
          Gui() { pub_ = nh_.advertise<std_msgs::String>("option", 10); }
         private:
          ros::NodeHandle nh_;
          ros::Publisher pub_;
          vendor_msgs::KinematicsPose pose_;
        };

        int main(int argc, char** argv) {
          ros::init(argc, argv, "gui");
          Gui gui;
          vendor_msgs::Limits limits;
          ros::spin();
        }
        """, "vendor_msgs", "std_msgs")
    assert node.completeness == "complete", node.completeness_reasons


def test_an_alias_or_enumeration_of_a_workspace_package_is_no_class(write_tree: Any) -> None:
    # mavros' frame_tf.h: ``using Covariance3d = sensor_msgs::Imu::_angular_velocity_
    # covariance_type;``, a type the parse may not know; built by the imu plugin, it made
    # the node partial as a class "whose code is not read". An alias or an enumeration
    # has no code; a class defined in a header is read where it is defined.
    header = """
        #pragma once
        #include <vendor/matrix.h>
        namespace grid {
        using Covariance = vendor::Matrix3;
        typedef vendor::Frame FrameId;
        enum class Mode : int { IDLE, RUN };
        class Watcher {
         public:
          Watcher() { ros::NodeHandle nh("~"); nh.param("rate", rate_, 1.0); }
          double rate_;
        };
        }  // namespace grid
        """
    user = """
        #include <ros/ros.h>
        #include "grid/types.h"
        int main(int argc, char** argv) {
          ros::init(argc, argv, "user");
          grid::Covariance covariance;
          grid::FrameId frame;
          ros::spin();
        }
        """
    model = _model(write_tree, {
        "src/grid/package.xml": _depends("grid", "roscpp"),
        "src/grid/CMakeLists.txt": "project(grid)\nfind_package(catkin REQUIRED)\n"
                                   "catkin_package(INCLUDE_DIRS include)\n",
        "src/grid/include/grid/types.h": header,
        "src/user/package.xml": _depends("user", "roscpp", "grid"),
        "src/user/CMakeLists.txt": "project(user)\nfind_package(catkin REQUIRED COMPONENTS"
                                   " roscpp grid)\nadd_executable(user src/user.cpp)\n",
        "src/user/src/user.cpp": user,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "user/user")
    said = [d.message for d in model.diagnostics if d.code == "CPP_CLASS_UNSEEN"]
    assert node.completeness == "complete" and not said, (node.completeness_reasons, said)


def _through_library(write_tree: Any, tag: str) -> Any:
    """``node`` declares only the workspace library ``planner``, whose header includes
    costmap_2d's (missing) and whose manifest names costmap_2d with ``tag``."""
    model = _model(write_tree, {
        "src/planner/package.xml": package_xml("planner").replace(
            "</package>", f"<depend>roscpp</depend><{tag}>costmap_2d</{tag}></package>"),
        "src/planner/CMakeLists.txt": "project(planner)\nadd_library(planner src/planner.cpp)\n",
        "src/planner/include/planner/planner.h":
            "#pragma once\n#include <costmap_2d/costmap_2d_ros.h>\n"
            "namespace planner { struct Planner { void plan(costmap_2d::Costmap2DROS* c); }; }\n",
        "src/planner/src/planner.cpp":
            "#include <planner/planner.h>\n"
            "void planner::Planner::plan(costmap_2d::Costmap2DROS*) {}\n",
        "src/node/package.xml": _depends("node", "roscpp", "planner"),
        "src/node/CMakeLists.txt": "project(node)\nadd_executable(node src/node.cpp)\n",
        "src/node/src/node.cpp": """
            #include <ros/ros.h>
            #include <planner/planner.h>
            int main(int argc, char** argv) {
              ros::init(argc, argv, "node");
              auto* costmap = new costmap_2d::Costmap2DROS("global_costmap", 0);
              planner::Planner().plan(costmap);
              ros::spin();
            }
            """,
    })
    return next(n for p in model.packages for n in p.nodes if n.name == "node/node")


def test_a_class_of_a_dependency_a_workspace_library_exports(write_tree: Any) -> None:
    # the node reaches costmap_2d through the planner's header: the planner exports it
    # (``run_depend`` of format 1, ``depend``, ``build_export_depend``)
    for tag in ("run_depend", "depend", "build_export_depend"):
        node = _through_library(write_tree, tag)
        assert node.completeness == "partial", tag
        assert any("costmap_2d::Costmap2DROS of ROS package costmap_2d" in r
                   for r in node.completeness_reasons), node.completeness_reasons


def test_a_dependency_a_workspace_library_does_not_export(write_tree: Any) -> None:
    # a test dependency of the planner reaches no package depending on it
    node = _through_library(write_tree, "test_depend")
    assert node.completeness == "complete", node.completeness_reasons


TEMPLATED = """
    #include <string>
    #include <ros/ros.h>
    #include <costmap_2d/costmap_2d_ros.h>

    void readRate(ros::NodeHandle& nh, const std::string& name, double& out) {
      nh.param(name, out, 1.0);
    }

    class Holder {
     public:
      template <typename T>
      void prepare(T& thing) {
        thing.reset();
        costmap_2d::Costmap2DROS local;
      }
     private:
      costmap_2d::Costmap2DROS* shared_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "teleop");
      ros::NodeHandle nh("~");
      double rate;
      readRate(nh, "rate", rate);
      ros::spin();
    }
    """


def test_a_class_built_in_a_function_that_makes_no_ros_call(write_tree: Any) -> None:
    # franka_hw's setupLimitInterface<T>: a function template whose calls depend on its
    # parameter and make no ROS call, building joint_limits_interface's classes. Its
    # body is not walked for calls; what it builds is still read (in every function)
    node, _ = _teleop(write_tree, TEMPLATED, "costmap_2d")
    assert node.completeness == "partial"
    assert any(r.startswith("teleop/src/teleop.cpp:14:")
               and "costmap_2d::Costmap2DROS of ROS package costmap_2d" in r
               for r in node.completeness_reasons), node.completeness_reasons
    assert "~rate" in [c.name for c in node.calls]


# LeGO-LOAM's mapOptmization builds gtsam's classes (``gtsam::Vector``, ``gtsam::Pose3``);
# its package.xml names gtsam, a library released into ROS 1 that makes no ROS calls,
# and where it is not installed the parse knows the names only as declared permissively
SMOOTHER = """
    #include <ros/ros.h>
    #include <gtsam/geometry/Pose3.h>
    #include <octomap/OcTree.h>
    #include <slam_lib/graph.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "smoother");
      ros::NodeHandle nh("~");
      double rate;
      nh.param("rate", rate, 1.0);
      gtsam::Pose3 pose;
      octomap::OcTree tree;
      LIBRARY_OBJECT
      ros::spin();
    }
    """


def _smoother(write_tree: Any, library: str, *deps: str, header: str = "") -> Any:
    code = SMOOTHER.replace("LIBRARY_OBJECT", library)
    if header:  # in place of slam_lib's, so that the lines stay where they are
        code = code.replace("#include <slam_lib/graph.h>", f"#include <{header}>")
    model = _model(write_tree, {
        "src/smoother/package.xml": _depends("smoother", "roscpp", *deps),
        "src/smoother/CMakeLists.txt":
            "project(smoother)\nadd_executable(smoother src/smoother.cpp)\n",
        "src/smoother/src/smoother.cpp": code,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "smoother/smoother")
    node.said = [d for d in model.diagnostics if d.code == "CPP_CLASS_UNSEEN"]
    return node


def test_a_library_known_to_make_no_ros_calls_leaves_it_complete(write_tree: Any) -> None:
    # gtsam and octomap are found nowhere, but the shipped table knows their manifests
    node = _smoother(write_tree, "", "gtsam", "octomap")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []
    assert "~rate" in [c.name for c in node.calls]


def test_an_unknown_missing_dependency_beside_them_stays_partial(write_tree: Any) -> None:
    # slam_lib is in no table and not installed: what its class does is not known
    node = _smoother(write_tree, "slam_lib::Graph graph(\"graph\");", "gtsam", "octomap",
                     "slam_lib")
    assert node.completeness == "partial"
    assert [d.location.line for d in node.said] == [13], node.said
    assert any("slam_lib::Graph of ROS package slam_lib" in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_the_table_names_its_sources() -> None:
    from haros_arch import safe_yaml
    from haros_arch.extract.cpp import NO_CLIENTS, no_clients

    with open(NO_CLIENTS, encoding="utf-8") as handle:
        data = safe_yaml.load(handle.read())
    assert "gtsam" in no_clients() and "roscpp" not in no_clients()
    assert set(data) == {"system", "released", "classes"}
    for name, entry in data["classes"].items():  # each package's list names its source
        repo, commit, *paths = entry["source"].split()
        assert repo.startswith("github:") and len(commit) == 40 and paths, name
        # each a name within the package's namespace, or one written in full
        assert entry["names"] and all(re.fullmatch(r"\w+(::\w+)*", n)
                                      for n in entry["names"]), name
    # every released library names the manifest read: repository, commit, path
    for name, source in data["released"].items():
        repo, commit, path = source.split()
        assert repo.startswith("github:") and len(commit) == 40, name
        assert path.endswith("package.xml"), name


def test_the_mavlink_message_library_leaves_it_complete(write_tree: Any) -> None:
    # mavros' plugins build MAVLink's messages (``mavlink::common::msg::COMMAND_LONG``);
    # the mavlink package is a plain CMake library with no ROS client of its own
    node = _smoother(write_tree, "mavlink::common::msg::COMMAND_LONG cmd{};", "gtsam",
                     "octomap", "mavlink")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []


def test_a_system_library_of_the_table_leaves_it_complete(write_tree: Any) -> None:
    # agilexrobotics' ugv_sdk builds standalone asio's io_service and names the rosdep
    # key asio (libasio-dev), a system library: no ROS calls of its own
    node = _smoother(write_tree, "asio::io_service io;", "gtsam", "octomap", "asio")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []


def test_the_zbar_library_leaves_it_complete(write_tree: Any) -> None:
    # zbar_ros' nodelet builds zbar::ImageScanner; zbar is the rosdep key of libzbar-dev,
    # a bar code library (sara_commun's copy of zbar_ros was partial for it)
    node = _smoother(write_tree, "zbar::ImageScanner scanner;", "gtsam", "octomap", "zbar",
                     header="zbar.h")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []


GUI = """
    #include <string>
    #include <ros/ros.h>
    #include <moveit/move_group_interface/move_group_interface.h>

    class QNode {
     public:
      void init() {
        std::string group = "arm";
        move_group_ = new moveit::planning_interface::MoveGroupInterface(group);
        ros::NodeHandle("~").param("rate", rate_, 10.0);
      }
     private:
      moveit::planning_interface::MoveGroupInterface* move_group_;
      double rate_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "gui");
      QNode node;
      node.init();
      ros::spin();
    }
    """


def test_a_class_of_a_namespace_that_begins_its_packages_names(write_tree: Any) -> None:
    # turtlebot3_manipulation_gui: MoveIt's classes are in namespace ``moveit``, its
    # packages moveit_core, moveit_ros_planning_interface, ...: the one that holds the
    # namespace's next part builds it (its MoveGroupInterface makes the move_group
    # action's client and more)
    node, _ = _teleop(write_tree, GUI, "moveit_core", "moveit_ros_planning",
                      "moveit_ros_planning_interface", "moveit_msgs")
    assert node.completeness == "partial"
    assert any(r.startswith("teleop/src/teleop.cpp:9:")
               and "moveit::planning_interface::MoveGroupInterface of ROS package "
               "moveit_ros_planning_interface is built here" in r
               for r in node.completeness_reasons), node.completeness_reasons
    # no dependency holds the next part: as before, a vendor's namespace
    node, _ = _teleop(write_tree, GUI, "moveit_core", "moveit_msgs")
    assert node.completeness == "complete", node.completeness_reasons


# urg_node keeps a laser_proc::LaserPublisher member and makes it with
# LaserTransport::advertiseLaser(nh_, 20): laser_proc, installed, advertises the multi-echo
# scan and its first, last and most intense echoes on that handle
LASER_PROC = """
    #include <ros/ros.h>
    #include <laser_proc/LaserTransport.h>

    class Driver {
     public:
      Driver() : nh_("hokuyo") {
        echoes_pub_ = laser_proc::LaserTransport::advertiseLaser(nh_, 20);
      }
     private:
      ros::NodeHandle nh_;
      laser_proc::LaserPublisher echoes_pub_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "driver");
      Driver driver;
      ros::spin();
    }
    """


def test_laser_proc_s_publisher_is_known(write_tree: Any) -> None:
    model = _model(write_tree, {
        "src/urg/package.xml": _depends("urg", "roscpp", "laser_proc", "sensor_msgs"),
        "src/urg/CMakeLists.txt": "project(urg)\nadd_executable(driver src/driver.cpp)\n",
        "src/urg/src/driver.cpp": LASER_PROC,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "urg/driver")
    assert node.completeness == "complete", node.completeness_reasons
    assert sorted((c.kind, c.name, c.type, c.queue_size) for c in node.calls) == [
        ("publish", "hokuyo/echoes", "sensor_msgs/MultiEchoLaserScan", 20),
        ("publish", "hokuyo/first", "sensor_msgs/LaserScan", 20),
        ("publish", "hokuyo/last", "sensor_msgs/LaserScan", 20),
        ("publish", "hokuyo/most_intense", "sensor_msgs/LaserScan", 20)]


def test_moveits_random_number_library_leaves_it_complete(write_tree: Any) -> None:
    # MoveIt's RobotState::getRandomNumberGenerator() builds
    # random_numbers::RandomNumberGenerator (ros-planning/random_numbers, a catkin
    # library over Boost.Random whose package.xml names boost alone): every node that
    # includes robot_state.h was partial for it (move_group, its capabilities, ...)
    node = _smoother(write_tree, "random_numbers::RandomNumberGenerator rng;", "gtsam",
                     "octomap", "random_numbers")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []


def test_the_ruckig_library_leaves_it_complete(write_tree: Any) -> None:
    # MoveIt's AddRuckigTrajectorySmoothing builds ruckig's InputParameter (pantor/ruckig,
    # a plain CMake package released into noetic)
    node = _smoother(write_tree, "ruckig::InputParameter input;", "gtsam", "octomap",
                     "ruckig")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []


def test_the_serial_port_library_leaves_it_complete(write_tree: Any) -> None:
    # mit-racecar's vesc_driver builds wjwwood/serial's serial::Serial (a catkin package
    # whose package.xml names catkin alone, released into noetic): the driver node and its
    # nodelet were partial for it
    node = _smoother(write_tree, "serial::Serial port(\"/dev/ttyACM0\");", "gtsam",
                     "octomap", "serial")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []


def test_a_class_of_a_ros_package_known_to_make_no_calls_leaves_it_complete(
        write_tree: Any) -> None:
    # m-explore's explore_lite keeps a costmap_2d::Costmap2D (the grid: no ROS call in
    # costmap_2d.cpp) and kth-ros-pkg/yumi's yumi_hw ros_control's joint limits handles
    # and interfaces; neither package in the workspace, both nodes were partial for them.
    # The shipped table lists such classes by package; another class of the same package
    # (Costmap2DROS reads ~costmap/*) still makes the node partial
    node = _smoother(write_tree, "costmap_2d::Costmap2D grid;\n"
                     "joint_limits_interface::PositionJointSaturationInterface sat;\n"
                     "joint_limits_interface::JointLimits limits;",
                     "gtsam", "octomap", "costmap_2d", "joint_limits_interface")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []
    # (as the code includes its header: our stand-in of ROS 1 costmap_2d declares it,
    # its code not read)
    node = _smoother(write_tree, "costmap_2d::Costmap2D grid;\n"
                     "costmap_2d::Costmap2DROS map(\"costmap\", grid);",
                     "gtsam", "octomap", "costmap_2d", header="costmap_2d/costmap_2d_ros.h")
    assert node.completeness == "partial"
    assert [d.location.line for d in node.said] == [14], node.said
    assert any("costmap_2d::Costmap2DROS of ROS package costmap_2d" in r
               for r in node.completeness_reasons), node.completeness_reasons


# abb_robot_driver's EGM hardware interface: ros_control's joint_limits_interface,
# installed, reads each joint's limits from the handle given (getJointLimits,
# getSoftJointLimits of joint_limits_rosparam.h); the node was partial for them
JOINT_LIMITS = """
    #include <ros/ros.h>
    #include <joint_limits_interface/joint_limits.h>
    #include <joint_limits_interface/joint_limits_rosparam.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "hw");
      ros::NodeHandle nh("egm");
      joint_limits_interface::JointLimits limits{};
      joint_limits_interface::SoftJointLimits soft{};
      joint_limits_interface::getJointLimits("joint_1", nh, limits);
      if (!joint_limits_interface::getSoftJointLimits("joint_1", nh, soft)) {
        soft.k_position = 1.0;
      }
      ros::spin();
    }
    """


def test_joint_limits_rosparam_reads_are_known(write_tree: Any) -> None:
    model = _model(write_tree, {
        "src/hw/package.xml": _depends("hw", "roscpp", "joint_limits_interface"),
        "src/hw/CMakeLists.txt": "project(hw)\nadd_executable(hw src/hw.cpp)\n",
        "src/hw/src/hw.cpp": JOINT_LIMITS,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "hw/hw")
    assert node.completeness == "complete", node.completeness_reasons
    reads = sorted((c.name, c.type) for c in node.calls if c.kind == "read")
    limits = "egm/joint_limits/joint_1/"
    assert reads == sorted(
        [(limits + name, "double") for name in (
            "min_position", "max_position", "max_velocity", "max_acceleration",
            "max_jerk", "max_effort", "k_position", "k_velocity", "soft_lower_limit",
            "soft_upper_limit")]
        + [(limits + name, "bool") for name in (
            "has_position_limits", "angle_wraparound", "has_velocity_limits",
            "has_acceleration_limits", "has_jerk_limits", "has_effort_limits")])


MANAGER = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include "robotis_controller/robotis_controller.h"
    #include "robotis_framework_common/motion_module.h"
    using namespace robotis_framework;

    class WalkingModule : public robotis_framework::MotionModule,
                          public robotis_framework::Singleton<WalkingModule> {
     public:
      void initialize(int cycle);
      ros::Publisher status_;
    };

    void WalkingModule::initialize(int cycle) {
      ros::NodeHandle nh;
      module_name_ = "walking_module";
      enable_ = false;
      status_ = nh.advertise<std_msgs::String>("/robotis/status", 1);
    }

    int main(int argc, char** argv) {
      ros::init(argc, argv, "op3_manager");
      ros::NodeHandle nh;
      RobotisController *controller = RobotisController::getInstance();
      ros::Publisher pose = nh.advertise<std_msgs::String>("/robotis/base/ini_pose", 1);
      controller->addMotionModule((MotionModule*) WalkingModule::getInstance());
      WalkingModule::getInstance()->initialize(8);
      ros::spin();
    }
    """


def test_a_singleton_of_a_missing_ros_package_makes_it_partial(write_tree: Any) -> None:
    """ROBOTIS-OP3's op3_manager reaches robotis_controller's RobotisController (its
    header missing, in namespace robotis_framework) through the static
    ``RobotisController::getInstance()``: that class's code, which serves
    ``/robotis/set_present_ctrl_modules`` in the manager's process, is not read, so the
    node is partial, said at the call (the package named after the class). Its own
    modules derive from the framework's declared ``MotionModule`` and ``Singleton<T>``:
    the base's ``module_name_`` and static ``getInstance()`` are members of the
    permissive class, so the module's calls parse (they were errors in main and in the
    module's method, the node partial for them instead)."""
    model = _model(write_tree, {
        "src/op3_manager/package.xml": _depends(
            "op3_manager", "roscpp", "std_msgs", "robotis_controller",
            "robotis_framework_common"),
        "src/op3_manager/CMakeLists.txt": (
            "project(op3_manager)\nadd_executable(op3_manager src/op3_manager.cpp)\n"),
        "src/op3_manager/src/op3_manager.cpp": MANAGER,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "op3_manager/op3_manager")
    assert node.completeness == "partial"
    assert [r.split(": ", 1)[1] for r in node.completeness_reasons] == [
        "RobotisController of ROS package robotis_controller is built here and its code "
        "is not read"]
    assert sorted(c.name for c in node.calls if c.kind == "publish") == [
        "/robotis/base/ini_pose", "/robotis/status"]
    errors = [d.message for d in model.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    assert errors == []


def test_a_package_the_build_finds_and_the_manifest_does_not_name(write_tree: Any) -> None:
    """vizzy f151bb2: vizzy_control's package.xml names no moveit package, its CMake
    finds moveit_ros_planning_interface among catkin's components, and gaze_sim builds
    a MoveGroupInterface (which subscribes joint_states): the node was complete, and
    gaze.launch's ``joint_states`` remap "unused". The packages the build finds count as
    the node's dependencies."""
    files = {
        "src/teleop/package.xml": _depends("teleop", "roscpp"),
        "src/teleop/CMakeLists.txt": (
            "project(teleop)\nfind_package(catkin REQUIRED COMPONENTS roscpp\n"
            "  moveit_ros_planning_interface)\ncatkin_package()\n"
            "add_executable(teleop src/teleop.cpp)\n"),
        "src/teleop/src/teleop.cpp": GUI,
    }
    model = _model(write_tree, files)
    node = next(n for p in model.packages for n in p.nodes if n.name == "teleop/teleop")
    assert node.completeness == "partial"
    assert any("moveit::planning_interface::MoveGroupInterface of ROS package "
               "moveit_ros_planning_interface is built here" in r
               for r in node.completeness_reasons), node.completeness_reasons


ARM = """
    #include <ros/ros.h>
    #include <moveit/move_group_interface/move_group_interface.h>

    bool moveArm() {
      double tolerance = 0.1;
      moveit::planning_interface::MoveGroupInterface group("right_arm");
      group.setGoalPositionTolerance(tolerance);
      return group.move();
    }

    int main(int argc, char** argv) {
      ros::init(argc, argv, "wave");
      ros::NodeHandle nh;
      moveArm();
    }
    """


def test_a_missing_class_built_where_no_ros_call_is_made(write_tree: Any) -> None:
    # (vizzy's waveDemo) MoveIt's headers are missing and the function that builds its
    # MoveGroupInterface makes no call of the API: the error on ``moveit`` still hides
    # what that class does, so its name is declared and the construction said
    node, _ = _teleop(write_tree, ARM, "moveit_ros_planning_interface")
    assert node.completeness == "partial"
    assert any(r.startswith("teleop/src/teleop.cpp:6:")
               and "moveit::planning_interface::MoveGroupInterface of ROS package "
               "moveit_ros_planning_interface is built here" in r
               for r in node.completeness_reasons), node.completeness_reasons


def test_a_missing_vendor_class_built_where_no_ros_call_is_made(write_tree: Any) -> None:
    # the same shape with a namespace that is no package the node depends on
    node, _ = _teleop(write_tree, ARM.replace("moveit::planning_interface::", "vendor::"),
                      "moveit_ros_planning_interface")
    assert node.completeness == "complete", node.completeness_reasons


def test_a_nested_type_of_a_missing_class_is_data(write_tree: Any) -> None:
    # ``MoveGroupInterface::Plan plan;`` builds the class's own plan, not the class
    code = ARM.replace("      return group.move();",
                       "      moveit::planning_interface::MoveGroupInterface::Plan plan;\n"
                       "      ros::param::param(\"~tolerance\", tolerance, 0.1);\n"
                       "      return group.move();")
    node, _ = _teleop(write_tree, code, "moveit_ros_planning_interface")
    reasons = node.completeness_reasons
    assert any(r.startswith("teleop/src/teleop.cpp:6:") for r in reasons), reasons
    assert not any("::Plan" in r for r in reasons), reasons


# ros_control_boilerplate's GenericHWInterface::registerJointLimits: the limits of each
# joint from the URDF first (joint_limits_urdf.h's two-argument overloads, which read
# no parameter), then from the handle given (joint_limits_rosparam.h's). With no stand-in
# of joint_limits_urdf.h the URDF calls were "too few arguments" errors in a function
# that reads parameters, and the node partial
JOINT_LIMITS_URDF = """
    #include <ros/ros.h>
    #include <urdf/model.h>
    #include <joint_limits_interface/joint_limits.h>
    #include <joint_limits_interface/joint_limits_rosparam.h>
    #include <joint_limits_interface/joint_limits_urdf.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "hw");
      ros::NodeHandle nh("arm");
      urdf::Model model;
      model.initParam("robot_description");
      urdf::JointConstSharedPtr joint = model.getJoint("joint_1");
      joint_limits_interface::JointLimits limits;
      joint_limits_interface::SoftJointLimits soft;
      bool has_limits = joint_limits_interface::getJointLimits(joint, limits);
      joint_limits_interface::getJointLimits("joint_1", nh, limits);
      if (joint_limits_interface::getSoftJointLimits(joint, soft)) {
        has_limits = true;
      }
      ros::spin();
    }
    """


def test_joint_limits_from_the_urdf_read_no_parameter(write_tree: Any) -> None:
    model = _model(write_tree, {
        "src/hw/package.xml": _depends("hw", "roscpp", "urdf", "joint_limits_interface"),
        "src/hw/CMakeLists.txt": "project(hw)\nadd_executable(hw src/hw.cpp)\n",
        "src/hw/src/hw.cpp": JOINT_LIMITS_URDF,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "hw/hw")
    assert node.completeness == "complete", node.completeness_reasons
    reads = sorted(c.name for c in node.calls if c.kind == "read")
    limits = "arm/joint_limits/joint_1/"
    assert reads == sorted([
        "robot_description", *(limits + name for name in (
            "min_position", "max_position", "max_velocity", "max_acceleration",
            "max_jerk", "max_effort", "has_position_limits", "angle_wraparound",
            "has_velocity_limits", "has_acceleration_limits", "has_jerk_limits",
            "has_effort_limits"))])


# mobipick's kinematics_speed_and_validity_evaluator builds MoveIt's RobotModelLoader,
# whose kinematics plugin loader reads ~<group>/kinematics_solver and its siblings on a
# handle of its own; the header is moveit_ros_planning's, which the package reaches only
# through moveit_ros_planning_interface, and the namespace robot_model_loader names no
# package: the node was complete and the launch file's solver parameters "unread"
EVALUATOR = """
    #include <string>
    #include <moveit/robot_model_loader/robot_model_loader.h>
    #include <ros/ros.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "evaluator");
      robot_model_loader::RobotModelLoader rml("robot_description");
      ros::spin();
    }
    """


def test_a_class_of_a_missing_header_s_folder_of_a_dependency(write_tree: Any) -> None:
    node, _ = _teleop(write_tree, EVALUATOR, "moveit_ros_planning_interface", "moveit_msgs")
    assert node.completeness == "partial"
    assert any(r.startswith("teleop/src/teleop.cpp:7:")
               and "robot_model_loader::RobotModelLoader of ROS package "
               "moveit_ros_planning_interface is built here" in r
               for r in node.completeness_reasons), node.completeness_reasons
    # no dependency begins with the header's folder: a vendor's library, as before
    node, _ = _teleop(write_tree, EVALUATOR.replace("<moveit/", "<vendor/"),
                      "moveit_ros_planning_interface")
    assert node.completeness == "complete", node.completeness_reasons
    # the namespace is none of the header's folders: not tied to it
    node, _ = _teleop(write_tree, EVALUATOR.replace(
        "robot_model_loader::RobotModelLoader", "loader::RobotModelLoader"),
        "moveit_ros_planning_interface")
    assert node.completeness == "complete", node.completeness_reasons


def test_a_missing_header_s_class_is_of_the_unit_s_own_dependency_first(
        write_tree: Any) -> None:
    # a workspace library exports moveit_a_adapter, which the unit reaches too: the
    # class is said of the dependency the unit's package names itself
    model = _model(write_tree, {
        "src/helper/package.xml": _depends("helper", "roscpp", "moveit_a_adapter"),
        "src/helper/CMakeLists.txt": "project(helper)\n",
        "src/teleop/package.xml": _depends("teleop", "roscpp", "helper",
                                           "moveit_ros_planning_interface"),
        "src/teleop/CMakeLists.txt": "project(teleop)\nadd_executable(teleop src/teleop.cpp)\n",
        "src/teleop/src/teleop.cpp": EVALUATOR,
    })
    node = next(n for p in model.packages for n in p.nodes if n.name == "teleop/teleop")
    assert any("robot_model_loader::RobotModelLoader of ROS package "
               "moveit_ros_planning_interface is built here" in r
               for r in node.completeness_reasons), node.completeness_reasons


# MoveIt 1's robot state and model (moveit_core's moveit::core, robot_state and
# robot_model its aliases) are data: their code makes no ROS call. A node building one
# from a missing header of a MoveIt dependency is still complete for it; the loader beside
# it is not.
STATE = """
    #include <moveit/robot_model_loader/robot_model_loader.h>
    #include <moveit/robot_state/robot_state.h>
    #include <ros/ros.h>

    void use(const robot_model::RobotModelConstPtr& model) {
      robot_state::RobotState state(model);
      moveit::core::RobotState copy(model);
    }

    int main(int argc, char** argv) {
      ros::init(argc, argv, "evaluator");
      ros::spin();
    }
    """


def test_moveit_s_robot_state_is_no_client_wherever_its_header_is_missing(
        write_tree: Any) -> None:
    node, _ = _teleop(write_tree, STATE, "moveit_ros_planning_interface")
    assert node.completeness == "complete", node.completeness_reasons
    loader = STATE.replace("ros::spin();",
                           'robot_model_loader::RobotModelLoader rml("robot_description");')
    node, _ = _teleop(write_tree, loader, "moveit_ros_planning_interface")
    assert node.completeness == "partial"
    assert [r for r in node.completeness_reasons if "RobotState" in r] == []


def test_moveits_geometry_library_leaves_it_complete(write_tree: Any) -> None:
    # MoveIt's collision_distance_field builds geometric_shapes' bodies::BoundingSphere
    # and bodies::BoundingCylinder (ros-planning/geometric_shapes, a catkin library whose
    # package.xml names no ROS client library): moveit_ros_planning's request adapters
    # and programs that read it were partial for them
    node = _smoother(write_tree, "bodies::BoundingSphere sphere;\n"
                     "shapes::Box box(1.0, 2.0, 3.0);", "gtsam", "octomap",
                     "geometric_shapes", header="geometric_shapes/bodies.h")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []


# mbzirc2020 (e474cee)'s UAV action server builds grvc-ual's UAL on a backend chosen by a
# parameter; the classes are in namespace grvc::ual, which names no package, and their
# headers are named after them: the backends read the server's ~pid/... parameters, so
# with the node whole 98 of them were false parameter-set-not-read findings
UAL = """
    #include <string>
    #include <ros/ros.h>
    #include <uav_abstraction_layer/ual.h>
    #include <ual_backend_mavros/ual_backend_mavros.h>
    #include <ual_backend_gazebo_light/ual_backend_gazebo_light.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "server");
      std::string kind;
      ros::param::param<std::string>("~ual_backend", kind, "mavros");
      grvc::ual::Backend* backend = nullptr;
      if (kind == "mavros") {
        backend = new grvc::ual::BackendMavros();
      } else {
        backend = new grvc::ual::BackendGazeboLight();
      }
      grvc::ual::UAL* ual = new grvc::ual::UAL(backend);
      ros::spin();
    }
    """


def test_classes_of_a_namespace_no_package_names_found_by_their_headers(
        write_tree: Any) -> None:
    node, _ = _teleop(write_tree, UAL, "uav_abstraction_layer", "ual_backend_mavros",
                      "ual_backend_gazebo_light")
    assert node.completeness == "partial"
    said = sorted(r.split(": ", 1)[1] for r in node.completeness_reasons)
    assert said == [
        "grvc::ual::BackendGazeboLight of ROS package ual_backend_gazebo_light is built "
        "here and its code is not read",
        "grvc::ual::BackendMavros of ROS package ual_backend_mavros is built here and its "
        "code is not read",
        "grvc::ual::UAL of ROS package uav_abstraction_layer is built here and its code "
        "is not read"], node.completeness_reasons
    # no dependency holds the headers' folders: a vendor's library, as before
    node, _ = _teleop(write_tree, UAL)
    assert node.completeness == "complete", node.completeness_reasons


def test_the_hebi_actuator_library_leaves_it_complete(write_tree: Any) -> None:
    # hebi_cpp_api_examples' nodes build hebi_cpp_api's hebi::Lookup and GroupCommand
    # (HebiRobotics/hebi_cpp_api_ros, a catkin package whose package.xml names catkin,
    # cmake_modules and eigen, released into noetic): 14 nodes were partial for them
    node = _smoother(write_tree, "hebi::Lookup lookup; hebi::GroupCommand cmd(6);",
                     "gtsam", "octomap", "hebi_cpp_api", header="hebi_cpp_api/lookup.hpp")
    assert node.completeness == "complete", node.completeness_reasons
    assert node.said == []
