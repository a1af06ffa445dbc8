"""An unqualified call of a standard library function that C++ finds through its
arguments (argument-dependent lookup: ``make_pair(laser->getName(), laser)``, a
``std::string`` argument) fails when the arguments' types come from a header the parse
lacks: clang says ``use of undeclared identifier 'make_pair'``. slam_gmapping's
initMapper, which reads parameters, had that error, and the node was partial: every
parameter the launch set and the node did not read (``map_udpate_interval``) was
undecided. Such an error, outside the statement of any ROS call, hides none: the node
stays complete. Where the arguments are values of names declared permissively, the
function is declared too, found the same way (``synthesis.Names.friends``)."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml


def _files(statement: str) -> dict[str, str]:
    return {
        "mapper/package.xml": package_xml("mapper", "catkin").replace(
            "<export>", "<depend>roscpp</depend><depend>std_msgs</depend><export>"),
        "mapper/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(mapper)
            find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
            add_executable(mapper src/mapper.cpp)
            """,
        "mapper/src/mapper.cpp": """
            #include <map>
            #include <string>
            #include <utility>
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            #include <gmapping/sensor/sensor_base/sensor.h>
            class Mapper {
            public:
              Mapper() : private_nh_("~") {}
              void init() {
                double interval;
                if (!private_nh_.getParam("map_update_interval", interval))
                  interval = 5.0;
                GMapping::SensorMap smap;
                """ + statement + """
                pub_ = node_.advertise<std_msgs::String>("entropy", 1);
              }
            private:
              ros::NodeHandle node_, private_nh_;
              ros::Publisher pub_;
              GMapping::RangeSensor* laser_;
            };
            int main(int argc, char ** argv)
            {
              ros::init(argc, argv, "mapper");
              Mapper mapper;
              mapper.init();
              ros::spin();
            }
            """,
    }


def _node(write_tree, statement: str):
    ws = scan([str(write_tree(_files(statement)))])
    pkg = ws.packages["mapper"]
    pkg.nodes, _ = cmake.parse_package(pkg, ws)
    found = extract_nodes(pkg.nodes, ws, cache_dir=None, jobs=1)
    return pkg.nodes[0], [d.code for d in found]


def test_a_standard_function_found_through_unknown_arguments_hides_no_call(write_tree):
    node, codes = _node(write_tree, "smap.insert(make_pair(laser_->getName(), laser_));")
    assert sorted((c.kind, c.name) for c in node.calls) == [
        ("publish", "entropy"), ("read", "~map_update_interval")]
    assert "CPP_ERROR_NEAR_CALL" not in codes
    assert node.completeness == "complete"


def test_in_a_ros_call_its_value_is_unknown(write_tree):
    # found through its unknown argument as a function declared permissively, the
    # ROS call parses, and the name it is given is one nobody knows: ``?``
    node, codes = _node(write_tree,
                        "private_nh_.param(make_pair(laser_->getName(), 1).first, interval, 1.0);")
    assert ("read", "~?") in [(c.kind, c.name) for c in node.calls]
    assert "CPP_DYNAMIC_NAME" in codes


def test_a_vendor_function_found_through_unknown_arguments_is_declared(write_tree):
    # not a standard function: the vendor's own, which C++ finds in the namespace of its
    # arguments' types (GMapping's); declared permissively, found the same way, it parses
    # and, handed no node, hides no call
    node, codes = _node(write_tree, "smap.insert(frobnicate(laser_->getName(), laser_));")
    assert "CPP_ERROR_NEAR_CALL" not in codes and node.completeness == "complete"
    assert ("publish", "entropy") in [(c.kind, c.name) for c in node.calls]
