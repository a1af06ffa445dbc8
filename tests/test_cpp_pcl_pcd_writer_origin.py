"""PCL's ``PCDWriter::write(file, PCLPointCloud2, origin, orientation, binary)`` is
declared by the pcl stand-in: pcl_ros' PCDWriter nodelet writes each cloud so in the
callback that reads ``~filename`` and was partial for "no matching member function for
call to 'write'"."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

CMAKE = """
    cmake_minimum_required(VERSION 3.0.2)
    project(writer)
    find_package(catkin REQUIRED COMPONENTS roscpp pcl_ros pcl_conversions)
    catkin_package()
    include_directories(${catkin_INCLUDE_DIRS})
    add_executable(writer src/writer.cpp)
    target_link_libraries(writer ${catkin_LIBRARIES})
    """

SOURCE = """
    #include <ros/ros.h>
    #include <pcl/io/pcd_io.h>
    #include <pcl_conversions/pcl_conversions.h>
    #include <sensor_msgs/PointCloud2.h>
    pcl::PCDWriter writer;
    void cb(const sensor_msgs::PointCloud2::ConstPtr& cloud) {
      std::string name;
      ros::param::get("~filename", name);
      pcl::PCLPointCloud2 pcl_cloud;
      pcl_conversions::toPCL(*cloud, pcl_cloud);
      writer.write(name, pcl_cloud, Eigen::Vector4f::Zero(), Eigen::Quaternionf::Identity(),
                   true);
    }
    int main(int argc, char** argv) {
      ros::init(argc, argv, "writer");
      ros::NodeHandle n("~");
      ros::Subscriber s = n.subscribe("input", 1, cb);
      ros::spin();
    }
    """


def test_a_cloud_written_with_its_origin_parses(write_tree) -> None:
    root = write_tree({"writer/package.xml": package_xml("writer", "catkin"),
                       "writer/CMakeLists.txt": CMAKE, "writer/src/writer.cpp": SOURCE})
    ws = scan([str(root)])
    package = ws.packages["writer"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    (node,) = package.nodes
    assert sorted((c.kind, c.name) for c in node.calls) == [
        ("read", "~filename"), ("subscribe", "~input")]
    assert node.completeness == "complete", node.completeness_reasons
