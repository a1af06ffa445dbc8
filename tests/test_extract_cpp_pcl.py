"""Perception nodes that use the Point Cloud Library in a workspace without PCL's sources
(installed, as in every ROS distribution): the stand-ins of ``standin/fallback`` give its
point types and registration macros, ``pcl::PointCloud``, filters, search, I/O and
perception_pcl's conversions and transforms, so the node parses clean and gives its calls;
a ``pcl::PointCloud<T>`` published or subscribed (pcl_ros, ROS 1) is a
``sensor_msgs/PointCloud2`` on the wire."""

from __future__ import annotations

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.extract.cpp.headers import FALLBACK, _fallback_file
from haros_arch.workspace import scan

UNCLEAN = ("CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_CALL_UNRESOLVED",
           "CPP_NAMES_DECLARED", "CPP_ERROR_NEAR_CALL")

PACKAGE = ('<package format="2"><name>p</name><version>1.0.0</version>'
           "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
           "<license>BSD</license></package>")

# a point type of the driver's own, registered the way ouster-ros and velodyne do
POINT = """
namespace lidar {
struct EIGEN_ALIGN16 Point {
  PCL_ADD_POINT4D;
  PCL_ADD_INTENSITY;
  float range;
  uint16_t ring;
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};
struct EIGEN_ALIGN16 ColorPoint {
  PCL_ADD_POINT4D;
  PCL_ADD_RGB;
  PCL_ADD_NORMAL4D;
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};
}  // namespace lidar
POINT_CLOUD_REGISTER_POINT_STRUCT(lidar::Point,
    (float, x, x)(float, y, y)(float, z, z)(float, intensity, intensity)
    (float, range, range)(uint16_t, ring, ring))
"""

ROS1 = """
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <pcl/point_types.h>
#include <pcl/point_cloud.h>
#include <pcl/register_point_struct.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/filters/passthrough.h>
#include <pcl/filters/crop_box.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/io/pcd_io.h>
#include <pcl_conversions/pcl_conversions.h>
#include <pcl_ros/point_cloud.h>
#include <pcl_ros/transforms.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf/transform_listener.h>
""" + POINT + """
namespace lidar {
typedef pcl::PointCloud<Point> Cloud;
class Filter : public nodelet::Nodelet {
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    points_ = nh.advertise<Cloud>("points", 10);
    raw_ = nh.advertise<sensor_msgs::PointCloud2>("raw", 10);
    xyz_ = nh.advertise<pcl::PointCloud<pcl::PointXYZ>>("xyz", 1);
    sub_ = nh.subscribe("scan", 1, &Filter::cloud, this);
    typed_ = nh.subscribe<pcl::PointCloud<pcl::PointXYZI>>("typed", 1, &Filter::typed, this);
  }
  void cloud(const sensor_msgs::PointCloud2ConstPtr& msg) {
    Cloud::Ptr in(new Cloud);
    pcl::fromROSMsg(*msg, *in);
    Point p;
    p.x = 1.f; p.intensity = 2.f; p.ring = 3;
    in->push_back(p);
    in->header.frame_id = "lidar";
    pcl::VoxelGrid<Point> grid;
    grid.setInputCloud(in);
    grid.setLeafSize(0.1f, 0.1f, 0.1f);
    Cloud out;
    grid.filter(out);
    pcl::PassThrough<Point> pass;
    pass.setInputCloud(out.makeShared());
    pass.setFilterFieldName("z");
    pass.setFilterLimits(-1.0, 1.0);
    pass.filter(out);
    pcl::CropBox<Point> box;
    box.setMin(Eigen::Vector4f(-1, -1, -1, 1));
    box.setNegative(true);
    pcl::PointIndices::Ptr inliers(new pcl::PointIndices);
    pcl::ExtractIndices<Point> extract;
    extract.setIndices(inliers);
    pcl::search::KdTree<Point>::Ptr tree(new pcl::search::KdTree<Point>);
    pcl::EuclideanClusterExtraction<Point> ec;
    ec.setSearchMethod(tree);
    std::vector<pcl::PointIndices> clusters;
    ec.extract(clusters);
    pcl::KdTreeFLANN<Point> flann;
    pcl::Indices found; std::vector<float> distances;
    flann.nearestKSearch(p, 3, found, distances);
    Cloud moved;
    pcl_ros::transformPointCloud("map", out, moved, listener_);
    pcl::io::savePCDFileBinary("out.pcd", moved);
    for (const auto& q : moved.points) { (void)q.x; }
    points_.publish(moved.makeShared());
    sensor_msgs::PointCloud2 wire;
    pcl::toROSMsg(moved, wire);
    pcl_conversions::fromPCL(moved.header, wire.header);
    raw_.publish(wire);
  }
  void typed(const pcl::PointCloud<pcl::PointXYZI>::ConstPtr& msg) { (void)msg->size(); }
  ros::Publisher points_, raw_, xyz_;
  ros::Subscriber sub_, typed_;
  tf::TransformListener listener_;
};
}  // namespace lidar
PLUGINLIB_EXPORT_CLASS(lidar::Filter, nodelet::Nodelet)
"""

