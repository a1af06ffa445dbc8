"""A ROS 1 node's PCL pointers are boost::shared_ptr, as Noetic's PCL 1.10 (and Melodic's
1.8) make them: hdl_graph_slam's prefiltering nodelet keeps a ``pcl::Filter<PointT>::Ptr
downsample_filter`` and assigns it ``boost::shared_ptr<pcl::VoxelGrid<PointT>>``
(prefiltering_nodelet.cpp:58 at 7216318^). The PCL stand-in's pointers were
std::shared_ptr whatever the unit's ROS, so the assignment was clang's "no viable
overloaded '='", the function that reads the filter's parameters a C++ error near a ROS
call, the nodelet partial, and the launch file's ``radius_min_neighbors``, which the
nodelet reads misspelt as ``radus_min_neighbors``, undecided instead of set and never read.
A ROS 2 unit keeps std::shared_ptr (PCL 1.12 of Humble's Ubuntu)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

UNCLEAN = ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")

ROS1 = """\
#include <ros/ros.h>
#include <pcl/point_types.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/filters/approximate_voxel_grid.h>
#include <pcl/filters/radius_outlier_removal.h>
#include <boost/shared_ptr.hpp>
#include <boost/make_shared.hpp>
#include <string>

typedef pcl::PointXYZI PointT;
pcl::Filter<PointT>::Ptr downsample_filter;
pcl::Filter<PointT>::Ptr outlier_filter;

void initialize_params(ros::NodeHandle& pnh) {
  std::string method = pnh.param<std::string>("downsample_method", "VOXELGRID");
  double resolution = pnh.param<double>("downsample_resolution", 0.1);
  if (method == "VOXELGRID") {
    boost::shared_ptr<pcl::VoxelGrid<PointT>> voxelgrid(new pcl::VoxelGrid<PointT>());
    voxelgrid->setLeafSize(resolution, resolution, resolution);
    downsample_filter = voxelgrid;
  } else {
    downsample_filter = boost::make_shared<pcl::ApproximateVoxelGrid<PointT>>();
  }
  pcl::RadiusOutlierRemoval<PointT>::Ptr rad(new pcl::RadiusOutlierRemoval<PointT>());
  rad->setMinNeighborsInRadius(pnh.param<int>("radus_min_neighbors", 2));
  outlier_filter = rad;
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "prefiltering");
  ros::NodeHandle pnh("~");
  initialize_params(pnh);
  ros::spin();
  return 0;
}
"""

ROS2 = """\
#include <rclcpp/rclcpp.hpp>
#include <pcl/point_types.h>
#include <pcl/point_cloud.h>
#include <pcl/filters/voxel_grid.h>
#include <memory>

typedef pcl::PointXYZ PointT;

class Filtering : public rclcpp::Node {
 public:
  Filtering() : rclcpp::Node("filtering") {
    double leaf = declare_parameter("leaf_size", 0.2);
    std::shared_ptr<pcl::VoxelGrid<PointT>> grid = std::make_shared<pcl::VoxelGrid<PointT>>();
    grid->setLeafSize(leaf, leaf, leaf);
    filter_ = grid;
    pcl::PointCloud<PointT>::Ptr cloud = std::make_shared<pcl::PointCloud<PointT>>();
    grid->setInputCloud(cloud);
  }
  pcl::Filter<PointT>::Ptr filter_;
};
"""

LAUNCH = """\
<launch>
  <node pkg="filters" type="prefiltering" name="prefiltering">
    <param name="downsample_method" value="VOXELGRID" />
    <param name="downsample_resolution" value="0.1" />
    <param name="radius_min_neighbors" value="2" />
  </node>
</launch>
"""


def _extract(tmp_path, text: str, depends: str):
    (tmp_path / "package.xml").write_text(package_xml("filters").replace(
        "</package>", f"{depends}<depend>pcl_ros</depend></package>"))
    source = tmp_path / "node.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)


def test_a_ros_1_filter_pointer_takes_a_boost_pointer_of_a_subclass(tmp_path) -> None:
    result = _extract(tmp_path, ROS1, "<buildtool_depend>catkin</buildtool_depend>"
                                      "<depend>roscpp</depend>")
    assert [(d.code, d.message) for d in result.diagnostics if d.code in UNCLEAN] == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("read", "~downsample_method", "str"),
        ("read", "~downsample_resolution", "double"),
        ("read", "~radus_min_neighbors", "int"),
    ]


def test_a_ros_2_filter_pointer_stays_a_std_pointer(tmp_path) -> None:
    result = _extract(tmp_path, ROS2, "<buildtool_depend>ament_cmake</buildtool_depend>"
                                      "<depend>rclcpp</depend>")
    assert [(d.code, d.message) for d in result.diagnostics if d.code in UNCLEAN] == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("declare", "leaf_size", "double")]


def test_the_misspelt_read_leaves_the_launch_parameter_unread(write_tree) -> None:
    root = write_tree({
        "src/filters/package.xml": package_xml("filters").replace(
            "</package>", "<depend>roscpp</depend><depend>pcl_ros</depend></package>"),
        "src/filters/CMakeLists.txt": (
            "project(filters)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
            "add_executable(prefiltering src/node.cpp)\n"),
        "src/filters/src/node.cpp": ROS1,
        "src/filters/launch/filters.launch": LAUNCH,
        "project.yaml": "project: p\ndistro: noetic\nworkspace: src\nconfigurations:\n"
                        "  c: [filters/launch/filters.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {})
    partial = [d.message for d in model.diagnostics if d.code == "CPP_NODE_PARTIAL"]
    assert partial == []
    found = run_catalogue(model)
    assert sorted(f.entities[0] for f in found if f.rule == "parameter-set-not-read") == [
        "parameter:/prefiltering/radius_min_neighbors"]
    assert [f for f in found if f.rule == "parameter-set-not-read-undecided"] == []
