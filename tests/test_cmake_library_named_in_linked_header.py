"""A node runs the library code that the inline code of another workspace package's
header builds: ctu-mrs' mrs_uav_managers nodelets build mrs_lib's ``ParamLoader``, a
class whose inline code in param_loader.h holds a ``ParamProvider``, defined in
mrs_lib's param_provider.cpp (and the nodelets link mrs_lib). The node's own files
never name ``ParamProvider``: only the header does, so the file that defines it was
not among the node's sources, its calls not read, and the node partial ("... is built
here and its code is not read"). The words of the headers of the linked packages that
the node's code includes count as the node's own: the file joins its sources. A file
of that library that the node's code and those headers never name stays out, so does
one that only a header names whose classes the node never uses, and one that exports a
plugin class the header names."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

FILES = {
    "loaders/package.xml": package_xml("loaders", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"),
    "loaders/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(loaders)
        find_package(catkin REQUIRED COMPONENTS roscpp std_msgs pluginlib)
        catkin_package(INCLUDE_DIRS include LIBRARIES loaders_provider loaders_misc)
        include_directories(include ${catkin_INCLUDE_DIRS})
        add_library(loaders_provider src/provider.cpp)
        add_library(loaders_misc src/unrelated.cpp src/plugin.cpp)
        """,
    "loaders/include/loaders/loader.h": """
        #pragma once
        #include <ros/ros.h>
        #include <loaders/provider.h>
        namespace loaders {
        class PluginThing;
        template <typename T>
        class Loader {
         public:
          explicit Loader(const ros::NodeHandle& nh) : nh_(nh) {}
          T load(const std::string& name) {
            Provider provider(nh_);
            provider.announce(name);
            return T();
          }
         private:
          ros::NodeHandle nh_;
          PluginThing* described_ = nullptr;  // a plugin class: its file stays out
        };
        }
        """,
    "loaders/include/loaders/provider.h": """
        #pragma once
        #include <ros/ros.h>
        namespace loaders {
        class Provider {
         public:
          explicit Provider(const ros::NodeHandle& nh);
          void announce(const std::string& name);
         private:
          ros::NodeHandle nh_;
          ros::Publisher pub_;
        };
        }
        """,
    "loaders/src/provider.cpp": """
        #include <std_msgs/String.h>
        #include <loaders/provider.h>
        namespace loaders {
        Provider::Provider(const ros::NodeHandle& nh) : nh_(nh) {
          pub_ = nh_.advertise<std_msgs::String>("loaded", 1);
        }
        void Provider::announce(const std::string& name) {
          std_msgs::String msg;
          msg.data = name;
          pub_.publish(msg);
        }
        }
        """,
    "loaders/include/loaders/unrelated.h": """
        #pragma once
        #include <ros/ros.h>
        namespace loaders { class Unrelated { public: explicit Unrelated(ros::NodeHandle& nh);
                                              ros::Publisher pub_; }; }
        """,
    # a header the node includes and whose class it never uses: its code does not run
    "loaders/include/loaders/bystander.h": """
        #pragma once
        #include <ros/ros.h>
        #include <loaders/unrelated.h>
        namespace loaders {
        class Bystander {
         public:
          explicit Bystander(ros::NodeHandle& nh) : unrelated_(nh) {}
         private:
          Unrelated unrelated_;
        };
        }
        """,
    "loaders/src/unrelated.cpp": """
        #include <std_msgs/String.h>
        #include <loaders/unrelated.h>
        namespace loaders {
        Unrelated::Unrelated(ros::NodeHandle& nh) {
          pub_ = nh.advertise<std_msgs::String>("unrelated", 1);
        }
        }
        """,
    "loaders/src/plugin.cpp": """
        #include <ros/ros.h>
        #include <std_msgs/String.h>
        #include <pluginlib/class_list_macros.h>
        namespace loaders {
        class Base { public: virtual ~Base() {} };
        class PluginThing : public Base {
         public:
          PluginThing();
          ros::Publisher pub_;
        };
        PluginThing::PluginThing() {
          ros::NodeHandle nh;
          pub_ = nh.advertise<std_msgs::String>("plugin", 1);
        }
        }
        PLUGINLIB_EXPORT_CLASS(loaders::PluginThing, loaders::Base)
        """,
    "robot/package.xml": package_xml("robot", "catkin").replace(
        "</package>", "<depend>roscpp</depend><depend>loaders</depend></package>"),
    "robot/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(robot)
        find_package(catkin REQUIRED COMPONENTS roscpp loaders)
        catkin_package()
        include_directories(${catkin_INCLUDE_DIRS})
        add_executable(robot src/robot.cpp)
        target_link_libraries(robot ${catkin_LIBRARIES})
        """,
    "robot/src/robot.cpp": """
        #include <ros/ros.h>
        #include <loaders/loader.h>
        #include <loaders/bystander.h>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "robot");
          ros::NodeHandle nh("~");
          loaders::Loader<int> loader(nh);
          int rate = loader.load("rate");
          ros::spin();
          return rate;
        }
        """,
}


def test_a_class_built_by_a_linked_header_brings_its_file(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages["robot"].nodes if n.executable == "robot")
    assert node.sources == ["robot/src/robot.cpp", "loaders/src/provider.cpp"]
    extract_nodes([node], ws, cache_dir=None, jobs=1)
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "~loaded")]
    assert node.completeness == "complete", node.completeness_reasons