ROS2 = """
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <pcl/point_types.h>
#include <pcl/PCLPointCloud2.h>
#include <pcl/common/transforms.h>
#include <pcl/common/common.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/search/kdtree.h>
#include <pcl_conversions/pcl_conversions.h>
#include <pcl_ros/transforms.hpp>
#include <tf2_ros/buffer.h>
""" + POINT + """
// a filter of the node's own reads the protected members of PCL's
template<class PointT> class VoxelGridEx : public pcl::VoxelGrid<PointT> {
 public:
  Eigen::Vector4f leaf() const { return this->leaf_size_; }
  bool all() const { return this->downsample_all_data_ && !this->filter_name_.empty(); }
};

class Downsampler : public rclcpp::Node {
 public:
  Downsampler() : rclcpp::Node("downsampler") {
    leaf_ = declare_parameter("leaf_size", 0.2);
    pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("output", 10);
    sub_ = create_subscription<sensor_msgs::msg::PointCloud2>(
      "input", 10, [this](sensor_msgs::msg::PointCloud2::ConstSharedPtr msg) { cloud(msg); });
  }
  void cloud(const sensor_msgs::msg::PointCloud2::ConstSharedPtr& msg) {
    pcl::PCLPointCloud2::Ptr pc2(new pcl::PCLPointCloud2);
    pcl_conversions::toPCL(*msg, *pc2);
    int x = pcl::getFieldIndex(*msg, "x");
    VoxelGridEx<pcl::PointXYZ> own;
    own.setLeafSize(own.leaf());
    if (x < 0 || !own.all()) return;
    pcl::VoxelGrid<pcl::PCLPointCloud2> grid;
    grid.setInputCloud(pc2);
    grid.setLeafSize(leaf_, leaf_, leaf_);
    pcl::PCLPointCloud2 small;
    grid.filter(small);
    pcl::PointCloud<lidar::Point>::Ptr points = std::make_shared<pcl::PointCloud<lidar::Point>>();
    pcl::fromPCLPointCloud2(small, *points);
    pcl::PointXYZ lo, hi;
    pcl::PointCloud<pcl::PointXYZ> xyz;
    pcl::copyPointCloud(*points, xyz);
    pcl::getMinMax3D(xyz, lo, hi);
    Eigen::Affine3f shift = pcl::getTransformation(1.f, 0.f, 0.f, 0.f, 0.f, 0.f);
    pcl::transformPointCloud(xyz, xyz, shift);
    sensor_msgs::msg::PointCloud2 out;
    pcl::toROSMsg(xyz, out);
    pcl::moveFromROSMsg(out, xyz);
    sensor_msgs::msg::PointCloud2 moved;
    pcl_ros::transformPointCloud("map", out, moved, *buffer_);
    pub_->publish(moved);
  }
  double leaf_;
  std::shared_ptr<tf2_ros::Buffer> buffer_;
  rclcpp::Publisher<sensor_msgs::msg::PointCloud2>::SharedPtr pub_;
  rclcpp::Subscription<sensor_msgs::msg::PointCloud2>::SharedPtr sub_;
};
"""


def _extract(tmp_path, text: str, root=None) -> CppResult:
    (tmp_path / "package.xml").write_text(PACKAGE)
    source = tmp_path / "node.cpp"
    source.write_text(text)
    return extract_cpp([str(source)], scan([str(root or tmp_path)]), cache_dir=None)


