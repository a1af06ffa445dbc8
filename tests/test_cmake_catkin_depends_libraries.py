"""catkin's generated config of a package adds the libraries of its
``catkin_package(CATKIN_DEPENDS ...)`` to its own ``<pkg>_LIBRARIES``, so a node that
links the package links those too (OpenMower's mower_comms_v1 links xesc_driver, whose
``XescDriver`` builds xesc_2040_driver's ``Xesc2040Driver``; xesc_driver's library
target links nothing: the node was partial, "of ROS package xesc_2040_driver is built
here and its code is not read"). A CATKIN_DEPENDS cycle ends."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml


def _library(name: str, depends: str, source: str, text: str) -> dict[str, str]:
    return {
        f"{name}/package.xml": package_xml(name, "catkin"),
        f"{name}/CMakeLists.txt": f"""
            cmake_minimum_required(VERSION 3.0.2)
            project({name})
            find_package(catkin REQUIRED COMPONENTS roscpp {depends})
            catkin_package(INCLUDE_DIRS include LIBRARIES {name} CATKIN_DEPENDS roscpp {depends})
            include_directories(include ${{catkin_INCLUDE_DIRS}})
            add_library({name} {source})
            """,
        f"{name}/{source}": text,
    }


FILES = {
    **_library("motor", "driver", "src/motor.cpp", """
        #include <ros/ros.h>
        #include <std_msgs/Float64.h>
        #include <motor/motor.h>
        namespace motor {
        Motor::Motor(ros::NodeHandle& nh) {
          pub_ = nh.advertise<std_msgs::Float64>("motor_current", 1);
        }
        }
        """),
    "motor/include/motor/motor.h": """
        #include <ros/ros.h>
        namespace motor { class Motor { public: explicit Motor(ros::NodeHandle& nh);
                                        ros::Publisher pub_; }; }
        """,
    **_library("driver", "motor", "src/driver.cpp", """
        #include <ros/ros.h>
        #include <driver/driver.h>
        #include <motor/motor.h>
        namespace driver {
        Driver::Driver(ros::NodeHandle& nh) { motor_ = new motor::Motor(nh); }
        }
        """),
    "driver/include/driver/driver.h": """
        #include <ros/ros.h>
        namespace motor { class Motor; }
        namespace driver { class Driver { public: explicit Driver(ros::NodeHandle& nh);
                                          motor::Motor* motor_; }; }
        """,
    "comms/package.xml": package_xml("comms", "catkin"),
    "comms/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.0.2)
        project(comms)
        find_package(catkin REQUIRED COMPONENTS roscpp driver)
        catkin_package()
        include_directories(${catkin_INCLUDE_DIRS})
        add_executable(comms src/comms.cpp)
        target_link_libraries(comms ${catkin_LIBRARIES})
        """,
    "comms/src/comms.cpp": """
        #include <ros/ros.h>
        #include <driver/driver.h>
        int main(int argc, char** argv) {
          ros::init(argc, argv, "comms");
          ros::NodeHandle n("left");
          driver::Driver d(n);
          ros::spin();
        }
        """,
}


def test_a_catkin_depends_library_comes_with_the_package(write_tree) -> None:
    root = write_tree(FILES)
    ws = scan([str(root)])
    for each in ws.packages.values():
        each.nodes, _ = cmake.parse_package(each, ws)
    node = next(n for n in ws.packages["comms"].nodes if n.executable == "comms")
    extract_nodes([node], ws, cache_dir=None, jobs=1)
    assert node.sources == ["comms/src/comms.cpp", "driver/src/driver.cpp",
                            "motor/src/motor.cpp"]
    assert [(c.kind, c.name) for c in node.calls] == [("publish", "left/motor_current")]
    assert node.completeness == "complete"
