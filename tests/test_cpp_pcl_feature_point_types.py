"""PCL's feature descriptors (pcl/point_types.h) are types of the pcl stand-in: a name in
capitals not declared, ``pcl::SHOT352``, was taken for a constant, so pcl_ros'
SHOTEstimation nodelet, which advertises a ``pcl::PointCloud<pcl::SHOT352>`` on
``output``, lost that publisher's name and type and was partial."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

CMAKE = """
    cmake_minimum_required(VERSION 3.0.2)
    project(features)
    find_package(catkin REQUIRED COMPONENTS roscpp pcl_ros)
    catkin_package()
    include_directories(${catkin_INCLUDE_DIRS})
    add_executable(features src/features.cpp)
    target_link_libraries(features ${catkin_LIBRARIES})
    """

SOURCE = """
    #include <ros/ros.h>
    #include <pcl_ros/point_cloud.h>
    #include <pcl/point_types.h>
    int main(int argc, char** argv) {
      ros::init(argc, argv, "features");
      ros::NodeHandle n("~");
      ros::Publisher shot = n.advertise<pcl::PointCloud<pcl::SHOT352> >("output", 1);
      ros::Publisher vfh = n.advertise<pcl::PointCloud<pcl::VFHSignature308> >("vfh", 1);
      ros::spin();
    }
    """


def test_a_cloud_of_a_feature_descriptor_is_a_point_cloud(write_tree) -> None:
    root = write_tree({"features/package.xml": package_xml("features", "catkin"),
                       "features/CMakeLists.txt": CMAKE,
                       "features/src/features.cpp": SOURCE})
    ws = scan([str(root)])
    package = ws.packages["features"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    (node,) = package.nodes
    assert [(c.kind, c.name, c.type) for c in node.calls] == [
        ("publish", "~output", "sensor_msgs/PointCloud2"),
        ("publish", "~vfh", "sensor_msgs/PointCloud2")]
    assert node.completeness == "complete", node.completeness_reasons