def _unclean(result: CppResult) -> list[tuple[str, str]]:
    return [(d.code, d.message) for d in result.diagnostics if d.code in UNCLEAN]


def test_a_ros_1_nodelet_with_pcl_parses_and_publishes_point_clouds(tmp_path) -> None:
    result = _extract(tmp_path, ROS1)
    assert _unclean(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "points", "sensor_msgs/PointCloud2"),
        ("publish", "raw", "sensor_msgs/PointCloud2"),
        ("publish", "xyz", "sensor_msgs/PointCloud2"),
        ("subscribe", "scan", "sensor_msgs/PointCloud2"),
        ("subscribe", "typed", "sensor_msgs/PointCloud2"),
        ("subscribe", "/tf", "tf2_msgs/TFMessage"),  # tf's listener
        ("subscribe", "/tf_static", "tf2_msgs/TFMessage"),
    ]


def test_a_ros_2_node_with_pcl_parses(tmp_path) -> None:
    result = _extract(tmp_path, ROS2)
    assert _unclean(result) == []
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("declare", "leaf_size", "double"),
        ("publish", "output", "sensor_msgs/msg/PointCloud2"),
        ("subscribe", "input", "sensor_msgs/msg/PointCloud2"),
    ]


def test_a_pcl_header_without_a_stand_in_file_is_the_umbrella() -> None:
    assert _fallback_file("pcl/segmentation/sac_segmentation.h") == f"{FALLBACK}/pcl/haros_pcl.h"
    assert _fallback_file("pcl_ros/transforms.hpp") == f"{FALLBACK}/pcl_ros/haros_pcl_ros.h"
    assert _fallback_file("pcl_msgs/PointIndices.h") is None
    assert _fallback_file("../pcl/point_types.h") is None


def test_the_workspace_s_own_pcl_conversions_win(tmp_path) -> None:
    """perception_pcl's sources in the workspace: its header, not the stand-in."""
    own = tmp_path / "perception_pcl" / "pcl_conversions"
    (own / "include" / "pcl_conversions").mkdir(parents=True)
    (own / "package.xml").write_text(PACKAGE.replace("<name>p</name>",
                                                     "<name>pcl_conversions</name>"))
    (own / "include" / "pcl_conversions" / "pcl_conversions.h").write_text(
        "namespace pcl_conversions { int workspace_own(); }\n")
    node = tmp_path / "node"
    node.mkdir()
    result = _extract(node, "#include <pcl_conversions/pcl_conversions.h>\n"
                            "int a = pcl_conversions::workspace_own();\n", tmp_path)
    assert _unclean(result) == []


def test_each_filter_and_registration_class_has_its_own_pointer(tmp_path) -> None:
    """``pcl::ApproximateVoxelGrid<PointT>::Ptr f(new ...); f->setLeafSize(...)``: a
    stand-in class without its own ``Ptr`` named its base's (``Filter<PointT>``), which
    has no ``setLeafSize``; so for StatisticalOutlierRemoval, RadiusOutlierRemoval and
    ICP / GICP / NDT's setters (hdl_graph_slam's prefiltering and registration code,
    errors in the functions that read its parameters)."""
    result = _extract(tmp_path, """
#include <ros/ros.h>
#include <pcl/point_types.h>
#include <pcl/filters/approximate_voxel_grid.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/registration/gicp.h>
#include <pcl/registration/ndt.h>
typedef pcl::PointXYZI PointT;
int main(int argc, char** argv) {
  ros::init(argc, argv, "filters");
  ros::NodeHandle pnh("~");
  pcl::Filter<PointT>::Ptr filter;
  pcl::ApproximateVoxelGrid<PointT>::Ptr grid(new pcl::ApproximateVoxelGrid<PointT>());
  grid->setLeafSize(0.1f, 0.1f, 0.1f);
  filter = grid;
  pcl::StatisticalOutlierRemoval<PointT>::Ptr sor(new pcl::StatisticalOutlierRemoval<PointT>());
  sor->setMeanK(pnh.param<int>("mean_k", 20));
  pcl::GeneralizedIterativeClosestPoint<PointT, PointT>::Ptr gicp(
      new pcl::GeneralizedIterativeClosestPoint<PointT, PointT>());
  gicp->setCorrespondenceRandomness(pnh.param<int>("randomness", 20));
  pcl::NormalDistributionsTransform<PointT, PointT>::Ptr ndt(
      new pcl::NormalDistributionsTransform<PointT, PointT>());
  ndt->setResolution(pnh.param<double>("resolution", 1.0));
  pcl::Registration<PointT, PointT>::Ptr registration = ndt;
  // hdl_localization's matching status: the target's search tree of the registration
  std::vector<int> k_indices;
  std::vector<float> k_sq_dists;
  registration->getSearchMethodTarget()->nearestKSearch(PointT(), 1, k_indices, k_sq_dists);
  registration->getInputTarget();
}
""")
    assert _unclean(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~mean_k"), ("read", "~randomness"), ("read", "~resolution")]


def test_the_one_argument_conversions_of_stamps_and_headers(tmp_path) -> None:
    """pcl_conversions' ``fromPCL(stamp)`` returns the ROS time (hdl_graph_slam's
    prefiltering deskew: ``ros::Time stamp = pcl_conversions::fromPCL(cloud->header.
    stamp);``), ``fromPCL(header)`` the message header and ``toPCL(x)`` the PCL side; the
    stand-in had only the two-argument forms, an error in the function that reads the
    node's parameters."""
    result = _extract(tmp_path, """
#include <ros/ros.h>
#include <pcl/point_types.h>
#include <pcl/point_cloud.h>
#include <pcl_conversions/pcl_conversions.h>
#include <std_msgs/Header.h>
typedef pcl::PointXYZI PointT;
void deskew(ros::NodeHandle& pnh, const pcl::PointCloud<PointT>::ConstPtr& cloud) {
  ros::Time stamp = pcl_conversions::fromPCL(cloud->header.stamp);
  std_msgs::Header header = pcl_conversions::fromPCL(cloud->header);
  pcl::PointCloud<PointT> out;
  out.header = pcl_conversions::toPCL(header);
  out.header.stamp = pcl_conversions::toPCL(stamp);
  pnh.param<double>("scan_period", 0.1);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "deskew");
  ros::NodeHandle pnh("~");
  deskew(pnh, pcl::PointCloud<PointT>::ConstPtr());
}
""")
    assert _unclean(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~scan_period")]


def test_a_point_type_aligned_after_its_body_parses(tmp_path) -> None:
    """LIO-SAM writes each point type's alignment after its body, ``} EIGEN_ALIGN16;``:
    Eigen's macro is GCC's ``__attribute__((aligned(16)))`` there, which may follow a
    class body; the stand-in's ``alignas(16)`` may not (clang: an attribute list cannot
    appear here), which left every such type and its uses an error. The type is 16-byte
    aligned either way."""
    result = _extract(tmp_path, """
#include <ros/ros.h>
#include <pcl/point_types.h>
#include <pcl/point_cloud.h>
#include <pcl_conversions/pcl_conversions.h>
#include <sensor_msgs/PointCloud2.h>
struct PointXYZIRPYT {
  PCL_ADD_POINT4D
  PCL_ADD_INTENSITY;
  float roll;
  double time;
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
} EIGEN_ALIGN16;
POINT_CLOUD_REGISTER_POINT_STRUCT(PointXYZIRPYT,
    (float, x, x)(float, y, y)(float, z, z)(float, intensity, intensity)
    (float, roll, roll)(double, time, time))
static_assert(alignof(PointXYZIRPYT) == 16, "aligned as Eigen aligns it");
typedef PointXYZIRPYT PointTypePose;
int main(int argc, char** argv) {
  ros::init(argc, argv, "map");
  ros::NodeHandle nh;
  ros::Publisher poses = nh.advertise<sensor_msgs::PointCloud2>("poses", 1);
  pcl::PointCloud<PointTypePose>::Ptr cloud(new pcl::PointCloud<PointTypePose>());
  PointTypePose p;
  p.roll = 1.f;
  cloud->push_back(p);
  sensor_msgs::PointCloud2 msg;
  pcl::toROSMsg(*cloud, msg);
  poses.publish(msg);
}
""")
    assert _unclean(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "poses")]
